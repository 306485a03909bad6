// The step in double; shaders/sim/predict.comp, shape_match.comp and strain_limit.comp are its
// GLSL twins (sim/solver/cpu_solver.h).
#include "sim/solver/cpu_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/base/parallel.h"
#include "sim/base/state_bytes.h"
#include "sim/core/measure_sample.h"
#include "sim/solver/wind.h"
#include "sim/solver/accuracy.h"
#include "sim/solver/state_io.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

Eigen::Vector3d toEigen(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
glm::dvec3 toGlm(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

Eigen::Quaterniond toEigen(const glm::dquat& q) {
  return {q.w, q.x, q.y, q.z};
}

// Pushes p out of one sphere onto its surface. With a strain limit, the push keeps the
// segment from `prev` no longer than maxLength: when the radial projection is out of reach,
// take the nearest point of the circle where the sphere meets the ball of reach around prev.
// (Moving along the chord toward prev instead would jump: a chord between two points on the
// sphere always cuts through it.)
bool pushOutOfSphere(glm::dvec3& p, const glm::dvec3& prev, const glm::dvec3& c, double radius,
                     double maxLength) {
  const glm::dvec3 d = p - c;
  const double len2 = glm::dot(d, d);
  if (len2 >= radius * radius) return false;
  const double len = std::sqrt(len2);
  const glm::dvec3 target = c + (len > 1e-15 ? d / len : glm::dvec3(0, 1, 0)) * radius;
  p = target;
  if (maxLength <= 0.0 || glm::length(target - prev) <= maxLength) return true;
  const glm::dvec3 toPrev = prev - c;
  const double dist = glm::length(toPrev);
  // No circle when prev is inside the sphere, or out of reach of it; keep the projection.
  if (dist < 1e-15 || dist + maxLength < radius || dist - radius > maxLength) return true;
  const glm::dvec3 u = toPrev / dist;
  const double a = (radius * radius - maxLength * maxLength + dist * dist) / (2.0 * dist);
  const double rho = std::sqrt(std::max(0.0, radius * radius - a * a));
  const glm::dvec3 centre = c + a * u;
  glm::dvec3 side = target - centre;
  side -= glm::dot(side, u) * u;
  const double sideLen = glm::length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (rho / sideLen);
  return true;
}

// The same for the head's distance field (sim/head/distance_grid.h), read in the head's frame: p
// moves along the field's normal out of the surface inflated by `radius`, and when that is
// out of reach of prev, onto the nearest point of the circle where the surface's tangent
// plane there meets the ball of reach. `normal` gets the outward normal (world); `clearance`
// the field's distance where p is left, where the push read it (p untouched, or the
// projection), else NaN (the circle's point).
bool pushOutOfHeadField(const DistanceGrid& g, const Pose& head, glm::dvec3& p,
                        const glm::dvec3& prev, double radius, double maxLength, glm::dvec3& normal,
                        double& clearance) {
  glm::dvec3 local = glm::inverse(head.rotation) * (p - head.translation), n;
  if (!pushOutOfField(g, local, radius, &n, &clearance)) return false;
  const glm::dvec3 target = head.apply(local);
  normal = head.rotation * n;
  p = target;
  if (maxLength <= 0.0 || glm::length(target - prev) <= maxLength) return true;
  const double above = glm::dot(prev - target, normal);
  if (std::abs(above) >= maxLength) return true;  // no circle: keep the projection
  const glm::dvec3 centre = prev - above * normal;
  const glm::dvec3 side = target - centre;
  const double sideLen = glm::length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (std::sqrt(maxLength * maxLength - above * above) / sideLen);
  clearance = NAN;
  return true;
}

// The head as limitStrain collides with it: its distance field, or its spheres (world), the
// surface inflated by the hair's radius.
struct HeadCollider {
  const DistanceGrid* field;
  const std::vector<Sphere>& spheres;
  const Pose& head;
  double radius;

  // How far q lies outside the head's surface (not inflated).
  double outside(const glm::dvec3& q) const {
    if (field) return field->sample(glm::inverse(head.rotation) * (q - head.translation));
    double d = INFINITY;
    for (const Sphere& sp : spheres)
      d = std::min(d, glm::length(q - glm::dvec3(sp.center)) - double(sp.radius));
    return d;
  }

  // One push of p out of the inflated surface, within reach of prev where it can (above).
  // `normal` gets the field's outward normal (spheres: left as it is); `clearance` how far the
  // point it leaves lies outside the head, where the push read it, else NaN.
  bool push(glm::dvec3& p, const glm::dvec3& prev, double maxLength, glm::dvec3& normal,
            double& clearance) const {
    clearance = NAN;
    if (field)
      return pushOutOfHeadField(*field, head, p, prev, radius, maxLength, normal, clearance);
    // Overlapping spheres can push a particle into each other: repeat until it is clear.
    bool touching = false;
    for (int pass = 0; pass < 4; ++pass) {
      bool moved = false;
      for (const Sphere& sp : spheres)
        moved |= pushOutOfSphere(p, prev, glm::dvec3(sp.center), sp.radius + radius, maxLength);
      touching |= moved;
      if (!moved) break;
    }
    return touching;
  }

  // Pushes p (where the strain limit put it, within maxLength of prev) out of the head and
  // keeps it within reach of prev: the push, and where that is out of reach or still in the
  // head (p went deep, where the surface nearest is another part of the head than the one
  // prev lies over; a concave part, where the tangent plane cuts into the head) the push again
  // from the nearest point of reach, twice; the last resort, the point where the segment from
  // prev enters the head, found by bisection. "In the head": deeper than the surface and than
  // prev (a root on the scalp lies within the radius). Returns whether p touched the head.
  bool pushOut(glm::dvec3& p, const glm::dvec3& prev, double maxLength, glm::dvec3& normal) const {
    double clearance;
    if (!push(p, prev, maxLength, normal, clearance)) return false;
    if (maxLength <= 0.0) return true;
    double level = NAN;  // min(0, how far prev lies outside), read once when needed
    for (int pass = 0;; ++pass) {
      const double length = glm::length(p - prev);
      const bool reach = length <= maxLength * (1.0 + CSM_REACH_SLACK_DOUBLE);
      // The push's own last read where it has one (the field's projection): no second read.
      const double depth = std::isnan(clearance) ? outside(p) : clearance;
      if (reach && depth >= 0.0) return true;
      if (std::isnan(level)) level = std::min(0.0, outside(prev));
      if (reach && depth >= level) return true;
      if (!reach) p = prev + (p - prev) * (maxLength / length);
      if (pass == 2) break;
      push(p, prev, maxLength, normal, clearance);
    }
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 20; ++k) {
      const double mid = 0.5 * (lo + hi);
      (outside(prev + mid * (p - prev)) >= level ? lo : hi) = mid;
    }
    p = prev + lo * (p - prev);
    if (field) {
      glm::dvec3 grad;
      field->sample(glm::inverse(head.rotation) * (p - head.translation), &grad);
      const double len = glm::length(grad);
      if (len > 1e-12) normal = head.rotation * (grad / len);
    }
    return true;
  }
};

}  // namespace

