// Stiffness: the shape-matching regions of every particle, and how far one step pulls toward
// the goals, for both stiffness models (METHOD.md section 4.1: stiffness depends on the step
// and the resolution). Both solvers build their regions here, so they agree by construction
// (the GPU's read them in shaders/sim/shape_match.comp).
//
// Why a calibrated model: with goals from predicted positions and a pull alpha per step, a
// bending mode that one application of the goals shrinks by mu feels a stiffness
// K = alpha mu / ((1 - alpha mu) h^2). On a long strand mu = c_w (kappa w l)^4 for a mode of
// wavenumber kappa (constant curvature is left alone), so CSM is an Euler-Bernoulli beam with
// bending stiffness per unit mass B = alpha c_w (w l)^4 / h^2: with the paper's alpha = 1 it
// grows as 1/h^2 and, at a fixed w in particles, falls as l^4. The calibrated model takes B
// and a window length L as the parameters, gives each strand the rate
// k = B / (c_w (w l)^4) with w its particles per side of L, and pulls by
// alpha = min(1, k h^2) each step: then K = k mu (exact while k h^2 <= 1), whatever h and l.
// The substeps follow: a frame of dt needs N >= dt sqrt(k_max) for alpha to stay below 1.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shaders/sim/shared_constants.glsl"
#include "sim/core/config.h"
#include "sim/core/results.h"
#include "sim/core/hair_state.h"

namespace csm {

// c_w for a window of w particles per side: one application of the goals (alpha = 1) removes
// mu = c_w (kappa w l)^4 of a small bending wave of wavenumber kappa on a long straight strand
// of segment l, in the limit kappa w l -> 0. Measured on CpuSolver (measureWindowCoefficient in
// sim/verify/window_coefficient.h; tests/cpu/stiffness_test.cpp measures it again for
// w = 1..16); beyond the table, (1 + 2/w) / 45, which it tends to (1/45 is the continuous
// window's).
double windowCoefficient(int w);

// Particles per side of a calibrated window of length L on a strand of n particles with mean
// segment l: L / l rounded, at least 1 (a region is never narrower than 3 particles), at most
// n - 1 (beyond it every region is the whole strand).
int calibratedWindow(double windowLength, double segmentLength, int particles);

// The shape-matching regions of a groom. Region k holds the particles [max(0, lo[k]), hi[k]]
// of its strand (indices within the strand) and, when lo[k] < 0, -lo[k] ghost particles behind
// the root (below). Regions are symmetric (i is in region k exactly when k is in region i), so
// the regions that contain particle i are the regions max(0, lo[i]) .. hi[i]: the goal of a
// particle averages over its own range.
//
// Ghosts (calibrated model, strands held by at least 2 pinned particles): the strand continues
// straight into the scalp, rigidly with the head, at the spacing of its first segment: ghost j
// rests at rest_0 - j (rest_1 - rest_0). They are members of the regions near the root but
// centres of none, and their sums are arithmetic series, O(1) per region. Without them the
// regions at the root are clipped and pivot about it: the root holds the strand the less
// firmly the longer the window (a 12 cm strand sags 4x more at a 4 cm window than at 1 cm);
// with them the scalp is a clamp whatever the window.
//
// Masses: shape matching is homogeneous in mass (a uniform scale cancels from centroids, A and
// J alike), so the regions weigh particles by mass over the linear density, i.e. by the strand
// length each carries (m): the density then cancels exactly, bit for bit, in both solvers.
struct Regions {
  std::vector<int> lo, hi;      // per particle
  std::vector<double> mass;     // per particle: m_i / |K_i| over the density (m), its share in
                                // each of its regions
  std::vector<double> inertia;  // per region: J_k = sum of mass |rest - rest centroid_k|^2
  // Per strand.
  std::vector<double> rate;       // k (1/s^2) of the calibrated model, else 0
  std::vector<int> window;        // particles per side
  std::vector<int> pinned;        // particles from the root that follow the head
  std::vector<uint8_t> tipHeld;   // 1: the last particle follows the head too (HairState)
  std::vector<double> ghostMass;  // per-region mass of a ghost (0: the strand has none)
  // The built-in end (calibrated model, clamped strands; ClampField below): per particle, x its
  // weight in the clamp's curvature (non-zero for the fit particles, the free ones within a
  // window of the clamp) and y = tau, its rest arc from the clamp over the fit's reach (negative
  // behind the clamp).
  std::vector<glm::dvec2> clampFit;
  std::vector<int> fitEnd;        // per strand: the fit particles are [pinned, fitEnd) (0: none)
  std::vector<double> endFactor;  // per strand: the ends' factor in its rate (below)
  std::vector<double> clampPull;  // per particle: its goal's share of the field's a (below)
  double longestFree = 0.0;       // the longest rest arc beyond a clamp (m; 0: no clamped strand)
  double maxRate = 0.0;
  double planRate = 0.0;  // the rate the steps follow (planRate below)

