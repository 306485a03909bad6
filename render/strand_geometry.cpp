#include "render/strand_geometry.h"

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "gl/debug.h"
#include "gl/draw.h"
#include "render/bindings.h"

namespace csm {
namespace {

constexpr std::uint32_t kRestart = 0xffffffffu;  // GL_PRIMITIVE_RESTART_FIXED_INDEX, uint

int bitsFor(std::uint32_t maxValue) {
  int bits = 1;
  while (bits < 32 && (std::uint64_t(1) << bits) <= maxValue) ++bits;
  return bits;
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

bool StrandGeometry::update(const Groom& groom, long generation, int subdivisionWanted,
                            const std::vector<Sphere>& spheres) {
  const Key key{generation, &groom, groom.strandCount(), groom.pointCount(),
                std::clamp(subdivisionWanted, 1, 64)};
  if (key == key_) return false;
  key_ = key;

  const std::size_t strands = groom.strandCount();
  std::uint32_t maxSegments = 1;
  for (std::size_t s = 0; s < strands; ++s)
    maxSegments = std::max(maxSegments, groom.strandSize(s) > 1 ? groom.strandSize(s) - 1 : 1);
  // The vertex id packs guide, point and side into 32 bits (hair_common.glsl), with all ones
  // reserved for primitive restart; a groom too big for the subdivision gets less of it.
  int subdivision = key.subdivision;
  for (;;) {
    pointBits_ = bitsFor(maxSegments * std::uint32_t(subdivision));
    const int guideBits = 31 - pointBits_;
    if (strands == 0 || guideBits >= 31 || (std::uint64_t(strands) >> guideBits) == 0) break;
    if (subdivision == 1) break;
    subdivision = std::max(1, subdivision / 2);
  }
  if (subdivision != key.subdivision)
    gl::logMessage(gl::LogLevel::Warning, "render.subdivision lowered to " +
                                              std::to_string(subdivision) +
                                              " so every vertex of this groom has an id");
  subdivision_ = subdivision;
  // The deep opacity maps are smooth by construction: half the subdivision is plenty there.
  shadowSubdivision_ = std::max(1, (subdivision + 1) / 2);

  std::vector<glm::vec4> rest(groom.pointCount());
  for (std::size_t i = 0; i < rest.size(); ++i) rest[i] = glm::vec4(groom.points[i], 1.0f);
  restPositions_ = gl::Buffer(rest, GL_STATIC_DRAW);
  strandFirst_ = gl::Buffer(groom.first, GL_STATIC_DRAW);

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
  strandAttributes_ = gl::Buffer(attributes, GL_STATIC_DRAW);
  if (dummyAttributes_.id() == 0) {
    // Bound in place of the per-strand attributes when the groom has none: every SSBO a
    // shader declares must be backed by a buffer.
    const glm::vec4 one(1.0f);
    dummyAttributes_ = gl::Buffer(GLsizeiptr(sizeof(one)), &one, GL_STATIC_DRAW);
  }

  order_ = drawOrder(groom);
  guides_ = order_.size();
  std::vector<std::uint32_t> strip, lines;
  stripPrefix_.assign(1, 0);
  linePrefix_.assign(1, 0);
  for (const std::uint32_t s : order_) {
    const std::uint32_t n = groom.strandSize(s);
    const std::uint32_t base = s << (pointBits_ + 1);
    const std::uint32_t points = (n - 1) * std::uint32_t(subdivision_) + 1;
    for (std::uint32_t p = 0; p < points; ++p) {
      strip.push_back(base | p << 1);
      strip.push_back(base | p << 1 | 1u);
    }
    strip.push_back(kRestart);
    const std::uint32_t shadowPoints = (n - 1) * std::uint32_t(shadowSubdivision_) + 1;
    for (std::uint32_t p = 0; p < shadowPoints; ++p) lines.push_back(base | p << 1);
    lines.push_back(kRestart);
    stripPrefix_.push_back(strip.size());
    linePrefix_.push_back(lines.size());
  }
  if (strip.empty()) strip.push_back(kRestart);
  if (lines.empty()) lines.push_back(kRestart);
  stripIndices_ = gl::Buffer(strip, GL_STATIC_DRAW);
  lineIndices_ = gl::Buffer(lines, GL_STATIC_DRAW);
  if (stripVao_.id() == 0) stripVao_ = gl::VertexArray();
  if (lineVao_.id() == 0) lineVao_ = gl::VertexArray();
  stripVao_.setIndexBuffer(stripIndices_);
  lineVao_.setIndexBuffer(lineIndices_);

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

void StrandGeometry::bind() const {
  restPositions_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kRestPositions);
  strandFirst_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kStrandFirst);
  (strandFlags_ ? strandAttributes_ : dummyAttributes_)
      .bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kStrandAttributes);
}

void StrandGeometry::draw(const gl::VertexArray& vao, const std::vector<std::size_t>& prefix,
                          unsigned mode, std::size_t guides, int instances) const {
  guides = std::min(guides, guides_);
  if (guides == 0 || instances <= 0) return;
  vao.bind();
  gl::drawElements(GLenum(mode), prefix[guides], GLsizei(instances));
}

void StrandGeometry::drawRibbons(std::size_t guides, int instances) const {
  draw(stripVao_, stripPrefix_, GL_TRIANGLE_STRIP, guides, instances);
}

void StrandGeometry::drawLines(std::size_t guides, int instances) const {
  draw(lineVao_, linePrefix_, GL_LINE_STRIP, guides, instances);
}

}  // namespace csm
