#include "sim/solver/stiffness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

namespace csm {
namespace {

// c_w for w = 1..16, as measureWindowCoefficient (sim/verify/window_coefficient.h) measures it
// (csmhair-bench --only window; the float rest positions leave about 1e-4 of noise in it).
constexpr double kWindowCoefficient[] = {0.0,      0.055560, 0.043748, 0.037031, 0.033429, 0.031197,
                                         0.029715, 0.028627, 0.027820, 0.027200, 0.026706, 0.026297,
                                         0.025956, 0.025664, 0.025414, 0.025197, 0.025007};
constexpr int kTableSize = int(sizeof kWindowCoefficient / sizeof kWindowCoefficient[0]) - 1;

// Ties (a window of exactly w + 1/2 segments) go up, in the regions and in the rate alike:
// rounding in the arc lengths must not split them.
constexpr double kTie = 1e-6;

// Strands whose segments are within this share of their mean are spaced evenly (endFactor).
constexpr double kEvenSpacing = 1e-4;
// The end factor's range.
constexpr double kEndFactorRange = 2.0;

glm::dvec3 restOf(const HairState& st, size_t i) {
  return glm::dvec3(st.rest[i].x, st.rest[i].y, st.rest[i].z);
}

// The clamp's curvature for strand s (ClampField in stiffness.h): fitted to the free particles
// within one window (and one held piece) of the clamp, at least three where the strand has
// them; least squares of
// u_j = a tau_j^2, so weight_j = tau_j^2 / sum tau^4.
void fitClampField(Regions& r, size_t s, uint32_t a, const std::vector<double>& arc,
                   double clampArc, double windowLength) {
  const int count = int(arc.size()), pinned = r.pinned[s];
  int end = pinned;
  const double wanted = std::max(windowLength, clampArc);
  while (end < count && (arc[end] - clampArc <= wanted * (1.0 + kTie) || end - pinned < 3)) ++end;
  const double scale = end > pinned ? arc[end - 1] - clampArc : 0.0;
  if (!(scale > 0.0)) return;
  r.fitEnd[s] = end;
  for (int i = 0; i < count; ++i) r.clampFit[a + i].y = (arc[i] - clampArc) / scale;
  double sum4 = 0.0;
  for (int j = pinned; j < end; ++j) sum4 += std::pow(r.clampFit[a + j].y, 4.0);
  for (int j = pinned; j < end; ++j)
    r.clampFit[a + j].x = std::pow(r.clampFit[a + j].y, 2.0) / sum4;
}

// The clamp field's a as a row over the free particles' displacements (ClampField): the fit
// particles' static weights.
Eigen::RowVectorXd clampFieldRow(const Regions& r, size_t s, uint32_t a, int free) {
  Eigen::RowVectorXd field = Eigen::RowVectorXd::Zero(free);
  for (int j = r.pinned[s]; j < r.fitEnd[s]; ++j) field[j - r.pinned[s]] = r.clampFit[a + j].x;
  return field;
}

// I - P over the free particles of strand s (first particle a, rest arcs `arc`) straightened, P
// the region goals linearised for small displacements across it (endFactor in stiffness.h);
// the clamp's pull is not in it (fitClampPull adds it).
Eigen::MatrixXd linearPull(const Regions& r, size_t s, uint32_t a, const std::vector<double>& arc) {
  const int count = int(arc.size()), pinned = r.pinned[s], free = count - pinned;
  if (free < 1 || count < 2) return {};
  // Behind the clamp a member's displacement is tau^2 times the field's a.
  const Eigen::RowVectorXd field = clampFieldRow(r, s, a, free);
  const double seg0 = arc[1] - arc[0];
  const double tau0 = r.clampFit[a].y, ghostTau = r.clampFit[a + 1].y - tau0;
  auto tauOf = [&](int j) {
    return std::max(j < 0 ? tau0 + j * ghostTau : r.clampFit[a + j].y, -kClampDepth);
  };
  auto xOf = [&](int j) { return j < 0 ? j * seg0 : arc[j]; };
  auto mOf = [&](int j) { return j < 0 ? r.ghostMass[s] : r.mass[a + j]; };
  // Each region's rigid fit, linearised: a translation ubar and a turn theta about its
  // centroid, rows over the free particles' displacements across the strand.
  Eigen::MatrixXd ubar = Eigen::MatrixXd::Zero(count, free), theta = ubar;
  std::vector<double> xbar(count);
  for (int k = 0; k < count; ++k) {
    const int lo = r.lo[a + k], hi = r.hi[a + k];
    double M = 0.0, X = 0.0;
    for (int j = lo; j <= hi; ++j) {
      M += mOf(j);
      X += mOf(j) * xOf(j);
    }
    xbar[k] = X / M;
    double J = 0.0, fieldU = 0.0, fieldT = 0.0;
    for (int j = lo; j <= hi; ++j) {
      const double m = mOf(j), dx = xOf(j) - xbar[k];
      J += m * dx * dx;
      if (j >= pinned) {
        ubar(k, j - pinned) += m / M;
        theta(k, j - pinned) += m * dx;
      } else {
        const double t2 = tauOf(j) * tauOf(j);
        fieldU += m / M * t2;
        fieldT += m * dx * t2;
      }
    }
    ubar.row(k) += fieldU * field;
    theta.row(k) += fieldT * field;
    theta.row(k) *= J > 0.0 ? 1.0 / J : 0.0;
  }
  // Goals average the regions that contain each particle: A = I - P.
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(free, free);
  for (int i = pinned; i < count; ++i) {
    const int l0 = std::max(0, r.lo[a + i]), l1 = r.hi[a + i];
    const double share = 1.0 / double(l1 - l0 + 1);
    for (int k = l0; k <= l1; ++k)
      A.row(i - pinned) -= share * (ubar.row(k) + (arc[i] - xbar[k]) * theta.row(k));
  }
  return A;
}

// The clamp's pull (Regions::clampPull) of strand s, given A = linearPull's I - P: for each free
// particle whose own region reaches behind the clamp, the beam's residual there over the
// field's a, both from the cantilever under a uniform load, u(x) = x^2 (6 L^2 - 4 L x + x^2) / 24
// (B = q = 1), whose interior residual is c_w (w l)^4. Fills the pulls (the caller has zeroed
// them) and adds them to A: A becomes I - P with the pull.
void fitClampPull(Regions& r, size_t s, uint32_t a, const std::vector<double>& arc, double clampArc,
                  double window, Eigen::MatrixXd& A) {
  const int count = int(arc.size()), pinned = r.pinned[s], free = count - pinned;
  if (A.rows() != free || free < 1) return;
  const double L = arc[count - 1] - clampArc;
  Eigen::VectorXd beam(free);
  for (int i = pinned; i < count; ++i) {
    const double x = arc[i] - clampArc;
    beam[i - pinned] = x * x * (6.0 * L * L - 4.0 * L * x + x * x) / 24.0;
  }
  const Eigen::RowVectorXd field = clampFieldRow(r, s, a, free);
  double fieldOfBeam = 0.0;
  for (int j = 0; j < free; ++j) fieldOfBeam += field[j] * beam[j];
  if (!(fieldOfBeam > 0.0)) return;
  const double interior = windowCoefficient(r.window[s]) * std::pow(window, 4.0);
  const Eigen::VectorXd residual = A * beam;
  for (int i = pinned; i < count; ++i) {
    if (r.lo[a + i] >= pinned) continue;
    r.clampPull[a + i] = (residual[i - pinned] - interior) / fieldOfBeam;
    A.row(i - pinned) -= r.clampPull[a + i] * field;
  }
}

// The tip's displacement u solving A u = 1 (A = I - P): the sag under a unit acceleration at
// k = 1.
double linearTipSag(const Eigen::MatrixXd& A) {
  if (A.rows() == 0) return 0.0;
  const Eigen::VectorXd u = A.partialPivLu().solve(Eigen::VectorXd::Ones(A.rows()));
  return u[A.rows() - 1];
}

// The ends of strands spaced evenly, by what sets them: the pulls are ratios of lengths to the
// fourth power and the factor a ratio of such, so neither depends on the scale.
using EndKey = std::array<long, 6>;
struct EndFit {
  std::vector<double> pull;  // the clamp's pull of each particle
  double factor = 1.0;
};
using EndFits = std::map<EndKey, EndFit>;

// The clamp's pull (fitClampPull) and the ends' factor (endFactor in stiffness.h) of strand s,
// the pulls written to r.clampPull; returns the factor.
double fitEnds(Regions& r, size_t s, uint32_t a, const std::vector<double>& arc, double clampArc,
               EndFits& cache) {
  const int count = int(arc.size());
  const double free = arc[count - 1] - clampArc;
  const double mean = count > 1 ? arc[count - 1] / (count - 1) : 0.0;
  const double window = mean * r.window[s];
  if (count < 3 || !(free >= window) || !(r.rate[s] > 0.0)) return 1.0;
  bool even = true;
  for (int j = 0; j + 1 < count && even; ++j)
    even = std::abs(arc[j + 1] - arc[j] - mean) <= kEvenSpacing * mean;
  const EndKey key{count,   r.pinned[s], r.fitEnd[s],
                   r.lo[a], r.window[s], std::lround(clampArc / mean / kEvenSpacing)};
  if (even) {
    const auto found = cache.find(key);
    if (found != cache.end()) {
      std::copy(found->second.pull.begin(), found->second.pull.end(), r.clampPull.begin() + a);
      return found->second.factor;
    }
  }
  Eigen::MatrixXd A = linearPull(r, s, a, arc);
  fitClampPull(r, s, a, arc, clampArc, window, A);
  // Per unit B and load: the beam's tip sag, and the strand's at k = B / (c_w (w l)^4).
  const double beam = std::pow(free, 4.0) / 8.0;
  const double csm = linearTipSag(A) * windowCoefficient(r.window[s]) * std::pow(window, 4.0);
  const double f = csm > 0.0 && std::isfinite(csm) ? csm / beam : 1.0;
  const double kept = std::clamp(f, 1.0 / kEndFactorRange, kEndFactorRange);
  if (even)
    cache.emplace(
        key, EndFit{std::vector<double>(r.clampPull.begin() + a, r.clampPull.begin() + a + count),
                    kept});
  return kept;
}

}  // namespace

double windowCoefficient(int w) {
  w = std::max(1, w);
  if (w <= kTableSize) return kWindowCoefficient[w];
  return (1.0 + 2.0 / w) / 45.0;
}

int calibratedWindow(double windowLength, double segmentLength, int particles) {
  const int most = std::max(1, particles - 1);
  if (!(segmentLength > 0.0)) return most;
  const double w = std::floor(windowLength / segmentLength + 0.5 + kTie);
  return int(std::clamp(w, 1.0, double(most)));
}

Regions buildRegions(const HairState& st, const SimConfig& sim) {
  Regions r;
  const size_t n = st.particleCount(), strands = st.strandCount();
  r.lo.assign(n, 0);
  r.hi.assign(n, 0);
  r.mass.assign(n, 0.0);
  r.inertia.assign(n, 0.0);
  r.rate.assign(strands, 0.0);
  r.window.assign(strands, 0);
  r.pinned.assign(strands, std::max(0, sim.pinned));
  r.tipHeld.assign(strands, 0);
  for (size_t s = 0; s < std::min(strands, st.tipHeld.size()); ++s) r.tipHeld[s] = st.tipHeld[s];
  r.ghostMass.assign(strands, 0.0);
  r.clampFit.assign(n, glm::dvec2(0.0));
  r.fitEnd.assign(strands, 0);
  r.endFactor.assign(strands, 1.0);
  r.clampPull.assign(n, 0.0);
  const bool calibrated = sim.stiffnessModel == StiffnessModel::Calibrated;
  const double L = sim.windowLength;
  std::vector<double> arc, seg;
  EndFits cache;
  for (size_t s = 0; s < strands; ++s) {
    const uint32_t a = st.strandFirst[s], b = st.strandFirst[s + 1];
    const int count = int(b - a);
    if (count <= 0) continue;
    // Rest arc length of each particle and the length of each segment j -> j+1.
    arc.assign(count, 0.0);
    seg.assign(count, 0.0);
    for (int j = 0; j + 1 < count; ++j) {
      seg[j] = glm::length(restOf(st, a + j + 1) - restOf(st, a + j));
      arc[j + 1] = arc[j] + seg[j];
    }
    const double meanSegment = count > 1 ? arc[count - 1] / (count - 1) : 0.0;
    int ghosts = 0;  // the most ghosts a region has
    double clampArc = 0.0;
    if (calibrated) {
      // The held piece by length: the clamp sits at arc s_c = sim.rootLength (at least the
      // sim.pinned particles' reach), between particles where it falls there; the particles
      // up to it follow the head.
      const int fewest = std::min(std::max(0, sim.pinned), count);
      clampArc = std::max(double(sim.rootLength), fewest > 0 ? arc[fewest - 1] : 0.0);
      int pinned = fewest;
      while ((fewest > 0 || sim.rootLength > 0.0f) && pinned < count &&
             arc[pinned] <= clampArc * (1.0 + kTie))
        ++pinned;
      r.pinned[s] = pinned;
      // In region k: the neighbours, and every i whose distance less a quarter of the two
      // facing segments is within L. The distance grows with |i - k|, so each side is a run.
      auto inside = [&](int i, int k) {
        if (std::abs(i - k) <= 1) return true;
        const int lo = std::min(i, k), hi = std::max(i, k);
        return arc[hi] - arc[lo] - 0.25 * (seg[lo] + seg[hi - 1]) <= L + kTie * L;
      };
      const bool clamped = r.pinned[s] >= 2 && count >= 2 && seg[0] > 0.0;
      for (int k = 0; k < count; ++k) {
        int lo = k, hi = k;
        while (lo > 0 && inside(lo - 1, k)) --lo;
        while (hi + 1 < count && inside(hi + 1, k)) ++hi;
        if (clamped && lo == 0) {
          // Ghost j sits at arc -j seg[0]; the segment facing it from k is seg[k - 1] (or the
          // ghost spacing for the root itself).
          const double facing = k > 0 ? seg[k - 1] : seg[0];
          int q = 0;
          while (q < count + 64 &&
                 (k + q + 1 <= 1 ||
                  arc[k] + (q + 1) * seg[0] - 0.25 * (facing + seg[0]) <= L + kTie * L))
            ++q;
          lo = -q;
          ghosts = std::max(ghosts, q);
        }
        r.lo[a + k] = lo;
        r.hi[a + k] = hi;
      }
      const int w = calibratedWindow(L, meanSegment, count);
      r.window[s] = w;
      const double reach = w * meanSegment;
      if (count > 1 && reach > 0.0)
        r.rate[s] = double(sim.bendingStiffness) / (windowCoefficient(w) * std::pow(reach, 4.0));
      // A ghost carries a whole segment of the root's spacing, shared like an inner
      // particle's among 2w + 1 regions.
      if (ghosts > 0) r.ghostMass[s] = seg[0] / (2.0 * w + 1.0);
      if (clamped) fitClampField(r, s, a, arc, clampArc, L);
    } else {
      const int w = std::max(1, sim.stiffnessWindow);
      r.window[s] = w;
      for (int k = 0; k < count; ++k) {
        r.lo[a + k] = std::max(0, k - w);
        r.hi[a + k] = std::min(count - 1, k + w);
      }
    }
    // Each particle carries half of each segment beside it, as makeHairState's masses do.
    for (int i = 0; i < count; ++i) {
      const double carried = std::max(0.5 * ((i > 0 ? seg[i - 1] : 0.0) + seg[i]), 1e-6);
      r.mass[a + i] = carried / double(r.hi[a + i] - std::max(0, r.lo[a + i]) + 1);
    }
    if (calibrated && r.fitEnd[s] > 0) {
      r.longestFree = std::max(r.longestFree, arc[count - 1] - clampArc);
      r.endFactor[s] = fitEnds(r, s, a, arc, clampArc, cache);
      r.rate[s] *= r.endFactor[s];
    }
    // J_k, directly: a build-time cost of O(region) per region.
    const glm::dvec3 root = restOf(st, a);
    const glm::dvec3 step = count > 1 ? restOf(st, a + 1) - root : glm::dvec3(0.0);
    const double mg = r.ghostMass[s];
    for (int k = 0; k < count; ++k) {
      const int lo = r.lo[a + k], hi = r.hi[a + k];
      auto at = [&](int i) { return i >= 0 ? restOf(st, a + i) : root + double(i) * step; };
      auto weight = [&](int i) { return i >= 0 ? r.mass[a + i] : mg; };
      double M = 0.0;
      glm::dvec3 c(0.0);
      for (int i = lo; i <= hi; ++i) {
        M += weight(i);
        c += weight(i) * at(i);
      }
      c /= M;
      double J = 0.0;
      for (int i = lo; i <= hi; ++i) {
        const glm::dvec3 d = at(i) - c;
        J += weight(i) * glm::dot(d, d);
      }
      r.inertia[a + k] = J;
    }
  }
  for (const double k : r.rate) r.maxRate = std::max(r.maxRate, k);
  r.planRate = planRate(r.rate);
  return r;
}

double planRate(const std::vector<double>& rates) {
  if (rates.empty()) return 0.0;
  std::vector<double> sorted = rates;
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const double limit = kOutlierRate * sorted[sorted.size() / 2];
  double rate = 0.0;
  for (const double k : rates)
    if (k <= limit) rate = std::max(rate, k);
  return rate;
}

bool regionsChanged(const SimConfig& a, const SimConfig& b) {
  return a.stiffnessModel != b.stiffnessModel || a.stiffnessWindow != b.stiffnessWindow ||
         a.windowLength != b.windowLength || a.bendingStiffness != b.bendingStiffness ||
         a.rootLength != b.rootLength || a.pinned != b.pinned;
}

FramePlan planFrame(const SimConfig& sim, double maxRate) {
  FramePlan p;
  const int fewest = std::max(1, sim.substeps);
  p.substeps = p.wanted = fewest;
  if (sim.stiffnessModel == StiffnessModel::Calibrated && maxRate > 0.0) {
    // A hair's breadth under a whole number of steps needs no extra step.
    const double need = std::ceil(double(sim.dt) * std::sqrt(maxRate) - 1e-6);
    p.wanted = int(std::clamp(need, double(fewest), 1e6));
    p.substeps = std::max(fewest, std::min(p.wanted, std::max(1, sim.maxSubsteps)));
    p.capped = p.wanted > p.substeps;
  }
  p.h = double(sim.dt) / p.substeps;
  return p;
}

StiffnessInfo describeStiffness(const Regions& regions, const SimConfig& sim, double dftl) {
  StiffnessInfo info = describeStiffness(regions, sim);
  info.dftl = dftl;
  return info;
}

StiffnessInfo describeStiffness(const Regions& regions, const SimConfig& sim) {
  StiffnessInfo info;
  info.model = sim.stiffnessModel;
  info.plan = planFrame(sim, regions.planRate);
  info.strands = regions.rate.size();
  info.dftl = sim.dftl;
  const double g = glm::length(glm::dvec3(sim.gravity));
  const double longest = regions.longestFree;
  if (sim.stiffnessModel == StiffnessModel::Calibrated && g > 0.0 && longest > 0.0)
    info.bendingNumber = double(sim.bendingStiffness) / (g * longest * longest * longest);
  bool first = true;
  for (size_t s = 0; s < regions.rate.size(); ++s) {
    const double k = regions.rate[s];
    const double alpha = stepAlpha(sim, k, info.plan.h);
    if (sim.stiffnessModel == StiffnessModel::Calibrated && k * info.plan.h * info.plan.h > 1.0)
      ++info.stifferStrands;
    const int w = regions.window[s];
    if (first) {
      info.alphaMin = info.alphaMax = alpha;
      info.rateMin = info.rateMax = k;
      info.windowMin = info.windowMax = w;
      first = false;
      continue;
    }
    info.alphaMin = std::min(info.alphaMin, alpha);
    info.alphaMax = std::max(info.alphaMax, alpha);
    info.rateMin = std::min(info.rateMin, k);
    info.rateMax = std::max(info.rateMax, k);
    info.windowMin = std::min(info.windowMin, w);
    info.windowMax = std::max(info.windowMax, w);
  }
  return info;
}

namespace {

std::string range(double lo, double hi, const char* format) {
  char a[32], b[32];
  std::snprintf(a, sizeof a, format, lo);
  std::snprintf(b, sizeof b, format, hi);
  return std::string(a) == b ? std::string(a) : std::string(a) + "-" + b;
}

}  // namespace

std::string stiffnessText(const StiffnessInfo& info) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%d steps of %.3g ms", info.plan.substeps, 1000.0 * info.plan.h);
  std::string s = buf;
  s += ", alpha " + range(info.alphaMin, info.alphaMax, "%.3g");
  s += ", " + range(info.windowMin, info.windowMax, "%.0f") +
       (info.windowMax == 1 ? " particle per side" : " particles per side");
  if (info.model == StiffnessModel::Calibrated)
    s += ", k " + range(info.rateMin, info.rateMax, "%.3g") + " /s^2";
  return s;
}

