#include "sim/head/head_model.h"

#include <stdexcept>

#include "sim/base/file_io.h"
#include "sim/head/mannequin.h"
#include "sim/head/mesh_field.h"
#include "sim/head/obj_mesh.h"
#include "sim/head/sphere_fit.h"

namespace csm {

std::string headMeshPath(const Config& c) {
  return resolveRelative(c.head.meshDir, c.head.mesh);
}

std::shared_ptr<const LoadedHead> loadHeadMesh(const std::string& path, std::string* error) {
  io::ObjReadResult read = io::readObjMesh(path);
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
      model->mesh_ = loadHeadMesh(model->meshPath_, error);
      if (!model->mesh_) return nullptr;
    }
  }
  model->fitted_ = c.head.fitSpheres;
  model->fittedCount_ = int(c.head.spheres.size());
  if (!model->fitted_) {
    model->spheres_ = c.head.spheres;
  } else if (previous && previous->fitted_ && previous->fittedCount_ == model->fittedCount_ &&
             &previous->shapeField() == &model->shapeField()) {
    model->spheres_ = previous->spheres_;
  } else {
    model->spheres_ = fitSpheres(model->shapeField(), model->fittedCount_);
  }
  return model;
}

std::shared_ptr<const HeadModel> HeadModel::require(const Config& c) {
  std::string error;
  std::shared_ptr<const HeadModel> model = build(c, &error);
  if (!model) throw std::runtime_error(error);
  return model;
}

const DistanceGrid& HeadModel::shapeField() const {
  return mesh_ ? mesh_->grid : mannequinGrid();
}

const SurfaceMesh* HeadModel::surface() const {
  if (!sdf_) return nullptr;
  return mesh_ ? &mesh_->mesh : &mannequinMesh();
}

}  // namespace csm
