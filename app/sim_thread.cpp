#include "app/sim_thread.h"

#include "app/import_progress.h"
#include "sim/run/simulation.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

// Behind real time by more than this, the paced clock starts again from now rather than
// running flat out to catch up.
constexpr double kMaxLagSeconds = 0.25;

}  // namespace

std::unique_ptr<SimThread> SimThread::start(Options options, Started* started, std::string* error) {
  std::unique_ptr<SimThread> t(new SimThread(std::move(options)));
  std::string startError;
  Started info;
  // The thread writes startError and info before its first publication or its end, both of
  // which the wait below sees; it touches neither after.
  t->thread_ = std::thread([raw = t.get(), &startError, &info] { raw->run(&startError, &info); });
  {
    std::unique_lock lock(t->mutex_);
    t->published_.wait(lock, [&] { return t->latest_ != nullptr || !t->running_; });
  }
  if (!t->latest_) {
    t->thread_.join();
    t->thread_ = {};
    if (error) *error = startError;
    return nullptr;
  }
  if (started) *started = info;
  return t;
}

SimThread::SimThread(Options options) : options_(std::move(options)) {}

SimThread::~SimThread() {
  if (thread_.joinable()) {
    post([](Pending& p, long) { p.quit = true; });
    thread_.join();
  }
  options_.context.reset();
}

// --- The thread ----------------------------------------------------------------------------

bool SimThread::makeSimulation(std::string* error, Started* started) {
  std::string why;
  if (options_.solver != "gpu" || gl_)
    sim_ = csm::makeSimulation(options_.solver, &why, options_.makeSolver);
  else
    why = "no GL context for the simulation thread";
  if (!sim_ && options_.solver == "gpu") {
    started->warning = "The GPU solver did not start (" + why + "); using the CPU solver.";
    sim_ = csm::makeSimulation("cpu", &why, options_.makeSolver);
  }
  if (!sim_) {
    *error = "no solver: " + why;
    return false;
  }
  started->solver = std::string(sim_->solverName());
  sim_->setImportProgress(
      [this, say = ImportProgressPrinter()](std::string_view stage, double done) mutable {
        if (options_.sayImportProgress) say(stage, done);
        {
          std::lock_guard lock(importMutex_);
          import_ = {std::string(stage), done};
        }
        if (options_.wake) options_.wake();
      });
  Sampling sampling;
  // Every frame sampled: a few numbers per work group, fenced; the Stats panel's strain and
  // the NaN check follow each frame a few frames late.
  sampling.every = 1;
  // This thread may wait for its own GPU work: the wall times are then honest, and the
  // commands it queues stay one frame deep.
  sampling.timeToCompletion = true;
  sim_->setSampling(sampling);
  return true;
}

void SimThread::run(std::string* startError, Started* started) {
  gl_ = options_.context && options_.context->makeCurrent();
  const bool ok = makeSimulation(startError, started);
  if (ok) publish(0);  // the empty frame: start() returns
  if (!ok) {
    std::lock_guard lock(mutex_);
    running_ = false;
    published_.notify_all();
  }
  while (ok) {
    Pending p;
    long ticket = 0;
    {
      std::unique_lock lock(mutex_);
      for (;;) {
        if (pending_.any()) break;
        if (canStep()) {
          if (!options_.paced || paused_ || timeline_.baking()) break;
          const auto due =
              anchorWall_ + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>(sim_->time() - anchorSim_));
          const auto now = Clock::now();
          if (now >= due) {
            if (std::chrono::duration<double>(now - due).count() > kMaxLagSeconds) {
              anchorWall_ = now;
              anchorSim_ = sim_->time();
            }
            break;
          }
          wakeThread_.wait_until(lock, due);
          continue;
        }
        wakeThread_.wait(lock);
      }
      p = std::move(pending_);
      pending_ = {};
      ticket = posted_;
    }
    if (p.quit) break;
    if (p.any()) {
      apply(p, ticket);
      publish(ticket);
      continue;  // commands first: a burst of slider moves is applied before a frame
    }
    stepFrame();
    publish(applied_);
  }
  // GL objects go while the context is current.
  {
    std::lock_guard lock(mutex_);
    buffers_.release();
    running_ = false;
    published_.notify_all();
  }
  sim_.reset();
  if (gl_) options_.context->releaseCurrent();
}

