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
#include "sim/core/measure_sample.h"
#include "sim/solver/accuracy.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

Eigen::Quaterniond toEigen(const glm::dquat& q) {
  return {q.w, q.x, q.y, q.z};
}

}  // namespace

void CpuSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  state_ = layOut(groom, config, head);
  torso_ = head;  // the body as one until a path says otherwise
  shape_ = headModel_.collider();
  const size_t n = state_.particleCount();
  measuredStrandOf_.clear();  // made again for this hair at its first measure
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
  rebuildRegions();
}

void CpuSolver::rebuildRegions() {
  regions_ = ::csm::buildRegions(state_, config_.sim);
  invMass_ = contactInverseMass(state_, regions_);
  sums_.prepare(hair());
}

StepHair CpuSolver::hair() {
  return StepHair{first_, rest_, restLength_, regions_, x_, v_, xOld_, xPred_, goal_};
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
  volume_.reset(rest_, first_, weight_, config_.collision.volumeCell, config_.collision.radius);
}

void CpuSolver::clearStages() {
  stages_ = {{"integrate", 0.0},
             {"shape_matching", 0.0},
             {"strain_limiting", 0.0},
             {"contacts", 0.0},
             {"volume", 0.0}};
}

void CpuSolver::stepFrame(const FramePath& path) {
  const Pose& to = path.to();
  clearStages();
  const FramePlan plan = planFrame(config_.sim, regions_.planRate);
  if (!failure_.empty()) {
    // No head to collide with (failure()): the clock runs, the hair stays.
    time_ += plan.substeps * plan.h;
    head_ = to;
    torso_ = path.torsoAt(1.0);
    return;
  }
  torso_ = path.torsoAt(0.0);
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
    const double s = double(k + 1) / plan.substeps;
    step(plan.h, path.at(s), path.torsoAt(s));
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
  return {contactRadius(c, meanWeight_),
          c.margin,
          c.compliance,
          c.friction,
          c.solve,
          c.penaltyStiffness,
          c.penaltyDamping};
}

void CpuSolver::step(double h, const Pose& head, const Pose& torso) {
  if (stages_.size() < 5) clearStages();  // a single step called directly
  const Pose before = head_, torsoBefore = torso_;
  std::vector<Sphere> spheres = worldSpheres(shape_.spheres, head);
  for (const Sphere& sp : worldSpheres(shape_.torsoSpheres, torso)) spheres.push_back(sp);
  auto t0 = Clock::now();
  predict(h, head);
  stages_[0].ms += msSince(t0);
  t0 = Clock::now();
  shapeMatch(head, h);
  stages_[1].ms += msSince(t0);
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
  limitStrain(h, spheres, head, before, torso, torsoBefore);
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
  torso_ = torso;
}

void CpuSolver::predict(double h, const Pose& head) {
  StepForces forces;
  forces.gravity = glm::dvec3(config_.sim.gravity);
  if (config_.wind.strength > 0.0f && config_.wind.drag > 0.0f) forces.wind = &config_.wind;
  forces.time = time_;
  if (volumeForces(config_.collision.mode) && !volume_.empty()) forces.volume = &volume_;
  forces.volumeSettings = volumeSettings();
  StepHair strands = hair();
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      for (uint32_t i = a; i < b; ++i)
        predictParticle(strands, forces, i, b, regions_.held(s, int(i - a), int(b - a)), head, h);
    }
  });
}

void CpuSolver::shapeMatch(const Pose& head, double h) {
  ShapeMatchSettings settings;
  settings.iterations = std::max(1, config_.sim.rotationIterations);
  settings.twistStep = twistStepOf(config_.sim, h, settings.iterations);
  settings.prefixSums = prefixSums_;
  settings.keep = std::exp(-double(config_.sim.damping) * h);
  StepHair strands = hair();
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s)
      shapeMatchStrand(strands, sums_, q_, config_.sim, settings, s, head, h);
  });
}

void CpuSolver::limitStrain(double h, const std::vector<Sphere>& spheres, const Pose& head,
                            const Pose& before, const Pose& torso, const Pose& torsoBefore) {
  SweepSettings settings;
  settings.limit = config_.sim.strainLimiting;
  settings.strainLimit = config_.sim.strainLimit;
  settings.headCollide = collidesWithHead(config_.collision.mode);
  settings.friction = config_.collision.headFriction;
  settings.dftl = dftlOf(config_);
  settings.before = &before;
  settings.torsoBefore = &torsoBefore;
  const HeadCollider collider{shape_.field,
                              spheres,
                              head,
                              config_.collision.radius,
                              shape_.torsoField,
                              shape_.hasTorso() ? &torso : nullptr,
                              shape_.spheres.size()};
  StepHair strands = hair();
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s)
      limitStrainStrand(strands, correction_, collider, settings, s, h);
  });
}

void CpuSolver::saveMore(StateWriter& w) const {
  std::vector<glm::dvec4> q(q_.size());
  for (size_t i = 0; i < q_.size(); ++i) q[i] = {q_[i].x(), q_[i].y(), q_[i].z(), q_[i].w()};
  w.putVector(q);
}

bool CpuSolver::readMore(StateReader& r) {
  std::vector<glm::dvec4> q;
  if (!r.getVector(q, q_.size())) return false;
  restoredQ_.resize(q.size());
  for (size_t i = 0; i < q.size(); ++i)
    restoredQ_[i] = Eigen::Quaterniond(q[i].w, q[i].x, q[i].y, q[i].z);
  return true;
}

void CpuSolver::restored() {
  q_ = std::move(restoredQ_);
  restoredQ_.clear();
  // The last list is of another state: nothing to count crossings against (as after a reset).
  candidates_ = ContactCandidates{};
  measureAnew();
}

void CpuSolver::carryMore(const Pose& by) {
  const Eigen::Quaterniond turn = toEigen(by.rotation);
  for (Eigen::Quaterniond& q : q_) q = (turn * q).normalized();
}

void CpuSolver::requestSample(long frame) {
  FrameSample sample;
  sample.frame = frame;
  std::vector<Sphere> spheres = worldSpheres(shape_.spheres, head_);
  for (const Sphere& sp : worldSpheres(shape_.torsoSpheres, torso_)) spheres.push_back(sp);
  sample.accuracy = measureAccuracy(
      x_, v_, first_, restLength_, spheres, regions_.pinned, PosedField{shape_.field, head_},
      BodyParts{PosedField{shape_.torsoField, torso_}, shape_.spheres.size()});
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

}  // namespace csm
