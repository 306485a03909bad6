#include "sim/solver/contacts.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/core/segment_pairs.h"
#include "sim/base/parallel.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {
namespace {

// Closest points strictly inside both segments.
bool interior(double s, double t) {
  constexpr double kInside = CSM_PAIR_INSIDE;
  return s > kInside && s < 1.0 - kInside && t > kInside && t < 1.0 - kInside;
}

bool skew(const glm::dvec3& n, const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(n) > kSkewSine * glm::length(a) * glm::length(b);
}

}  // namespace

uint32_t pairFlags(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& b0,
                   const glm::dvec3& b1, double s, double t, double distance, double twoR) {
  uint32_t f = 0;
  if (interior(s, t)) f |= kPairInterior;
  if (distance < twoR) f |= kPairNear;
  const glm::dvec3 n = glm::cross(a1 - a0, b1 - b0);
  if (glm::dot(n, a0 - b0) > 0.0) f |= kPairPositive;
  if (skew(n, a1 - a0, b1 - b0)) f |= kPairSkew;
  return f;
}

int8_t keptSide(uint32_t flags) {
  if ((flags & (kPairInterior | kPairSkew)) != (kPairInterior | kPairSkew)) return 0;
  return (flags & kPairPositive) ? 1 : -1;
}

glm::dvec3 contactNormal(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                         const glm::dvec3& q1, double s, double t, double d, int side,
                         double& separation) {
  const glm::dvec3 between = glm::mix(p0, p1, s) - glm::mix(q0, q1, t);
  if (side != 0 && interior(s, t)) {
    const glm::dvec3 n = glm::cross(p1 - p0, q1 - q0);
    if (skew(n, p1 - p0, q1 - q0)) {
      const glm::dvec3 nrm = (double(side) / glm::length(n)) * n;
      separation = glm::dot(between, nrm);
      return nrm;
    }
  }
  separation = d;
  return separationDirection(p0, p1, q0, q1, s, t, d);
}

double meanWeight(std::span<const float> weight) {
  if (weight.empty()) return 1.0;
  double total = 0.0;
  for (float w : weight) total += w;
  return total / double(weight.size());
}

double contactRadius(const CollisionConfig& c, double meanWeight) {
  if (!c.wisps) return c.radius;
  return double(c.radius) * std::sqrt(std::max(1.0, meanWeight));
}

double contactRadius(const CollisionConfig& c, std::span<const float> weight) {
  return contactRadius(c, meanWeight(weight));
}