SimThread::ImportStatus SimThread::importStatus() const {
  std::lock_guard lock(importMutex_);
  return import_;
}

void SimThread::apply(Pending& p, long ticket) {
  std::string error;
  // An import's progress shows while this command builds the groom, and no longer.
  struct Done {
    SimThread& t;
    ~Done() {
      std::lock_guard lock(t.importMutex_);
      t.import_ = {};
    }
  } done{*this};
  const long generation = sim_->generation();
  bool opened = false;
  if (p.open) {
    const OpenScene& scene = *p.open;
    if (sim_->load(scene.config, scene.baseDir, &error, scene.head)) {
      opened = true;
      loaded_ = true;
      sim_->setUserPose(Pose{});
      event(SimEvent::Kind::Opened, p.openTicket, counts());
    } else {
      event(SimEvent::Kind::OpenFailed, p.openTicket, error);
    }
  }
  if (p.config && loaded_) {
    if (!sim_->setConfig(*p.config, &error))
      event(SimEvent::Kind::ConfigRefused, p.configTicket, error);
    else if (sim_->generation() != generation && !p.open)
      event(SimEvent::Kind::Regrew, p.configTicket, counts());
  }
  if (p.reset && loaded_) sim_->reset();
  if (p.userPose) sim_->setUserPose(*p.userPose);
  if (p.paused) paused_ = *p.paused;
  steps_ += p.steps;
  const bool restarted = sim_->generation() != generation || (p.reset && loaded_) || opened;
  if (restarted) {
    maxStrain_.clear();
    timeline_.restarted(*sim_);
  }
  if (opened || sim_->generation() != generation) timeline_.openShot("", 0, 0);
  const bool resumed = applyTimeline(p, ticket);
  // The paced clock starts again from here when the hair starts again or starts moving; not
  // on every command (a drag posts one a frame), which would let it run ahead of real time.
  if (restarted || resumed || (p.paused && !*p.paused) || p.steps > 0 || p.timeline.bake) {
    anchorWall_ = Clock::now();
    anchorSim_ = sim_->time();
  }
  applied_ = ticket;
}

bool SimThread::applyTimeline(const Pending& p, long ticket) {
  if (p.timeline.recording) timeline_.setRecording(*p.timeline.recording);
  if (p.timeline.shot && loaded_) {
    const TimelineEdits::Shot& shot = *p.timeline.shot;
    timeline_.openShot(shot.dir, shot.frames, shot.particles);
  }
  if (p.timeline.show && timeline_.show(*p.timeline.show)) paused_ = true;
  bool resumed = false;
  if (p.timeline.resume && loaded_) {
    std::string message;
    if (timeline_.resume(*sim_, *p.timeline.resume, &message)) {
      maxStrain_.clear();
      paused_ = true;
      resumed = true;
      event(SimEvent::Kind::Resumed, ticket, message);
    } else {
      event(SimEvent::Kind::ResumeFailed, ticket, message);
    }
  }
  if (p.timeline.keepA && loaded_) timeline_.keepAsA(*sim_);
  if (p.timeline.budget || p.timeline.keepA)
    timeline_.setBudget(p.timeline.budget ? *p.timeline.budget : timeline_.budget());
  if (p.timeline.showA) timeline_.showA(*p.timeline.showA);
  if (p.timeline.exportRange && loaded_) {
    const auto& [dir, range] = *p.timeline.exportRange;
    std::string message;
    const bool ok = timeline_.exportFrames(*sim_, dir, range.first, range.second, &message);
    event(ok ? SimEvent::Kind::Exported : SimEvent::Kind::ExportFailed, ticket, message);
  }
  if (p.timeline.bake && loaded_ && timeline_.bake(*p.timeline.bake)) paused_ = false;
  return resumed;
}

bool SimThread::canStep() const {
  if (!loaded_ || sim_->stopped() || timeline_.showing()) return false;
  if (options_.frameLimit >= 0 && sim_->frame() >= options_.frameLimit) return false;
  return !paused_ || steps_ > 0;
}

