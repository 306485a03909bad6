#include "test/cycle_a.glsl"
