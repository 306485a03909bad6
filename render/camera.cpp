#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace csm {

glm::mat4 cameraView(const CameraConfig& camera) {
  const float yaw = glm::radians(camera.yaw), pitch = glm::radians(camera.pitch);
  const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                         std::cos(pitch) * std::cos(yaw));
  return glm::lookAt(camera.target + camera.distance * offset, camera.target,
                     glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 cameraProjection(const CameraConfig& camera, float aspect) {
  // The near plane follows the distance so depth precision does too; hair reaches about
  // 0.4 m in front of the target at most.
  const float nearPlane = std::max(0.002f, 0.02f * camera.distance);
  return glm::perspective(glm::radians(camera.fov), aspect, nearPlane, camera.distance + 10.0f);
}

}  // namespace csm