void SimThread::stepFrame() {
  if (paused_ && steps_ > 0) --steps_;
  sim_->stepFrame();
  if (timeline_.stepped(*sim_)) paused_ = true;  // a bake's last frame
  std::vector<FrameSample> samples = sim_->takeSamples();
  for (const FrameSample& s : samples) maxStrain_.push(float(s.accuracy.maxStrain));
  if (options_.recordMetrics) {
    std::lock_guard lock(mutex_);
    metricsLog_.addFrame(sim_->lastStepMs(), sim_->diagnostics().stageTimes());
    for (const FrameSample& s : samples) metricsLog_.addSample(s);
  }
  // canStep() held before this step, so a stop now is new.
  if (sim_->stopped()) {
    event(SimEvent::Kind::Nan, applied_,
          "the simulation produced NaN at frame " + std::to_string(sim_->nanFrame()) + " (" +
              std::to_string(sim_->nanParticles()) + " particles)");
  }
}

std::string SimThread::counts() const {
  return std::to_string(sim_->counts().strands) + " strands, " +
         std::to_string(sim_->counts().particles) + " particles";
}

void SimThread::event(SimEvent::Kind kind, long ticket, std::string text) {
  std::lock_guard lock(mutex_);
  events_.push_back({kind, ticket, std::move(text)});
}

void SimThread::publish(long ticket) {
  auto f = std::make_shared<SimFrame>();
  f->ticket = ticket;
  f->loaded = loaded_;
  // takeFigures names a loaded scene's solver with its other figures; before a scene loads the
  // panels name it all the same.
  if (!loaded_) {
    f->solver = std::string(sim_->solverName());
    f->solverVariant = sim_->diagnostics().variant();
  }
  if (loaded_) {
    takeFigures(*sim_, *f);
    f->frame = sim_->frame();
    f->time = sim_->time();
    f->generation = sim_->generation();
    f->groom = sim_->sharedGroom();
    f->followers = sim_->sharedFollowers();
    f->head = sim_->sharedHead();
    f->headPose = sim_->headPose();
    f->torsoPose = sim_->torsoPose();
    f->stepMs = sim_->lastStepMs();
    f->stages = sim_->diagnostics().stageTimes();
    f->sample = sim_->latestSample();
    f->maxStrain = maxStrain_;
    f->nanFrame = sim_->nanFrame();
    f->nanParticles = sim_->nanParticles();
    f->idle = !canStep();
    f->timeline = timeline_.status(*sim_);
    const FrameRecording::Shown* shown = timeline_.shownFrame();
    const unsigned buffer = gl_ ? sim_->positionBuffer() : 0;
    if (shown) {
      // A recorded frame on show: its positions, time and head instead of the live ones.
      f->frame = shown->frame;
      f->time = shown->time;
      f->headPose = shown->head;
      f->torsoPose = sim_->bodyPoseAt(shown->time).torso;
      auto host = std::make_shared<std::vector<glm::vec4>>();
      host->reserve(shown->positions.size());
      for (const glm::vec3& x : shown->positions) host->emplace_back(x, 1.0f);
      f->hostPositions = std::move(host);
    } else if (buffer != 0 && f->particles > 0) {
      f->slot = buffers_.write(buffer, f->particles * sizeof(glm::vec4));
      f->positionBuffer = buffers_.buffer(f->slot);
    } else {
      auto host = std::make_shared<std::vector<glm::vec4>>();
      sim_->readPositions(*host);
      f->hostPositions = std::move(host);
    }
  }
  {
    std::lock_guard lock(mutex_);
    f->serial = ++serial_;
    if (f->slot >= 0) buffers_.publish(f->slot);
    latest_ = std::move(f);
  }
  published_.notify_all();
  if (options_.wake) options_.wake();
}

// --- Commands ------------------------------------------------------------------------------

long SimThread::post(const std::function<void(Pending&, long)>& edit) {
  long ticket;
  {
    std::lock_guard lock(mutex_);
    ticket = ++posted_;
    pending_.posted = true;
    edit(pending_, ticket);
  }
  wakeThread_.notify_all();
  return ticket;
}

