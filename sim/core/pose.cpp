#include "sim/core/pose.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace csm {

glm::mat4 Pose::matrix() const {
  glm::dmat4 m = glm::mat4_cast(rotation);
  m[3] = glm::dvec4(translation, 1.0);
  return glm::mat4(m);
}

Pose compose(const Pose& a, const Pose& b) {
  return {glm::normalize(a.rotation * b.rotation), a.rotation * b.translation + a.translation};
}

Pose inverse(const Pose& p) {
  const glm::dquat r = glm::conjugate(p.rotation);
  return {r, -(r * p.translation)};
}

Pose interpolate(const Pose& a, const Pose& b, double s) {
  return {glm::slerp(a.rotation, b.rotation, s), glm::mix(a.translation, b.translation, s)};
}

namespace {

Pose along(const std::vector<Pose>& keys, double s) {
  if (keys.size() < 2) return keys.empty() ? Pose{} : keys.front();
  if (!(s > 0.0)) return keys.front();
  if (s >= 1.0) return keys.back();
  const double u = s * double(keys.size() - 1);
  const size_t k = std::min(keys.size() - 2, size_t(u));
  return interpolate(keys[k], keys[k + 1], u - double(k));
}

}  // namespace

Pose FramePath::at(double s) const {
  return along(keys, s);
}

Pose FramePath::torsoAt(double s) const {
  return torso.empty() ? at(s) : along(torso, s);
}

Pose torsoPose(const HeadConfig& head, double t) {
  if (head.motion == HeadMotion::Spin || head.motion == HeadMotion::Bounce)
    return headPose(head, t);
  return {};
}

namespace {

// The part of a rotation of `angle` (radians) beyond `limit`, about `axis`.
glm::dquat beyond(double angle, const glm::dvec3& axis, double limit) {
  const double over = angle > limit ? angle - limit : angle < -limit ? angle + limit : 0.0;
  return glm::angleAxis(over, axis);
}

}  // namespace

Pose torsoUnder(const Pose& head, const Pose& body, const glm::dvec3& pivot) {
  // The neck's turn, in the world: the head's pose over the body's.
  const Pose neck = compose(head, inverse(body));
  const glm::dvec3 up = glm::normalize(body.rotation * glm::dvec3(0.0, 1.0, 0.0));
  glm::dquat q = glm::normalize(neck.rotation);
  if (q.w < 0.0) q = -q;
  // Swing after twist: the twist about the torso's up, the swing the rest.
  const glm::dvec3 v(q.x, q.y, q.z);
  glm::dquat twist(q.w, glm::dot(v, up) * up);
  twist = glm::length(twist) > 1e-12 ? glm::normalize(twist) : glm::dquat(1.0, 0.0, 0.0, 0.0);
  const glm::dquat swing = glm::normalize(q * glm::inverse(twist));
  const double twistAngle =
      2.0 * std::atan2(glm::dot(glm::dvec3(twist.x, twist.y, twist.z), up), twist.w);
  const glm::dvec3 swingVector(swing.x, swing.y, swing.z);
  const double swingSin = glm::length(swingVector);
  const double swingAngle = 2.0 * std::atan2(swingSin, std::abs(swing.w));
  const glm::dvec3 swingAxis = swingSin > 1e-12
                                   ? swingVector / swingSin * (swing.w < 0 ? -1.0 : 1.0)
                                   : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dquat over =
      glm::normalize(beyond(swingAngle, swingAxis, glm::radians(kNeckSwingDegrees)) *
                     beyond(twistAngle, up, glm::radians(kNeckTwistDegrees)));
  // Turned about the neck, which goes where the head takes it.
  const glm::dvec3 at = body.apply(pivot);
  const Pose extra{over, neck.apply(at) - over * at};
  return compose(extra, body);
}

Pose rotationAbout(const glm::dvec3& pivot, const glm::dvec3& axis, double degrees) {
  Pose p;
  p.rotation = glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
  p.translation = pivot - p.rotation * pivot;
  return p;
}

Pose headPose(const HeadConfig& head, double t) {
  const double phase = 2.0 * M_PI * head.frequency * t;
  const double a = head.amplitude;
  const glm::dvec3 pivot(head.pivot);
  switch (head.motion) {
    case HeadMotion::None:
      return {};
    case HeadMotion::Nod:
      return rotationAbout(pivot, {1, 0, 0}, a * std::sin(phase));
    case HeadMotion::Shake:
      return rotationAbout(pivot, {0, 1, 0}, a * std::sin(phase));
    case HeadMotion::Spin:
      return rotationAbout(pivot, {0, 1, 0}, 360.0 * head.frequency * t);
    case HeadMotion::Sway:
      return rotationAbout(pivot, {0, 0, 1}, a * std::sin(phase));
    case HeadMotion::Bounce: {
      Pose p;
      p.translation.y = 0.01 * a * std::sin(phase);
      return p;
    }
  }
  return {};
}

std::vector<Sphere> worldSpheres(const std::vector<Sphere>& local, const Pose& pose) {
  std::vector<Sphere> out;
  out.reserve(local.size());
  for (const Sphere& s : local)
    out.push_back({glm::vec3(pose.apply(glm::dvec3(s.center))), s.radius});
  return out;
}

}  // namespace csm
