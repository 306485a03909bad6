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
  return along(torso, s);
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

Pose torsoPose(const HeadConfig& head, double t) {
  if (head.motion == HeadMotion::Spin || head.motion == HeadMotion::Bounce)
    return headPose(head, t);
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
