#include "app/camera_control.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/renderer.h"
#include "sim/params.h"

namespace csm {
namespace {

// The parameter's own range, so the mouse can never set what a preset could not hold.
float clampToParam(const char* key, float value) {
  const Param* p = findParam(key);
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
  const Param* p = findParam("camera.target");
  if (p) target = glm::clamp(target, glm::vec3(float(p->min)), glm::vec3(float(p->max)));
  camera.target = target;
}

void zoomCamera(CameraConfig& camera, float steps) {
  camera.distance = clampToParam("camera.distance", camera.distance * std::pow(0.9f, steps));
}

void frameHead(CameraConfig& camera, const Config& config, const Pose& head) {
  glm::dvec3 centre(0.0);
  double radius = 0.1;
  if (!config.head.spheres.empty()) {
    centre = glm::dvec3(config.head.spheres.front().center);
    radius = config.head.spheres.front().radius;
  }
  // Hair hangs below the scalp: aim a little under the head's centre, and fit a sphere that
  // holds the head and the longest strands hanging from its crown.
  const double hair = config.hairstyle.file.empty() ? config.hairstyle.lengthMax : 2.0 * radius;
  const glm::dvec3 aim = head.apply(centre - glm::dvec3(0.0, 0.35 * hair, 0.0));
  const double fit = radius + 0.75 * hair;
  const double halfFov = glm::radians(double(camera.fov)) * 0.5;
  camera.target = glm::vec3(aim);
  camera.distance = clampToParam("camera.distance", float(1.15 * fit / std::sin(halfFov)));
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
