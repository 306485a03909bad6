#include "sim/metrics.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace csm {

std::vector<double> restLengths(const Groom& groom) {
  std::vector<double> l(groom.pointCount(), 0.0);
  for (size_t s = 0; s < groom.strandCount(); ++s)
    for (uint32_t i = groom.first[s]; i + 1 < groom.first[s + 1]; ++i)
      l[i] = glm::length(glm::dvec3(groom.points[i + 1]) - glm::dvec3(groom.points[i]));
  return l;
}

Accuracy measureAccuracy(std::span<const glm::vec4> x, std::span<const glm::vec4> v,
                         const Groom& groom, std::span<const double> restLength,
                         std::span<const Sphere> spheres, int pinned) {
  Accuracy acc;
  double strainSum = 0.0;
  uint64_t segments = 0;
  auto finite = [](const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  };
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const uint32_t a = groom.first[s], b = groom.first[s + 1];
    for (uint32_t i = a; i < b; ++i) {
      if (!finite(x[i]) || (i < v.size() && !finite(v[i]))) {
        ++acc.nanCount;
        continue;
      }
      if (i < v.size()) acc.maxSpeed = std::max(acc.maxSpeed, double(glm::length(glm::vec3(v[i]))));
      if (int(i - a) >= pinned)
        for (const Sphere& sp : spheres)
          if (glm::length(glm::dvec3(glm::vec3(x[i])) - glm::dvec3(sp.center)) <
              double(sp.radius) * (1.0 - 1e-6)) {
            ++acc.headPenetrations;
            break;
          }
      if (i + 1 < b && restLength[i] > 0.0 && finite(x[i + 1])) {
        const double len =
            glm::length(glm::dvec3(glm::vec3(x[i + 1])) - glm::dvec3(glm::vec3(x[i])));
        const double strain = len / restLength[i] - 1.0;
        acc.maxStrain = segments == 0 ? strain : std::max(acc.maxStrain, strain);
        strainSum += std::abs(strain);
        ++segments;
      }
    }
  }
  acc.meanStrain = segments ? strainSum / segments : 0.0;
  return acc;
}

}  // namespace csm
