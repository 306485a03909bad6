#include "sim/head/head_model.h"

#include <algorithm>
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

std::shared_ptr<const LoadedHead> loadHeadMesh(const std::string& path, std::string* error) {
  io::ObjReadResult read = io::readHeadMeshFile(path);
  if (!read.mesh) {
    if (error) *error = read.error;
    return nullptr;
  }
  auto head = std::make_shared<LoadedHead>();
  head->mesh = std::move(*read.mesh);
  head->grid = meshDistanceGrid(head->mesh, 0.004, 0.02);
  return head;
}

std::shared_ptr<const HeadModel> HeadModel::build(const Config& c, std::string* error,
                                                  const HeadModel* previous) {
  auto model = std::make_shared<HeadModel>();
  model->sdf_ = c.collision.headShape == HeadShape::Sdf;
  model->meshPath_ = c.head.mesh.empty() ? std::string() : headMeshPath(c);
  if (!model->meshPath_.empty()) {
    if (previous && previous->meshPath_ == model->meshPath_) {
      model->mesh_ = previous->mesh_;
    } else {
      std::string why;
      model->mesh_ = loadHeadMesh(model->meshPath_, &why);
      if (!model->mesh_) {
        if (error) *error = "head.mesh: " + why;
        return nullptr;
      }
    }
    model->torsoPath_ = torsoMeshPath(c);
  }
  if (!model->torsoPath_.empty()) {
    if (previous && previous->meshPath_ == model->meshPath_ &&
        previous->torsoPath_ == model->torsoPath_) {
      model->torso_ = previous->torso_;
      model->whole_ = previous->whole_;
    } else {
      std::string why;
      model->torso_ = loadHeadMesh(model->torsoPath_, &why);
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