void extractRotation(const Eigen::Matrix3d& A, double J, Eigen::Quaterniond& q, int iterations,
                     const Eigen::Vector3d& axis, double twistStep) {
  if (!(J > 0.0)) return;
  // A rotation made non-finite by a non-finite step would stay so for good through the warm
  // start: start again from no rotation, and leave q as it is when A is not finite.
  if (!q.coeffs().allFinite()) q = Eigen::Quaterniond::Identity();
  const double axisLength = axis.norm();
  const bool twist = twistStep < 1.0 && axisLength > 0.0;
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Matrix3d R = q.matrix();
    // The torque that turns R's columns toward A's, over the rest moment: a Newton step near
    // convergence, where sum r.a = J.
    const Eigen::Vector3d torque =
        R.col(0).cross(A.col(0)) + R.col(1).cross(A.col(1)) + R.col(2).cross(A.col(2));
    Eigen::Vector3d omega = torque / J;
    if (twist) {
      const Eigen::Vector3d e = R * (axis / axisLength);
      omega -= (1.0 - twistStep) * omega.dot(e) * e;
    }
    const double angle = omega.norm();
    if (!(angle >= 1e-12) || !std::isfinite(angle)) break;
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
}

void CpuSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  shape_ = headModel_.collider();
  failure_ = headModel_.handed() ? std::string() : std::string(kNoHeadFailure);
  time_ = 0.0;
  head_ = head;
  state_ = makeHairState(groom, config.sim, head);
  const HairState& st = state_;
  const size_t n = st.particleCount(), strands = st.strandCount();
  first_ = st.strandFirst;
  strandOf_ = st.particleStrand;
  measuredStrandOf_.clear();  // made again for this hair at its first measure
  rest_.resize(n);
  mass_.resize(n);
  x_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    rest_[i] = glm::dvec3(glm::vec3(st.rest[i]));
    mass_[i] = st.rest[i].w;
    x_[i] = head.apply(rest_[i]);
  }
  restLength_.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i)
    if (strandOf_[i] == strandOf_[i + 1]) restLength_[i] = glm::length(rest_[i + 1] - rest_[i]);
  v_.assign(n, glm::dvec3(0.0));
  xOld_ = x_;
  xPred_ = x_;
  goal_ = x_;
  candidates_ = {};
  correction_.clear();
  q_.assign(n, toEigen(head.rotation));
  contacts_ = {};
  measureAnew();
  resetVolume();
  stages_.clear();
  samples_.clear();

  const size_t m = n + strands;
  prefMass_.assign(m, 0.0);
  prefMassRest_.assign(m, Eigen::Vector3d::Zero());
  prefMassX_.assign(m, Eigen::Vector3d::Zero());
  prefA_.assign(m, Eigen::Matrix3d::Zero());
  prefR_.assign(m, Eigen::Matrix3d::Zero());
  prefT_.assign(m, Eigen::Vector3d::Zero());
  regionC_.assign(n, Eigen::Vector3d::Zero());
  regionCRest_.assign(n, Eigen::Vector3d::Zero());
  rebuildRegions();
}