double softHairDftl(double bendingNumber, int steps, bool capped) {
  // Measured by csmhair-bench --only soft_hair at 25, 12.5 and 6 cm: rows B / (g L^3), columns
  // steps a frame, the least of 0, 0.25, 0.5, 0.75, 0.9 that keeps the energy within 1.1x at
  // every length whose steps were not capped.
  constexpr double kNumber[] = {1e-3, 2e-3, 3e-3, 5e-3, 1e-2, 2e-2};
  constexpr int kSteps[] = {1, 2, 4, 8, 16, 32};
  constexpr double kDftl[6][6] = {
      {0.5, 0.75, 0.75, 0.9, 0.9, 0.9},  {0.5, 0.75, 0.75, 0.75, 0.9, 0.9},
      {0.5, 0.5, 0.75, 0.75, 0.75, 0.9}, {0.5, 0.5, 0.75, 0.75, 0.75, 0.75},
      {0.0, 0.0, 0.0, 0.25, 0.25, 0.5},  {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
  // Steps capped (alpha = 1 for the stiffest strands): 0.5 held in every such cell.
  constexpr double kCapped = 0.5;
  // The softer row at or below the number (softer than measured: the softest), the column at
  // or above the steps (more than measured: the most).
  int row = 0;
  while (row + 1 < 6 && kNumber[row + 1] <= bendingNumber) ++row;
  int column = 0;
  while (column + 1 < 6 && kSteps[column] < steps) ++column;
  return std::max(kDftl[row][column], capped ? kCapped : 0.0);
}

std::string stiffnessWarning(const StiffnessInfo& info) {
  char buf[256];
  std::string out;
  if (info.plan.capped) {
    std::snprintf(buf, sizeof buf,
                  "the stiffness asks for %d steps per frame, over the step budget "
                  "(sim.max_substeps) of %d: %zu of %zu strands run at alpha = 1, softer than "
                  "asked",
                  info.plan.wanted, info.plan.substeps, info.stifferStrands, info.strands);
    out = buf;
  } else if (info.stifferStrands > 0) {
    std::snprintf(buf, sizeof buf,
                  "%zu of %zu strands, shorter than the window, are stiffer than %d steps a frame "
                  "resolve: they run at alpha = 1 (as stiff as the steps allow)",
                  info.stifferStrands, info.strands, info.plan.substeps);
    out = buf;
  }
  const double wanted = info.bendingNumber > 0.0
                            ? softHairDftl(info.bendingNumber, info.plan.substeps, info.plan.capped)
                            : 0.0;
  if (info.dftl < wanted - 1e-6) {
    std::snprintf(buf, sizeof buf,
                  "soft hair: at B / (g L^3) = %.2g (the longest strand) and %d steps a frame "
                  "the strain-limiting sweep whips the tips and gains energy unless sim.dftl is "
                  "at least %.2g (it is %.2g); more steps do not help",
                  info.bendingNumber, info.plan.substeps, wanted, info.dftl);
    out += out.empty() ? buf : std::string("; ") + buf;
  }
  return out;
}

}  // namespace csm
