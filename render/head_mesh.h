// The body as drawn: a mesh in the head's frame, instanced once per placement (world centre,
// scale, the turn of its part) of an SSBO (head.vert). Spheres: a unit UV sphere once per
// sphere, each where its part (the head or the torso) has it. The mannequin or head.mesh: the
// head's mesh (sim/head/head_model.h) at the head's pose and the torso's at its own.
#pragma once

#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "sim/core/pose.h"
#include "sim/head/surface_mesh.h"
#include "sim/head/head_model.h"

namespace csm {

class HeadMesh {
 public:
  HeadMesh();
  // This frame's body: the mannequin's or head.mesh's surfaces where the scene's head is a field,
  // else the scene's spheres, at the head's pose and the torso's.
  void update(const HeadModel& model, const Pose& head, const Pose& torso);
  void bind() const;  // the placements' SSBO
  // The meshes with `program` (head.vert's, in use), or with `full` false their coarser versions
  // (a mesh of more than kCoarseTriangles: the mannequin's 180,000 cost llvmpipe ~40 ms a frame,
  // twice with shadows).
  void draw(gl::Program& program, bool full = true) const;
  static constexpr size_t kCoarseTriangles = 30000;
  int sphereCount() const { return placements_; }
  bool isMannequin() const { return mannequin_; }
  // Whether the head drawn is the built-in mannequin's, whose eyes and lips head.frag paints.
  bool paintsFace() const { return face_; }

 private:
  struct Mesh {
    gl::Buffer positions{gl::NoCreate}, normals{gl::NoCreate}, indices{gl::NoCreate};
    gl::VertexArray vao{gl::NoCreate};
    std::size_t indexCount = 0;
  };
  static Mesh upload(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                     const std::vector<uint32_t>& indices);

  // A part's mesh in full and coarser, and the surface they are of.
  struct Part {
    Mesh full, coarse;
    const SurfaceMesh* uploaded = nullptr;
  };
  void uploadPart(const SurfaceMesh* surface, Part& part);

  Mesh sphere_;
  Part head_, torso_;
  gl::Buffer placementBuffer_{gl::NoCreate};
  int placements_ = 0;
  bool mannequin_ = false;
  bool face_ = false;
};

}  // namespace csm