long SimThread::open(const Config& config, const std::string& baseDir,
                     std::shared_ptr<const HeadModel> head) {
  return post([&](Pending& p, long ticket) {
    // A new scene makes what was posted for the old one moot.
    p.config.reset();
    p.configTicket = 0;
    p.reset = false;
    p.userPose.reset();
    p.open = OpenScene{config, baseDir, std::move(head)};
    p.openTicket = ticket;
  });
}

long SimThread::setConfig(const Config& config) {
  return post([&](Pending& p, long ticket) {
    p.config = config;
    p.configTicket = ticket;
  });
}

long SimThread::reset() {
  return post([](Pending& p, long) { p.reset = true; });
}

long SimThread::setUserPose(const Pose& pose) {
  return post([&](Pending& p, long) { p.userPose = pose; });
}

long SimThread::setPaused(bool paused) {
  return post([&](Pending& p, long) { p.paused = paused; });
}

long SimThread::step() {
  return post([](Pending& p, long) { ++p.steps; });
}

long SimThread::setRecording(bool on) {
  return post([&](Pending& p, long) { p.timeline.recording = on; });
}

long SimThread::setCacheBudget(size_t bytes) {
  return post([&](Pending& p, long) { p.timeline.budget = bytes; });
}

long SimThread::show(long frame) {
  return post([&](Pending& p, long) { p.timeline.show = frame; });
}

long SimThread::resume(long frame) {
  return post([&](Pending& p, long) {
    p.timeline.show.reset();
    p.timeline.resume = frame;
  });
}

long SimThread::bake(long frames) {
  return post([&](Pending& p, long) { p.timeline.bake = frames; });
}

long SimThread::exportRecorded(const std::string& dir, long first, long last) {
  return post([&](Pending& p, long) {
    p.timeline.exportRange = std::make_pair(dir, std::make_pair(first, last));
  });
}

long SimThread::openShot(const std::string& dir, long frames, size_t particles) {
  return post([&](Pending& p, long) {
    p.timeline.shot = TimelineEdits::Shot{dir, frames, particles};
    p.timeline.show = frames > 0 ? 1 : -1;
  });
}

long SimThread::keepAsA() {
  return post([](Pending& p, long) { p.timeline.keepA = true; });
}

long SimThread::showA(bool on) {
  return post([&](Pending& p, long) { p.timeline.showA = on; });
}

long SimThread::latestSerial() const {
  std::lock_guard lock(mutex_);
  return latest_ ? latest_->serial : 0;
}

long SimThread::ticket() const {
  std::lock_guard lock(mutex_);
  return posted_;
}

bool SimThread::sync(double timeoutSeconds) {
  return waitForTicket(ticket(), timeoutSeconds);
}

bool SimThread::waitForTicket(long ticket, double timeoutSeconds) {
  std::unique_lock lock(mutex_);
  return published_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [&] {
    return !running_ || (latest_ && latest_->ticket >= ticket);
  }) && running_;
}

bool SimThread::waitFor(const std::function<bool(const SimFrame&)>& done, double timeoutSeconds) {
  if (!sync(timeoutSeconds)) return false;
  std::unique_lock lock(mutex_);
  return published_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [&] {
    // Nothing more will come when the thread is idle (paused with no step asked for, stopped
    // on NaN, at the limit) and no command is waiting.
    return !running_ || done(*latest_) || (latest_->idle && !pending_.any());
  });
}

// --- The UI's side -------------------------------------------------------------------------

std::shared_ptr<const SimFrame> SimThread::acquire() {
  std::lock_guard lock(mutex_);
  if (latest_) buffers_.hold(latest_->slot);
  return latest_;
}

void SimThread::drawn() {
  buffers_.drawn();
}

std::vector<SimEvent> SimThread::takeEvents() {
  std::lock_guard lock(mutex_);
  std::vector<SimEvent> out;
  out.swap(events_);
  return out;
}

MetricsLog SimThread::metrics() const {
  std::lock_guard lock(mutex_);
  return metricsLog_;
}

}  // namespace csm
