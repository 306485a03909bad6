#include "render/head_mesh.h"

#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/draw.h"
#include "render/bindings.h"

namespace csm {

HeadMesh::HeadMesh() {
  // A unit UV sphere, counter-clockwise seen from outside; positions double as normals.
  constexpr int kStacks = 32, kSlices = 64;
  std::vector<glm::vec3> vertices;
  for (int i = 0; i <= kStacks; ++i) {
    const float theta = float(M_PI) * float(i) / kStacks;
    for (int j = 0; j <= kSlices; ++j) {
      const float phi = 2.0f * float(M_PI) * float(j) / kSlices;
      vertices.emplace_back(std::sin(theta) * std::sin(phi), std::cos(theta),
                            std::sin(theta) * std::cos(phi));
    }
  }
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < kStacks; ++i)
    for (int j = 0; j < kSlices; ++j) {
      const std::uint32_t a = std::uint32_t(i * (kSlices + 1) + j), b = a + kSlices + 1;
      indices.insert(indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  vertices_ = gl::Buffer(vertices, GL_STATIC_DRAW);
  indices_ = gl::Buffer(indices, GL_STATIC_DRAW);
  indexCount_ = indices.size();
  vao_ = gl::VertexArray();
  vao_.setAttribute(0, vertices_, 3, GL_FLOAT, sizeof(glm::vec3), 0);
  vao_.setIndexBuffer(indices_);
  spheres_ = gl::Buffer(GLsizeiptr(sizeof(glm::vec4)), nullptr, GL_DYNAMIC_DRAW);
}

void HeadMesh::update(const std::vector<Sphere>& worldSpheres) {
  std::vector<glm::vec4> data;
  for (const Sphere& s : worldSpheres) data.emplace_back(s.center, s.radius);
  sphereCount_ = int(data.size());
  if (!data.empty()) spheres_.upload(data);
}

void HeadMesh::bind() const {
  spheres_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kHeadSpheres);
}

void HeadMesh::draw() const {
  if (sphereCount_ == 0) return;
  vao_.bind();
  gl::drawElements(GL_TRIANGLES, indexCount_, sphereCount_);
}

}  // namespace csm
