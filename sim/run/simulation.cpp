#include "sim/run/simulation.h"

#include <algorithm>
#include <chrono>

#include <glm/geometric.hpp>

#include "sim/groom/scene_groom.h"
#include "sim/param/sim_params.h"
#include "sim/run/scene_checks.h"

namespace csm {

bool Simulation::load(const Config& config, const std::string& baseDir, std::string* error,
                      std::shared_ptr<const HeadModel> head) {
  if (!regrow(config, baseDir, error, head.get())) return false;
  startingSolver();
  reset();
  return solverReady(error);
}

void Simulation::startingSolver() const {
  // The solver's set-up for a large imported groom takes longer than the import itself (its
  // buffers, the collision lists): the progress says so rather than stopping at 100 %.
  if (importProgress_ && !config_.hairstyle.file.empty())
    importProgress_("starting the solver", 1.0);
}

bool Simulation::regrow(const Config& config, const std::string& baseDir, std::string* error,
                        const HeadModel* known) {
  // A head file that `known` or the running scene already holds is not read again.
  GrownScene grown;
  if (!growScene(config, baseDir, known ? known : scene_.head.get(), importProgress_, grown, error))
    return false;
  scene_ = std::move(grown);
  config_ = config;
  baseDir_ = baseDir;
  boundRoots();
  ++generation_;
  return true;
}

FollowerStats Simulation::drawnPositions(const std::vector<glm::vec4>& simulated,
                                         std::vector<glm::vec4>& out) const {
  return csm::drawnPositions(scene_, simulated, headPose(), out);
}

bool Simulation::setConfig(const Config& config, std::string* error) {
  if (needsRegrow(config_, config)) {
    // Keep the clock and the camera: only the hair starts again from rest.
    if (!regrow(config, baseDir_, error)) return false;
    lastPose_ = headPoseAt(time_);
    lastUserPose_ = userPose_;
    startingSolver();
    solver_->setHead(scene_.head);
    solver_->reset(*scene_.groom, config_, lastPose_);
    restartSamples();
    return solverReady(error);
  }
  config_ = config;
  solver_->setConfig(config_);
  return true;
}

bool Simulation::solverReady(std::string* error) const {
  const std::string failure = solver_->diagnostics().failure();
  if (failure.empty()) return true;
  if (error) *error = std::string(solver_->name()) + " solver: " + failure;
  return false;
}

void Simulation::boundRoots() {
  const Groom& g = *scene_.groom;
  glm::dvec3 lo(0.0), hi(0.0);
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const glm::dvec3 r(g.points[g.first[s]]);
    lo = s == 0 ? r : glm::min(lo, r);
    hi = s == 0 ? r : glm::max(hi, r);
  }
  rootCentre_ = 0.5 * (lo + hi);
  rootRadius_ = 0.0;
  for (size_t s = 0; s < g.strandCount(); ++s)
    rootRadius_ =
        std::max(rootRadius_, glm::length(glm::dvec3(g.points[g.first[s]]) - rootCentre_));
}

Pose Simulation::jumpOf(const Pose& from, const Pose& to) const {
  // How far a root moves at most: the centre's displacement plus the radius times the turn's
  // chord, 2 sin(angle / 2).
  const glm::dquat turn = to.rotation * glm::conjugate(from.rotation);
  const double halfSine = std::min(1.0, glm::length(glm::dvec3(turn.x, turn.y, turn.z)));
  const double reach =
      glm::length(to.apply(rootCentre_) - from.apply(rootCentre_)) + 2.0 * halfSine * rootRadius_;
  const double allowed = kMaxRootSpeed * double(config_.sim.dt);
  if (!(reach > allowed)) return Pose{};
  // Past the bound: how far the farthest root does move.
  double farthest = 0.0;
  const Groom& g = *scene_.groom;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const glm::dvec3 r(g.points[g.first[s]]);
    farthest = std::max(farthest, glm::length(to.apply(r) - from.apply(r)));
  }
  if (!(farthest > allowed)) return Pose{};
  const Pose carriedTo = interpolate(from, to, 1.0 - allowed / farthest);
  return compose(carriedTo, inverse(from));
}

