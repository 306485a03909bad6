#include "app/viewer_session.h"

#include <cstdio>
#include <filesystem>

#include "app/camera_control.h"
#include "app/params.h"
#include "app/preset.h"
#include "sim/run/make_solver.h"
#include "sim/param/sim_params.h"
#include "sim/run/scene_checks.h"
#include "sim/solver/stiffness.h"

namespace csm {

std::unique_ptr<ViewerSession> ViewerSession::create(SessionOptions options, std::string* error) {
  std::unique_ptr<ViewerSession> s(new ViewerSession());
  s->quiet_ = options.quiet;
  s->uiThread_ = std::this_thread::get_id();
  SimThread::Options so;
  so.makeSolver = options.makeSolver ? std::move(options.makeSolver) : SolverByName(makeSolver);
  so.solver = options.solver;
  so.paced = options.paced;
  so.frameLimit = options.frameLimit;
  so.recordMetrics = options.recordMetrics;
  so.wake = std::move(options.wake);
  // The first scene opens before the window shows: its import says where it stands on stderr.
  so.sayImportProgress = !options.quiet;
  so.context = std::move(options.context);
  SimThread::Started started;
  s->sim_ = SimThread::start(std::move(so), &started, error);
  if (!s->sim_) return nullptr;
  if (!started.warning.empty()) s->log(MessageLevel::Warning, started.warning);
  s->controls_ = std::make_unique<SimControls>(
      *s->sim_, s->frame_, s->doc_,
      [raw = s.get()](MessageLevel level, std::string text) { raw->log(level, std::move(text)); });
  s->update();
  return s;
}

ViewerSession::~ViewerSession() {
  // The commands' controls first, then the thread (it uses the shared context).
  controls_.reset();
  sim_.reset();
}

void ViewerSession::log(MessageLevel level, std::string text) {
  if (!quiet_ && level != MessageLevel::Info) std::fprintf(stderr, "csmhair: %s\n", text.c_str());
  ViewerMessage m{level, std::move(text), std::chrono::steady_clock::now()};
  if (std::this_thread::get_id() != uiThread_) {
    std::lock_guard lock(inboxMutex_);
    inbox_.push_back(std::move(m));
    return;
  }
  messages_.push_back(std::move(m));
  if (messages_.size() > 200) messages_.erase(messages_.begin(), messages_.begin() + 100);
}

void ViewerSession::drainInbox() {
  std::vector<ViewerMessage> in;
  {
    std::lock_guard lock(inboxMutex_);
    in.swap(inbox_);
  }
  for (ViewerMessage& m : in) messages_.push_back(std::move(m));
  if (messages_.size() > 200) messages_.erase(messages_.begin(), messages_.begin() + 100);
}

void ViewerSession::changed() {
  if (changed_) changed_();
}

// --- The simulation's frames ---------------------------------------------------------------

void ViewerSession::update() {
  // Events first: the frame taken after them is at least as new as each.
  const std::vector<SimEvent> events = sim_->takeEvents();
  if (std::shared_ptr<const SimFrame> f = sim_->acquire()) frame_ = std::move(f);
  for (const SimEvent& e : events) handle(e);
  drainInbox();
  checkStiffness();
}

void ViewerSession::handle(const SimEvent& e) {
  switch (e.kind) {
    case SimEvent::Kind::Opened:
      if (pendingOpen_ && pendingOpen_->ticket == e.ticket) {
        doc_.opened(pendingOpen_->preset, pendingOpen_->path);
        pendingOpen_.reset();
        userPose_ = Pose{};
        changed();
        log(MessageLevel::Info, "opened " +
                                    (doc_.path().empty() ? "the built-in preset" : doc_.path()) +
                                    ": " + e.text);
        stiffnessWarning_.clear();
      }
      break;
    case SimEvent::Kind::OpenFailed:
      if (pendingOpen_ && pendingOpen_->ticket == e.ticket) {
        const std::string what = pendingOpen_->path.empty() ? "the preset" : pendingOpen_->path;
        openError_ = e.text;
        presetErrors_ = {what + ": " + e.text};
        presetErrorsNote_ = "not loaded; the scene shown is the one that was running";
        log(MessageLevel::Error, what + ": " + e.text);
        pendingOpen_.reset();
      }
      break;
    case SimEvent::Kind::ConfigRefused:
      // The frames carry the config that still runs: the widgets show it again.
      log(MessageLevel::Error, "not applied: " + e.text);
      {
        Preset running = doc_.current();
        running.scene = frame_->config;
        doc_.applied(running);
      }
      changed();
      break;
    case SimEvent::Kind::Regrew:
      log(MessageLevel::Info, "regrew the hair: " + e.text);
      break;
    case SimEvent::Kind::Resumed:
      log(MessageLevel::Info, e.text + "; paused (Space goes on)");
      break;
    case SimEvent::Kind::ResumeFailed:
    case SimEvent::Kind::ExportFailed:
      log(MessageLevel::Error, e.text);
      break;
    case SimEvent::Kind::Exported:
      log(MessageLevel::Info, e.text);
      break;
    case SimEvent::Kind::Nan:
      if (controls_->current(e.ticket)) {
        controls_->setPaused(true);
        log(MessageLevel::Error, e.text + "; paused. R resets the hair to rest.");
      }
      break;
  }
}

bool ViewerSession::sync(double timeoutSeconds) {
  const bool ok = sim_->sync(timeoutSeconds);
  update();
  return ok;
}

bool ViewerSession::waitForSimFrame(long frame, double timeoutSeconds) {
  const bool ok =
      sim_->waitFor([frame](const SimFrame& f) { return f.frame >= frame; }, timeoutSeconds);
  update();
  return ok;
}

// --- The scene -------------------------------------------------------------------------

void ViewerSession::startOpen(const Preset& preset, const std::string& baseDir,
                              const std::string& path, std::shared_ptr<const HeadModel> head) {
  PendingOpen p;
  p.preset = preset;
  p.baseDir = baseDir;
  p.path = path;
  // Running, from the new scene's first frame on (posted first: the open is the last
  // command open() waits for).
  controls_->setPaused(false);
  p.ticket = sim_->open(preset.scene, baseDir, std::move(head));
  pendingOpen_ = std::move(p);
  // A NaN of the old scene goes with it.
  controls_->opened(pendingOpen_->ticket);
}

bool ViewerSession::open(const Preset& preset, const std::string& baseDir,
                         const std::string& presetPath, std::string* error,
                         std::shared_ptr<const HeadModel> head) {
  openError_.clear();
  startOpen(preset, baseDir, presetPath, std::move(head));
  const long ticket = pendingOpen_->ticket;
  const bool answered = sim_->waitForTicket(ticket);
  update();
  if (!answered) {
    if (error) *error = "the simulation thread did not answer";
    return false;
  }
  if (pendingOpen_ && pendingOpen_->ticket == ticket) {  // no event: cannot happen
    pendingOpen_.reset();
    if (error) *error = "the simulation did not open the preset";
    return false;
  }
  if (!openError_.empty()) {
    if (error) *error = openError_;
    // Said by the caller: not the preset problems window.
    presetErrors_.clear();
    return false;
  }
  return true;
}

void ViewerSession::openShot(const std::string& dir, long frames, size_t particles) {
  controls_->playRecording(false);
  sim_->waitForTicket(sim_->openShot(dir, frames, particles));
  update();
}

bool ViewerSession::loadPreset(const std::string& path) {
  Preset c = defaultPreset();
  PresetErrors errors;
  if (!csm::loadPreset(path, c, errors)) {
    presetErrors_ = errors.messages;
    presetErrorsNote_ = "not loaded; the scene shown is the one that was running";
    log(MessageLevel::Error, path + " is not a valid preset; the current scene stays");
    return false;
  }
  presetErrors_.clear();
  startOpen(c, std::filesystem::absolute(path).parent_path().string(), path);
  return true;
}

void ViewerSession::showPresetErrors(const std::string& text, const std::string& note) {
  presetErrors_.clear();
  presetErrorsNote_ = note;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) presetErrors_.push_back(text.substr(start, end - start));
    start = end + 1;
  }
}

