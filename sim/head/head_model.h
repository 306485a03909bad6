// The head of one scene: what the hair collides with, grows from and what is drawn, built once
// when the scene loads (Simulation) and handed to the solvers, the hair generator and the
// renderer. Nothing about the head is looked up by config anywhere else: a scene's head is
// this object, and a head mesh that cannot be read is an error when the scene loads.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/config.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_fit.h"
#include "sim/head/scalp_marks.h"
#include "sim/head/surface_mesh.h"

namespace csm {

// What a solver collides with, read every step: the field when collision.head_shape is sdf,
// else the spheres (head frame); and where the body has a torso (the mannequin, or
// head.torso_mesh), the torso's, in its own frame, which moves with the torso's pose.
struct SceneHead {
  const DistanceGrid* field = nullptr;  // null: the spheres
  std::vector<Sphere> spheres;
  const DistanceGrid* torsoField = nullptr;  // null: no torso, or its spheres
  std::vector<Sphere> torsoSpheres;
  bool hasTorso() const { return torsoField != nullptr || !torsoSpheres.empty(); }
};

// A head read from an OBJ or PLY (head.mesh, or head.torso_mesh), brought into the head frame, and
// its field (4 mm, a 2 cm margin).
struct LoadedHead {
  SurfaceMesh mesh;
  DistanceGrid grid;
  HeadFit fit;             // what brought the file into the head frame
  size_t cappedHoles = 0;  // openings closed (a scan open at the neck)
};
// Reads, checks, fits (`options`; or `given`, the head's own fit, for its torso) and samples the
// mesh at `path`. Null with a message naming the file and line, or the size it has once fitted
// (over 1 m: not a head).
std::shared_ptr<const LoadedHead> loadHeadMesh(const std::string& path, std::string* error,
                                               const HeadFitOptions& options = {},
                                               const HeadFit* given = nullptr);
// head.mesh_scale, mesh_up, mesh_facing and mesh_place.
HeadFitOptions headFitOptions(const Config& c);
// head.mesh, and head.torso_mesh, resolved against the folder of the preset it came from
// (empty: the mannequin; no torso of the user's).
std::string headMeshPath(const Config& c);
std::string torsoMeshPath(const Config& c);

class HeadModel {
 public:
  // The head `c` asks for: head.mesh read and sampled, or the mannequin; head.spheres, or as many
  // fitted inside the shape when head.fit_spheres is set. Parts that `previous` already holds
  // for the same inputs (the mesh of the same path, spheres fitted to the same field and count)
  // are shared, not made again. Null with a message naming the file (and line) when head.mesh
  // cannot be read ("head.mesh: ..." or "head.torso_mesh: ...").
  static std::shared_ptr<const HeadModel> build(const Config& c, std::string* error,
                                                const HeadModel* previous = nullptr);
  // The same, for code that has checked the scene already (tests, tools): throws
  // std::runtime_error with the message where build fails.
  static std::shared_ptr<const HeadModel> require(const Config& c);

  // The whole body at rest, where hair grows and is draped, whatever moves later: its field
  // when collision.head_shape is sdf, else null (the spheres).
  const DistanceGrid* field() const { return sdf_ ? &shapeField() : nullptr; }
  // The field of the whole shape at rest whatever collision.head_shape says: head.mesh's (with
  // head.torso_mesh's), or the mannequin's.
  const DistanceGrid& shapeField() const;
  // Every sphere, the head's and the torso's, in the head frame at rest: what the scene grows
  // hair from and draws when collision.head_shape is spheres.
  const std::vector<Sphere>& spheres() const { return spheres_; }
  // The surface drawn whole at rest: head.mesh's or the mannequin's when collision.head_shape is
  // sdf; null (spheres) otherwise.
  const SurfaceMesh* surface() const;
  // The body's parts as they move: whether it has a torso (the mannequin; a head.mesh with a
  // head.torso_mesh), the head's surface and the torso's (null: none, or spheres), and how many
  // of spheres() are the head's (the rest, the torso's: those whose centre lies below head.pivot).
  bool articulated() const { return articulated_; }
  const SurfaceMesh* headSurface() const;
  const SurfaceMesh* torsoSurface() const;
  size_t headSphereCount() const { return headSpheres_; }
  // True when the shape is the built-in mannequin (no head.mesh).
  bool mannequin() const { return !mesh_; }
  // The head.mesh file it was read from, resolved (headMeshPath); empty for the mannequin.
  const std::string& meshPath() const { return meshPath_; }
  // How head.mesh came into the head frame (null: the mannequin).
  const HeadFit* meshFit() const { return mesh_ ? &mesh_->fit : nullptr; }
  // The landmarks the scalp is laid out by: the mannequin's, or those found on head.mesh.
  const ScalpMarks& scalpMarks() const { return marks_; }
  // What the scene says of its head when it loads: head.mesh's fit and landmarks; empty for the
  // mannequin.
  const std::string& summary() const { return summary_; }
  // What a solver reads every step: each part's field or spheres, in its own frame.
  SceneHead collider() const;

 private:
  bool sdf_ = true;
  std::string meshPath_;                    // empty: the mannequin
  std::shared_ptr<const LoadedHead> mesh_;  // null: the mannequin
  HeadFitOptions fitOptions_;
  ScalpMarks marks_ = mannequinScalpMarks();
  std::string summary_;
  std::string describe() const;
  std::string torsoPath_;  // empty: no torso of the user's
  std::shared_ptr<const LoadedHead> torso_;
  std::shared_ptr<const DistanceGrid> whole_;  // head.mesh and head.torso_mesh at rest
  bool articulated_ = false;
  bool fitted_ = false;
  int fittedCount_ = 0;
  std::vector<Sphere> spheres_;  // the head's first, then the torso's
  size_t headSpheres_ = 0;
};

// A solver's head: the one its owner handed it (Solver::setHead) before its reset. Simulation
// hands the head it built when the scene loaded; tests and tools that run a solver on its own
// hand one built from their scene (sim/verify/solver_head.h). A solver never builds one: without
// it, the solver's reset says so in failure() (kNoHeadFailure) and it steps nothing.
class SolverHead {
 public:
  void hand(std::shared_ptr<const HeadModel> model) { model_ = std::move(model); }
  bool handed() const { return model_ != nullptr; }
  // What the solver collides with: the handed head's; nothing when none was handed.
  SceneHead collider() const { return model_ ? model_->collider() : SceneHead{}; }
  const std::shared_ptr<const HeadModel>& shared() const { return model_; }

 private:
  std::shared_ptr<const HeadModel> model_;
};

inline constexpr const char* kNoHeadFailure =
    "no head was handed to the solver (Solver::setHead before reset)";

}  // namespace csm
