// The follower pass: every drawn strand of a groom simulated through its guides
// (sim/groom/guides.h), made each frame on the GPU from the guides' positions, before the
// passes that draw (shaders/render/hair_followers.comp; sim/groom/followers.h is its CPU twin).
// Its output is a positions buffer of the drawn groom, which the rest of the renderer draws as it
// draws a groom simulated whole.
#pragma once

#include <cstddef>
#include <string>

#include "gl/buffer.h"
#include "gl/program.h"
#include "sim/core/pose.h"
#include "sim/groom/guides.h"
#include "sim/head/head_model.h"

namespace csm {

class FollowerPass {
 public:
  // Builds the two programs; false with the compiler's log. Keeps the old ones on failure.
  bool build(std::string* log);
  // Uploads the binding, the guides' layout and the head's shape when `generation` or the
  // binding changed.
  void update(const FollowerBinding& binding, long generation, const HeadModel& head);
  // Makes the drawn points from the guides' positions (`guidePositions`: an SSBO of vec4 per
  // guide particle, world) with the head at body.head and the torso at body.torso, each part
  // keeping them out of it. Returns the drawn positions' SSBO.
  unsigned run(unsigned guidePositions, const BodyPose& body);

  const gl::Buffer& positions() const { return positions_; }
  // Points the last run moved out of the head (reads back: for tests and measures).
  std::size_t pushedPoints() const;
  std::size_t drawnPoints() const { return points_; }

 private:
  gl::Program turns_{gl::NoCreate}, followers_{gl::NoCreate};
  const FollowerBinding* binding_ = nullptr;
  long generation_ = -1;
  std::size_t points_ = 0, guideParticles_ = 0, guides_ = 0, strands_ = 0;
  gl::Buffer drawnRest_{gl::NoCreate}, drawnFirst_{gl::NoCreate}, guideStrand_{gl::NoCreate},
      guideFirst_{gl::NoCreate}, turnsOut_{gl::NoCreate}, boundGuides_{gl::NoCreate},
      boundWeights_{gl::NoCreate}, positions_{gl::NoCreate}, head_{gl::NoCreate},
      pushed_{gl::NoCreate};
  // One part of the body in head_: 0 nothing, 1 a field, 2 spheres; from `first`.
  struct PartShape {
    int shape = 0, first = 0, spheres = 0;
    glm::ivec3 dims{0};
    glm::vec3 origin{0.0f};
    float cell = 1.0f;
  };
  PartShape headPart_, torsoPart_;
};

}  // namespace csm