ContactCandidates findCandidates(std::span<const glm::dvec3> x, std::span<const glm::dvec3> rest,
                                 std::span<const uint32_t> strand, const ContactSettings& settings,
                                 const ContactCandidates& previous, ContactStats& stats) {
  const double r = settings.radius, twoR = 2.0 * r;
  uint64_t oversize = 0;
  const std::vector<SegmentPair> pairs =
      findContactsGrid(x, strand, twoR + settings.margin, &oversize);
  stats = ContactStats{};
  stats.oversize = oversize;
  stats.candidates = pairs.size();
  ContactCandidates out;
  const size_t n = x.size();
  out.start.assign(n + 1, 0);
  out.flags.reserve(pairs.size());
  // Each pair's contact distance and flags, independent of the others: pairs the groom put
  // closer than 2r keep their rest distance (rest is in the head frame, which moves rigidly).
  std::vector<double> contactDistance(pairs.size());
  std::vector<uint32_t> pairFlagsOf(pairs.size());
  parallelFor(pairs.size(), 1024, [&](size_t first, size_t last) {
    for (size_t k = first; k < last; ++k) {
      const SegmentPair& p = pairs[k];
      double s, t;
      const double restD =
          std::sqrt(closestSegmentPoints(rest[p.a], rest[p.a + 1], rest[p.b], rest[p.b + 1], s, t));
      contactDistance[k] = std::min(twoR, restD);
      pairFlagsOf[k] =
          pairFlags(x[p.a], x[p.a + 1], x[p.b], x[p.b + 1], p.s, p.t, p.distance, twoR);
    }
  });
  size_t seen = 0;  // merge with the previous list, both sorted by (a, b)
  for (size_t k = 0; k < pairs.size(); ++k) {
    const SegmentPair& p = pairs[k];
    const double d0 = contactDistance[k];
    if (p.distance < twoR) ++stats.contacts;
    if (p.distance < d0) {
      const double depth = (d0 - p.distance) / r;
      ++stats.depth[depthBin(depth)];
      stats.maxDepth = std::max(stats.maxDepth, float(depth));
    }
    if (p.distance < r) ++stats.penetrations;
    const uint32_t f = pairFlagsOf[k];
    const uint64_t key = (uint64_t(p.a) << 32) | p.b;
    out.flags.emplace_back(key, f);
    while (seen < previous.flags.size() && previous.flags[seen].first < key) ++seen;
    if (seen < previous.flags.size() && previous.flags[seen].first == key &&
        crossed(previous.flags[seen].second, f)) {
      ++stats.crossings;
      if (d0 < twoR) ++stats.crossingsClose;
    }
    ++out.start[p.a + 1];
    ++out.start[p.b + 1];
  }
  for (size_t i = 0; i < n; ++i) out.start[i + 1] += out.start[i];
  out.other.resize(out.start[n]);
  out.distance.resize(out.start[n]);
  out.side.resize(out.start[n]);
  // Pairs come sorted by (a, b): a segment's partners below it (as b) all come before those
  // above it (as a), each in ascending order, so filling in pair order sorts every list.
  std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
  for (size_t k = 0; k < pairs.size(); ++k) {
    const SegmentPair& p = pairs[k];
    const int8_t side = keptSide(out.flags[k].second);
    for (auto [self, other] : {std::pair(p.a, p.b), std::pair(p.b, p.a)}) {
      out.other[fill[self]] = other;
      out.side[fill[self]] = side;
      out.distance[fill[self]++] = contactDistance[k];
    }
  }
  return out;
}

bool listsBefore(int substep, int substeps, int lists) {
  const int n = std::clamp(lists, 1, std::max(substeps, 1));
  for (int j = 1; j < n; ++j)
    if (j * substeps / n == substep) return true;
  return false;
}

std::vector<double> contactInverseMass(const HairState& state, const Regions& regions) {
  std::vector<double> w(state.particleCount(), 0.0);
  for (size_t s = 0; s < state.strandCount(); ++s) {
    const uint32_t first = state.strandFirst[s], count = state.strandFirst[s + 1] - first;
    for (uint32_t i = first; i < first + count; ++i)
      if (!regions.held(s, int(i - first), int(count))) w[i] = 1.0 / double(state.rest[i].w);
  }
  return w;
}

void applyCorrections(std::span<const glm::dvec4> correction, std::span<const uint32_t> first,
                      double h, std::span<glm::dvec3> x, std::span<glm::dvec3> v) {
  const size_t strands = first.size() - 1;
  parallelFor(strands, 64, [&](size_t from, size_t to) {
    for (size_t s = from; s < to; ++s)
      for (uint32_t i = first[s] + 1; i < first[s + 1]; ++i) {
        const glm::dvec3 moved = particleCorrection(correction, i, first[s], first[s + 1]);
        x[i] += moved;
        v[i] += moved / h;
      }
  });
}

namespace {
// The most a pair moves one end of a segment in a sweep, in units of the pair's depth. With one
// end held, a pair at s along the segment asks the free end for depth / s, and no later pair in
// the sweep takes it back (a mean over the pairs did): Fig. 1's crowded roots then kick tips to
// 12 m/s. 2.5 leaves every pair at s >= 0.4 as it is; a segment with no held end never asks
// more than 1.21 (g / (g^2 + (1 - g)^2) at g = 1/sqrt(2), the other segment held).
constexpr double kLever = CSM_CONTACT_LEVER;  // the GPU pass shares it
// How far (m) a sweep must move an end to count as one of the particle's segments: less counts
// for that fraction of one, so a pair that starts to touch does not halve the move that the
// particle's other segment sends at once (a jump that float and double took apart).
constexpr double kFullWeight = CSM_FULL_WEIGHT;
}  // namespace

