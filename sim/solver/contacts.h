// Strand contacts as constraints (METHOD.md section 3), the CPU reference of the GPU passes
// (shaders/sim/candidates*.comp, contact_solve.comp):
//  - once per frame (or collision.lists times), the candidate pairs: segments closer than
//    2r + margin, each listed on both of its segments, with its contact distance (2r, or the
//    pair's rest distance when the groom put it closer) and what the contact measures need;
//  - every substep, after shape matching, each segment's correction from its candidates as
//    compliant position constraints (XPBD, collision.iterations iterations, each a sweep of
//    every segment's list that moves only the segment's own ends, in list order) with
//    Coulomb friction; each iteration but the last moves the particles (applyCorrections),
//    and the strain-limit sweep moves each particle by the mean of the corrections of the
//    last iteration that its two segments sent it, before limiting it.
// Every sweep and sum runs in a fixed order (a segment's candidates by their index), so the
// result does not depend on the schedule.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/results.h"
#include "sim/core/hair_state.h"
#include "sim/solver/stiffness.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {

// The orientation flags of a pair: whether its closest points are inside both segments (only
// then can the sign of the triple product flip by one passing through the other), whether it
// is closer than 2r, the sign, and whether the segments are skew enough (the sine of their
// angle above kSkewSine) for that sign to say which side each is on: a sign change of nearly
// parallel segments can come from turning, not passing.
inline constexpr uint32_t kPairInterior = CSM_PAIR_INTERIOR, kPairNear = CSM_PAIR_NEAR,
                          kPairPositive = CSM_PAIR_POSITIVE, kPairSkew = CSM_PAIR_SKEW;
inline constexpr double kSkewSine = CSM_SKEW_SINE;
uint32_t pairFlags(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& b0,
                   const glm::dvec3& b1, double s, double t, double distance, double twoR);
// The side a listed pair keeps (ContactCandidates::side) from its flags.
int8_t keptSide(uint32_t flags);
// The direction a contact pushes p (the lower segment; q the other way) and the separation
// along it, for segments p0-p1 and q0-q1 with closest points at s and t, d apart. A pair with
// a kept side, still interior and skew, is pushed along the common normal toward that side:
// its separation is negative when one has passed through the other in the substeps since the
// list (the closest points alone would push it on through). Any other pair is pushed along
// its closest points, its separation d.
glm::dvec3 contactNormal(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                         const glm::dvec3& q1, double s, double t, double d, int side,
                         double& separation);
// A crossing between two lists: the pair was interior in both, near in one, and flipped.
inline bool crossed(uint32_t before, uint32_t now) {
  return (before & now & kPairInterior) && ((before | now) & kPairNear) &&
         ((before ^ now) & kPairPositive);
}

// One frame's candidates, by segment: segment i's are [start[i], start[i+1]).
struct ContactCandidates {
  std::vector<uint32_t> start;   // per particle + 1
  std::vector<uint32_t> other;   // the other segment, ascending within a segment
  std::vector<double> distance;  // contact distance
  // The side to keep (contactNormal): +1 or -1, the sign of the pair's triple product when it
  // was listed interior and skew; 0 for a pair held apart along its closest points only.
  std::vector<int8_t> side;
  // Pairs a < b with their flags, sorted, for the next list's crossings.
  std::vector<std::pair<uint64_t, uint32_t>> flags;
};

// Whether a frame of `substeps` substeps with collision.lists = `lists` lists its candidates
// again before substep `substep`: list j (0 < j < n, n = min(lists, substeps)) comes before
// substep floor(j substeps / n). Substep 0 has the frame's own list.
bool listsBefore(int substep, int substeps, int lists);

// Whether a change of settings makes the last candidate search measure something else: the
// mode, the radius or the margin.
// collision.contact_memory_mb in bytes: what the GPU's growing contact buffers may take.
inline uint64_t contactBudgetBytes(const CollisionConfig& c) {
  return uint64_t(std::max(c.contactMemoryMb, 1)) << 20;
}

inline bool contactMeasuresChanged(const CollisionConfig& a, const CollisionConfig& b) {
  return a.mode != b.mode || a.radius != b.radius || a.margin != b.margin;
}

