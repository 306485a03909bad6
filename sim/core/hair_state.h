// The simulation state, in the layout the GPU keeps it (std430 arrays of vec4 and uint):
// both solvers read and write this layout, so tests and metrics compare them directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"

namespace csm {

struct HairState {
  std::vector<uint32_t> strandFirst{0};  // strand s: particles [strandFirst[s], strandFirst[s+1])
  std::vector<uint32_t> particleStrand;  // the strand of each particle
  std::vector<glm::vec4> rest;           // xyz rest position in the head frame, w mass (kg)
  std::vector<glm::vec4> position;       // xyz world position, w unused
  std::vector<glm::vec4> velocity;       // xyz world velocity, w unused
  // Per strand: 1 where the head holds the last particle as it holds the root (Groom::tipHeld);
  // empty when none is held.
  std::vector<uint8_t> tipHeld;
  // Per strand: the strands it stands for (Groom::weight); empty when each stands for itself.
  std::vector<float> weight;

  size_t strandCount() const { return strandFirst.size() - 1; }
  size_t particleCount() const { return rest.size(); }
};

// Masses follow segment lengths (a particle carries half of each segment beside it), so the
// strand's mass is density x length whatever its particle count.
HairState makeHairState(const Groom& groom, const SimConfig& sim, const Pose& head);

}  // namespace csm
