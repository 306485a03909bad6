// The follower stage on the CPU: every drawn strand made from its guides' positions, as the
// renderer's follower pass (shaders/render/hair_followers.comp) makes them on the GPU each
// frame. Used where the drawn strands leave the program (--export-hair, the sequence export),
// by the measures, and by the tests as the pass's reference.
//
// A follower's point at rest-length share u takes, from each of its guides, the guide's point
// at the same share and its own rest offset from that point turned as the guide has turned
// there: the head's rotation, then the shortest rotation from the guide's rest tangent (turned
// with the head) to its tangent now. Weighted by the binding's weights. A point the blend puts
// inside the body (the head or the torso, each at its pose) is moved out to its surface, and
// counted.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "sim/core/pose.h"
#include "sim/groom/guides.h"
#include "sim/head/head_model.h"

namespace csm {

// The turn of every guide point: rotation from the rest shape (head frame) to now (world).
// `guidePositions`: the simulated positions, world, in the guide groom's order.
std::vector<glm::quat> guideTurns(const FollowerBinding& b,
                                  const std::vector<glm::vec3>& guidePositions, const Pose& head);

// What the follower stage did to keep the drawn points out of the body.
struct FollowerStats {
  std::size_t pushed = 0;  // points moved out of the body
  double deepest = 0.0;    // the deepest a point but a root is left inside it (m; 0: none)
};

// Every drawn point (world) into `out` (resized to the drawn groom's points); the points moved
// out of the body (`collider`: each part's field, else its spheres, in its own frame, the head's
// at body.head and the torso's at body.torso), and how deep any is left.
FollowerStats makeFollowers(const FollowerBinding& b, const std::vector<glm::vec3>& guidePositions,
                            const BodyPose& body, const SceneHead& collider,
                            std::vector<glm::vec3>& out);
// The same with the body as one, at the head's pose.
FollowerStats makeFollowers(const FollowerBinding& b, const std::vector<glm::vec3>& guidePositions,
                            const Pose& head, const SceneHead& collider,
                            std::vector<glm::vec3>& out);

}  // namespace csm