struct ContactSettings {
  double radius = 0.001, margin = 0.001, compliance = 0.0, friction = 0.3;
  ContactSolve solve = ContactSolve::Sweep;  // collision.solve
  // The penalty model (collision.contact_model = penalty): 1/s^2 and 1/s.
  double penaltyStiffness = 20000.0, penaltyDamping = 20.0;
};

// The radius two simulated strands touch at (each at this, 2r apart): collision.radius, or for
// guides as wisps (collision.wisps) the radius of a bundle of the strands a guide stands for on
// average, r sqrt(mean weight) (`weight`: per strand, HairState::weight; empty, 1 each).
double contactRadius(const CollisionConfig& c, std::span<const float> weight);
// The same from the mean weight (meanWeight), which the solvers keep from their reset.
double contactRadius(const CollisionConfig& c, double meanWeight);
// The strands a strand stands for on average: 1 when `weight` is empty.
double meanWeight(std::span<const float> weight);

// The candidates of positions x (rest: the same particles in the head frame, for rest
// distances), measured; `previous` is the last list (crossings), or empty.
ContactCandidates findCandidates(std::span<const glm::dvec3> x, std::span<const glm::dvec3> rest,
                                 std::span<const uint32_t> particleStrand,
                                 const ContactSettings& settings, const ContactCandidates& previous,
                                 ContactStats& stats);

// The inverse mass of each particle as the contacts see it: 0 for the particles the head
// holds (each strand's first regions.pinned), which follow the head whatever pushes them.
std::vector<double> contactInverseMass(const HairState& state, const Regions& regions);

// Moves each particle of the strands [first[s], first[s+1]) but the root by what its segments
// sent (particleCorrection), its velocity by that over h: one contact iteration before the
// next. The held particles were sent nothing (their inverse mass is 0).
void applyCorrections(std::span<const glm::dvec4> correction, std::span<const uint32_t> first,
                      double h, std::span<glm::dvec3> x, std::span<glm::dvec3> v);

// The corrections of one substep of length h: segment i takes its candidates in order, moving
// its own ends by each pair's share before the next pair (the other segments stay at x);
// correction[2i] is what that moved particle i by and correction[2i+1] particle i+1, as one
// segment (w up to 1). collision.solve = jacobi instead evaluates every pair from x and sends
// the sum, as that many pairs (w). x and v after shape matching; invMass per particle, 0 for
// the held ones (they follow the head).
void solveContacts(const ContactCandidates& candidates, std::span<const glm::dvec3> x,
                   std::span<const glm::dvec3> v, std::span<const double> invMass, double h,
                   const ContactSettings& settings, std::vector<glm::dvec4>& correction);

// The paper's penalty model (collision.contact_model = penalty), one substep of length h: each
// of segment i's candidates closer than its contact distance d0 asks for an acceleration
// k (d0 - separation) along the contact normal, less c times the approach speed along it (never
// a pull), and Coulomb friction against the contact points' relative sliding, up to mu times
// the normal change of velocity and half the sliding; each end of the segment takes its
// barycentric share (the held ones none). correction[2i] is the change of velocity of
// particle i, correction[2i+1] that of particle i+1 (w 0): applyPenalty adds them to the
// velocities after the strain limit, so the next substep's prediction feels them, as the
// paper's force from the last collision pass does. x and v where the substep ends.
void penaltyVelocities(const ContactCandidates& candidates, std::span<const glm::dvec3> x,
                       std::span<const glm::dvec3> v, std::span<const double> invMass, double h,
                       const ContactSettings& settings, std::vector<glm::dvec4>& correction);
// Adds to each particle of the strands [first[s], first[s+1]) what its two segments sent
// (penaltyVelocities): the forces of its contacts add up.
void applyPenalty(std::span<const glm::dvec4> correction, std::span<const uint32_t> first,
                  std::span<glm::dvec3> v);

// What particle i of the strand [first, end) moves by: the mean of what its segments sent.
inline glm::dvec3 particleCorrection(std::span<const glm::dvec4> correction, uint32_t i,
                                     uint32_t first, uint32_t end) {
  glm::dvec4 c(0.0);
  if (i + 1 < end) c += correction[2 * size_t(i)];
  if (i > first) c += correction[2 * size_t(i - 1) + 1];
  return c.w > 0.0 ? glm::dvec3(c) / c.w : glm::dvec3(0.0);
}

}  // namespace csm
