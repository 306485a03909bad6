// The sphere nearest a set of points by least squares: a point p of a sphere about c of radius r
// has |p|^2 = 2 c.p + k (k = r^2 - |c|^2), linear in c and k, so the fit is one small linear
// solve. The scalp the roots of a groom file lie on (sim/groom/scene_groom.cpp) and the cranium
// of a head mesh (sim/head/head_fit.cpp) are found this way.
#pragma once

#include <optional>
#include <span>

#include <glm/vec3.hpp>

namespace csm {

struct SphereFit {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// Each point's equation weighted by weights[i] (all 1 when `weights` is empty), solved about the
// points' weighted mean in units of their spread (the farthest point from it), so that the system
// is well scaled whatever the points' units. Null when the solve gives no real radius (fewer than
// four points, all at one place, or a square radius that is not above 0). A flat set gives a
// finite but huge radius: what that means is the caller's.
std::optional<SphereFit> fitSphere(std::span<const glm::dvec3> points,
                                   std::span<const double> weights = {});

}  // namespace csm
