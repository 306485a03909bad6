// The head as drawn: instances of a unit UV sphere, one per head sphere, placed by an SSBO
// of world centres and radii.
#pragma once

#include <vector>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "sim/head.h"

namespace csm {

class HeadMesh {
 public:
  HeadMesh();
  // This frame's spheres, in world space.
  void update(const std::vector<Sphere>& worldSpheres);
  void bind() const;  // the spheres' SSBO
  void draw() const;
  int sphereCount() const { return sphereCount_; }

 private:
  gl::Buffer vertices_{gl::NoCreate}, indices_{gl::NoCreate}, spheres_{gl::NoCreate};
  gl::VertexArray vao_{gl::NoCreate};
  std::size_t indexCount_ = 0;
  int sphereCount_ = 0;
};

}  // namespace csm
