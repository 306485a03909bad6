#include "render/head_mesh.h"

#include <cmath>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/draw.h"
#include "render/bindings.h"
#include "sim/head/mannequin.h"

namespace csm {

HeadMesh::Mesh HeadMesh::upload(const std::vector<glm::vec3>& positions,
                                const std::vector<glm::vec3>& normals,
                                const std::vector<uint32_t>& indices) {
  Mesh m;
  m.positions = gl::Buffer(positions, gl::BufferUsage::StaticDraw);
  m.normals = gl::Buffer(normals, gl::BufferUsage::StaticDraw);
  m.indices = gl::Buffer(indices, gl::BufferUsage::StaticDraw);
  m.indexCount = indices.size();
  m.vao = gl::VertexArray();
  m.vao.setAttribute(0, m.positions, 3, gl::AttributeType::Float, sizeof(glm::vec3), 0);
  m.vao.setAttribute(1, m.normals, 3, gl::AttributeType::Float, sizeof(glm::vec3), 0);
  m.vao.setIndexBuffer(m.indices);
  return m;
}

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
  sphere_ = upload(vertices, vertices, indices);
  placementBuffer_ =
      gl::Buffer(GLsizeiptr(sizeof(glm::vec4)), nullptr, gl::BufferUsage::DynamicDraw);
}

namespace {

glm::vec4 quaternion(const Pose& p) {
  const glm::quat q(p.rotation);
  return {q.x, q.y, q.z, q.w};
}

}  // namespace

void HeadMesh::uploadPart(const SurfaceMesh* surface, Part& part) {
  if (surface == part.uploaded) return;
  part.uploaded = surface;
  if (!surface) return;
  // Uploaded once per head (the mannequin or head.mesh's OBJ), from the scalp centre, so that a
  // vertex's position is also its direction on the scalp map (render/scalp_map.h).
  const SurfaceMesh& m = *surface;
  std::vector<glm::vec3> positions(m.positions);
  for (glm::vec3& p : positions) p -= glm::vec3(kMannequinScalpCentre);
  part.full = upload(positions, m.normals, m.indices);
  SurfaceMesh coarse = coarserMesh(SurfaceMesh{positions, m.normals, m.indices}, kCoarseTriangles);
  part.coarse = upload(coarse.positions, coarse.normals, coarse.indices);
}

void HeadMesh::update(const HeadModel& model, const Pose& head, const Pose& torso) {
  std::vector<glm::vec4> data;
  const SurfaceMesh* surface = model.headSurface();
  mannequin_ = surface != nullptr;
  face_ = mannequin_ && model.mannequin();
  if (mannequin_) {
    uploadPart(surface, head_);
    uploadPart(model.torsoSurface(), torso_);
    data.emplace_back(glm::vec3(head.apply(kMannequinScalpCentre)), 1.0f);
    data.push_back(quaternion(head));
    data.emplace_back(glm::vec3(torso.apply(kMannequinScalpCentre)), 1.0f);
    data.push_back(quaternion(torso));
    placements_ = torso_.uploaded ? 2 : 1;
  } else {
    // The head's spheres at its pose, the torso's at the torso's.
    const std::vector<Sphere>& spheres = model.spheres();
    for (size_t k = 0; k < spheres.size(); ++k) {
      const Pose& pose = k < model.headSphereCount() ? head : torso;
      data.emplace_back(glm::vec3(pose.apply(glm::dvec3(spheres[k].center))), spheres[k].radius);
      data.push_back(quaternion(pose));
    }
    placements_ = int(spheres.size());
  }
  if (!data.empty()) placementBuffer_.upload(data);
}

void HeadMesh::bind() const {
  placementBuffer_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kHeadSpheres);
}

void HeadMesh::draw(gl::Program& program, bool full) const {
  if (placements_ == 0) return;
  if (!mannequin_) {
    program.setUniform("uPlacementBase", 0);
    sphere_.vao.bind();
    gl::drawElements(gl::Primitive::Triangles, sphere_.indexCount, placements_);
    return;
  }
  const Part* parts[] = {&head_, &torso_};
  for (int k = 0; k < placements_; ++k) {
    const Mesh& m = full ? parts[k]->full : parts[k]->coarse;
    program.setUniform("uPlacementBase", k);
    m.vao.bind();
    gl::drawElements(gl::Primitive::Triangles, m.indexCount, 1);
  }
}

}  // namespace csm
