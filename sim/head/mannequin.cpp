#include "sim/head/mannequin.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/surface_mesh.h"

namespace csm {

namespace {

double sphere(const glm::dvec3& p, const glm::dvec3& c, double r) {
  return glm::length(p - c) - r;
}

// Inigo Quilez's ellipsoid bound: exact on the surface, close to the distance near it.
double ellipsoid(const glm::dvec3& p, const glm::dvec3& c, const glm::dvec3& r) {
  const glm::dvec3 q = p - c;
  const double k0 = glm::length(q / r);
  const double k1 = glm::length(q / (r * r));
  return k1 > 1e-12 ? k0 * (k0 - 1.0) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

double capsule(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double r) {
  const glm::dvec3 pa = p - a, ba = b - a;
  const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
  return glm::length(pa - ba * h) - r;
}

// Polynomial smooth minimum: the union of two shapes with a fillet of about k.
double smoothUnion(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

double smoothSubtract(double a, double cut, double k) {
  return -smoothUnion(-a, cut, k);
}

}  // namespace

double mannequinDistance(const glm::dvec3& q) {
  // Left-right symmetric: model the right half (x >= 0) and mirror.
  const glm::dvec3 p(std::abs(q.x), q.y, q.z);
  // Cranium and the face's mass below the forehead.
  double d = ellipsoid(p, {0.0, 0.005, -0.012}, {0.074, 0.095, 0.094});
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.045, 0.025}, {0.060, 0.075, 0.060}), 0.03);
  // Jaw and chin.
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.083, 0.034}, {0.050, 0.040, 0.054}), 0.025);
  d = smoothUnion(d, sphere(p, {0.0, -0.110, 0.068}, 0.019), 0.02);
  // Cheekbones and brow ridge.
  d = smoothUnion(d, sphere(p, {0.043, -0.030, 0.058}, 0.022), 0.02);
  d = smoothUnion(d, capsule(p, {0.0, 0.004, 0.076}, {0.040, 0.004, 0.072}, 0.012), 0.015);
  // Eye sockets, each with its eye.
  d = smoothSubtract(d, sphere(p, {0.032, -0.013, 0.091}, 0.017), 0.008);
  d = smoothUnion(d, sphere(p, {0.032, -0.014, 0.070}, 0.0125), 0.004);
  // Nose: bridge, tip and wings.
  d = smoothUnion(d, capsule(p, {0.0, -0.004, 0.086}, {0.0, -0.043, 0.103}, 0.008), 0.012);
  d = smoothUnion(d, sphere(p, {0.0, -0.046, 0.100}, 0.011), 0.008);
  d = smoothUnion(d, sphere(p, {0.012, -0.051, 0.091}, 0.008), 0.008);
  // Lips.
  d = smoothUnion(d, capsule(p, {0.0, -0.071, 0.086}, {0.019, -0.073, 0.080}, 0.0065), 0.008);
  d = smoothUnion(d, capsule(p, {0.0, -0.083, 0.083}, {0.016, -0.082, 0.078}, 0.006), 0.008);
  // Ears.
  d = smoothUnion(d, ellipsoid(p, {0.074, -0.025, -0.010}, {0.011, 0.030, 0.019}), 0.008);
  // Neck and shoulders.
  d = smoothUnion(d, capsule(p, {0.0, -0.070, -0.020}, {0.0, -0.250, -0.025}, 0.055), 0.03);
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.305, -0.015}, {0.190, 0.075, 0.095}), 0.06);
  return d;
}

const DistanceGrid& mannequinGrid() {
  static const DistanceGrid grid =
      sampleDistance(mannequinDistance, {-0.215, -0.415, -0.125}, {0.215, 0.115, 0.135}, 0.004);
  return grid;
}

const SurfaceMesh& mannequinMesh() {
  static const SurfaceMesh mesh = meshZeroLevel(mannequinGrid(), mannequinDistance);
  return mesh;
}

}  // namespace csm