void CpuSolver::rebuildRegions() {
  regions_ = ::csm::buildRegions(state_, config_.sim);
  invMass_ = contactInverseMass(state_, regions_);
  // Static prefix sums: per-region masses and mass-weighted rest positions (root-relative).
  for (size_t s = 0; s + 1 < first_.size(); ++s) {
    const uint32_t a = first_[s], b = first_[s + 1];
    const size_t pb = a + s;
    for (uint32_t i = a; i < b; ++i) {
      const size_t j = pb + (i - a);
      const double m = regions_.mass[i];
      prefMass_[j + 1] = prefMass_[j] + m;
      prefMassRest_[j + 1] = prefMassRest_[j] + m * toEigen(rest_[i] - rest_[a]);
    }
  }
}

void CpuSolver::setConfig(const Config& config) {
  const bool remeasure = contactMeasuresChanged(config_.collision, config.collision);
  const bool rebuild = regionsChanged(config_.sim, config.sim);
  const bool regrid = volumeGridChanged(config_.collision, config.collision);
  config_ = config;
  shape_ = headModel_.collider();
  if (rebuild) rebuildRegions();
  if (regrid) resetVolume();
  if (remeasure) measureAnew();
}

VolumeSettings CpuSolver::volumeSettings() const {
  const CollisionConfig& c = config_.collision;
  return {c.volumeFriction, c.volumeStiffness};
}

void CpuSolver::resetVolume() {
  if (!volumeForces(config_.collision.mode)) {
    volume_.release();
    return;
  }
  volume_.reset(rest_, first_, config_.collision.volumeCell, config_.collision.radius);
}

void CpuSolver::clearStages() {
  stages_ = {{"integrate", 0.0},
             {"shape_matching", 0.0},
             {"strain_limiting", 0.0},
             {"contacts", 0.0},
             {"volume", 0.0}};
}

void CpuSolver::stepFrame(const Pose& from, const Pose& to) {
  clearStages();
  const FramePlan plan = planFrame(config_.sim, regions_.planRate);
  if (!failure_.empty()) {
    // No head to collide with (failure()): the clock runs, the hair stays.
    time_ += plan.substeps * plan.h;
    head_ = to;
    return;
  }
  ++framesSinceMeasure_;
  // The frame's contact candidates, from where it starts (METHOD.md section 3.3).
  auto t0 = Clock::now();
  if (strandContacts(config_.collision.mode)) {
    ContactCandidates previous = std::move(candidates_);
    candidates_ = findCandidates(x_, rest_, strandOf_, contactSettings(), previous, contacts_);
  } else {
    candidates_ = {};
    contacts_ = {};
  }
  stages_[3].ms += msSince(t0);
  // The volume mode's grid, from where the frame starts, fixed to the head there.
  t0 = Clock::now();
  if (volumeForces(config_.collision.mode))
    volume_.splat(x_, v_, head_, config_.collision.volumeFraction);
  stages_[4].ms += msSince(t0);
  for (int k = 0; k < plan.substeps; ++k) {
    if (strandContacts(config_.collision.mode) &&
        listsBefore(k, plan.substeps, config_.collision.lists))
      listAgain();
    step(plan.h, interpolate(from, to, double(k + 1) / plan.substeps));
  }
}

