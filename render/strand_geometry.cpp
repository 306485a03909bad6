#include "render/strand_geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/draw.h"
#include "gl/fence.h"
#include "render/bindings.h"
#include "sim/base/point_grid.h"

namespace csm {
namespace {

// Duff et al. 2017's basis around a unit vector, as hair_common.glsl's basisAround: the
// children's frame at the root.
void basisAround(const glm::vec3& n, glm::vec3& b1, glm::vec3& b2) {
  const float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sgn + n.z);
  const float b = n.x * n.y * a;
  b1 = glm::vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  b2 = glm::vec3(b, sgn + n.y * n.y * a, -n.y);
}

float median(std::vector<float> v) {
  if (v.empty()) return 0.0f;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The drawable strands in an order whose every prefix is an even sample of the head: a
// shuffle with a fixed seed (std::mt19937's sequence is fixed by the standard; the shuffle
// is done here, not by std::shuffle, whose algorithm is the library's choice).
std::vector<std::uint32_t> drawOrder(const Groom& groom) {
  std::vector<std::uint32_t> order;
  for (std::size_t s = 0; s < groom.strandCount(); ++s)
    if (groom.strandSize(s) >= 2) order.push_back(std::uint32_t(s));
  std::mt19937 random(20240601u);
  for (std::size_t i = order.size(); i > 1; --i) {
    const std::size_t j = std::size_t(random() % i);
    std::swap(order[i - 1], order[j]);
  }
  return order;
}

}  // namespace

GuideLinks guideLinks(const Groom& groom) {
  const std::size_t strands = groom.strandCount();
  GuideLinks out;
  out.data.assign(2 * strands, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  std::vector<glm::vec3> roots, dirs;
  std::vector<std::size_t> strandOf;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (std::size_t s = 0; s < strands; ++s) {
    out.data[2 * s + 1] = glm::vec4(std::bit_cast<float>(std::uint32_t(s)), 0.0f, 0.0f, 0.0f);
    if (groom.strandSize(s) < 2) continue;
    const glm::vec3 r = groom.points[groom.first[s]];
    const glm::vec3 d = groom.points[groom.first[s] + 1] - r;
    if (!(glm::length(d) > 0.0f) || !std::isfinite(r.x + r.y + r.z)) continue;
    roots.push_back(r);
    dirs.push_back(glm::normalize(d));
    strandOf.push_back(s);
    lo = glm::min(lo, r);
    hi = glm::max(hi, r);
  }
  if (roots.size() < 2) return out;
  // Roots lie on a surface: n of them over about the box's largest face are about
  // sqrt(area / n) apart. Cells twice that find each root's nearest neighbour.
  const glm::vec3 e = glm::max(hi - lo, glm::vec3(1e-6f));
  const float area = std::max({e.x * e.y, e.y * e.z, e.z * e.x});
  const float guess = std::sqrt(area / float(roots.size()));
  std::vector<float> nearest(roots.size(), 0.0f);
  {
    const PointGrid grid(roots, 2.0f * guess);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      float best = 2.0f * guess;
      grid.within(roots[i], 2.0f * guess, [&](std::size_t j) {
        if (j != i) best = std::min(best, glm::length(roots[j] - roots[i]));
      });
      nearest[i] = best;
    }
  }
  out.spacing = std::max(median(nearest), 1e-5f);
  // The density within three spacings, against its median: about half on an edge.
  const float radius = 3.0f * out.spacing;
  const PointGrid grid(roots, radius);
  std::vector<float> counts(roots.size(), 0.0f);
  std::vector<glm::vec3> centroids(roots.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < roots.size(); ++i) {
    float best = 2.5f * out.spacing;
    std::size_t neighbour = i;
    grid.within(roots[i], radius, [&](std::size_t j) {
      counts[i] += 1.0f;
      centroids[i] += roots[j];
      const float d = glm::length(roots[j] - roots[i]);
      if (j != i && d < best && glm::dot(dirs[i], dirs[j]) > 0.5f) best = d, neighbour = j;
    });
    centroids[i] /= counts[i];
    out.data[2 * strandOf[i] + 1] =
        glm::vec4(std::bit_cast<float>(std::uint32_t(strandOf[neighbour])),
                  glm::length(roots[neighbour] - roots[i]), out.spacing, 0.0f);
  }
  const float typical = std::max(median(counts), 1.0f);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    glm::vec3 b1, b2;
    basisAround(dirs[i], b1, b2);
    const glm::vec3 b = glm::cross(dirs[i], b1);
    glm::vec2 inward(glm::dot(centroids[i] - roots[i], b1), glm::dot(centroids[i] - roots[i], b));
    const float len = glm::length(inward);
    inward = len > 1e-9f ? inward / len : glm::vec2(0.0f);
    out.data[2 * strandOf[i]] =
        glm::vec4(inward, 0.0f, std::clamp(counts[i] / typical, 0.0f, 1.0f));
  }
  return out;
}

