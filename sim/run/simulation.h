// A running scene: the config, the groom grown from it, a solver and the head's motion, and the
// frame loop the headless runs, the window's simulation thread and the benchmarks share: a frame
// stepped, its measures sampled without waiting (the solver's fenced ring, read a few frames
// late), a stop on NaN. A changed parameter either takes effect on the next step or, when it
// changes the hair's shape, regrows the groom. The solver stays inside: what is drawn and shown
// of it (positions, counts, diagnostics) is read through here.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/followers.h"
#include "sim/groom/guides.h"
#include "sim/groom/scene_groom.h"
#include "sim/run/grown_scene.h"
#include "sim/head/head_model.h"
#include "sim/core/pose.h"
#include "sim/core/solver.h"

namespace csm {

// The fastest the user's move of the head may move the roots (m/s). A head the user moves
// faster (a jump: a reset of the viewer's drag, a fast drag, setUserPose) carries the hair
// with it, rigidly, for the part of the move beyond this speed; the rest, and the preset's
// own motion, are simulated. A head shaken hard turns at about 700 degrees a second, which moves
// roots 10-12 cm from the neck's axis at 1.2-1.5 m/s.
inline constexpr double kMaxRootSpeed = 2.0;

// A point of a running scene to go back to (sim/run/frame_recording.h): the solver's whole state,
// the clock, the head's poses and the config it ran with, for the groom of one generation.
struct SimulationState {
  long generation = -1;  // the groom it belongs to (Simulation::generation)
  long frame = 0;
  double time = 0.0;
  long carried = 0;
  long cuts = 0;
  Pose userPose, lastUserPose, lastPose;
  Config config;
  SavedState solver;
  size_t bytes() const { return sizeof(*this) + solver.bytes.size(); }
};

// How a simulation samples its frames' measures and times them.
struct Sampling {
  // Frames between samples; 1 samples every frame (metrics), more only watches for NaN, 0
  // takes none (timing runs, and runs that check their results themselves).
  int every = 0;
  // Take each frame's sample before the next frame (waiting for it): for runs that write
  // frames out, so that none is written before its NaN check.
  bool wait = false;
  // Wait for each frame's GPU work to end before timing it (glFinish): honest wall times for
  // the metrics, a stall otherwise.
  bool timeToCompletion = false;
};

class Simulation {
 public:
  explicit Simulation(std::unique_ptr<Solver> solver, const Sampling& sampling = {})
      : solver_(std::move(solver)), sampling_(sampling) {}

  // Where a long groom import stands, while load or setConfig build one (sim/groom/scene_groom.h).
  void setImportProgress(ImportProgress progress) { importProgress_ = std::move(progress); }

  // Grows the groom and resets the solver. On failure keeps what it had and says why. `head`,
  // when given, is the scene's head already built from `config` (setupScene's): its mesh, field
  // and fitted spheres are used rather than read and made again.
  bool load(const Config& config, const std::string& baseDir, std::string* error,
            std::shared_ptr<const HeadModel> head = nullptr);
  // Applies a changed config: regrows when a Rebuild parameter changed, else goes live.
  // Returns false (keeping the old scene) when the new groom cannot be built.
  bool setConfig(const Config& config, std::string* error);
  // Back to the rest shape, time 0.
  void reset();

