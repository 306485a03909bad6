// The head hair grows on and is pushed out of, for the generator (sim/groom/hairstyle.h) and a
// file's groom fitted to the head (sim/groom/scene_groom.h): the scene's spheres (the first is
// the scalp), or its distance field.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/head/distance_grid.h"
#include "sim/head/mannequin.h"
#include "sim/head/scalp_marks.h"

namespace csm {

// Moves p outside every sphere (inflated by margin). Returns true when it moved.
inline bool pushOutOfSpheres(glm::dvec3& p, const std::vector<Sphere>& head, double margin) {
  bool moved = false;
  for (int pass = 0; pass < 2; ++pass)
    for (const Sphere& s : head) {
      const glm::dvec3 c(s.center);
      const glm::dvec3 d = p - c;
      const double r = s.radius + margin;
      const double len = glm::length(d);
      if (len < r) {
        p = c + (len > 1e-12 ? d / len : glm::dvec3(0, 1, 0)) * r;
        moved = true;
      }
    }
  return moved;
}

// The head the hair grows on: the spheres (the first is the scalp), or a distance field.
struct GrowthHead {
  const std::vector<Sphere>& spheres;
  const DistanceGrid* field;
  // Where the field's scalp ends (null: the spheres, or the mannequin's).
  const ScalpMarks* marks = nullptr;

  double browY() const { return marks ? marks->browY : kMannequinBrowY; }

  // The scalp point in direction dir (a unit vector from the scalp's centre).
  glm::dvec3 root(const glm::dvec3& dir) const {
    if (field) return surfaceAlong(*field, kMannequinScalpCentre, dir);
    const Sphere& scalp = spheres.front();
    return glm::dvec3(scalp.center) + dir * double(scalp.radius);
  }
  // Distance from p to the head's surface (negative inside), and the outward direction of
  // the surface nearest p.
  double distance(const glm::dvec3& p, glm::dvec3& normal) const {
    double nearest = 1e30;
    glm::dvec3 n(0.0);
    if (field) {
      nearest = field->sample(p, &n);
    } else {
      for (const Sphere& s : spheres) {
        const double d = glm::length(p - glm::dvec3(s.center)) - s.radius;
        if (d < nearest) nearest = d, n = p - glm::dvec3(s.center);
      }
    }
    normal = glm::length(n) > 1e-12 ? glm::normalize(n) : glm::dvec3(0.0, 1.0, 0.0);
    return nearest;
  }
  glm::dvec3 normal(const glm::dvec3& p) const {
    glm::dvec3 n;
    distance(p, n);
    return n;
  }
  bool pushOut(glm::dvec3& p, double margin) const {
    return field ? pushOutOfField(*field, p, margin) : pushOutOfSpheres(p, spheres, margin);
  }
  // The face is left open: on a field, hair that comes down beside the face (below 18 mm over
  // the brow, within the head's width, in front of the ears) turns back behind the ears. A turn
  // of the growing direction, not a move of the point, so that strands keep their own paths
  // instead of being pressed onto one surface.
  glm::dvec3 steer(const glm::dvec3& p, const glm::dvec3& want) const {
    const double top = browY() + 0.018;
    if (!field || p.y > top || std::abs(p.x) > 0.11 || p.z < -0.03) return want;
    const double depth = std::min(1.0, (p.z + 0.03) / 0.03 + (top - p.y) / 0.03);
    return glm::normalize(want + glm::dvec3(0.0, 0.0, -3.0 * depth));
  }
};

}  // namespace csm