bool ViewerSession::applyConfig(const Preset& next) {
  // Nothing is read from disk here: a changed head.mesh is read by the simulation thread as it
  // regrows, which refuses a bad one (ConfigRefused) and keeps the scene that runs.
  std::vector<std::string> problems = crossCheck(next.scene);
  const std::string capacity = checkCapacity(next.scene);
  if (!capacity.empty()) problems.push_back(capacity);
  if (!problems.empty()) {
    for (const std::string& p : problems) log(MessageLevel::Error, "not applied: " + p);
    doc_.discardEdits();  // the widgets show what runs
    return false;
  }
  const bool sceneChanged = !sameScene(doc_.current().scene, next.scene);
  if (sceneChanged && pendingOpen_) {
    // The edit would land on the preset being replaced; the view may change meanwhile.
    log(MessageLevel::Warning, "not applied: a preset is loading; change it once it shows");
    doc_.discardEdits();
    return false;
  }
  if (sceneChanged) sim_->setConfig(next.scene);
  doc_.applied(next);
  changed();
  return true;
}

void ViewerSession::checkStiffness() {
  if (!frame_->loaded) return;
  if (frame_->head && frame_->head->summary() != headSummary_) {
    headSummary_ = frame_->head->summary();
    if (!headSummary_.empty()) log(MessageLevel::Info, headSummary_);
  }
  if (const std::string groom = groomReportText(frame_->groomReport); groom != groomWarning_) {
    groomWarning_ = groom;
    if (!groom.empty()) log(MessageLevel::Warning, groom);
  }
  const std::string warning = stiffnessWarning(frame_->stiffness);
  if (warning == stiffnessWarning_) return;
  stiffnessWarning_ = warning;
  if (!warning.empty()) log(MessageLevel::Warning, warning);
}