void Simulation::reset() {
  time_ = 0.0;
  frame_ = 0;
  carried_ = 0;
  lastPose_ = headPoseAt(0.0);
  lastUserPose_ = userPose_;
  solver_->setHead(scene_.head);
  solver_->reset(*scene_.groom, config_, lastPose_);
  restartSamples();
}

Pose Simulation::headPoseAt(double t) const {
  return compose(userPose_, csm::headPose(config_.head, t));
}

void Simulation::stepFrame() {
  using Clock = std::chrono::steady_clock;
  if (stopped()) return;
  SolverDiagnostics& diagnostics = solver_->diagnostics();
  // Timed to completion, the frame's time starts when the GPU has done what came before it
  // (the last sample's measures among them).
  if (sampling_.timeToCompletion) diagnostics.finish();
  const auto t0 = Clock::now();
  advance();
  if (sampling_.timeToCompletion) diagnostics.finish();
  lastStepMs_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  const bool due = sampling_.wait || sampling_.every == 1 ||
                   (sampling_.every > 1 && frame_ % sampling_.every == 0);
  if (due) diagnostics.requestSample(frame_);
  takeReady(sampling_.wait);
}

void Simulation::replayFrame() {
  advance();
}

void Simulation::takeReady(bool wait) {
  while (std::optional<FrameSample> s = solver_->diagnostics().takeSample(wait)) accept(*s);
}

void Simulation::accept(const FrameSample& sample) {
  latest_ = sample;
  taken_.push_back(sample);
  if (sample.accuracy.nanCount > 0 && !stopped()) {
    nanFrame_ = sample.frame;
    nanParticles_ = sample.accuracy.nanCount;
  }
}

void Simulation::drainSamples() {
  takeReady(true);
}

std::vector<FrameSample> Simulation::takeSamples() {
  std::vector<FrameSample> out;
  out.swap(taken_);
  return out;
}

void Simulation::restartSamples() {
  solver_->diagnostics().dropSamples();
  latest_.reset();
  nanFrame_ = -1;
  nanParticles_ = 0;
}

void Simulation::advance() {
  const double next = time_ + config_.sim.dt;
  // The user's move of the head this frame (a drag, a reset of it), beyond the preset's motion.
  const Pose motion = csm::headPose(config_.head, next);
  const Pose to = compose(userPose_, motion);
  const Pose jump = jumpOf(compose(lastUserPose_, motion), to);
  if (jump.rotation != glm::dquat(1.0, 0.0, 0.0, 0.0) || jump.translation != glm::dvec3(0.0)) {
    // The hair goes with the head for the part of its motion too fast to simulate.
    solver_->state().carry(jump);
    lastPose_ = compose(jump, lastPose_);
    ++carried_;
  }
  solver_->stepFrame(lastPose_, to);
  lastPose_ = to;
  lastUserPose_ = userPose_;
  time_ = next;
  ++frame_;
}

std::unique_ptr<FrameCopy> Simulation::copyFrame(SimulationState* state) {
  if (state) {
    save(*state, false);
  }
  return solver_->state().copyFrame(state != nullptr);
}

void Simulation::save(SimulationState& out) const {
  save(out, true);
}

void Simulation::save(SimulationState& out, bool withSolver) const {
  out.generation = generation_;
  out.frame = frame_;
  out.time = time_;
  out.carried = carried_;
  out.userPose = userPose_;
  out.lastUserPose = lastUserPose_;
  out.lastPose = lastPose_;
  out.config = config_;
  if (withSolver) solver_->state().save(out.solver);
}

bool Simulation::restore(const SimulationState& in, std::string* error) {
  if (in.generation != generation_) {
    if (error) *error = "the saved state is of another groom (the hair was regrown since)";
    return false;
  }
  // The config it ran with first (live parameters only, the groom being the same): a changed
  // window rebuilds the regions, which the saved rotations then fill.
  const Config now = config_;
  config_ = in.config;
  solver_->setConfig(config_);
  if (!solver_->state().restore(in.solver, error)) {
    config_ = now;
    solver_->setConfig(config_);
    return false;
  }
  frame_ = in.frame;
  time_ = in.time;
  carried_ = in.carried;
  userPose_ = in.userPose;
  lastUserPose_ = in.lastUserPose;
  lastPose_ = in.lastPose;
  restartSamples();
  return true;
}

}  // namespace csm
