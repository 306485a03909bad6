#include "sim/head/head_model.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <glm/common.hpp>

#include "sim/base/file_io.h"
#include "sim/head/mannequin.h"
#include "sim/head/mesh_field.h"
#include "sim/head/obj_mesh.h"
#include "sim/head/sphere_fit.h"

namespace csm {

std::string headMeshPath(const Config& c) {
  return resolveRelative(c.head.meshDir, c.head.mesh);
}

std::string torsoMeshPath(const Config& c) {
  return c.head.torsoMesh.empty() ? std::string()
                                  : resolveRelative(c.head.meshDir, c.head.torsoMesh);
}

namespace {

constexpr double kMaxHeadSize = 1.0;  // m

// The field of two parts at rest: the nearer of their fields, sampled on their boxes' union.
std::shared_ptr<const DistanceGrid> unionGrid(const DistanceGrid& a, const DistanceGrid& b) {
  const glm::dvec3 lo = glm::min(glm::dvec3(a.origin), glm::dvec3(b.origin));
  const glm::dvec3 hi = glm::max(glm::dvec3(a.origin) + glm::dvec3(a.dims - 1) * double(a.cell),
                                 glm::dvec3(b.origin) + glm::dvec3(b.dims - 1) * double(b.cell));
  const double cell = std::min(a.cell, b.cell);
  return std::make_shared<const DistanceGrid>(sampleDistance(
      [&](const glm::dvec3& p) { return std::min(a.sample(p), b.sample(p)); }, lo, hi, cell));
}

}  // namespace

HeadFitOptions headFitOptions(const Config& c) {
  HeadFitOptions o;
  o.scale = c.head.meshScale;
  o.up = c.head.meshUp;
  o.facing = c.head.meshFacing;
  o.place = c.head.meshPlace;
  return o;
}

std::shared_ptr<const LoadedHead> loadHeadMesh(const std::string& path, std::string* error,
                                               const HeadFitOptions& options,
                                               const HeadFit* given) {
  io::ObjReadResult read = io::readHeadMeshFile(path);
  if (!read.mesh) {
    if (error) *error = read.error;
    return nullptr;
  }
  auto head = std::make_shared<LoadedHead>();
  head->mesh = std::move(*read.mesh);
  head->cappedHoles = read.cappedHoles;
  if (given) {
    head->fit = *given;
    given->applyTo(head->mesh);
  } else {
    head->fit = fitHead(head->mesh, read.holes, options);
  }
  // A head and shoulders is well under a metre: more, once fitted, is not a head (or not in the
  // unit given), and its field would not fit in memory at 4 mm.
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::vec3& p : head->mesh.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(size <= kMaxHeadSize)) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f m", size);
    if (error)
      *error = path + ": the mesh is " + text + " across once in the head frame (" +
               head->fit.text() + "); a head and shoulders is under 1 m";
    return nullptr;
  }
  head->grid = meshDistanceGrid(head->mesh, 0.004, 0.02);
  return head;
}

std::shared_ptr<const HeadModel> HeadModel::build(const Config& c, std::string* error,
                                                  const HeadModel* previous) {
  auto model = std::make_shared<HeadModel>();
  model->sdf_ = c.collision.headShape == HeadShape::Sdf;
  model->meshPath_ = c.head.mesh.empty() ? std::string() : headMeshPath(c);
  model->fitOptions_ = headFitOptions(c);
  const bool sameMesh = previous && previous->meshPath_ == model->meshPath_ &&
                        previous->fitOptions_ == model->fitOptions_;
  if (!model->meshPath_.empty()) {
    if (sameMesh) {
      model->mesh_ = previous->mesh_;
      model->marks_ = previous->marks_;
    } else {
      std::string why;
      model->mesh_ = loadHeadMesh(model->meshPath_, &why, model->fitOptions_);
      if (!model->mesh_) {
        if (error) *error = "head.mesh: " + why;
        return nullptr;
      }
      model->marks_ = measureScalpMarks(model->mesh_->grid);
    }
    model->torsoPath_ = torsoMeshPath(c);
  }
  if (!model->torsoPath_.empty()) {
    if (sameMesh && previous->torsoPath_ == model->torsoPath_) {
      model->torso_ = previous->torso_;
      model->whole_ = previous->whole_;
    } else {
      std::string why;
      // The torso is in the head's file frame: the head's fit brings it in.
      model->torso_ = loadHeadMesh(model->torsoPath_, &why, {}, &model->mesh_->fit);
      if (!model->torso_) {
        if (error) *error = "head.torso_mesh: " + why;
        return nullptr;
      }
      model->whole_ = unionGrid(model->mesh_->grid, model->torso_->grid);
    }
  }
  model->articulated_ = !model->mesh_ || model->torso_;
  model->fitted_ = c.head.fitSpheres;
  model->fittedCount_ = int(c.head.spheres.size());
  std::vector<Sphere> spheres;
  if (!model->fitted_) {
    spheres = c.head.spheres;
  } else if (previous && previous->fitted_ && previous->fittedCount_ == model->fittedCount_ &&
             &previous->shapeField() == &model->shapeField()) {
    spheres = previous->spheres_;
  } else {
    spheres = fitSpheres(model->shapeField(), model->fittedCount_);
  }
  // The head's spheres first, then the torso's: those whose centre lies below the neck's pivot.
  auto torso = [&](const Sphere& s) { return model->articulated_ && s.center.y < c.head.pivot.y; };
  for (const Sphere& s : spheres)
    if (!torso(s)) model->spheres_.push_back(s);
  model->headSpheres_ = model->spheres_.size();
  model->summary_ = model->describe();
  for (const Sphere& s : spheres)
    if (torso(s)) model->spheres_.push_back(s);
  return model;
}

std::shared_ptr<const HeadModel> HeadModel::require(const Config& c) {
  std::string error;
  std::shared_ptr<const HeadModel> model = build(c, &error);
  if (!model) throw std::runtime_error(error);
  return model;
}

std::string HeadModel::describe() const {
  if (!mesh_) return {};
  std::string s = "head.mesh: " + mesh_->fit.text();
  if (mesh_->cappedHoles > 0)
    s += "; " + std::to_string(mesh_->cappedHoles) +
         (mesh_->cappedHoles == 1 ? " opening capped" : " openings capped");
  return s + "; " + marks_.text;
}

const DistanceGrid& HeadModel::shapeField() const {
  if (whole_) return *whole_;
  return mesh_ ? mesh_->grid : mannequinGrid();
}

const SurfaceMesh* HeadModel::surface() const {
  if (!sdf_) return nullptr;
  return mesh_ ? &mesh_->mesh : &mannequinMesh();
}

const SurfaceMesh* HeadModel::headSurface() const {
  if (!sdf_) return nullptr;
  return mesh_ ? &mesh_->mesh : &mannequinHeadMesh();
}

const SurfaceMesh* HeadModel::torsoSurface() const {
  if (!sdf_ || !articulated_) return nullptr;
  return torso_ ? &torso_->mesh : &mannequinTorsoMesh();
}

SceneHead HeadModel::collider() const {
  SceneHead out;
  out.spheres.assign(spheres_.begin(), spheres_.begin() + long(headSpheres_));
  out.torsoSpheres.assign(spheres_.begin() + long(headSpheres_), spheres_.end());
  if (!sdf_) return out;
  out.field = mesh_ ? &mesh_->grid : &mannequinHeadGrid();
  if (articulated_) out.torsoField = torso_ ? &torso_->grid : &mannequinTorsoGrid();
  return out;
}

}  // namespace csm
