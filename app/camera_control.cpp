#include "app/camera_control.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include "app/params.h"
#include "sim/head/head_model.h"
#include "render/camera.h"

namespace csm {
namespace {

// The parameter's own range, so the mouse can never set what a preset could not hold.
float clampToParam(const char* key, float value) {
  const PresetParam* p = findParam(key);
  return p ? std::clamp(value, float(p->min), float(p->max)) : value;
}

// The camera's right and up axes in world space: rows of cameraView's rotation, so the
// mouse agrees with whatever convention the renderer uses.
void cameraAxes(const CameraConfig& camera, glm::vec3& right, glm::vec3& up) {
  const glm::mat4 v = cameraView(camera);
  right = glm::vec3(v[0][0], v[1][0], v[2][0]);
  up = glm::vec3(v[0][1], v[1][1], v[2][1]);
}

}  // namespace

void orbitCamera(CameraConfig& camera, float dxPixels, float dyPixels) {
  float yaw = camera.yaw - dxPixels * kOrbitDegreesPerPixel;
  yaw = std::remainder(yaw, 360.0f);  // stays in [-180, 180], well inside the range
  camera.yaw = clampToParam("camera.yaw", yaw);
  camera.pitch = clampToParam("camera.pitch", camera.pitch + dyPixels * kOrbitDegreesPerPixel);
}

void panCamera(CameraConfig& camera, float dxPixels, float dyPixels, int viewportHeight) {
  if (viewportHeight <= 0) return;
  glm::vec3 right, up;
  cameraAxes(camera, right, up);
  // Metres per pixel at the target's depth.
  const float perPixel =
      2.0f * camera.distance * std::tan(glm::radians(camera.fov) * 0.5f) / float(viewportHeight);
  glm::vec3 target = camera.target - right * (dxPixels * perPixel) + up * (dyPixels * perPixel);
  const PresetParam* p = findParam("camera.target");
  if (p) target = glm::clamp(target, glm::vec3(float(p->min)), glm::vec3(float(p->max)));
  camera.target = target;
}

void zoomCamera(CameraConfig& camera, float steps) {
  camera.distance = clampToParam("camera.distance", camera.distance * std::pow(0.9f, steps));
}

void frameHead(CameraConfig& camera, const Config& config, const HeadModel& model,
               const Pose& head) {
  // A box around the head spheres, the scalp's grown by the longest strand (hair can reach
  // that far from it in any direction); the camera aims at its centre and backs off until
  // its largest half-extent fits the vertical field of view.
  glm::dvec3 lo(1e30), hi(-1e30);
  auto add = [&](const glm::dvec3& c, double r) {
    lo = glm::min(lo, c - r);
    hi = glm::max(hi, c + r);
  };
  const std::vector<Sphere>& spheres = model.spheres();
  for (const Sphere& s : spheres) add(glm::dvec3(s.center), s.radius);
  const double scalp = spheres.empty() ? 0.1 : spheres.front().radius;
  const double hair = config.hairstyle.file.empty() ? config.hairstyle.lengthMax : 2.0 * scalp;
  add(spheres.empty() ? glm::dvec3(0.0) : glm::dvec3(spheres.front().center), scalp + hair);
  const glm::dvec3 half = 0.5 * (hi - lo);
  const double extent = std::max({half.x, half.y, half.z});
  const double halfFov = glm::radians(double(camera.fov)) * 0.5;
  camera.target = glm::vec3(head.apply(0.5 * (lo + hi)));
  camera.distance = clampToParam("camera.distance", float(1.1 * extent / std::sin(halfFov)));
}

Pose dragHead(const Pose& user, const CameraConfig& camera, const HeadConfig& head, float dxPixels,
              float dyPixels) {
  glm::vec3 right, up;
  cameraAxes(camera, right, up);
  // The preset's motions turn about the pivot, so it stays where the user's pose puts it.
  const glm::dvec3 pivot = user.apply(glm::dvec3(head.pivot));
  Pose p = user;
  if (dxPixels != 0.0f)
    p = compose(rotationAbout(pivot, glm::dvec3(0.0, 1.0, 0.0), dxPixels * kHeadDegreesPerPixel),
                p);
  if (dyPixels != 0.0f)
    p = compose(rotationAbout(pivot, glm::dvec3(right), dyPixels * kHeadDegreesPerPixel), p);
  return p;
}

}  // namespace csm