  // One frame, unless stopped on NaN: the head's pose at the next time, the solver's frame,
  // the sample when one is due; then the samples that are ready (with Sampling::wait, this
  // frame's), whose NaN count stops the simulation.
  void stepFrame();
  // One frame as stepFrame steps it, neither timed nor sampled: frames already stepped once,
  // stepped again from a restored state (sim/run/frame_recording.h).
  void replayFrame();
  void setSampling(const Sampling& sampling) { sampling_ = sampling; }
  // Takes every sample still in flight, waiting for them (the end of a run).
  void drainSamples();
  // Samples taken since the last call, oldest first.
  std::vector<FrameSample> takeSamples();
  const std::optional<FrameSample>& latestSample() const { return latest_; }
  // The NaN policy: a sample that counts non-finite particles stops the simulation until the
  // hair starts again (a reset, a regrow, a restore).
  bool stopped() const { return nanFrame_ >= 0; }
  long nanFrame() const { return nanFrame_; }
  uint64_t nanParticles() const { return nanParticles_; }
  // Wall time of the last stepFrame, ms.
  double lastStepMs() const { return lastStepMs_; }
  // Saves where the scene is; restores it, config included, so that the frames after run as
  // they did from there. Fails (false, *error set) for a state of another groom (a regrow in
  // between) and then changes nothing.
  void save(SimulationState& out) const;
  bool restore(const SimulationState& in, std::string* error);
  // The frame as it stands, read later (SolverState::copyFrame): with `state`, that is filled now
  // but for its solver part, which the copy's read() fills.
  std::unique_ptr<FrameCopy> copyFrame(SimulationState* state);
  // An extra transform of the head on top of the preset's motion (the viewer's drag).
  void setUserPose(const Pose& pose) { userPose_ = pose; }
  const Pose& userPose() const { return userPose_; }
  Pose headPoseAt(double t) const;
  // The body at time t: the head's pose and the torso's (the clip's two parts; without a clip the
  // head nods, shakes, sways and is dragged alone, the torso standing or spinning and bouncing
  // with head.motion, and turned with the head past the neck's reach: csm::torsoUnder).
  BodyPose bodyPoseAt(double t) const;
  // The motion clip the scene runs (motion.clip), null without one.
  const MotionClip* clip() const { return scene_.clip.get(); }
  // Frames that play the clip once through (0 without a clip).
  long clipFrames() const;
  // Frames since the last reset whose clip cut (MotionClip::cutsBetween) the hair was carried over.
  long clipCuts() const { return cuts_; }
  // The fastest the head's motion has moved a root since the last reset (m/s, over a frame):
  // what a particle's speed is compared with.
  double peakRootSpeed() const { return peakRootSpeed_; }
  // The fastest any particle would have moved were the hair fixed rigidly to the head (m/s):
  // the speed the head's motion explains, beyond which a particle is flung by the simulation.
  double peakRigidSpeed() const { return peakRigidSpeed_; }
  // The fastest a particle may move for the motion to explain it (m/s): the rigid hair's peak,
  // plus what gravity gives a strand falling its own length from rest, sqrt(2 g L) with L the
  // longest strand, plus the wind's fastest (its strength with full gusts and turbulence).
  double explainedPeakSpeed() const;
  Pose headPose() const { return headPoseAt(time_); }
  Pose torsoPose() const { return bodyPoseAt(time_).torso; }

