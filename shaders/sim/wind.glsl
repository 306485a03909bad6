// The wind field u(x, t): direction x strength x (1 + gusts(t)) + spatial turbulence.
// The same formula as csm::windVelocity (sim/solver/wind.cpp), in float; keep the two in step.
// Needs common.glsl (P).
const float kPi = 3.14159265358979;

vec3 windVelocity(vec3 x, float t) {
  float strength = P.windStrength;
  if (strength <= 0.0) return vec3(0.0);
  vec3 dir = P.windDirection;  // normalised on the CPU
  float w = 2.0 * kPi * P.gustFrequency;
  // Two incommensurate sines: gusts that do not repeat visibly.
  float gust = 0.6 * sin(w * t) + 0.4 * sin(2.7 * w * t + 1.7);
  float speed = strength * max(0.0, 1.0 + P.gusts * gust);
  // Divergence-free-looking swirl from sines of the other coordinates, drifting with time.
  float k = 2.0 * kPi / P.turbulenceScale;
  float drift = 1.3 * w + 0.7;
  vec3 swirl = vec3(sin(k * x.y + drift * t) + sin(k * x.z - 0.6 * drift * t),
                    sin(k * x.z + 1.1 * drift * t + 2.0) + sin(k * x.x - 0.8 * drift * t + 1.0),
                    sin(k * x.x + 0.9 * drift * t + 4.0) + sin(k * x.y - 1.2 * drift * t + 3.0));
  return dir * speed + 0.5 * P.turbulence * strength * swirl;
}