void CpuSolver::listAgain() {
  // The state where this list is made is not measured (the frame's measures are of where it
  // started); the crossings since the last list count, and the segments out of the grid.
  const auto t0 = Clock::now();
  ContactStats within;
  candidates_ = findCandidates(x_, rest_, strandOf_, contactSettings(), candidates_, within);
  contacts_.crossings += within.crossings;
  contacts_.crossingsClose += within.crossingsClose;
  contacts_.oversize += within.oversize;
  stages_[3].ms += msSince(t0);
}

ContactSettings CpuSolver::contactSettings() const {
  const CollisionConfig& c = config_.collision;
  return {c.radius, c.margin,           c.compliance,    c.friction,
          c.solve,  c.penaltyStiffness, c.penaltyDamping};
}

void CpuSolver::step(double h, const Pose& head) {
  if (stages_.size() < 5) clearStages();  // a single step called directly
  const Pose before = head_;
  const std::vector<Sphere> spheres = worldSpheres(shape_.spheres, head);
  auto t0 = Clock::now();
  predict(h, head);
  stages_[0].ms += msSince(t0);
  t0 = Clock::now();
  shapeMatch(head, h);
  stages_[1].ms += msSince(t0);
  t0 = Clock::now();
  integrate(h);
  stages_[0].ms += msSince(t0);
  t0 = Clock::now();
  const bool penalty = config_.collision.model == ContactModel::Penalty;
  if (strandContacts(config_.collision.mode) && !candidates_.start.empty() && !penalty) {
    // All but the last iteration move the particles here; the last one's corrections are
    // applied by the strain-limit sweep.
    for (int k = 1; k < config_.collision.iterations; ++k) {
      solveContacts(candidates_, x_, v_, invMass_, h, contactSettings(), correction_);
      applyCorrections(correction_, first_, h, x_, v_);
    }
    solveContacts(candidates_, x_, v_, invMass_, h, contactSettings(), correction_);
    stages_[3].ms += msSince(t0);
    t0 = Clock::now();
  } else {
    correction_.clear();
  }
  limitStrain(h, spheres, head, before);
  stages_[2].ms += msSince(t0);
  if (strandContacts(config_.collision.mode) && !candidates_.start.empty() && penalty) {
    // The paper's penalty forces where the substep ends, felt by the next one's prediction.
    t0 = Clock::now();
    penaltyVelocities(candidates_, x_, v_, invMass_, h, contactSettings(), correction_);
    applyPenalty(correction_, first_, v_);
    correction_.clear();
    stages_[3].ms += msSince(t0);
  }
  time_ += h;
  head_ = head;
}

glm::dvec3 CpuSolver::windDrag(uint32_t i, uint32_t end, double h) const {
  // Drag acts on the wind across the strand, not along it; implicit in the velocity, so it
  // neither overshoots nor depends on the step: c / (1 + h c) instead of c.
  const glm::dvec3 d = x_[std::min(i + 1, end - 1)] - x_[i - 1];
  const double len = glm::length(d);
  const glm::dvec3 t = len > 1e-12 ? d / len : glm::dvec3(0.0);
  const glm::dvec3 rel = windVelocity(config_.wind, x_[i], time_) - v_[i];
  const double c = config_.wind.drag;
  return c / (1.0 + h * c) * (rel - glm::dot(rel, t) * t);
}

void CpuSolver::predict(double h, const Pose& head) {
  const SimConfig& sim = config_.sim;
  const glm::dvec3 gravity(sim.gravity);
  const bool wind = config_.wind.strength > 0.0f && config_.wind.drag > 0.0f;
  const bool volume = volumeForces(config_.collision.mode) && !volume_.empty();
  const VolumeSettings vs = volumeSettings();
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      for (uint32_t i = a; i < b; ++i) {
        xOld_[i] = x_[i];
        if (regions_.held(s, int(i - a), int(b - a))) {
          // Kinematic roots (and held tips) follow the head.
          xPred_[i] = head.apply(rest_[i]);
          continue;
        }
        glm::dvec3 acc = gravity;
        if (wind) acc += windDrag(i, b, h);
        if (volume) v_[i] += volume_.velocityChange(x_[i], v_[i], h, vs);
        v_[i] += h * acc;
        xPred_[i] = x_[i] + h * v_[i];
      }
    }
  });
}