void solveContacts(const ContactCandidates& c, std::span<const glm::dvec3> x,
                   std::span<const glm::dvec3> v, std::span<const double> invMass, double h,
                   const ContactSettings& settings, std::vector<glm::dvec4>& correction) {
  const size_t n = x.size();
  if (c.start.size() != n + 1) {
    correction.assign(2 * n, glm::dvec4(0.0));
    return;
  }
  correction.resize(2 * n);  // every entry written below
  const double tilde = settings.compliance / (h * h);
  const double mu = settings.friction;
  const bool sweep = settings.solve == ContactSolve::Sweep;
  parallelFor(n, 512, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const uint32_t a = uint32_t(i);
      // No candidates, or no segment (a strand's last particle: x[a + 1] is another strand's
      // or past the end).
      if (c.start[i] == c.start[i + 1]) {
        correction[2 * i] = correction[2 * i + 1] = glm::dvec4(0.0);
        continue;
      }
      // The segment's own ends, and their velocities, as its sweep has moved them so far (a
      // move of dx changes the velocity by dx / h, as applyCorrections does): each pair's
      // friction takes what sliding the pairs before it left, not the same sliding again (on
      // Fig. 1 that drove tips to 49 m/s). The other segments stay where the iteration found
      // them; jacobi evaluates every pair from there too.
      glm::dvec3 a0 = x[a], a1 = x[a + 1];
      glm::dvec3 va0 = v[a], va1 = v[a + 1];
      glm::dvec3 moved0(0.0), moved1(0.0);  // what the pairs moved the ends by, in order
      double count = 0.0;                   // how many did
      for (uint32_t k = c.start[i]; k < c.start[i + 1]; ++k) {
        const uint32_t b = c.other[k];
        // The pair as both of its segments see it: the lower index first (s on it).
        const bool lower = a < b;
        const uint32_t p = lower ? a : b, q = lower ? b : a;
        const glm::dvec3& p0 = lower ? a0 : x[b];
        const glm::dvec3& p1 = lower ? a1 : x[b + 1];
        const glm::dvec3& q0 = lower ? x[b] : a0;
        const glm::dvec3& q1 = lower ? x[b + 1] : a1;
        double s, t;
        const double d = std::sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
        double separation;
        const glm::dvec3 nrm = contactNormal(p0, p1, q0, q1, s, t, d, c.side[k], separation);
        const double C = separation - c.distance[k];
        if (!(C < 0.0) || std::isinf(C)) continue;  // a segment gone non-finite moves no other
        const double wp0 = invMass[p], wp1 = invMass[p + 1];
        const double wq0 = invMass[q], wq1 = invMass[q + 1];
        const double W =
            wp0 * (1 - s) * (1 - s) + wp1 * s * s + wq0 * (1 - t) * (1 - t) + wq1 * t * t;
        if (W <= 0.0) continue;  // both held
        const double lambda = -C / (W + tilde);
        // Coulomb friction on the relative sliding of the contact points this step: removed
        // up to mu times the normal correction.
        const glm::dvec3& vp0 = lower ? va0 : v[b];
        const glm::dvec3& vp1 = lower ? va1 : v[b + 1];
        const glm::dvec3& vq0 = lower ? v[b] : va0;
        const glm::dvec3& vq1 = lower ? v[b + 1] : va1;
        const glm::dvec3 slide = h * (glm::mix(vp0, vp1, s) - glm::mix(vq0, vq1, t));
        glm::dvec3 tangent = slide - glm::dot(slide, nrm) * nrm;
        const double slideLen = glm::length(tangent);
        const double taken = std::min(slideLen, mu * W * lambda);
        tangent = slideLen > 1e-15 ? tangent * (taken / (slideLen * W)) : glm::dvec3(0.0);
        // Along n for p, against n for q; the friction against the sliding for both.
        glm::dvec3 push = lower ? lambda * nrm - tangent : -(lambda * nrm - tangent);
        const double g0 = lower ? 1 - s : 1 - t, g1 = lower ? s : t;
        // The sweep moves neither end further than kLever times the pair's depth.
        const double most = lambda * std::max(g0 * invMass[a], g1 * invMass[a + 1]);
        if (sweep && most > kLever * -C) push *= kLever * -C / most;
        const glm::dvec3 move0 = push * (g0 * invMass[a]), move1 = push * (g1 * invMass[a + 1]);
        moved0 += move0;
        moved1 += move1;
        count += 1.0;
        if (sweep) {
          a0 += move0;
          a1 += move1;
          va0 += move0 / h;
          va1 += move1 / h;
        }
      }
      // The sweep sends where it left each end, as one segment (kFullWeight), so a particle
      // moves by the mean of its segments' sweeps; jacobi the sum over its pairs, as that
      // many, so the mean over its pairs. particleCorrection divides by the weights.
      if (sweep) {
        const double l0 = std::min(glm::length(moved0) / kFullWeight, 1.0);
        const double l1 = std::min(glm::length(moved1) / kFullWeight, 1.0);
        correction[2 * i] = glm::dvec4(moved0 * l0, l0);
        correction[2 * i + 1] = glm::dvec4(moved1 * l1, l1);
      } else {
        correction[2 * i] = glm::dvec4(moved0, count);
        correction[2 * i + 1] = glm::dvec4(moved1, count);
      }
    }
  });
}