bool ViewerSession::setParam(std::string_view key, std::string_view text, std::string* error) {
  const PresetParam* p = findParam(key);
  std::string why;
  if (!p) {
    why = std::string(key) + ": unknown parameter";
  } else {
    Preset next = doc_.current();
    why = paramFromText(*p, next, text);
    if (why.empty()) {
      if (applyConfig(next)) return true;
      // applyConfig has said why.
      if (error) *error = messages_.empty() ? "not applied" : messages_.back().text;
      return false;
    } else {
      why = std::string(key) + "=" + std::string(text) + ": " + why;
    }
  }
  log(MessageLevel::Error, why);
  if (error) *error = why;
  return false;
}

bool ViewerSession::save() {
  if (doc_.path().empty()) {
    log(MessageLevel::Warning, "the built-in preset has no file: use Save as");
    return false;
  }
  return saveAs(doc_.path());
}

bool ViewerSession::saveAs(const std::string& path) {
  std::string error;
  if (!doc_.saveAs(path, &error)) {
    log(MessageLevel::Error, "save failed: " + error);
    return false;
  }
  log(MessageLevel::Info, "saved " + path);
  changed();
  return true;
}

void ViewerSession::revert() {
  if (applyConfig(doc_.loaded())) log(MessageLevel::Info, "reverted to the loaded preset");
}

void ViewerSession::resetView() {
  Preset next = doc_.current();
  next.view.camera = doc_.loaded().view.camera;
  applyConfig(next);
}

void ViewerSession::frameHead() {
  if (!frame_->head) return;  // nothing loaded yet
  Preset next = doc_.current();
  csm::frameHead(next.view.camera, next.scene, *frame_->head, frame_->headPose);
  applyConfig(next);
}

void ViewerSession::dragHead(float dx, float dy) {
  userPose_ =
      csm::dragHead(userPose_, doc_.current().view.camera, doc_.current().scene.head, dx, dy);
  sim_->setUserPose(userPose_);
}

void ViewerSession::resetHead() {
  userPose_ = Pose{};
  sim_->setUserPose(userPose_);
}

}  // namespace csm
