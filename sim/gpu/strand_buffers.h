// The hair on the GPU: the state the passes step (positions, velocities, predictions, each
// region's rotation) and the layout they read (rest shape, strands, regions, the order the
// per-strand passes take strands in), bound at the points of shaders/sim/bindings.glsl.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "sim/core/hair_state.h"
#include "sim/solver/stiffness.h"

namespace csm::gpu {

struct StrandBuffers {
  // The state and layout of `state`; each region's rotation starts at the head's.
  void upload(const HairState& state, const glm::dquat& head);
  // Region masses, inertia and ranges, each strand's stiffness rate, and the inverse masses
  // the strand contacts use (0 for held particles), for the regions of `state`.
  void uploadRegions(const HairState& state, const Regions& regions);
  // Storage views where the shaders declare them (rest and regions are read as texels).
  void bind() const;
  // The bytes of its buffers.
  uint64_t bytes() const;

  size_t particles = 0, strands = 0;
  uint32_t segments = 0;
  int longestStrand = 0;  // particles
  // The per-particle passes' work groups: their size and count (groupFirst has one more entry).
  uint32_t groupParticles = 0, groups = 0;
  double meanSegment = 0.0;  // mean rest length of a segment (m)

  gl::Buffer rest{gl::NoCreate}, position{gl::NoCreate}, velocity{gl::NoCreate},
      predicted{gl::NoCreate}, rotation{gl::NoCreate}, strandFirst{gl::NoCreate},
      particleStrand{gl::NoCreate}, strandOrder{gl::NoCreate}, region{gl::NoCreate},
      strandStiffness{gl::NoCreate}, particleConstants{gl::NoCreate}, groupFirst{gl::NoCreate};
  // texelFetch views for reads that differ per invocation (see gl/buffer_texture.h).
  gl::BufferTexture positionTex{gl::NoCreate}, velocityTex{gl::NoCreate}, restTex{gl::NoCreate},
      predictedTex{gl::NoCreate}, regionTex{gl::NoCreate}, particleConstantsTex{gl::NoCreate};
};

}  // namespace csm::gpu
