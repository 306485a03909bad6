// The GPU solver's parameter block in C++: SimParams and Substep expanded from the one list in
// shaders/sim/shared_constants.glsl, which shaders/sim/common.glsl expands for GLSL, so the two
// cannot drift apart (std430; tests/gpu/gpu_solver_test.cpp checks every field's offset against
// the linked program's).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shaders/sim/shared_constants.glsl"

namespace csm::gpu {

// GLSL's names for the types the list uses.
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec3 = glm::uvec3;
using mat4 = glm::mat4;
using uint = uint32_t;

struct SimParams {
  CSM_SIM_PARAMS(CSM_MEMBER)
};

struct Substep {
  CSM_SUBSTEP(CSM_MEMBER)
};

static_assert(sizeof(SimParams) == 12 * 16 + 2 * 64 + 7 * 16);
static_assert(offsetof(SimParams, cellEdge) == 10 * 16);
static_assert(offsetof(SimParams, listHalf) == offsetof(SimParams, bucketMask) + 12);
static_assert(sizeof(Substep) == 208);
static_assert(sizeof(SimParams) + CSM_MAX_SUBSTEPS * sizeof(Substep) <= 65536);

// The parameter block read as a uniform block: the frame's parameters and CSM_MAX_SUBSTEPS
// steps, the size the shaders declare (common.glsl), used or not.
constexpr size_t kParamBlockBytes = sizeof(SimParams) + CSM_MAX_SUBSTEPS * sizeof(Substep);

}  // namespace csm::gpu