void CpuSolver::shapeMatch(const Pose& head, double h) {
  const int iterations = std::max(1, config_.sim.rotationIterations);
  const double twistStep = twistStepOf(config_.sim, h, iterations);
  const std::vector<int>& lo = regions_.lo;
  const std::vector<int>& hi = regions_.hi;
  const Eigen::Matrix3d headRotation = toEigen(head.rotation).toRotationMatrix();
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      const int n = int(b - a);
      const size_t pb = a + s;
      // Ghosts behind the root (sim/solver/stiffness.h): -j d at rest, -j D now, root-relative.
      const double mg = regions_.ghostMass[s];
      const Eigen::Vector3d d = n > 1 ? toEigen(rest_[a + 1] - rest_[a]) : Eigen::Vector3d::Zero();
      const Eigen::Vector3d D = headRotation * d;
      // Root-relative coordinates keep the prefix sums' differences exact enough in float on the
      // GPU; the CPU uses the same formulation so the two compare term by term.
      const glm::dvec3 origin = xPred_[a];
      // The built-in end (ClampField, sim/solver/stiffness.h): behind the clamp the regions see
      // the free strand's displacement continued, not the rest shape.
      const int pinned = regions_.pinned[s];
      const std::vector<glm::dvec2>& fit = regions_.clampFit;
      ClampField field;
      for (int j = pinned; j < regions_.fitEnd[s]; ++j)
        field.a += fit[a + j].x * (xPred_[a + j] - head.apply(rest_[a + j]));
      if (n > 1) field.reflect(toGlm(D));
      const glm::dvec3 pull = field.across(toGlm(D));
      auto behind = [&](int j) { return j < pinned ? field.at(fit[a + j].y) : glm::dvec3(0.0); };
      const double tau0 = fit[a].y, ghostTau = n > 1 ? fit[a + 1].y - tau0 : 0.0;
      auto ghostShift = [&](int g) { return toEigen(field.at(tau0 - g * ghostTau)); };
      // Each particle's coordinates in the sums, root-relative.
      auto yOf = [&](int j) { return toEigen(xPred_[a + j] + behind(j) - origin); };
      auto yrOf = [&](int j) { return toEigen(rest_[a + j] - rest_[a]); };
      for (int j = 0; j < n; ++j) {
        const double m = regions_.mass[a + j];
        const Eigen::Vector3d y = yOf(j);
        const Eigen::Vector3d yr = yrOf(j);
        prefMassX_[pb + j + 1] = prefMassX_[pb + j] + m * y;
        prefA_[pb + j + 1] = prefA_[pb + j] + m * y * yr.transpose();
      }
      for (int k = 0; k < n; ++k) {
        const int ghosts = std::max(0, -lo[a + k]);
        const int l0 = std::max(0, lo[a + k]), l1 = hi[a + k];
        double M;
        Eigen::Vector3d sumX, sumRest;
        Eigen::Matrix3d sumA;
        if (sums_ == RegionSums::Prefix) {
          M = prefMass_[pb + l1 + 1] - prefMass_[pb + l0];
          sumX = prefMassX_[pb + l1 + 1] - prefMassX_[pb + l0];
          sumRest = prefMassRest_[pb + l1 + 1] - prefMassRest_[pb + l0];
          sumA = prefA_[pb + l1 + 1] - prefA_[pb + l0];
          if (ghosts > 0) {
            const double s1 = mg * ghostSum1(ghosts), s2 = mg * ghostSum2(ghosts);
            M += mg * ghosts;
            sumX -= s1 * D;
            sumRest -= s1 * d;
            sumA += s2 * D * d.transpose();
            for (int g = 1; g <= ghosts; ++g) {
              const Eigen::Vector3d shift = ghostShift(g);
              sumX += mg * shift;
              sumA -= (mg * g) * shift * d.transpose();
            }
          }
        } else {
          M = 0.0;
          sumX.setZero();
          sumRest.setZero();
          sumA.setZero();
          for (int j = -ghosts; j <= l1; ++j) {
            const double m = j < 0 ? mg : regions_.mass[a + j];
            const Eigen::Vector3d y = j < 0 ? Eigen::Vector3d(j * D + ghostShift(-j)) : yOf(j);
            const Eigen::Vector3d yr = j < 0 ? Eigen::Vector3d(j * d) : yrOf(j);
            if (j >= 0 && j < l0) continue;
            M += m;
            sumX += m * y;
            sumRest += m * yr;
            sumA += m * y * yr.transpose();
          }
        }
        const Eigen::Vector3d c = sumX / M, cRest = sumRest / M;
        const Eigen::Matrix3d A = sumA - M * c * cRest.transpose();
        // The twist axis: the region's rest chord (ghosts continue the root segment).
        const int first = lo[a + k];
        const Eigen::Vector3d chord =
            yrOf(hi[a + k]) - (first >= 0 ? yrOf(first) : Eigen::Vector3d(first * d));
        extractRotation(A, regions_.inertia[a + k], q_[a + k], iterations, chord, twistStep);
        const Eigen::Matrix3d R = q_[a + k].matrix();
        regionC_[a + k] = c;
        regionCRest_[a + k] = cRest;
        prefR_[pb + k + 1] = prefR_[pb + k] + R;
        prefT_[pb + k + 1] = prefT_[pb + k] + (c - R * cRest);
      }
      // Goals (paper eq. 1) averaged over the regions that contain each particle, which are the
      // regions lo[i]..hi[i] (regions are symmetric):
      // g_i = ((sum R_k) xr_i + sum (c_k - R_k cr_k)) / |K_i|, both sums prefix differences.
      for (int i = 0; i < n; ++i) {
        const int l0 = std::max(0, lo[a + i]), l1 = hi[a + i];
        const Eigen::Vector3d yr = toEigen(rest_[a + i] - rest_[a]);
        Eigen::Matrix3d sumR;
        Eigen::Vector3d sumT;
        if (sums_ == RegionSums::Prefix) {
          sumR = prefR_[pb + l1 + 1] - prefR_[pb + l0];
          sumT = prefT_[pb + l1 + 1] - prefT_[pb + l0];
        } else {
          sumR.setZero();
          sumT.setZero();
          for (int k = l0; k <= l1; ++k) {
            const Eigen::Matrix3d R = q_[a + k].matrix();
            sumR += R;
            sumT += regionC_[a + k] - R * regionCRest_[a + k];
          }
        }
        goal_[a + i] = origin + toGlm((sumR * yr + sumT) / double(l1 - l0 + 1)) +
                       regions_.clampPull[a + i] * pull;
      }
    }
  });
}