bool StrandGeometry::update(const Groom& groom, long generation, int subdivisionWanted,
                            const std::vector<Sphere>& spheres) {
  const Key key{generation, &groom, groom.strandCount(), groom.pointCount(),
                std::clamp(subdivisionWanted, 1, 64)};
  if (key == key_) return false;
  key_ = key;

  const std::size_t strands = groom.strandCount();
  subdivision_ = key.subdivision;
  // The deep opacity maps are smooth by construction: half the subdivision is plenty there.
  // Children, thinner than a pixel, have a point per particle: their bends are a pixel or
  // two across, and a software rasterizer pays for every line segment.
  shadowStride_ = subdivision_ % 2 == 0 ? 2 : 1;
  childStride_ = subdivision_;

  std::vector<glm::vec4> rest(groom.pointCount());
  for (std::size_t i = 0; i < rest.size(); ++i) rest[i] = glm::vec4(groom.points[i], 1.0f);
  restPositions_ = gl::Buffer(rest, gl::BufferUsage::StaticDraw);
  strandFirst_ = gl::Buffer(groom.first, gl::BufferUsage::StaticDraw);

  strandFlags_ = 0;
  std::vector<glm::vec4> attributes(std::max<std::size_t>(strands, 1), glm::vec4(1.0f));
  if (groom.color.size() == strands && strands > 0) {
    strandFlags_ |= 1;
    for (std::size_t s = 0; s < strands; ++s)
      attributes[s] = glm::vec4(glm::clamp(groom.color[s], 0.0f, 1.0f), 1.0f);
  }
  if (groom.thickness.size() == strands && strands > 0) {
    double sum = 0.0;
    for (float t : groom.thickness) sum += std::max(t, 0.0f);
    const double mean = sum / double(strands);
    if (mean > 0.0) {
      strandFlags_ |= 2;
      // Relative to the groom's mean, so render.strand_width stays the typical width.
      for (std::size_t s = 0; s < strands; ++s)
        attributes[s].a = float(std::clamp(groom.thickness[s] / mean, 0.1, 4.0));
    }
  }
  strandAttributes_ = gl::Buffer(attributes, gl::BufferUsage::StaticDraw);
  if (dummyAttributes_.id() == 0) {
    // Bound in place of the per-strand attributes when the groom has none: every SSBO a
    // shader declares must be backed by a buffer.
    const glm::vec4 one(1.0f);
    dummyAttributes_ = gl::Buffer(GLsizeiptr(sizeof(one)), &one, gl::BufferUsage::StaticDraw);
  }

  // Spline points: (n - 1) subdivision + 1 per strand of n >= 2 particles.
  splineFirstHost_.assign(strands + 1, 0);
  std::vector<std::uint32_t> pointStrand;
  for (std::size_t s = 0; s < strands; ++s) {
    const std::uint32_t n = groom.strandSize(s);
    const std::uint32_t points = n >= 2 ? (n - 1) * std::uint32_t(subdivision_) + 1 : 0;
    splineFirstHost_[s + 1] = splineFirstHost_[s] + points;
    pointStrand.insert(pointStrand.end(), points, std::uint32_t(s));
  }
  splinePoints_ = pointStrand.size();
  if (pointStrand.empty()) pointStrand.push_back(0);
  // A child's points: every childStride_-th spline point ((n - 1) subdivision is a multiple).
  childFirstHost_.assign(strands + 1, 0);
  std::vector<std::uint32_t> childStrand;
  for (std::size_t s = 0; s < strands; ++s) {
    const std::uint32_t points = splineFirstHost_[s + 1] - splineFirstHost_[s];
    const std::uint32_t own = points > 0 ? (points - 1) / std::uint32_t(childStride_) + 1 : 0;
    childFirstHost_[s + 1] = childFirstHost_[s] + own;
    childStrand.insert(childStrand.end(), own, std::uint32_t(s));
  }
  childRun_ = childStrand.size();
  if (childStrand.empty()) childStrand.push_back(0);
  childFirst_ = gl::Buffer(childFirstHost_, gl::BufferUsage::StaticDraw);
  childStrand_ = gl::Buffer(childStrand, gl::BufferUsage::StaticDraw);
  splineFirst_ = gl::Buffer(splineFirstHost_, gl::BufferUsage::StaticDraw);
  pointStrand_ = gl::Buffer(pointStrand, gl::BufferUsage::StaticDraw);
  links_ = guideLinks(groom);
  if (links_.data.empty()) links_.data.assign(2, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  guideLinks_ = gl::Buffer(links_.data, gl::BufferUsage::StaticDraw);
  const GLsizeiptr pointBytes = GLsizeiptr(std::max<std::size_t>(splinePoints_, 1) * 16);
  guidePoints_ = gl::Buffer(pointBytes, nullptr, gl::BufferUsage::DynamicCopy);
  guideTangents_ = gl::Buffer(pointBytes, nullptr, gl::BufferUsage::DynamicCopy);
  guideFrames_ = gl::Buffer(pointBytes, nullptr, gl::BufferUsage::DynamicCopy);
  guideShade_ = gl::Buffer(2 * pointBytes, nullptr, gl::BufferUsage::DynamicCopy);

  order_ = drawOrder(groom);
  guides_ = order_.size();
  std::vector<std::uint32_t> strip, shadow;
  stripPrefix_.assign(1, 0);
  shadowPrefix_.assign(1, 0);
  const std::uint32_t stride = std::uint32_t(shadowStride_);
  // Independent triangles and line segments, not strips with primitive restart: a software
  // rasterizer (llvmpipe's draw module) runs each restarted strip as a draw of its own,
  // which cost more than the vertices themselves for children of short strands.
  for (const std::uint32_t s : order_) {
    const std::uint32_t first = splineFirstHost_[s], points = splineFirstHost_[s + 1] - first;
    for (std::uint32_t p = first; p + 1 < first + points; ++p) {
      const std::uint32_t a = p << 1, b = (p + 1) << 1;
      strip.insert(strip.end(), {a, a | 1u, b, b, a | 1u, b | 1u});
    }
    std::uint32_t last = first;
    for (std::uint32_t p = stride; p < points; p += stride) {
      shadow.insert(shadow.end(), {last, first + p});
      last = first + p;
    }
    if (last != first + points - 1) shadow.insert(shadow.end(), {last, first + points - 1});
    stripPrefix_.push_back(strip.size());
    shadowPrefix_.push_back(shadow.size());
  }
  for (auto* v : {&strip, &shadow})
    if (v->empty()) v->push_back(0);
  stripIndices_ = gl::Buffer(strip, gl::BufferUsage::StaticDraw);
  shadowIndices_ = gl::Buffer(shadow, gl::BufferUsage::StaticDraw);
  for (gl::VertexArray* vao : {&stripVao_, &shadowVao_, &childVao_})
    if (vao->id() == 0) *vao = gl::VertexArray();
  stripVao_.setIndexBuffer(stripIndices_);
  shadowVao_.setIndexBuffer(shadowIndices_);
  children_ = -1;

  // A sphere in the head's frame that holds the hair wherever it swings: no particle gets
  // further from its root than the strand's length (plus the strain limit's slack).
  glm::vec3 lo(0.0f), hi(0.0f);
  if (!groom.points.empty()) lo = hi = groom.points[0];
  for (const glm::vec3& p : groom.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  for (const Sphere& sp : spheres) {
    lo = glm::min(lo, sp.center - sp.radius);
    hi = glm::max(hi, sp.center + sp.radius);
  }
  boundCenter_ = 0.5f * (lo + hi);
  float radius = 0.05f;
  for (const Sphere& sp : spheres)
    radius = std::max(radius, glm::length(sp.center - boundCenter_) + sp.radius);
  for (std::size_t s = 0; s < strands; ++s) {
    const std::uint32_t f = groom.first[s], n = groom.strandSize(s);
    float length = 0.0f;
    for (std::uint32_t i = 1; i < n; ++i)
      length += glm::length(groom.points[f + i] - groom.points[f + i - 1]);
    if (n > 0)
      radius = std::max(radius, glm::length(groom.points[f] - boundCenter_) + 1.1f * length);
  }
  boundRadius_ = radius + 0.01f;
  return true;
}

int StrandGeometry::setChildren(int wanted) {
  const std::size_t perChild = std::max<std::size_t>(childRun_, 1) * 32;
  const int children = int(std::min<std::size_t>(std::size_t(std::clamp(wanted, 0, 1 << 16)),
                                                 kMaxChildBytes / perChild));
  if (children == children_) return children;
  children_ = children;
  const std::size_t items = std::max<std::size_t>(childRun_ * std::size_t(children), 1);
  childPoints_ = gl::Buffer(GLsizeiptr(items * 16), nullptr, gl::BufferUsage::DynamicCopy);
  childColors_ = gl::Buffer(GLsizeiptr(items * 16), nullptr, gl::BufferUsage::DynamicCopy);
  // Segments by child rank, then guides in draw order: drawing k children of every guide is
  // a prefix (a share of the strands drops children before guides).
  std::vector<std::uint32_t> lines;
  childPrefix_.assign(1, 0);
  const std::uint32_t n = std::uint32_t(children);
  for (std::uint32_t k = 0; k < n; ++k) {
    for (const std::uint32_t s : order_) {
      const std::uint32_t first = childFirstHost_[s];
      const std::uint32_t count = childFirstHost_[s + 1] - first;
      const std::uint32_t base = first * n + k * count;
      for (std::uint32_t p = 0; p + 1 < count; ++p)
        lines.insert(lines.end(), {base + p, base + p + 1});
    }
    childPrefix_.push_back(lines.size());
  }
  if (lines.empty()) lines.push_back(0);
  childIndices_ = gl::Buffer(lines, gl::BufferUsage::StaticDraw);
  childVao_.setIndexBuffer(childIndices_);
  return children;
}

void StrandGeometry::bind() const {
  restPositions_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kRestPositions);
  strandFirst_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kStrandFirst);
  (strandFlags_ ? strandAttributes_ : dummyAttributes_)
      .bindBase(gl::BufferTarget::ShaderStorage, bindings::kStrandAttributes);
  splineFirst_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kSplineFirst);
  pointStrand_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kPointStrand);
  guideLinks_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kGuideLinks);
  guidePoints_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kGuidePoints);
  guideTangents_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kGuideTangents);
  guideFrames_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kGuideFrames);
  guideShade_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kGuideShade);
  childPoints_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kChildPoints);
  childColors_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kChildColors);
  childFirst_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kChildFirst);
  childStrand_.bindBase(gl::BufferTarget::ShaderStorage, bindings::kChildStrand);
}

