// The window coefficient c_w of the paper model (sim/solver/stiffness.h), measured on the CPU
// solver: tests check stiffness.cpp's table against it, and csmhair-bench window prints both.
#pragma once

namespace csm {

// A long straight strand bent by a small sine wave of wavenumber kappa, with nothing acting but
// the goals of the paper model with window w and alpha = 1; mu is the share of the wave one step
// removes, and c_w = mu / (kappa w l)^4, extrapolated to kappa -> 0 from kappa w l = 0.1 and 0.2.
double measureWindowCoefficient(int w);

}  // namespace csm