void CpuSolver::integrate(double h) {
  const SimConfig& sim = config_.sim;
  const double keep = std::exp(-double(sim.damping) * h);
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      const double alpha = stepAlpha(sim, regions_.rate[s], h);
      for (uint32_t i = a; i < b; ++i) {
        const bool pinned = regions_.held(s, int(i - a), int(b - a));
        x_[i] = pinned ? xPred_[i] : xPred_[i] + alpha * (goal_[i] - xPred_[i]);
        v_[i] = (x_[i] - xOld_[i]) / h;
        if (!pinned) v_[i] *= keep;
      }
    }
  });
}

void CpuSolver::limitStrain(double h, const std::vector<Sphere>& spheres, const Pose& head,
                            const Pose& before) {
  const SimConfig& sim = config_.sim;
  const bool limit = sim.strainLimiting;
  const bool headCollide = collidesWithHead(config_.collision.mode);
  const bool contacts = !correction_.empty();
  const double r = config_.collision.radius;
  const double friction = config_.collision.headFriction;
  const double dftl = sim.dftl;
  const DistanceGrid* field = shape_.field;
  const HeadCollider collider{field, spheres, head, r};
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      const int pinned = regions_.pinned[s];
      // One sweep from root to tip: each segment is fixed against an already final parent, so
      // no iteration is needed (paper section 3.2). A held tip stays where the head put it.
      const uint32_t end = b - (regions_.tipHeld[s] != 0 ? 1u : 0u);
      for (uint32_t i = a + std::max(1, pinned); i < end; ++i) {
        const double maxLength = limit ? (1.0 + sim.strainLimit) * restLength_[i - 1] : 0.0;
        if (contacts) {
          // The strand contacts' correction (sim/solver/contacts.h), a change of velocity too.
          const glm::dvec3 moved = particleCorrection(correction_, i, a, b);
          x_[i] += moved;
          v_[i] += moved / h;
        }
        const glm::dvec3 start = x_[i];
        if (limit) {
          const glm::dvec3 d = x_[i] - x_[i - 1];
          const double len = glm::length(d);
          if (len > maxLength) x_[i] = x_[i - 1] + d * (maxLength / len);
        }
        const glm::dvec3 strained = x_[i];
        glm::dvec3 fieldNormal(0.0);
        // A non-finite particle stays so, for the NaN check to see: the pushes below would put
        // it on the head (their fallback normal) as if nothing had happened.
        const bool collide = headCollide && std::isfinite(x_[i].x + x_[i].y + x_[i].z);
        const bool touching = collide && collider.pushOut(x_[i], x_[i - 1], maxLength, fieldNormal);
        const glm::dvec3 vBeforeHead = v_[i] + (strained - start) / h;
        v_[i] = vBeforeHead + (x_[i] - strained) / h;
        if (touching) {
          // Coulomb friction against the moving head: the tangential speed relative to the
          // surface loses at most mu times the normal speed the contact took away this step,
          // so a resting strand feels mu g_n whatever the step.
          const glm::dvec3 local = glm::inverse(head.rotation) * (x_[i] - head.translation);
          const glm::dvec3 surfaceVel = (x_[i] - before.apply(local)) / h;
          glm::dvec3 n = fieldNormal;
          if (!field) {
            const Sphere* nearest = &spheres.front();
            double best = 1e300;
            for (const Sphere& sp : spheres) {
              double dist = glm::length(x_[i] - glm::dvec3(sp.center)) - sp.radius;
              if (dist < best) best = dist, nearest = &sp;
            }
            n = glm::normalize(x_[i] - glm::dvec3(nearest->center));
          }
          const double vnBefore = glm::dot(vBeforeHead - surfaceVel, n);
          const glm::dvec3 rel = v_[i] - surfaceVel;
          const double vn = std::max(0.0, glm::dot(rel, n));
          const glm::dvec3 vt = rel - glm::dot(rel, n) * n;
          const double vtLen = glm::length(vt);
          const double taken = friction * std::max(0.0, vn - vnBefore);
          const double keepT = vtLen > taken ? 1.0 - taken / vtLen : 0.0;
          v_[i] = surfaceVel + vn * n + keepT * vt;
        }
        // Dynamic follow-the-leader (Mueller et al. 2012): the parent takes back part of the
        // velocity its child got from the strain-limit correction, against the heavy-tip look.
        if (dftl > 0.0 && int(i - 1 - a) >= pinned) v_[i - 1] -= dftl * (strained - start) / h;
      }
      if (limit && end < b) tieStrain(a + std::max(1, pinned), end, h);
    }
  });
}