void StrandGeometry::draw(const gl::VertexArray& vao, const std::vector<std::size_t>& prefix,
                          gl::Primitive mode, std::size_t count) const {
  count = std::min(count, prefix.size() - 1);
  if (count == 0 || prefix[count] == 0) return;
  vao.bind();
  const std::size_t total = prefix[count];
  if (!paced_) {
    gl::drawElements(mode, total);
    return;
  }
  // A software rasterizer (llvmpipe) keeps a draw's binned triangles until its threads have
  // drawn them, and takes more draws while they work: a 100,000-strand groom's ribbons held
  // 1.19 GB inside glDrawElements, chunks flushed one after another as much. Each chunk waits
  // for the one before the last: binning and drawing still overlap.
  gl::Fence before, last;
  for (std::size_t at = 0; at < total; at += kDrawChunk) {
    before.waitUncounted();
    gl::drawElements(mode, std::min(kDrawChunk, total - at), 1, at);
    before = std::move(last);
    last = gl::Fence::insert();
  }
}

void StrandGeometry::drawRibbons(std::size_t guides) const {
  draw(stripVao_, stripPrefix_, gl::Primitive::Triangles, guides);
}

void StrandGeometry::drawThinGuides(std::size_t guides) const {
  // The shadow passes' lines: two points a simulated segment, where a line a pixel wide
  // shows no corners.
  draw(shadowVao_, shadowPrefix_, gl::Primitive::Lines, guides);
}

void StrandGeometry::drawGuideLines(std::size_t guides) const {
  draw(shadowVao_, shadowPrefix_, gl::Primitive::Lines, guides);
}

void StrandGeometry::drawChildren(int children) const {
  if (children > 0) draw(childVao_, childPrefix_, gl::Primitive::Lines, std::size_t(children));
}

}  // namespace csm
