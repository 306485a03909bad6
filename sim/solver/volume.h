// Hair-hair as a continuum, the volume mode (Petrovic et al. 2005, "Volumetric methods for
// simulation and rendering of hair"; McAdams et al. 2009, "Detail preserving continuum
// simulation of straight hair"), the CPU reference of shaders/sim/volume_splat.comp and the
// volume terms of predict.comp:
//  - once per frame, each particle splats its share of strand length (half of each segment
//    beside it, times the strands its strand stands for: a guide as its followers and itself
//    would) and that length times its velocity onto the nodes of a grid fixed to the head
//    (trilinear weights, fixed-point integers: the sums do not depend on the order);
//  - every substep, each free particle's velocity moves toward the hair's mean velocity where
//    it is (friction between neighbouring hairs, a rate in 1/s, so the same at any step), and
//    hair is pushed down the gradient of the volume fraction it fills beyond what is allowed
//    there: collision.volume_fraction, or what the groom itself packed at rest.
// Cost: linear in particles, one grid of fixed size.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {

// Fixed-point units of the grid's sums: 2^-24 m of strand, 2^-24 m^2/s of length times speed.
inline constexpr double kVolumeUnit = CSM_VOLUME_UNIT;

struct VolumeSettings {
  double friction = 5.0;   // 1/s
  double stiffness = 2.0;  // m^2/s^2: acceleration per unit gradient (1/m) of excess fraction
};

// Whether a change of settings needs the grid built anew (VolumeGrid::reset) or let go
// (VolumeGrid::release): only the volume modes keep one.
inline bool volumeGridChanged(const CollisionConfig& a, const CollisionConfig& b) {
  if (volumeForces(a.mode) != volumeForces(b.mode)) return true;
  return volumeForces(b.mode) && (a.volumeCell != b.volumeCell || a.radius != b.radius);
}

class VolumeGrid {
 public:
  // A grid (in the head's frame) over all the hair can reach: the roots' box grown by the
  // longest strand and a cell. `rest` in the head frame, strands [first[s], first[s+1]);
  // `weight` per strand, the strands each stands for (HairState::weight; empty: 1 each), so a
  // guided groom fills the grid as the groom it stands for does.
  void reset(std::span<const glm::dvec3> rest, std::span<const uint32_t> first,
             std::span<const float> weight, double cell, double radius);
  // Lets the grid and its sums go (a mode without the volume keeps none): empty after.
  void release();
  bool empty() const { return nodes() == 0; }
  size_t nodes() const { return size_t(dims_.x) * dims_.y * dims_.z; }
  glm::ivec3 dims() const { return dims_; }
  glm::dvec3 origin() const { return origin_; }
  double cell() const { return cell_; }
  // The volume fraction a node's fixed-point length unit fills.
  double fillPerUnit() const { return fillPerUnit_; }
  // Each particle's share of strand length (m), times its strand's weight.
  const std::vector<double>& particleLength() const { return length_; }
  // The volume fraction the rest groom fills at each node (per node, for the push).
  const std::vector<float>& restFraction() const { return restFraction_; }

  // Splats world positions `x` and velocities `v` into the sums of a grid fixed to the head
  // at `head`, and each node's volume fraction over what is allowed there (the larger of
  // `allowedFraction` and the rest fraction) and its gradient, which the push interpolates.
  void splat(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v, const Pose& head,
             double allowedFraction);
  // The velocity change of the particle at world position x with velocity v over a step h,
  // from the last splat.
  glm::dvec3 velocityChange(const glm::dvec3& x, const glm::dvec3& v, double h,
                            const VolumeSettings& s) const;

  // The sums (for tests and the GPU comparison): per node, length then momentum x, y, z.
  const std::vector<int64_t>& sums() const { return sums_; }

 private:
  // Calls visit(node, weight) for the 8 nodes around head-frame x (trilinear weights; x
  // clamped to the grid).
  template <class Visit>
  void forCorners(const glm::dvec3& x, Visit visit) const;
  void splatLocal(std::span<const glm::dvec3> x, std::span<const glm::dvec3> v);
  glm::dvec3 toHead(const glm::dvec3& x) const;

  glm::dvec3 origin_{0.0};
  glm::ivec3 dims_{0};
  double cell_ = 0.01, fillPerUnit_ = 0.0;  // volume fraction per fixed-point length unit
  Pose head_;                               // the pose the last splat was fixed to
  std::vector<double> length_;
  std::vector<float> restFraction_;
  std::vector<int64_t> sums_;         // 4 per node
  std::vector<glm::dvec3> gradient_;  // per node: of the excess fraction (1/m), head frame
};

}  // namespace csm
