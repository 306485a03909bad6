// The deep opacity maps (Yuksel & Keyser 2008) and the head's shadow map, seen from the
// light: the nearest hair's depth (z0), four opacity layers behind it, the head's depth. The
// light is orthographic around the sphere that holds hair and head this frame.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "gl/framebuffer.h"
#include "gl/texture.h"

namespace csm {

class ShadowMaps {
 public:
  // Reallocates when the size changes.
  void resize(int size);
  int size() const { return size_; }

  // World -> light clip space for a light travelling along `direction` (any length), around
  // the sphere at `center` of `radius`; depth maps linearly over 2 radius.
  static glm::mat4 lightViewProjection(glm::vec3 direction, glm::vec3 center, float radius);

  // Clears all three maps (to "nothing in the way").
  void clear();
  gl::Framebuffer& lightDepthTarget() { return lightDepthFbo_; }
  gl::Framebuffer& headShadowTarget() { return headShadowFbo_; }
  gl::Framebuffer& opacityTarget() { return opacityFbo_; }

  // DEPTH_COMPONENT32F, the nearest hair's light-space depth (1 where there is none).
  const gl::Texture& lightDepth() const { return lightDepth_; }
  // RGBA16F, channel k the cumulative opacity of layer k.
  const gl::Texture& opacityLayers() const { return opacityLayers_; }
  // DEPTH_COMPONENT32F with a comparison sampler: the head's back faces.
  const gl::Texture& headShadow() const { return headShadow_; }

 private:
  int size_ = 0;
  gl::Texture lightDepth_{gl::NoCreate}, headShadow_{gl::NoCreate}, opacityLayers_{gl::NoCreate};
  gl::Framebuffer lightDepthFbo_{gl::NoCreate}, headShadowFbo_{gl::NoCreate},
      opacityFbo_{gl::NoCreate};
};

}  // namespace csm
