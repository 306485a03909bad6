#include "sim/run/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/groom/scene_groom.h"
#include "sim/param/sim_params.h"
#include "sim/solver/wind.h"

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
  return csm::drawnPositions(scene_, simulated, BodyPose{headPose(), torsoPose()}, out);
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
    startMoving();
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
  hairRadius_ = rootRadius_;
  for (const glm::vec3& p : g.points)
    hairRadius_ = std::max(hairRadius_, glm::length(glm::dvec3(p) - rootCentre_));
  longestStrand_ = 0.0;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    double length = 0.0;
    for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i)
      length += glm::length(glm::dvec3(g.points[i]) - glm::dvec3(g.points[i - 1]));
    longestStrand_ = std::max(longestStrand_, length);
  }
}

double Simulation::explainedPeakSpeed() const {
  const double g = glm::length(glm::dvec3(config_.sim.gravity));
  return peakRigidSpeed_ + std::sqrt(2.0 * g * longestStrand_) + windPeakSpeed(config_.wind);
}

double Simulation::rootReach(const Pose& from, const Pose& to, double radius) const {
  // The centre's displacement plus the radius times the turn's chord, 2 sin(angle / 2).
  const glm::dquat turn = to.rotation * glm::conjugate(from.rotation);
  const double halfSine = std::min(1.0, glm::length(glm::dvec3(turn.x, turn.y, turn.z)));
  return glm::length(to.apply(rootCentre_) - from.apply(rootCentre_)) + 2.0 * halfSine * radius;
}

Pose Simulation::jumpOf(const Pose& from, const Pose& to) const {
  const double reach = rootReach(from, to, rootRadius_);
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
  cuts_ = 0;
  peakRootSpeed_ = 0.0;
  peakRigidSpeed_ = 0.0;
  lastPose_ = headPoseAt(0.0);
  lastUserPose_ = userPose_;
  solver_->setHead(scene_.head);
  solver_->reset(*scene_.groom, config_, lastPose_);
  startMoving();
  restartSamples();
}

void Simulation::startMoving() {
  // A clip that starts in motion (a run) starts the hair moving with the body, as if it had
  // been running: from rest, the first frames would yank it faster than anything in the clip.
  if (!scene_.clip) return;
  const double h = 0.25 * double(config_.sim.dt);
  const Pose move = compose(headPoseAt(time_ + h), inverse(headPoseAt(time_)));
  if (move.rotation == glm::dquat(1.0, 0.0, 0.0, 0.0) && move.translation == glm::dvec3(0.0))
    return;
  std::vector<glm::vec4> x, v;
  solver_->state().readPositions(x);
  v.resize(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const glm::dvec3 p(x[i]);
    v[i] = glm::vec4(glm::vec3((move.apply(p) - p) / h), 0.0f);
  }
  solver_->state().write(x, v);
}

Pose Simulation::headPoseAt(double t) const {
  if (scene_.clip)
    return compose(userPose_,
                   scene_.clip->sample(t, config_.motion.loop, config_.motion.inPlace).head);
  return compose(userPose_, csm::headPose(config_.head, t));
}

BodyPose Simulation::bodyPoseAt(double t) const {
  if (!scene_.clip) {
    const Pose head = headPoseAt(t);
    return {head, torsoPoseAt(config_, nullptr, t, head)};
  }
  BodyPose body = scene_.clip->sample(t, config_.motion.loop, config_.motion.inPlace);
  body.head = compose(userPose_, body.head);
  return body;
}

long Simulation::clipFrames() const {
  if (!scene_.clip) return 0;
  return std::max(1L, long(std::ceil(scene_.clip->duration() / double(config_.sim.dt) - 1e-9)));
}

FramePath Simulation::framePath(double next) {
  if (!scene_.clip) {
    const Pose to = headPoseAt(next);
    return FramePath{
        {lastPose_, to},
        {torsoPoseAt(config_, nullptr, time_, lastPose_), torsoPoseAt(config_, nullptr, next, to)}};
  }
  // The clip where each substep may end: as many keys as the most steps a frame.
  const int keys = std::clamp(std::max(config_.sim.substeps, config_.sim.maxSubsteps), 2, 64);
  const double dt = next - time_;
  FramePath path;
  std::vector<double> at(size_t(keys) + 1);
  for (int i = 0; i <= keys; ++i) {
    at[size_t(i)] = i == keys ? next : time_ + dt * double(i) / keys;
    const BodyPose body = bodyPoseAt(at[size_t(i)]);
    path.keys.push_back(body.head);
    path.torso.push_back(body.torso);
  }
  // A live change of the clip's settings (in place, loop) moves where the clip has the head now:
  // the hair goes there with it, rigidly, as over a cut.
  const MotionClip& clip = *scene_.clip;
  const Pose now =
      compose(lastUserPose_, clip.sample(time_, config_.motion.loop, config_.motion.inPlace).head);
  if (rootReach(lastPose_, now, hairRadius_) > 1e-6) {
    const Pose jump = compose(now, inverse(lastPose_));
    solver_->state().carry(jump);
    lastPose_ = now;
    ++carried_;
  }
  // A cut in the clip carries the hair with the head, as a reset of the head does: the keys
  // before it are moved by the jump, so the path runs on from the pose after it.
  for (double cut : clip.cutsBetween(time_, next, config_.motion.loop)) {
    const Pose before = headPoseAt(cut - 1e-6 * clip.frameTime());
    const Pose jump = compose(headPoseAt(cut), inverse(before));
    solver_->state().carry(jump);
    lastPose_ = compose(jump, lastPose_);
    for (int i = 0; i <= keys; ++i)
      if (at[size_t(i)] < cut) {
        path.keys[size_t(i)] = compose(jump, path.keys[size_t(i)]);
        path.torso[size_t(i)] = compose(jump, path.torso[size_t(i)]);
      }
    ++cuts_;
  }
  path.keys.front() = lastPose_;
  return path;
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
  FramePath path = framePath(next);
  // The user's move of the head this frame (a drag, a reset of it), beyond the preset's motion.
  const Pose motion =
      scene_.clip ? scene_.clip->sample(next, config_.motion.loop, config_.motion.inPlace).head
                  : csm::headPose(config_.head, next);
  const Pose to = path.to();
  const Pose jump = jumpOf(compose(lastUserPose_, motion), to);
  if (jump.rotation != glm::dquat(1.0, 0.0, 0.0, 0.0) || jump.translation != glm::dvec3(0.0)) {
    // The hair goes with the head for the part of its motion too fast to simulate.
    solver_->state().carry(jump);
    lastPose_ = compose(jump, lastPose_);
    path.keys.front() = lastPose_;
    ++carried_;
  }
  const double perKey = double(path.keys.size() - 1) / double(config_.sim.dt);
  for (size_t k = 1; k < path.keys.size(); ++k) {
    const Pose& a = path.keys[k - 1];
    const Pose& b = path.keys[k];
    peakRootSpeed_ = std::max(peakRootSpeed_, rootReach(a, b, rootRadius_) * perKey);
    peakRigidSpeed_ = std::max(peakRigidSpeed_, rootReach(a, b, hairRadius_) * perKey);
  }
  solver_->stepFrame(path);
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
  out.cuts = cuts_;
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
  cuts_ = in.cuts;
  userPose_ = in.userPose;
  lastUserPose_ = in.lastUserPose;
  lastPose_ = in.lastPose;
  restartSamples();
  return true;
}

}  // namespace csm
