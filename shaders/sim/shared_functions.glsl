// Functions the C++ and the shaders share, written once for both languages: GLSL compiles them in
// float (wind.glsl and common.glsl include this file), C++ in double (sim/base/shared_functions.h
// includes it inside csm::shared, with CSM_REAL double and GLSL's built-ins given their C++
// meaning). Only what both languages parse alike goes here: no swizzles, no vector built-ins
// beyond arithmetic, literals that are exact in both (a float literal is double in C++).
#ifndef CSM_SIM_SHARED_FUNCTIONS_GLSL
#define CSM_SIM_SHARED_FUNCTIONS_GLSL
// The includer has included shared_constants.glsl (CSM_PI).

#ifndef CSM_SHARED
// GLSL: functions as they are, in float.
#define CSM_SHARED
#define CSM_REAL float
#define CSM_REAL3 vec3
#endif

// The wind field u(x, t) (METHOD.md section 2.3): the direction (unit) times the strength times
// (1 + gusts(t)), plus a spatial turbulence. Two incommensurate sines make gusts that do not
// repeat visibly; the swirl, from sines of the other coordinates drifting with time, looks
// divergence-free. The caller returns no wind where the strength is not above 0.
CSM_SHARED CSM_REAL3 windField(CSM_REAL3 dir, CSM_REAL strength, CSM_REAL gusts,
                               CSM_REAL gustFrequency, CSM_REAL turbulence,
                               CSM_REAL turbulenceScale, CSM_REAL3 x, CSM_REAL t) {
  CSM_REAL w = 2.0 * CSM_PI * gustFrequency;
  CSM_REAL gust = 0.6 * sin(w * t) + 0.4 * sin(2.7 * w * t + 1.7);
  CSM_REAL speed = strength * max(0.0, 1.0 + gusts * gust);
  CSM_REAL k = 2.0 * CSM_PI / turbulenceScale;
  CSM_REAL drift = 1.3 * w + 0.7;
  CSM_REAL3 swirl = CSM_REAL3(sin(k * x.y + drift * t) + sin(k * x.z - 0.6 * drift * t),
                              sin(k * x.z + 1.1 * drift * t + 2.0) + sin(k * x.x - 0.8 * drift * t + 1.0),
                              sin(k * x.x + 0.9 * drift * t + 4.0) + sin(k * x.y - 1.2 * drift * t + 3.0));
  return dir * speed + 0.5 * turbulence * strength * swirl;
}

// Whether strand s is in the contact measures' sample of 1 in `stride` (sim/core/measure_sample.h
// says why): a 32-bit integer finalizer of the strand's index, so that the sample spreads over
// the groom.
CSM_SHARED bool inMeasureSample(uint s, uint stride) {
  if (stride <= 1u) return true;
  s ^= s >> 16u;
  s *= 0x7feb352du;
  s ^= s >> 15u;
  s *= 0x846ca68bu;
  s ^= s >> 16u;
  return s % stride == 0u;
}

#endif
