#include "render/follower_pass.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec4.hpp>

#include "gl/draw.h"
#include "gl/gl.h"
#include "gl/shader_source.h"
#include "render/bindings.h"
#include "render/compute_dispatch.h"

namespace csm {
namespace {

template <class T>
gl::Buffer staticBuffer(std::vector<T> data) {
  if (data.empty()) data.resize(1);
  return gl::Buffer(data, gl::BufferUsage::StaticDraw);
}

}  // namespace

bool FollowerPass::build(std::string* log) {
  std::string all, one;
  std::optional<gl::Program> turns =
      gl::buildProgram("render/hair_followers.comp GUIDE_TURNS",
                       {{gl::ShaderStage::Compute, "render/hair_followers.comp"}},
                       {gl::Define{"GUIDE_TURNS", ""}}, &one);
  all += one;
  std::optional<gl::Program> followers =
      gl::buildProgram("render/hair_followers.comp",
                       {{gl::ShaderStage::Compute, "render/hair_followers.comp"}}, {}, &one);
  all += one;
  if (log) *log = all;
  if (!turns || !followers) return false;
  turns_ = std::move(*turns);
  followers_ = std::move(*followers);
  return true;
}

void FollowerPass::update(const FollowerBinding& b, long generation, const HeadModel& head) {
  if (&b == binding_ && generation == generation_) return;
  binding_ = &b;
  generation_ = generation;
  const Groom& g = b.drawn;
  points_ = g.pointCount();
  strands_ = g.strandCount();
  guides_ = b.guideCount();
  std::vector<glm::vec4> rest(points_);
  for (std::size_t i = 0; i < points_; ++i) rest[i] = glm::vec4(g.points[i], b.share[i]);
  drawnRest_ = staticBuffer(std::move(rest));
  drawnFirst_ = staticBuffer(g.first);
  guideStrand_ = staticBuffer(b.guideStrand);
  std::vector<std::uint32_t> guideFirst(guides_ + 1, 0);
  for (std::size_t k = 0; k < guides_; ++k)
    guideFirst[k + 1] = guideFirst[k] + g.strandSize(b.guideStrand[k]);
  guideParticles_ = guideFirst.back();
  guideFirst_ = staticBuffer(std::move(guideFirst));
  boundGuides_ = staticBuffer(b.guides);
  boundWeights_ = staticBuffer(b.weights);
  turnsOut_ = gl::Buffer(GLsizeiptr(std::max<std::size_t>(guideParticles_, 1) * 16), nullptr,
                         gl::BufferUsage::DynamicCopy);
  positions_ = gl::Buffer(GLsizeiptr(std::max<std::size_t>(points_, 1) * 16), nullptr,
                          gl::BufferUsage::DynamicCopy);
  pushed_ = gl::Buffer(GLsizeiptr(sizeof(std::uint32_t)), nullptr, gl::BufferUsage::DynamicCopy);
  // The body the followers are kept out of: each part at its own pose (the CPU's followers,
  // sim/groom/followers.h, do the same), the head's shape and then the torso's in one buffer.
  const SceneHead collider = head.collider();
  std::vector<glm::vec4> shape;
  auto add = [&](const DistanceGrid* field, const std::vector<Sphere>& spheres) {
    PartShape part;
    part.first = int(shape.size());
    if (field && !field->empty()) {
      part.shape = 1;
      shape.insert(shape.end(), field->nodes.begin(), field->nodes.end());
      part.dims = field->dims;
      part.origin = field->origin;
      part.cell = field->cell;
    } else if (!spheres.empty()) {
      part.shape = 2;
      for (const Sphere& s : spheres) shape.emplace_back(s.center, s.radius);
      part.spheres = int(spheres.size());
    }
    return part;
  };
  headPart_ = add(collider.field, collider.spheres);
  torsoPart_ = add(collider.torsoField, collider.torsoSpheres);
  head_ = staticBuffer(std::move(shape));
}

unsigned FollowerPass::run(unsigned guidePositions, const BodyPose& body) {
  const Pose& head = body.head;
  if (!binding_ || turns_.id() == 0) return positions_.id();
  const glm::quat q(head.rotation);
  const glm::vec4 rotation(q.x, q.y, q.z, q.w);
  gl::bindStorageBuffer(bindings::kFollowGuidePositions, guidePositions);
  drawnRest_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowDrawnRest);
  drawnFirst_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowDrawnFirst);
  guideStrand_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowGuideStrand);
  guideFirst_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowGuideFirst);
  turnsOut_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowGuideTurns);
  boundGuides_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowBoundGuides);
  boundWeights_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowBoundWeights);
  positions_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowDrawnPositions);
  head_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowHead);
  pushed_.clearToZero();
  pushed_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kFollowPushed);
  for (gl::Program* p : {&turns_, &followers_}) {
    p->use();
    p->setUniform("uGuides", unsigned(guides_));
    p->setUniform("uStrands", unsigned(strands_));
    p->setUniform("uHeadRotation", rotation);
  }
  dispatchOver(turns_, guideParticles_);
  followers_.use();
  followers_.setUniform("uHeadTranslation", glm::vec3(head.translation));
  followers_.setUniform("uHeadShape", headPart_.shape);
  followers_.setUniform("uFieldDims", headPart_.dims);
  followers_.setUniform("uFieldOrigin", headPart_.origin);
  followers_.setUniform("uFieldCell", headPart_.cell);
  followers_.setUniform("uTorsoShape", torsoPart_.shape);
  followers_.setUniform("uTorsoFieldDims", torsoPart_.dims);
  followers_.setUniform("uTorsoFieldOrigin", torsoPart_.origin);
  followers_.setUniform("uTorsoFieldCell", torsoPart_.cell);
  followers_.setUniform("uSpheres", headPart_.spheres);
  followers_.setUniform("uTorsoFirst", torsoPart_.first);
  followers_.setUniform("uTorsoSpheres", torsoPart_.spheres);
  const glm::quat t(body.torso.rotation);
  followers_.setUniform("uTorsoRotation", glm::vec4(t.x, t.y, t.z, t.w));
  followers_.setUniform("uTorsoTranslation", glm::vec3(body.torso.translation));
  dispatchOver(followers_, points_);
  return positions_.id();
}

std::size_t FollowerPass::pushedPoints() const {
  if (pushed_.id() == 0) return 0;
  std::uint32_t n = 0;
  pushed_.read(0, sizeof(n), &n);
  return n;
}

}  // namespace csm