  // The solver's name, its counts (the simulated strands and their particles) and what it says of
  // itself (stage times, stiffness, memory, failure, its kernel path).
  std::string_view solverName() const { return solver_->name(); }
  SolverCounts counts() const { return solver_->counts(); }
  SolverDiagnostics& diagnostics() const { return solver_->diagnostics(); }
  // The simulated positions (world, a vec4 a particle) and velocities read back, and the GL
  // buffer that holds the positions where the solver keeps them on the GPU (0: read them).
  void readPositions(std::vector<glm::vec4>& out) const { solver_->state().readPositions(out); }
  void readVelocities(std::vector<glm::vec4>& out) const { solver_->state().readVelocities(out); }
  unsigned positionBuffer() const { return solver_->state().positionBuffer(); }
  const Config& config() const { return config_; }
  // The strands simulated: the whole groom, or its guides (hairstyle.guides).
  const Groom& groom() const { return *scene_.groom; }
  // The same groom, for a reader on another thread that keeps it past a regrow (the
  // viewer's renderer): a regrow makes a new one and leaves this one as it is.
  std::shared_ptr<const Groom> sharedGroom() const { return scene_.groom; }
  // The strands drawn and how they follow the guides; null when every strand is simulated.
  const FollowerBinding* followers() const { return scene_.followers.get(); }
  std::shared_ptr<const FollowerBinding> sharedFollowers() const { return scene_.followers; }
  // The drawn strands' positions (world, a vec4 a point) from the simulated ones at this frame's
  // head: the followers made on the CPU (sim/groom/followers.h), or the simulated positions as
  // they are. Returns what keeping the followers out of the head took (nothing without them).
  FollowerStats drawnPositions(const std::vector<glm::vec4>& simulated,
                               std::vector<glm::vec4>& out) const;
  // Strands drawn: the followers' groom's, or the simulated groom's.
  size_t drawnStrands() const { return scene_.drawnStrands(); }
  // The scene's head (built when the groom was), shared the same way: what the renderer draws.
  const HeadModel& head() const { return *scene_.head; }
  std::shared_ptr<const HeadModel> sharedHead() const { return scene_.head; }
  const GroomReport& groomReport() const { return scene_.report; }
  // The head, the groom and the followers together (sim/run/grown_scene.h).
  const GrownScene& scene() const { return scene_; }
  const std::string& baseDir() const { return baseDir_; }
  double time() const { return time_; }
  long frame() const { return frame_; }
  // Frames since the last reset whose user move of the head was partly carried (kMaxRootSpeed).
  long carriedFrames() const { return carried_; }
  // Bumped whenever the groom is regrown, so renderers know to rebuild their buffers.
  long generation() const { return generation_; }

 private:
  void save(SimulationState& out, bool withSolver) const;
  // Grows the groom for `config` and keeps it; the solver is not touched.
  // `known`: a head whose parts (mesh, fitted spheres) a new one may share; else the running one.
  bool regrow(const Config& config, const std::string& baseDir, std::string* error,
              const HeadModel* known = nullptr);
  void boundRoots();
  // The hair moving with the body where a clip starts in motion (after a reset).
  void startMoving();
  // False, saying why, when the solver could not take the groom at its reset.
  bool solverReady(std::string* error) const;
  // The part of the head's move from `from` to `to` that moves the roots faster than
  // kMaxRootSpeed, as a rigid transform of the world (identity when none).
  Pose jumpOf(const Pose& from, const Pose& to) const;
  // How far a root moves at most when the head goes from `from` to `to` (m).
  double rootReach(const Pose& from, const Pose& to, double radius) const;

  std::unique_ptr<Solver> solver_;
  Config config_;
  std::string baseDir_;
  GrownScene scene_;  // the head (handed to the solver), the groom, the followers
  ImportProgress importProgress_;
  void startingSolver() const;
  // The head's move and the solver's frame (stepFrame, replayFrame).
  void advance();
  // The head through the frame from time_ to `next`: the preset's motion (the frame's ends) or
  // the clip's, sampled between (its cuts carried).
  FramePath framePath(double next);
  // The samples of the hair before are moot: dropped, and the NaN stop cleared.
  void restartSamples();
  void takeReady(bool wait);
  void accept(const FrameSample& sample);
  Sampling sampling_;
  std::vector<FrameSample> taken_;
  std::optional<FrameSample> latest_;
  long nanFrame_ = -1;
  uint64_t nanParticles_ = 0;
  double lastStepMs_ = 0.0;
  Pose userPose_;
  Pose lastUserPose_;  // the user's pose the last frame ran with
  Pose lastPose_;
  // The roots' bounding sphere in the head frame, for their speed.
  glm::dvec3 rootCentre_{0.0};
  double rootRadius_ = 0.0;
  double hairRadius_ = 0.0;     // every rest particle's, about the same centre
  double longestStrand_ = 0.0;  // the longest strand's rest length (m)
  long carried_ = 0;
  long cuts_ = 0;
  double peakRootSpeed_ = 0.0;
  double peakRigidSpeed_ = 0.0;
  double time_ = 0.0;
  long frame_ = 0;
  long generation_ = 0;
};

}  // namespace csm
