// One finished frame of the window's simulation (app/sim_thread.h publishes them), and the
// running scene's figures a headless run describes itself by (app/metrics.h runDescription): its
// own header, so that the metrics and the simulation thread need not include each other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "app/history.h"
#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/core/results.h"
#include "sim/groom/guides.h"
#include "sim/groom/scene_groom.h"
#include "sim/motion/clip.h"
#include "sim/run/timeline.h"

namespace csm {

class HeadModel;
class Simulation;

// One finished frame as the simulation thread hands it over. Immutable once published.
struct SimFrame {
  long ticket = 0;  // the last command applied before this frame was published
  long serial = 0;  // counts publications
  bool loaded = false;
  long frame = 0;
  double time = 0.0;
  long generation = 0;  // changes when the groom is regrown
  Config config;
  std::shared_ptr<const Groom> groom;  // the strands simulated
  // The strands drawn from the guides when the groom is simulated through guides (null: none).
  std::shared_ptr<const FollowerBinding> followers;
  GroomReport groomReport;
  std::shared_ptr<const HeadModel> head;   // the scene's head (built with the groom)
  Pose headPose;                           // where the head was at the end of the frame
  Pose torsoPose;                          // and the torso
  std::size_t strands = 0, particles = 0;  // simulated
  std::size_t drawnStrands = 0;            // drawn: the followers' groom's, else `strands`
  long carriedFrames = 0;  // frames whose head motion was partly carried (kMaxRootSpeed)
  std::shared_ptr<const MotionClip> clip;  // motion.clip, read (null: head.motion)
  long clipCuts = 0;                       // cuts of the clip the hair was carried over
  StiffnessInfo stiffness;
  MemoryUse memory;           // the solver's buffers by kind (SolverDiagnostics::memoryUse)
  std::string solver;         // the solver's name
  std::string solverVariant;  // the GPU solver's kernel path (SolverDiagnostics::variant)
  // The simulation's own figures: the last step's wall time (to completion) and stages, the
  // latest sample (a few frames old) and one max strain per sample.
  double stepMs = 0.0;
  std::vector<StageTime> stages;
  std::optional<FrameSample> sample;
  History maxStrain{120};
  // The NaN policy: the first frame whose sample counted non-finite particles; the thread
  // steps no further until a reset or a regrow.
  long nanFrame = -1;
  uint64_t nanParticles = 0;
  bool idle = false;  // will step no further without a command (paused, stopped, limit)
  // The timeline (sim/run/timeline.h): what is recorded, and the recorded frame on show instead
  // of the live one (then `frame`, `time`, `headPose` and the positions are that frame's).
  TimelineStatus timeline;
  // This frame's positions (vec4 per particle): a buffer of the share group, to draw after
  // SimThread::acquire() (which orders the window's context after the copy), or a host copy.
  unsigned positionBuffer = 0;
  int slot = -1;
  std::shared_ptr<const std::vector<glm::vec4>> hostPositions;
};

// The solver as the window shows it: its name and, when it has one, its variant, "gpu (particle)".
std::string solverLabel(const SimFrame& frame);
// The running scene's figures into `frame`: the solver, its counts and stiffness, the config,
// the groom's report and the head's carried frames. What the simulation thread copies into
// every frame it publishes, and what a headless run describes itself by (runDescription).
void takeFigures(const Simulation& sim, SimFrame& frame);

}  // namespace csm
