// The functions the C++ and the shaders share (shaders/sim/shared_functions.glsl), compiled here
// from the same text in double: GLSL's names for the types and the built-ins they use, given
// their C++ meaning inside csm::shared.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "shaders/sim/shared_constants.glsl"

namespace csm::shared {

using uint = std::uint32_t;
using std::max;
using std::sin;

#define CSM_SHARED inline
#define CSM_REAL double
#define CSM_REAL3 glm::dvec3
#include "shaders/sim/shared_functions.glsl"
#undef CSM_SHARED
#undef CSM_REAL
#undef CSM_REAL3

}  // namespace csm::shared
