// Hair-hair contacts on the CPU: the reference for the GPU pass, the CPU solver's own
// collision pass, and the contact metrics of any solver.
//
// Segment i joins particles i and i+1 of one strand (its index is its first particle's).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace csm {

struct SegmentPair {
  uint32_t a, b;  // segment indices, a < b
  double s, t;    // closest points: x_a + s (x_{a+1} - x_a), x_b + t (x_{b+1} - x_b)
  double distance;
  bool operator==(const SegmentPair& o) const { return a == o.a && b == o.b; }
};

// Closest points of segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection, 5.1.9);
// the GPU's are shaders/sim/common.glsl's closestSegmentPoints.
// Returns the squared distance.
double closestSegmentPoints(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                            const glm::dvec3& q1, double& s, double& t);

// The unit direction from q's closest point to p's, for segments p0-p1 and q0-q1 with closest
// points at s and t, d apart; where they touch, their common normal (+y when parallel too).
glm::dvec3 separationDirection(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                               const glm::dvec3& q1, double s, double t, double d);

// True when segments a and b may touch: both exist and are not neighbours along one strand
// (pairs of one strand closer than `strandGap` segments are skipped).
inline constexpr uint32_t kStrandGap = 2;

// Every segment pair closer than `maxDistance`, sorted by (a, b). Brute force over all pairs.
std::vector<SegmentPair> findContactsBruteForce(std::span<const glm::dvec3> x,
                                                std::span<const uint32_t> particleStrand,
                                                double maxDistance);
// The same pairs, found through a uniform grid whose cells (half the median segment, at least
// twice the contact distance) hold every segment whose padded box touches them. Segments with a
// non-finite end or a box longer than 32 cells along an axis are left out (no pairs for them)
// and counted in *oversize.
std::vector<SegmentPair> findContactsGrid(std::span<const glm::dvec3> x,
                                          std::span<const uint32_t> particleStrand,
                                          double maxDistance, uint64_t* oversize = nullptr);

}  // namespace csm
