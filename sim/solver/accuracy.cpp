#include "sim/solver/accuracy.h"

#include <algorithm>
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
// How far apart two points of a float state can read when the segment between them has its
// rest length: one unit in the last place of each point's largest coordinate. A strain within
// it is not measured (0), one beyond it is measured less it, so that a segment of a micrometre
// 0.3 m from the origin, whose float length is known to 10 %, does not read as 10 % stretched.
// The GPU's measure does the same (shaders/sim/measure.comp).
double floatBlur(const glm::dvec3& a, const glm::dvec3& b) {
  auto largest = [](const glm::dvec3& p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  };
  return 0x1p-23 * (largest(a) + largest(b));
}

template <class Position, class Velocity, class Pinned>
Accuracy measure(size_t strands, const uint32_t* first, Position x, Velocity v, size_t velocities,
                 std::span<const double> restLength, std::span<const Sphere> spheres, Pinned pinned,
                 const PosedField& field, const BodyParts& parts, bool floatState) {
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
      if (int(i - a) >= pinned(s) && field.grid) {
        if (field.contains(xi))
          ++acc.headPenetrations;
        else if (parts.torso.contains(xi))
          ++acc.torsoPenetrations;
      } else if (int(i - a) >= pinned(s)) {
        // Inside a head sphere, else inside a torso sphere (those from parts.headSpheres on).
        int in = 0;
        for (size_t k = 0; k < spheres.size() && in != 1; ++k)
          if (glm::length(xi - glm::dvec3(spheres[k].center)) <
              double(spheres[k].radius) * (1.0 - 1e-6))
            in = k < parts.headSpheres ? 1 : 2;
        acc.headPenetrations += in == 1;
        acc.torsoPenetrations += in == 2;
      }
      if (i + 1 < b && restLength[i] > 0.0 && finite(x(i + 1))) {
        const glm::dvec3 next = x(i + 1);
        double stretch = glm::length(next - xi) - restLength[i];
        if (floatState) {
          const double blur = floatBlur(xi, next);
          stretch = stretch > blur ? stretch - blur : stretch < -blur ? stretch + blur : 0.0;
        }
        const double strain = stretch / restLength[i];
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
                         std::span<const Sphere> spheres, int pinned, const PosedField& field,
                         const BodyParts& parts) {
  // Through float, as the positions are: the speed and strain of a float state.
  return measure(
      groom.strandCount(), groom.first.data(),
      [&](uint32_t i) { return glm::dvec3(glm::vec3(x[i])); },
      [&](uint32_t i) { return glm::dvec3(glm::vec3(v[i])); }, v.size(), restLength, spheres,
      [&](size_t) { return pinned; }, field, parts, true);
}

Accuracy measureAccuracy(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v,
                         std::span<const uint32_t> first, std::span<const double> restLength,
                         std::span<const Sphere> spheres, std::span<const int> pinned,
                         const PosedField& field, const BodyParts& parts) {
  return measure(
      first.empty() ? 0 : first.size() - 1, first.data(), [&](uint32_t i) { return x[i]; },
      [&](uint32_t i) { return v[i]; }, v.size(), restLength, spheres,
      [&](size_t s) { return pinned[s]; }, field, parts, false);
}

}  // namespace csm
