// The preset's orbit camera as matrices.
#pragma once

#include <glm/mat4x4.hpp>

#include "render/view_config.h"

namespace csm {

glm::mat4 cameraView(const CameraConfig& camera);
glm::mat4 cameraProjection(const CameraConfig& camera, float aspect);

}  // namespace csm