void penaltyVelocities(const ContactCandidates& c, std::span<const glm::dvec3> x,
                       std::span<const glm::dvec3> v, std::span<const double> invMass, double h,
                       const ContactSettings& settings, std::vector<glm::dvec4>& correction) {
  const size_t n = x.size();
  correction.assign(2 * n, glm::dvec4(0.0));
  if (c.start.size() != n + 1) return;
  const double k = settings.penaltyStiffness, damping = settings.penaltyDamping;
  const double mu = settings.friction;
  parallelFor(n, 512, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const uint32_t a = uint32_t(i);
      glm::dvec3 dv0(0.0), dv1(0.0);
      for (uint32_t j = c.start[i]; j < c.start[i + 1]; ++j) {
        const uint32_t b = c.other[j];
        // The pair as both of its segments see it: the lower index first (s on it).
        const bool lower = a < b;
        const uint32_t p = lower ? a : b, q = lower ? b : a;
        double s, t;
        const double d = std::sqrt(closestSegmentPoints(x[p], x[p + 1], x[q], x[q + 1], s, t));
        double separation;
        const glm::dvec3 nrm =
            contactNormal(x[p], x[p + 1], x[q], x[q + 1], s, t, d, c.side[j], separation);
        const double depth = c.distance[j] - separation;
        if (!(depth > 0.0) || std::isinf(depth)) continue;
        const glm::dvec3 rel = glm::mix(v[p], v[p + 1], s) - glm::mix(v[q], v[q + 1], t);
        const double approach = glm::dot(rel, nrm);  // negative when closing
        const double push = h * (k * depth - damping * approach);
        if (!(push > 0.0)) continue;  // a penalty never pulls
        const glm::dvec3 slide = rel - approach * nrm;
        const double slideLen = glm::length(slide);
        const double taken = std::min(0.5 * slideLen, mu * push);
        glm::dvec3 dv = push * nrm;
        if (slideLen > 1e-15) dv -= slide * (taken / slideLen);
        if (!lower) dv = -dv;
        const double g0 = lower ? 1 - s : 1 - t, g1 = lower ? s : t;
        if (invMass[a] > 0.0) dv0 += g0 * dv;
        if (invMass[a + 1] > 0.0) dv1 += g1 * dv;
      }
      correction[2 * i] = glm::dvec4(dv0, 0.0);
      correction[2 * i + 1] = glm::dvec4(dv1, 0.0);
    }
  });
}

void applyPenalty(std::span<const glm::dvec4> correction, std::span<const uint32_t> first,
                  std::span<glm::dvec3> v) {
  if (correction.size() != 2 * v.size()) return;
  const size_t strands = first.empty() ? 0 : first.size() - 1;
  parallelFor(strands, 64, [&](size_t s0, size_t s1) {
    for (size_t s = s0; s < s1; ++s)
      for (uint32_t i = first[s]; i < first[s + 1]; ++i) {
        glm::dvec3 dv(0.0);
        if (i + 1 < first[s + 1]) dv += glm::dvec3(correction[2 * size_t(i)]);
        if (i > first[s]) dv += glm::dvec3(correction[2 * size_t(i - 1) + 1]);
        v[i] += dv;
      }
  });
}

}  // namespace csm
