#include "render/shadow_maps.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/debug.h"

namespace csm {

void ShadowMaps::resize(int size) {
  if (size == size_) return;
  size_ = size;
  lightDepth_ = gl::Texture::create2D(gl::TextureFormat::Depth32f, size, size);
  lightDepth_.setFilter(gl::Filter::Nearest, gl::Filter::Nearest).setWrap(gl::Wrap::ClampToEdge);
  headShadow_ = gl::Texture::create2D(gl::TextureFormat::Depth32f, size, size);
  headShadow_.setFilter(gl::Filter::Linear, gl::Filter::Linear)
      .setWrap(gl::Wrap::ClampToEdge)
      .setDepthCompare(gl::DepthCompare::LessOrEqual);
  // Half floats: layers sum a few hundred strand opacities at most, and blending them is
  // cheaper than in 32-bit floats.
  opacityLayers_ = gl::Texture::create2D(gl::TextureFormat::Rgba16f, size, size);
  opacityLayers_.setFilter(gl::Filter::Nearest, gl::Filter::Nearest).setWrap(gl::Wrap::ClampToEdge);

  lightDepthFbo_ = gl::Framebuffer();
  lightDepthFbo_.attach(gl::Attachment::Depth, lightDepth_).setDrawBuffers({gl::Attachment::None});
  headShadowFbo_ = gl::Framebuffer();
  headShadowFbo_.attach(gl::Attachment::Depth, headShadow_).setDrawBuffers({gl::Attachment::None});
  opacityFbo_ = gl::Framebuffer();
  opacityFbo_.attach(gl::Attachment::Color0, opacityLayers_)
      .setDrawBuffers({gl::Attachment::Color0});
  for (const gl::Framebuffer* f : {&lightDepthFbo_, &headShadowFbo_, &opacityFbo_}) {
    std::string message;
    if (!f->checkComplete(&message)) gl::logMessage(gl::LogLevel::Error, "shadow maps: " + message);
  }
}

glm::mat4 ShadowMaps::lightViewProjection(glm::vec3 dir, glm::vec3 center, float radius) {
  dir = glm::length(dir) > 1e-6f ? glm::normalize(dir) : glm::vec3(0.0f, -1.0f, 0.0f);
  const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAt(center - dir * radius, center, up);
  return glm::ortho(-radius, radius, -radius, radius, 0.0f, 2.0f * radius) * view;
}

void ShadowMaps::clear() {
  headShadowFbo_.clearDepth(1.0f);
  opacityFbo_.clearColor(0, std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f});
  lightDepthFbo_.clearDepth(1.0f);
}

}  // namespace csm
