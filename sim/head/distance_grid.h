// The head's shape as the hair meets it: a signed distance field sampled on a grid in the
// head's frame (negative inside), read by trilinear interpolation with the gradient as the
// normal, and what the solvers, the generator and the measures do with it.
#pragma once

#include <functional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/pose.h"

namespace csm {

// A distance field on the nodes of a regular grid. Each node holds the gradient (xyz) and the
// distance (w), so one trilinear read gives both, and the normal turns smoothly across cells.
struct DistanceGrid {
  glm::vec3 origin{0.0f};        // the lowest node (m)
  float cell = 0.0f;             // node spacing (m)
  glm::ivec3 dims{0};            // nodes per axis
  std::vector<glm::vec4> nodes;  // x fastest, then y, then z

  bool empty() const { return nodes.empty(); }
  size_t index(int i, int j, int k) const {
    return size_t(i) + size_t(dims.x) * (size_t(j) + size_t(dims.y) * size_t(k));
  }
  // Distance at p (trilinear), and the interpolated gradient when asked (not normalised). Far
  // outside the grid the distance is to the grid's box, whose border lies outside the shape.
  // The GPU reads the same nodes the same way (shaders/sim/head_field.glsl).
  double sample(const glm::dvec3& p, glm::dvec3* gradient = nullptr) const;
};

// A signed distance function: negative inside, about the distance to the surface near it.
using DistanceFunction = std::function<double(const glm::dvec3&)>;

// Samples f on the nodes of the box [lo, hi] spaced `cell`, gradients by central differences.
DistanceGrid sampleDistance(const DistanceFunction& f, const glm::dvec3& lo, const glm::dvec3& hi,
                            double cell);

// A field placed in the world by the head's pose: the head a measure counts particles in.
struct PosedField {
  const DistanceGrid* grid = nullptr;
  Pose pose;
  // Whether a world point lies inside the surface.
  bool contains(const glm::dvec3& world) const;
};

// Moves p (head frame) out of the field's surface inflated by `radius`; true when it moved.
// `normal` gets the outward direction there, `distance` the field's distance where p is left
// (its last read).
bool pushOutOfField(const DistanceGrid& g, glm::dvec3& p, double radius,
                    glm::dvec3* normal = nullptr, double* distance = nullptr);

// Projects p onto the zero level of the field along its gradient (a few Newton steps).
glm::dvec3 projectToSurface(const DistanceGrid& g, glm::dvec3 p);

// The point where the ray from `from` along unit `dir` first leaves the shape, searched from
// outside inwards (the ray starts inside); used to put roots on the scalp.
glm::dvec3 surfaceAlong(const DistanceGrid& g, const glm::dvec3& from, const glm::dvec3& dir);

}  // namespace csm