// A strand held at both ends: the sweep from the root leaves what stretch there is to its last
// free segment, the one into the held tip. Sweeps back from the tip, then forth from the root,
// each limiting a segment against its already final neighbour, share it out along the strand;
// they stop once one moves nothing (CSM_TIED_SWEEPS pairs at most). A move is a change of
// velocity too, as the sweep's. Twins: shaders/sim/strain_limit.comp, strand_group.glsl.
void CpuSolver::tieStrain(uint32_t first, uint32_t tip, double h) {
  const double stretch = 1.0 + double(config_.sim.strainLimit);
  auto pull = [&](uint32_t i, uint32_t anchor, double rest) {
    const glm::dvec3 d = x_[i] - x_[anchor];
    const double len = glm::length(d), most = stretch * rest;
    if (!(len > most)) return false;
    const glm::dvec3 to = x_[anchor] + d * (most / len);
    v_[i] += (to - x_[i]) / h;
    x_[i] = to;
    return true;
  };
  for (int pass = 0; pass < CSM_TIED_SWEEPS; ++pass) {
    bool moved = false;
    for (uint32_t i = tip; i-- > first;) moved = pull(i, i + 1, restLength_[i]) || moved;
    if (!moved) break;
    moved = false;
    for (uint32_t i = first; i < tip; ++i) moved = pull(i, i - 1, restLength_[i - 1]) || moved;
    if (!moved) break;
  }
}

