// What tests read of the renderer's last frame, and the knob they turn: the deep opacity maps
// and the light's projection, the strands' geometry, the follower pass's output, the draws paced
// in chunks or whole. The frame loop needs none of it, so it stays off HairRenderer's interface;
// the probe is its friend.
//   RendererProbe(renderer).lightDepth()
#pragma once

#include <glm/mat4x4.hpp>

#include "gl/texture.h"
#include "render/follower_pass.h"
#include "render/hair_renderer.h"
#include "render/strand_geometry.h"

namespace csm {

class RendererProbe {
 public:
  explicit RendererProbe(const HairRenderer& renderer) : renderer_(renderer) {}

  // The deep opacity maps of the last frame (ShadowMaps).
  const gl::Texture& lightDepth() const { return renderer_.shadow_->lightDepth(); }
  const gl::Texture& opacityLayers() const { return renderer_.shadow_->opacityLayers(); }
  // World -> light clip space of the last frame (orthographic, depth maps linearly).
  const glm::mat4& lightViewProjection() const { return renderer_.lightViewProj_; }
  const StrandGeometry& geometry() const { return *renderer_.geometry_; }
  // The follower pass of the last frame that drew followers (its output, points moved out).
  const FollowerPass& followerPass() const { return renderer_.followers_; }
  // Long draws in chunks, each waiting for the one before the last, or whole.
  static void setPacedDraws(HairRenderer& renderer, bool on) { renderer.setPacedDraws(on); }

 private:
  const HairRenderer& renderer_;
};

}  // namespace csm
