// Whole strands packed into work groups for the per-particle passes (strand_step.comp,
// strand_strain.comp; shaders/sim/strand_group.glsl): a group takes strands in order while their
// particles fit, so it covers one run of particles and no strand is split.
#pragma once

#include <cstdint>
#include <vector>

namespace csm::gpu {

// The group size for strands of at most `longestStrand` particles: a power of two, at least
// kMinGroupParticles (enough strands a group to fill a GPU's SIMD groups) and the longest strand.
constexpr uint32_t kMinGroupParticles = 128;
uint32_t groupParticlesFor(int longestStrand);

// Where each group starts in the particle arrays, and one past the last group's end:
// strand s = [strandFirst[s], strandFirst[s + 1]) goes whole into the first group it fits in
// after the one before it. Every strand must hold at most `groupParticles` particles.
std::vector<uint32_t> packStrandGroups(const std::vector<uint32_t>& strandFirst,
                                       uint32_t groupParticles);

}  // namespace csm::gpu
