// The wind at x and time t: the field of shared_functions.glsl (windField, the same text the C++
// compiles for csm::windVelocity, sim/solver/wind.cpp) at this frame's wind. Needs common.glsl
// (P).
vec3 windVelocity(vec3 x, float t) {
  float strength = P.windStrength;
  if (strength <= 0.0) return vec3(0.0);
  return windField(P.windDirection, strength, P.gusts, P.gustFrequency, P.turbulence,
                   P.turbulenceScale, x, t);
}