  size_t size() const { return lo.size(); }
  // Whether the head holds particle j of strand s (of `count`): a pinned one from the root, or
  // the tip of a strand held at both ends.
  bool held(size_t s, int j, int count) const {
    return j < pinned[s] || (tipHeld[s] != 0 && j == count - 1);
  }
};

// Paper: regions [k - w, k + w] clipped to the strand, sim.pinned pinned particles, no ghosts.
// Calibrated: particle i is in region k when their rest arc distance, less a quarter of each of
// the two segments that face each other, is within sim.windowLength (for even spacing:
// w = L / l rounded), or when they are neighbours; ghosts likewise; the particles within
// sim.rootLength of the root (at least sim.pinned) are pinned. Per-region masses follow FastLSM
// (Rivers & James 2007): each particle's mass is shared equally among the regions that
// contain it, so the goals exert no net force on a free strand.
Regions buildRegions(const HairState& state, const SimConfig& sim);

// The clamp is the beam's built-in end: the scalp holds the strand's position and direction at
// arc s_c (sim.rootLength, at least the pinned particles' reach), between particles where it
// falls there. Behind it the members of the regions (the held particles and the ghosts) do not
// sit rigidly on the rest shape: they take the displacement u(tau) = a tau^2 from the
// head-carried rest shape, the free strand's curvature at the clamp continued behind it, with
// value and slope zero at the clamp. a = sum over the fit particles of weight_j u_j (least
// squares, static weights: clampFit.x). Shape matching over whole windows leaves constant
// curvature alone, so the regions at the root see a beam that goes on: without it they saw the
// curvature stop at the scalp and turned the strand about the clamp, the more the wider the
// window (METHOD.md section 4.3). The cubic and quartic terms of the cantilever's shape were
// tried: continued behind the clamp they flip sign and amplify the free particles' motion, and
// the strand blew up.
//
// Behind the clamp the field is the fit reflected across the plane normal to the clamp's
// direction: across the strand it continues evenly (the curvature goes on), along it oddly (a
// bent strand draws its length in toward the clamp on both sides, as an arc does). Small sag
// has no component along the strand and is unchanged; a strand bent hard at the clamp (full
// gravity at a 4 cm window) turns there 39 degrees instead of 49.
//
// The fit reaches at least one window and one held piece past the clamp; behind it the field
// goes on for 1.5 such reaches and keeps its value deeper (the regions centred on the held
// particles reach that far). Without that bound a strand of three particles, one of them free,
// continued its one free particle's displacement 25-fold into its deepest ghost and blew up; at
// 1.5 the extrapolation at most doubles and a quarter (2 did not hold).
inline constexpr double kClampDepth = CSM_CLAMP_DEPTH;
struct ClampField {
  glm::dvec3 a{0.0};
  glm::dvec3 at(double tau) const {
    tau = tau < -kClampDepth ? -kClampDepth : tau;
    return (tau * tau) * a;
  }
  // `along`: the clamp's direction in the world (any length).
  void reflect(const glm::dvec3& along) {
    const double l2 = glm::dot(along, along);
    if (l2 > 0.0) a -= (2.0 * glm::dot(a, along) / l2) * along;
  }
  // a across the clamp's direction: what the clamp's pull (Regions::clampPull) scales.
  glm::dvec3 across(const glm::dvec3& along) const {
    const double l2 = glm::dot(along, along);
    return l2 > 0.0 ? a - (glm::dot(a, along) / l2) * along : a;
  }
};

// Sums over the first q ghosts of a strand, each of per-region mass m: with root-relative
// coordinates ghost j is at -j d (d = rest_1 - rest_0 in the head frame, D = its current world
// image), so sum m = q m, sum m y = -S1 m D, sum m ybar = -S1 m d, sum m y ybar^T = S2 m D d^T
// with S1 = q(q+1)/2, S2 = q(q+1)(2q+1)/6.
inline double ghostSum1(int q) {
  return 0.5 * q * (q + 1.0);
}
inline double ghostSum2(int q) {
  return q * (q + 1.0) * (2.0 * q + 1.0) / 6.0;
}

// The rate a frame's steps follow: the largest k of the strands within kOutlierRate of the
// median strand's. k grows as 1/length^4 once a strand is shorter than the window (a strand of
// 7.5 um asks for a million steps a frame): such strands are nearly rigid whatever their k and
// run at alpha = 1 when stiffer than the steps resolve (describeStiffness counts them), so a
// few degenerate strands of a real groom cannot set the steps of the rest. 16: a strand that
// spans half the window the median strand spans still sets them.
inline constexpr double kOutlierRate = 16.0;
double planRate(const std::vector<double>& rates);

// The ends' factor in a clamped strand's rate (calibrated model, Regions::endFactor). c_w is
// the interior's coefficient; near the clamp and the free tip the regions are continued
// (ClampField) or clipped, and a strand whose free length is a few windows sags more than the
// beam of the same B (12 cm clamped over 1.7 cm: +11 % at a 4 cm window, +61 % at 6 cm).
// buildRegions multiplies each such strand's k by its tip's sag under a uniform load from the
// goals linearised (I - P over the free particles of the strand straightened, each region's
// rigid fit a translation and a turn, behind the clamp the field's tau^2 a; (I - P) u = 1 solved
// for the tip), over the Euler-Bernoulli beam's, g L^4 / (8 B): the strand then sags as the beam
// at every window, and the factor tends to 1 as the strand grows longer than the window. Strands
// whose free length is under one window keep k (they are nearly rigid, and with one or two free
// particles the field's extrapolation left no margin for a larger pull); the factor is kept
// within [1/2, 2]. Evenly spaced strands share the factor by their shape in segments.

// True when a change from `a` to `b` changes the regions (the solvers rebuild them).
bool regionsChanged(const SimConfig& a, const SimConfig& b);

// Paper: sim.substeps. Calibrated: at least sim.substeps, and enough that
// alpha = k_max h^2 <= 1, up to sim.max_substeps.
FramePlan planFrame(const SimConfig& sim, double maxRate);

// The pull toward the goals in one step of length h, for a strand of calibrated rate k.
inline double stepAlpha(const SimConfig& sim, double rate, double h) {
  if (sim.stiffnessModel == StiffnessModel::Paper) return sim.stiffness;
  const double a = rate * h * h;
  return a < 1.0 ? a : 1.0;
}

// Twist of nearly straight regions (see extractRotation in sim/solver/cpu_solver.h): the paper
// model turns it by the full iteration, so it relaxes faster with more substeps; the calibrated
// model relaxes it at kTwistIterationsPerSecond, what the paper's default of 3 iterations per
// 1/240 s step gives, whatever the step.
inline constexpr double kTwistIterationsPerSecond = 720.0;
inline double twistStepOf(const SimConfig& sim, double h, int iterations) {
  if (sim.stiffnessModel == StiffnessModel::Paper) return 1.0;
  const double s = kTwistIterationsPerSecond * h / std::max(1, iterations);
  return s < 1.0 ? s : 1.0;
}

StiffnessInfo describeStiffness(const Regions& regions, const SimConfig& sim);
// The same, with the DFTL the solver applies (dftlOf: sim.dftl, or more under a clip).
StiffnessInfo describeStiffness(const Regions& regions, const SimConfig& sim, double dftl);

// "4 steps of 4.17 ms, alpha 0.71-1, 2-3 particles per side" and the like, for logs.
std::string stiffnessText(const StiffnessInfo& info);
// The DFTL correction (sim.dftl) that calibrated hair needs at `steps` steps a frame, by its
// bending number B / (g L^3) (StiffnessInfo::bendingNumber). The goals barely act on soft hair,
// and the strain-limiting sweep, which moves a child and never its parent, whips the tips as
// plain follow-the-leader does. Measured (csmhair-bench --only soft_hair: four strands of 16
// particles released horizontally, 2 s, at 25, 12.5 and 6 cm with B scaled by the length cubed,
// i.e. the same numbers; at 25 cm, free 21.4 cm, B / (g L^3) = B / 0.096): without DFTL the
// energy grows to 1.4-2.2x its start at every step count from 2 to 32 up to a number of 5e-3,
// and more steps make it worse (1e-2: 1.0-1.05 at 4 steps, 1.23-1.32 at 32). This is that map:
// the least of 0, 0.25, 0.5, 0.75, 0.9 that keeps the energy within 1.1x at all three lengths, for
// the measured number at or below the hair's and the measured steps at or above `steps`; where
// the steps are capped (alpha = 1) at least 0.5. 0.9 held in every cell;
// tests/cpu/stiffness_test.cpp checks cells of it.
double softHairDftl(double bendingNumber, int steps, bool capped = false);

// The warnings that apply, joined by "; ": the cap binds, or else some strands are stiffer than
// the steps; soft hair with less DFTL than softHairDftl. Empty when none.
std::string stiffnessWarning(const StiffnessInfo& info);

}  // namespace csm
