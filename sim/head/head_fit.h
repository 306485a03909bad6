// A head mesh brought into the head frame (METHOD.md section 6.6): scans and data sets' heads
// come in their own units (metres, centimetres, millimetres, inches) and axes (y up or z up, the
// face toward +z, -y or wherever the scanner stood). Each of the four is inferred from the shape
// and said, or taken from the preset: the up axis from the neck's opening, the unit from the
// cranium's size, the facing from where the surface has most detail (the face's nose, eyes and
// lips against the smooth back of the head), and the place from the cranium, which is put where
// the mannequin's is so that the neck, the scalp and head.pivot meet it as they meet the mannequin.
#pragma once

#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/head/surface_mesh.h"

namespace csm {

struct HeadFitOptions {
  float scale = 0.0f;  // metres per file unit; 0 infers it
  ClipUp up = ClipUp::Auto;
  ClipFacing facing = ClipFacing::Auto;
  bool place = true;  // the cranium moved onto the mannequin's; false keeps the file's place
  bool operator==(const HeadFitOptions&) const = default;
};

// What was done to the file's points: p' = rotation * (scale * p) + translation.
struct HeadFit {
  double scale = 1.0;
  glm::dmat3 rotation{1.0};
  glm::dvec3 translation{0.0};
  std::string unit;        // "m", "dm", "cm", "mm", "in"; empty when head.mesh_scale gave it
  std::string up, facing;  // the file's axes that became +y and +z ("+y", "-z", ...)
  std::string upWhy, facingWhy, placeWhy;
  double craniumRadius = 0.0;  // metres, the sphere fitted to the top of the head
  bool changed() const;        // anything other than the identity
  glm::vec3 apply(const glm::vec3& p) const;
  void applyTo(SurfaceMesh& mesh) const;  // positions and normals
  // One sentence for the log: what was inferred or given, why, and which setting overrides it.
  std::string text() const;
};

// The mannequin's cranium as this fit measures it (the sphere fitted to the top 7 cm of its head
// mesh); tests/cpu/head_fit_test.cpp measures the mannequin against it.
inline constexpr double kMannequinCraniumY = 0.018, kMannequinCraniumZ = -0.012,
                        kMannequinCraniumRadius = 0.081;

// Infers or takes the fit and applies it to `mesh` (positions and normals). `holes` are the centres
// of the openings the reader capped (a scan open at the neck), in the file's units.
HeadFit fitHead(SurfaceMesh& mesh, const std::vector<glm::vec3>& holes, const HeadFitOptions& o);

// The sphere fitted (least squares, weighted by area) to the part of the surface within `depth`
// of its highest point along `up`: the cranium's centre and radius, in the mesh's units.
struct Cap {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};
Cap craniumCap(const SurfaceMesh& mesh, const glm::dvec3& up, double depth);

}  // namespace csm
