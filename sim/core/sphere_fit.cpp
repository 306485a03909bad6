#include "sim/core/sphere_fit.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

namespace csm {

std::optional<SphereFit> fitSphere(std::span<const glm::dvec3> points,
                                   std::span<const double> weights) {
  auto weight = [&](size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  glm::dvec3 mean(0.0);
  double total = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    mean += weight(i) * points[i];
    total += weight(i);
  }
  if (points.size() < 4 || !(total > 0.0)) return std::nullopt;
  mean /= total;
  double spread = 0.0;
  for (const glm::dvec3& p : points) spread = std::max(spread, glm::length(p - mean));
  if (!(spread > 0.0)) return std::nullopt;
  // Weighted least squares: each row scaled by the square root of its weight.
  Eigen::MatrixXd m(points.size(), 4);
  Eigen::VectorXd rhs(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3 q = (points[i] - mean) / spread;
    const double w = std::sqrt(weight(i));
    m.row(Eigen::Index(i)) << 2.0 * w * q.x, 2.0 * w * q.y, 2.0 * w * q.z, w;
    rhs(Eigen::Index(i)) = w * glm::dot(q, q);
  }
  const Eigen::Vector4d x = m.colPivHouseholderQr().solve(rhs);
  const glm::dvec3 c(x(0), x(1), x(2));
  const double r2 = x(3) + glm::dot(c, c);
  if (!std::isfinite(r2) || !(r2 > 0.0)) return std::nullopt;
  return SphereFit{mean + spread * c, spread * std::sqrt(r2)};
}

}  // namespace csm
