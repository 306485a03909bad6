#include "sim/gpu/strand_buffers.h"

#include <algorithm>
#include <numeric>

#include <glm/vec2.hpp>

#include "sim/solver/contacts.h"
#include "sim/gpu/buffer_fill.h"
#include "sim/gpu/strand_groups.h"
#include "shaders/sim/bindings.glsl"
#include "shaders/sim/shared_constants.glsl"

namespace csm::gpu {

void StrandBuffers::upload(const HairState& st, const glm::dquat& head) {
  particles = st.particleCount();
  strands = st.strandCount();
  longestStrand = 0;
  segments = 0;
  std::vector<uint32_t> order(strands);
  std::iota(order.begin(), order.end(), 0u);
  for (size_t s = 0; s < strands; ++s) {
    const int size = int(st.strandFirst[s + 1] - st.strandFirst[s]);
    longestStrand = std::max(longestStrand, size);
    segments += uint32_t(std::max(0, size - 1));
  }
  // Strands of equal length side by side: a SIMD group of the per-strand passes then runs
  // loops of one length (the state itself keeps the groom's order).
  std::stable_sort(order.begin(), order.end(), [&](uint32_t l, uint32_t r) {
    return st.strandFirst[l + 1] - st.strandFirst[l] < st.strandFirst[r + 1] - st.strandFirst[r];
  });
  double restSum = 0.0;
  for (size_t i = 0; i + 1 < particles; ++i)
    if (st.particleStrand[i] == st.particleStrand[i + 1])
      restSum += glm::length(glm::dvec3(st.rest[i + 1]) - glm::dvec3(st.rest[i]));
  meanSegment = segments > 0 ? restSum / segments : 0.0;

  fill(position, st.position);
  fill(velocity, st.velocity);
  fill(strandFirst, st.strandFirst);
  fill(particleStrand, st.particleStrand);
  fill(predicted, st.position);
  fill(strandOrder, order);
  groupParticles = groupParticlesFor(longestStrand);
  const std::vector<uint32_t> groupStarts = packStrandGroups(st.strandFirst, groupParticles);
  groups = uint32_t(groupStarts.size() - 1);
  fill(groupFirst, groupStarts);
  fill(rotation, std::vector<glm::vec4>(particles, glm::vec4(head.x, head.y, head.z, head.w)));
  view(positionTex, position, gl::TextureFormat::Rgba32f);
  view(velocityTex, velocity, gl::TextureFormat::Rgba32f);
  view(predictedTex, predicted, gl::TextureFormat::Rgba32f);
}

void StrandBuffers::uploadRegions(const HairState& state, const Regions& regions) {
  const size_t particleCount = particles, strandCount = strands;
  std::vector<glm::vec4> perParticle(particleCount);
  for (size_t i = 0; i < particleCount; ++i) {
    const double J = regions.inertia[i];
    perParticle[i] = glm::vec4(float(regions.mass[i]), J > 0.0 ? float(1.0 / J) : 0.0f,
                               float(regions.lo[i]), float(regions.hi[i]));
  }
  fill(region, perParticle);
  // The rest shape with each particle's clamp tau in w (CSM_BIND_REST), which the regions set.
  std::vector<glm::vec4> restTau(particleCount);
  for (size_t i = 0; i < particleCount; ++i)
    restTau[i] = glm::vec4(glm::vec3(state.rest[i]), float(regions.clampFit[i].y));
  fill(rest, restTau);
  view(restTex, rest, gl::TextureFormat::Rgba32f);
  std::vector<glm::vec4> perStrand(strandCount);
  for (size_t s = 0; s < strandCount; ++s)
    perStrand[s] = glm::vec4(float(regions.rate[s]), float(regions.ghostMass[s]),
                             float(regions.pinned[s] + (regions.tipHeld[s] ? CSM_TIP_HELD : 0)),
                             float(regions.fitEnd[s]));
  fill(strandStiffness, perStrand);
  view(regionTex, region, gl::TextureFormat::Rgba32f);
  const std::vector<double> w = contactInverseMass(state, regions);
  // Per particle: the contacts' inverse mass, the clamp's pull (CSM_BIND_PARTICLE_CONSTANTS).
  std::vector<glm::vec2> constants(particleCount);
  for (size_t i = 0; i < particleCount; ++i)
    constants[i] = glm::vec2(float(w[i]), float(regions.clampPull[i]));
  fill(particleConstants, constants);
  view(particleConstantsTex, particleConstants, gl::TextureFormat::Rg32f);
}

void StrandBuffers::bind() const {
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  position.bindBase(ssbo, CSM_BIND_POSITION);
  velocity.bindBase(ssbo, CSM_BIND_VELOCITY);
  strandFirst.bindBase(ssbo, CSM_BIND_STRAND_FIRST);
  particleStrand.bindBase(ssbo, CSM_BIND_PARTICLE_STRAND);
  predicted.bindBase(ssbo, CSM_BIND_PREDICTED);
  rotation.bindBase(ssbo, CSM_BIND_ROTATION);
  strandOrder.bindBase(ssbo, CSM_BIND_STRAND_ORDER);
  strandStiffness.bindBase(ssbo, CSM_BIND_STRAND_STIFFNESS);
  groupFirst.bindBase(ssbo, CSM_BIND_STRAND_GROUPS);
  // Read as storage too by the passes built with CSM_STORAGE_READS (particle_reads.glsl).
  rest.bindBase(ssbo, CSM_BIND_REST);
  region.bindBase(ssbo, CSM_BIND_REGION);
  particleConstants.bindBase(ssbo, CSM_BIND_PARTICLE_CONSTANTS);
  positionTex.bind(CSM_TEX_POSITION);
  velocityTex.bind(CSM_TEX_VELOCITY);
  restTex.bind(CSM_TEX_REST);
  predictedTex.bind(CSM_TEX_PREDICTED);
  regionTex.bind(CSM_TEX_REGION);
  particleConstantsTex.bind(CSM_TEX_PARTICLE_CONSTANTS);
}

uint64_t StrandBuffers::bytes() const {
  uint64_t sum = 0;
  for (const gl::Buffer* b :
       {&rest, &position, &velocity, &predicted, &rotation, &strandFirst, &particleStrand,
        &strandOrder, &region, &strandStiffness, &particleConstants, &groupFirst})
    sum += uint64_t(b->size());
  return sum;
}

}  // namespace csm::gpu
