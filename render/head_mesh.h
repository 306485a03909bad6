// The head as drawn: a mesh in the head's frame, instanced once per placement (world centre,
// scale) of an SSBO and turned by the head's rotation (head.vert). Spheres: a unit UV sphere
// once per head sphere. The mannequin or head.mesh: its mesh (sim/head/head_model.h) once.
#pragma once

#include <vector>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "sim/core/pose.h"
#include "sim/head/surface_mesh.h"
#include "sim/head/head_model.h"

namespace csm {

class HeadMesh {
 public:
  HeadMesh();
  // This frame's head: the mannequin's or head.mesh's surface where the scene's head is a field,
  // else the scene's spheres, at the head's pose.
  void update(const HeadModel& model, const Pose& head);
  void bind() const;  // the placements' SSBO
  // The head mesh, or with `full` false its coarser version (a mesh of more than
  // kCoarseTriangles: the mannequin's 180,000 cost llvmpipe ~40 ms a frame, twice with shadows).
  void draw(bool full = true) const;
  static constexpr size_t kCoarseTriangles = 30000;
  int sphereCount() const { return placements_; }
  bool isMannequin() const { return mannequin_; }

 private:
  struct Mesh {
    gl::Buffer positions{gl::NoCreate}, normals{gl::NoCreate}, indices{gl::NoCreate};
    gl::VertexArray vao{gl::NoCreate};
    std::size_t indexCount = 0;
  };
  static Mesh upload(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                     const std::vector<uint32_t>& indices);

  Mesh sphere_, mannequinGpu_, coarseGpu_;
  gl::Buffer placementBuffer_{gl::NoCreate};
  int placements_ = 0;
  bool mannequin_ = false;
  const SurfaceMesh* uploaded_ = nullptr;  // the head in mannequinGpu_
};

}  // namespace csm
