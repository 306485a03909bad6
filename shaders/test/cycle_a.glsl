// Includes test/cycle_b.glsl, which includes this file: a cycle the loader must reject.
#include "test/cycle_b.glsl"
