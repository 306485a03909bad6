// The CPU side of the volume mode; shaders/sim/volume_splat.comp and volume_field.comp are the
// GPU twins (sim/solver/volume.h).
#include "sim/solver/volume.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

namespace csm {
namespace {

constexpr int kMaxNodesPerAxis = 256;

}  // namespace

template <class Visit>
void VolumeGrid::forCorners(const glm::dvec3& x, Visit visit) const {
  const glm::dvec3 u = (x - origin_) / cell_;
  // Clamped before the cast to int: a point far off (or not finite) takes the border's cell.
  glm::dvec3 cellOf = glm::clamp(glm::floor(u), glm::dvec3(0.0), glm::dvec3(dims_ - 2));
  for (int a = 0; a < 3; ++a)
    if (std::isnan(cellOf[a])) cellOf[a] = 0.0;
  const glm::ivec3 base(cellOf);
  const glm::dvec3 f = glm::clamp(u - glm::dvec3(base), 0.0, 1.0);
  for (int c = 0; c < 8; ++c) {
    const glm::ivec3 d(c & 1, (c >> 1) & 1, c >> 2);
    const glm::ivec3 n = base + d;
    const double w = (d.x ? f.x : 1.0 - f.x) * (d.y ? f.y : 1.0 - f.y) * (d.z ? f.z : 1.0 - f.z);
    visit((size_t(n.z) * dims_.y + n.y) * dims_.x + n.x, w);
  }
}

glm::dvec3 VolumeGrid::toHead(const glm::dvec3& x) const {
  return glm::conjugate(head_.rotation) * (x - head_.translation);
}

void VolumeGrid::release() {
  *this = VolumeGrid();
}

void VolumeGrid::reset(std::span<const glm::dvec3> rest, std::span<const uint32_t> first,
                       std::span<const float> weight, double cell, double radius) {
  length_.assign(rest.size(), 0.0);
  glm::dvec3 lo(1e30), hi(-1e30);
  double longest = 0.0;
  for (size_t s = 0; s + 1 < first.size(); ++s) {
    const uint32_t a = first[s], b = first[s + 1];
    if (a == b) continue;
    lo = glm::min(lo, rest[a]);
    hi = glm::max(hi, rest[a]);
    double along = 0.0;
    for (uint32_t i = a; i + 1 < b; ++i) {
      const double l = glm::length(rest[i + 1] - rest[i]);
      length_[i] += 0.5 * l;
      length_[i + 1] += 0.5 * l;
      along += l;
    }
    longest = std::max(longest, along);
    if (s < weight.size())
      for (uint32_t i = a; i < b; ++i) length_[i] *= double(weight[s]);
  }
  if (lo.x > hi.x) {
    dims_ = glm::ivec3(0);
    sums_.clear();
    restFraction_.clear();
    return;
  }
  // Everything a strand can reach from its root (and a cell more), with nodes no finer than
  // the cap allows.
  lo -= longest + cell;
  hi += longest + cell;
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  cell_ = std::max(cell, extent / (kMaxNodesPerAxis - 1));
  origin_ = lo;
  dims_ = glm::ivec3(glm::ceil((hi - lo) / cell_)) + 1;
  dims_ = glm::max(dims_, glm::ivec3(2));
  fillPerUnit_ = glm::pi<double>() * radius * radius / (cell_ * cell_ * cell_) / kVolumeUnit;
  sums_.assign(4 * nodes(), 0);
  gradient_.assign(nodes(), glm::dvec3(0.0));
  head_ = Pose{};
  splatLocal(rest, std::vector<glm::dvec3>(rest.size(), glm::dvec3(0.0)));
  restFraction_.resize(nodes());
  for (size_t n = 0; n < nodes(); ++n)
    restFraction_[n] = float(double(sums_[4 * n]) * fillPerUnit_);
}

void VolumeGrid::splat(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v,
                       const Pose& head, double allowedFraction) {
  head_ = head;
  std::vector<glm::dvec3> local(x.size());
  for (size_t i = 0; i < x.size(); ++i) local[i] = toHead(x[i]);
  splatLocal(local, v);
  // Each node's volume fraction over what is allowed there, then its gradient by central
  // differences between the neighbouring nodes (one-sided on the grid's faces, which hair
  // does not reach): interpolated trilinearly, a push continuous across cell faces.
  std::vector<double> excess(nodes());
  for (size_t n = 0; n < nodes(); ++n) {
    const double allowed = std::max(allowedFraction, double(restFraction_[n]));
    excess[n] = std::max(0.0, double(sums_[4 * n]) * fillPerUnit_ - allowed);
  }
  const glm::ivec3 stride(1, dims_.x, dims_.x * dims_.y);
  for (int z = 0; z < dims_.z; ++z)
    for (int y = 0; y < dims_.y; ++y)
      for (int x = 0; x < dims_.x; ++x) {
        const glm::ivec3 n(x, y, z);
        const size_t node = size_t(n.x + n.y * stride.y + n.z * stride.z);
        for (int axis = 0; axis < 3; ++axis) {
          const int below = std::max(n[axis] - 1, 0) - n[axis];
          const int above = std::min(n[axis] + 1, dims_[axis] - 1) - n[axis];
          gradient_[node][axis] =
              (excess[node + above * stride[axis]] - excess[node + below * stride[axis]]) /
              (double(above - below) * cell_);
        }
      }
}

void VolumeGrid::splatLocal(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v) {
  std::fill(sums_.begin(), sums_.end(), 0);
  for (size_t i = 0; i < x.size() && i < length_.size(); ++i) {
    if (!std::isfinite(x[i].x + x[i].y + x[i].z)) continue;
    forCorners(x[i], [&](size_t node, double w) {
      int64_t* q = &sums_[4 * node];
      const double wl = w * length_[i] * kVolumeUnit;
      q[0] += std::llround(wl);
      q[1] += std::llround(wl * v[i].x);
      q[2] += std::llround(wl * v[i].y);
      q[3] += std::llround(wl * v[i].z);
    });
  }
}

glm::dvec3 VolumeGrid::velocityChange(const glm::dvec3& xWorld, const glm::dvec3& v, double h,
                                      const VolumeSettings& s) const {
  if (empty()) return glm::dvec3(0.0);
  const glm::dvec3 x = toHead(xWorld);
  double length = 0.0;
  glm::dvec3 momentum(0.0);
  forCorners(x, [&](size_t node, double w) {
    const int64_t* q = &sums_[4 * node];
    length += w * double(q[0]);
    momentum += w * glm::dvec3(double(q[1]), double(q[2]), double(q[3]));
  });
  glm::dvec3 dv(0.0);
  if (length > 0.0) dv += (1.0 - std::exp(-s.friction * h)) * (momentum / length - v);
  if (s.stiffness > 0.0) {
    glm::dvec3 gradient(0.0);
    forCorners(x, [&](size_t node, double w) { gradient += w * gradient_[node]; });
    dv -= h * s.stiffness * (head_.rotation * gradient);
  }
  return dv;
}

}  // namespace csm
