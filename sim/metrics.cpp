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

namespace {

bool finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The measures over strands [first[s], first[s+1]), positions and velocities by particle.
template <class Position, class Velocity, class Pinned>
Accuracy measure(size_t strands, const uint32_t* first, Position x, Velocity v, size_t velocities,
                 std::span<const double> restLength, std::span<const Sphere> spheres, Pinned pinned,
                 const PosedField& field) {
  Accuracy acc;
  double strainSum = 0.0;
  uint64_t segments = 0;
  for (size_t s = 0; s < strands; ++s) {
    const uint32_t a = first[s], b = first[s + 1];
    for (uint32_t i = a; i < b; ++i) {
      const glm::dvec3 xi = x(i);
      if (!finite(xi) || (i < velocities && !finite(v(i)))) {
        ++acc.nanCount;
        continue;
      }
      if (i < velocities) acc.maxSpeed = std::max(acc.maxSpeed, glm::length(v(i)));
      if (int(i - a) >= pinned(s) && field.grid)
        acc.headPenetrations += field.contains(xi);
      else if (int(i - a) >= pinned(s))
        for (const Sphere& sp : spheres)
          if (glm::length(xi - glm::dvec3(sp.center)) < double(sp.radius) * (1.0 - 1e-6)) {
            ++acc.headPenetrations;
            break;
          }
      if (i + 1 < b && restLength[i] > 0.0 && finite(x(i + 1))) {
        const double strain = glm::length(x(i + 1) - xi) / restLength[i] - 1.0;
        acc.maxStrain = segments == 0 ? strain : std::max(acc.maxStrain, strain);
        strainSum += std::abs(strain);
        ++segments;
      }
    }
  }
  acc.meanStrain = segments ? strainSum / segments : 0.0;
  return acc;
}

}  // namespace

Accuracy measureAccuracy(std::span<const glm::vec4> x, std::span<const glm::vec4> v,
                         const Groom& groom, std::span<const double> restLength,
                         std::span<const Sphere> spheres, int pinned, const PosedField& field) {
  // Through float, as the positions are: the speed and strain of a float state.
  return measure(
      groom.strandCount(), groom.first.data(),
      [&](uint32_t i) { return glm::dvec3(glm::vec3(x[i])); },
      [&](uint32_t i) { return glm::dvec3(glm::vec3(v[i])); }, v.size(), restLength, spheres,
      [&](size_t) { return pinned; }, field);
}

Accuracy measureAccuracy(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v,
                         std::span<const uint32_t> first, std::span<const double> restLength,
                         std::span<const Sphere> spheres, std::span<const int> pinned,
                         const PosedField& field) {
  return measure(
      first.empty() ? 0 : first.size() - 1, first.data(), [&](uint32_t i) { return x[i]; },
      [&](uint32_t i) { return v[i]; }, v.size(), restLength, spheres,
      [&](size_t s) { return pinned[s]; }, field);
}

}  // namespace csm