void CpuSolver::readPositions(std::vector<glm::vec4>& out) {
  readDoublePositions(x_, out);
}

void CpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  readDoubleVelocities(v_, out);
}

void CpuSolver::writeState(const std::vector<glm::vec4>& positions,
                           const std::vector<glm::vec4>& velocities) {
  writeDoubleState(positions, velocities, x_, v_);
}

void CpuSolver::saveState(SolverState& out) {
  StateWriter w(out.bytes);
  w.put(x_.size());
  w.putVector(x_);
  w.putVector(v_);
  std::vector<glm::dvec4> q(q_.size());
  for (size_t i = 0; i < q_.size(); ++i) q[i] = {q_[i].x(), q_[i].y(), q_[i].z(), q_[i].w()};
  w.putVector(q);
  w.put(time_);
  w.put(head_);
}

bool CpuSolver::restoreState(const SolverState& in, std::string* error) {
  StateReader r(in.bytes);
  std::vector<glm::dvec3> x, v;
  std::vector<glm::dvec4> q;
  double time = 0.0;
  Pose head;
  if (!r.expectCount(x_.size(), "particles", error)) return false;
  if (!r.getVector(x, x_.size()) || !r.getVector(v, x_.size()) || !r.getVector(q, q_.size()) ||
      !r.get(time) || !r.get(head) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another solver";
    return false;
  }
  x_ = std::move(x);
  v_ = std::move(v);
  for (size_t i = 0; i < q_.size(); ++i) q_[i] = Eigen::Quaterniond(q[i].w, q[i].x, q[i].y, q[i].z);
  time_ = time;
  head_ = head;
  // The last list is of another state: nothing to count crossings against (as after a reset).
  candidates_ = ContactCandidates{};
  measureAnew();
  return true;
}

void CpuSolver::carry(const Pose& by) {
  for (glm::dvec3& p : x_) p = by.apply(p);
  for (glm::dvec3& u : v_) u = by.rotation * u;
  const Eigen::Quaterniond turn = toEigen(by.rotation);
  for (Eigen::Quaterniond& q : q_) q = (turn * q).normalized();
  head_ = compose(by, head_);
}

void CpuSolver::requestSample(long frame) {
  FrameSample sample;
  sample.frame = frame;
  sample.accuracy =
      measureAccuracy(x_, v_, first_, restLength_, worldSpheres(shape_.spheres, head_),
                      regions_.pinned, PosedField{shape_.field, head_});
  if (strandContacts(config_.collision.mode)) {
    sample.contacts = contacts_;
    sample.contactsMeasured = true;
  } else if (measureContacts_) {
    // Where this frame started, as a strand mode's list measures it: the search made when
    // the last frame ended (after its sample, or when the measures or the settings changed).
    // With frames stepped since and no sample between, where this one ends (the crossings of
    // the frames before it that no sample reported are lost).
    if (framesSinceMeasure_ > 1) measureNow();
    sample.contacts = measuredStats_;
    sample.contactsMeasured = true;
    // The next frame's start, searched here, outside its timing.
    if (framesSinceMeasure_ != 0) measureNow();
  }
  samples_.push_back(sample);
}

void CpuSolver::setContactMeasures(bool always) {
  const bool was = measureContacts_;
  measureContacts_ = always;
  if (always && !was) measureAnew();
}

void CpuSolver::measureAnew() {
  // The last search measured another state or other pairs: nothing to count crossings
  // against, and no sample reports it.
  measured_ = {};
  framesSinceMeasure_ = 2;
  if (measureContacts_ && !strandContacts(config_.collision.mode)) measureNow();
}

void CpuSolver::measureNow() {
  const uint32_t stride = measureStride(x_.size());
  if (stride != measureStride_ || measuredStrandOf_.size() != strandOf_.size()) {
    measureStride_ = stride;
    measuredStrandOf_ = sampledStrands(strandOf_, stride);
  }
  measured_ =
      findCandidates(x_, rest_, measuredStrandOf_, contactSettings(), measured_, measuredStats_);
  measuredStats_.measureStride = stride;
  framesSinceMeasure_ = 0;
}

std::optional<FrameSample> CpuSolver::takeSample(bool) {
  if (samples_.empty()) return std::nullopt;
  FrameSample s = samples_.front();
  samples_.pop_front();
  return s;
}

}  // namespace csm
