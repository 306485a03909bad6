// The head: a rigid pose over time and the spheres the hair collides with.
#pragma once

#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "sim/core/config.h"

namespace csm {

// A rigid transform: x_world = rotation * x_local + translation.
struct Pose {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 translation{0.0};

  glm::dvec3 apply(const glm::dvec3& p) const { return rotation * p + translation; }
  glm::mat4 matrix() const;
};

// a after b: first b, then a.
Pose compose(const Pose& a, const Pose& b);
// The pose that undoes p.
Pose inverse(const Pose& p);
// Slerp of the rotation, lerp of the translation.
Pose interpolate(const Pose& a, const Pose& b, double s);
// A rotation of `degrees` about `axis` through `pivot`.
Pose rotationAbout(const glm::dvec3& pivot, const glm::dvec3& axis, double degrees);

// The body's two rigid parts (docs/METHOD.md section 6.11): the head (cranium, face, upper neck),
// which the roots follow, and the torso (lower neck, shoulders, upper chest).
struct BodyPose {
  Pose head;
  Pose torso;
};

// Where the body is over one frame: keys at evenly spaced fractions of it, the first where the
// frame starts and the last where it ends (two keys: the frame's ends; a motion clip gives more,
// sampled between its frames, so every substep of a frame sees the clip where it is then).
// `keys` are the head's; `torso` the torso's at the same fractions (a motion clip's), or empty
// where the body moves as one with the head.
struct FramePath {
  std::vector<Pose> keys;
  std::vector<Pose> torso;
  const Pose& from() const { return keys.front(); }
  const Pose& to() const { return keys.back(); }
  // At fraction s (0..1) of the frame: the keys around it interpolated.
  Pose at(double s) const;
  // The torso there: the head's pose when `torso` is empty.
  Pose torsoAt(double s) const;
};

// The preset's head motion at time t (seconds): nod, shake and sway turn the head alone about
// head.pivot; spin and bounce move the whole body (torsoPose).
Pose headPose(const HeadConfig& head, double t);
// The torso's part of it: spin and bounce; at rest for the others.
Pose torsoPose(const HeadConfig& head, double t);

// How far the neck turns the head from the torso: about the torso's up (a shake) and any other
// way (a nod, a sway), in degrees.
inline constexpr double kNeckTwistDegrees = 70.0, kNeckSwingDegrees = 40.0;
// Where the torso stands when the head takes pose `head` over a body at `body` (the body's own
// motion: csm::torsoPose): with the body while the neck can make the turn between them, turned
// with the head about the neck (`pivot`, head frame) by what lies beyond the neck's reach.
Pose torsoUnder(const Pose& head, const Pose& body, const glm::dvec3& pivot);

// Head spheres in world space for a pose.
std::vector<Sphere> worldSpheres(const std::vector<Sphere>& local, const Pose& pose);

}  // namespace csm
