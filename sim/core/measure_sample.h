// The strands a mode without strand contacts measures them on (--metrics, the Stats panel): every
// strand up to CSM_MEASURED_PARTICLES particles, 1 in measureStride beyond, by a hash of the strand
// (shaders/sim/shared_constants.glsl says why), by a hash of the strand both languages compile from
// one text (inMeasureSample, shaders/sim/shared_functions.glsl), so both solvers measure the same
// strands.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shaders/sim/shared_constants.glsl"
#include "sim/base/shared_functions.h"

namespace csm {

// 1 where every strand is measured; else the share's denominator.
inline uint32_t measureStride(std::size_t particles) {
  const std::size_t budget = CSM_MEASURED_PARTICLES;
  return uint32_t(std::max<std::size_t>(1, (particles + budget - 1) / budget));
}

// Whether strand s is in the sample of 1 in `stride`.
using shared::inMeasureSample;

// The particles' strands as a measure search takes them (the CPU solver; tests comparing the
// GPU's): a particle of a strand outside the sample is a strand of its own, past every strand's
// index, so it makes no segment.
inline std::vector<uint32_t> sampledStrands(std::span<const uint32_t> particleStrand,
                                            uint32_t stride) {
  constexpr uint32_t kUnmeasured = 0x80000000u;
  std::vector<uint32_t> out(particleStrand.begin(), particleStrand.end());
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!inMeasureSample(out[i], stride)) out[i] = kUnmeasured + uint32_t(i);
  return out;
}

}  // namespace csm
