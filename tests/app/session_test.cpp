// The viewer's logic without a window (app/viewer_session.h): what a panel edit, a preset load,
// a save, a revert and the timeline's commands do to the running scene, on the CPU solver, with
// no display, no GL and no renderer. The window's tests (tests/window/) check the same through
// the pixels under Xvfb; these run in the quick tier.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "app/cache_run.h"
#include "app/headless.h"
#include "app/preset.h"
#include "app/shot_cache.h"
#include "app/viewer_session.h"
#include "sim/groom/cyhair.h"
#include "sim/run/cache_files.h"
#include "sim/run/make_solver.h"
#include "tests/app/app_fixture.h"
#include "tests/test_solvers.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = CSM_SOURCE_DIR;

fs::path tempDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("csm_session_test_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

using test::makeSession;

Preset smallPreset(int strands = 150) {
  return test::smallPreset(strands);
}

bool said(const ViewerSession& s, const std::string& start) {
  return std::any_of(s.messages().begin(), s.messages().end(),
                     [&](const ViewerMessage& m) { return m.text.rfind(start, 0) == 0; });
}

std::vector<glm::vec4> positionsShown(const ViewerSession& s) {
  REQUIRE(s.simFrame().hostPositions);
  return *s.simFrame().hostPositions;
}

}  // namespace

TEST_CASE("Session: a preset opens, a live edit takes effect and a Rebuild one regrows",
          "[app][session][quick]") {
  std::unique_ptr<ViewerSession> s = makeSession();
  std::string error;
  REQUIRE(s->open(smallPreset(), "", "", &error));
  REQUIRE(s->waitForSimFrame(3));
  CHECK(s->simFrame().loaded);
  CHECK(s->simFrame().strands == 150);
  CHECK(said(*s, "opened the built-in preset: 150 strands"));
  const long generation = s->simFrame().generation;
  const double t = s->simFrame().time;

  // Live: the wind, through the one setter, reaches the simulation between frames.
  REQUIRE(s->setParam("wind.strength", "6"));
  REQUIRE(s->sync());
  CHECK(s->simFrame().config.wind.strength == 6.0f);
  CHECK(s->simFrame().generation == generation);
  CHECK(s->simFrame().time >= t);
  CHECK(s->document().modified());
  const auto keys = s->document().modifiedKeys();
  CHECK(std::find(keys.begin(), keys.end(), "wind.strength") != keys.end());

  // Rebuild: the strand count regrows the hair, said in the messages; the clock runs on.
  REQUIRE(s->setParam("hairstyle.strands", "90"));
  REQUIRE(s->sync());
  CHECK(s->simFrame().strands == 90);
  CHECK(s->simFrame().generation > generation);
  CHECK(said(*s, "regrew the hair: 90 strands"));

  // The camera is the view's: the scene does not change, the document does.
  REQUIRE(s->setParam("camera.yaw", "40"));
  CHECK(s->document().current().view.camera.yaw == 40.0f);
  // An edited copy applied as the panels apply it.
  Preset& edited = s->editedPreset();
  edited.scene.sim.damping = 2.5f;
  REQUIRE(s->applyConfig(Preset(edited)));
  REQUIRE(s->sync());
  CHECK(s->simFrame().config.sim.damping == 2.5f);
}

TEST_CASE("Session: a value the scene cannot take is refused, the widgets show what runs",
          "[app][session][quick]") {
  std::unique_ptr<ViewerSession> s = makeSession();
  std::string error;
  REQUIRE(s->open(smallPreset(), "", "", &error));
  REQUIRE(s->sync());
  const int before = s->simFrame().config.hairstyle.minParticles;
  CHECK_FALSE(s->setParam("hairstyle.min_particles", "40", &error));
  CHECK(error.find("not applied") != std::string::npos);
  REQUIRE(s->sync());
  CHECK(s->simFrame().config.hairstyle.minParticles == before);
  CHECK(s->document().current().scene.hairstyle.minParticles == before);
  CHECK(s->document().edited().scene.hairstyle.minParticles == before);
  // Not a value at all, and not a parameter: said with the key.
  CHECK_FALSE(s->setParam("wind.strength", "strong", &error));
  CHECK(error.find("wind.strength=strong") != std::string::npos);
  CHECK_FALSE(s->setParam("wind.strenght", "3", &error));
  CHECK(error.find("unknown parameter") != std::string::npos);
}

TEST_CASE("Session: a broken preset file is refused with its messages, the scene runs on",
          "[app][session][quick]") {
  const fs::path dir = tempDir("broken");
  std::unique_ptr<ViewerSession> s = makeSession();
  std::string error;
  REQUIRE(s->open(smallPreset(120), "", "", &error));
  REQUIRE(s->sync());
  const fs::path broken = dir / "broken.json";
  std::ofstream(broken) << R"({"sim": {"substeps": 0}, "wind": {"strenght": 3}})";
  CHECK_FALSE(s->loadPreset(broken.string()));
  std::string all;
  for (const std::string& m : s->presetErrors()) all += m + "\n";
  INFO(all);
  CHECK(all.find("sim.substeps") != std::string::npos);
  CHECK(all.find("strenght") != std::string::npos);
  CHECK(all.find("broken.json") != std::string::npos);
  CHECK(s->presetErrorsNote().find("not loaded") != std::string::npos);
  REQUIRE(s->sync());
  CHECK(s->simFrame().strands == 120);
  s->dismissPresetErrors();
  CHECK(s->presetErrors().empty());

  // A preset of the tree loads, replacing the scene once it runs.
  REQUIRE(s->loadPreset((kSource / "presets/short_shake.json").string()));
  CHECK(s->loading());
  REQUIRE(s->sync());
  CHECK_FALSE(s->loading());
  CHECK(s->document().path() == (kSource / "presets/short_shake.json").string());
  CHECK(s->simFrame().strands == 6000);
  fs::remove_all(dir);
}

TEST_CASE("Session: save as writes the preset whole, revert goes back to it",
          "[app][session][quick]") {
  const fs::path dir = tempDir("save");
  std::unique_ptr<ViewerSession> s = makeSession();
  std::string error;
  REQUIRE(s->open(smallPreset(200), "", "", &error));
  // The built-in preset has no file to save over.
  CHECK_FALSE(s->save());
  CHECK(said(*s, "the built-in preset has no file"));
  REQUIRE(s->setParam("wind.gusts", "1.25"));
  CHECK(s->document().modified());
  const fs::path out = dir / "mine.json";
  REQUIRE(s->saveAs(out.string()));
  CHECK_FALSE(s->document().modified());
  CHECK(s->document().path() == out.string());
  Preset back = defaultPreset();
  PresetErrors errors;
  REQUIRE(loadPreset(out.string(), back, errors));
  CHECK(back.scene.wind.gusts == 1.25f);
  CHECK(back.scene.hairstyle.strands == 200);
  // Nothing but the preset is left in the folder (written beside it and renamed).
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);

  // An edit, then revert: back to what was saved, in the simulation too.
  REQUIRE(s->setParam("sim.damping", "3"));
  REQUIRE(s->sync());
  CHECK(s->simFrame().config.sim.damping == 3.0f);
  s->revert();
  REQUIRE(s->sync());
  CHECK(s->simFrame().config.sim.damping == back.scene.sim.damping);
  CHECK(said(*s, "reverted to the loaded preset"));
  // Save over the opened file now works; a folder that cannot be written says why.
  REQUIRE(s->setParam("wind.gusts", "0.5"));
  REQUIRE(s->save());
  CHECK_FALSE(s->saveAs((dir / "no_such_folder" / "x.json").string()));
  CHECK(said(*s, "save failed"));
  fs::remove_all(dir);
}

TEST_CASE("Session: the stiffness window changes live, a capped stiffness is said once",
          "[app][session][quick]") {
  std::unique_ptr<ViewerSession> s = makeSession();
  REQUIRE(s->loadPreset((kSource / "presets/default.json").string()));
  REQUIRE(s->sync());
  REQUIRE(s->setParam("hairstyle.strands", "300"));
  REQUIRE(s->waitForSimFrame(s->simFrame().frame + 2));
  const long generation = s->simFrame().generation;
  const StiffnessInfo before = s->simFrame().stiffness;
  CHECK(before.model == StiffnessModel::Calibrated);
  CHECK(before.windowMax == 2);  // 4 cm on 2 cm segments
  CHECK(before.plan.substeps == 4);
  CHECK_FALSE(before.plan.capped);

  // Half the window: one particle a side, a stiffer rate, more steps; live, not regrown.
  REQUIRE(s->setParam("sim.window_length", "0.02"));
  REQUIRE(s->sync());
  const StiffnessInfo half = s->simFrame().stiffness;
  CHECK(s->simFrame().generation == generation);
  CHECK(half.windowMax == 1);
  CHECK(half.rateMax > 10.0 * before.rateMax);
  CHECK(half.plan.substeps > before.plan.substeps);
  // It asks for 16 steps: the default step budget (8) binds, said in the log once.
  CHECK(half.plan.wanted > 8);
  CHECK(half.plan.substeps == 8);
  CHECK(half.plan.capped);
  REQUIRE(s->waitForSimFrame(s->simFrame().frame + 2));
  auto warnings = [&] {
    return std::count_if(s->messages().begin(), s->messages().end(), [](const ViewerMessage& m) {
      return m.level == MessageLevel::Warning && m.text.find("max_substeps") != std::string::npos;
    });
  };
  CHECK(warnings() == 1);

  // A lower budget: a warning in the log, once.
  REQUIRE(s->setParam("sim.max_substeps", "5"));
  REQUIRE(s->sync());
  CHECK(s->simFrame().stiffness.plan.capped);
  CHECK(s->simFrame().stiffness.plan.substeps == 5);
  CHECK(warnings() == 2);
  REQUIRE(s->setParam("wind.strength", "2"));  // another live change: no second warning
  REQUIRE(s->sync());
  CHECK(warnings() == 2);

  // The paper model takes its window in particles and sim.substeps as they are.
  REQUIRE(s->setParam("sim.stiffness_model", "paper"));
  REQUIRE(s->sync());
  const StiffnessInfo paper = s->simFrame().stiffness;
  CHECK(paper.model == StiffnessModel::Paper);
  CHECK(paper.plan.substeps == s->simFrame().config.sim.substeps);
  CHECK(paper.windowMax == s->simFrame().config.sim.stiffnessWindow);
}

TEST_CASE("Session: the timeline shows, resumes bit for bit, bakes, exports and runs B",
          "[app][session][timeline][quick]") {
  const fs::path dir = tempDir("timeline");
  std::unique_ptr<ViewerSession> s = makeSession(20);
  Preset p = smallPreset(100);
  p.scene.head.amplitude = 30.0f;  // a nod that moves the hair between frames
  std::string error;
  REQUIRE(s->open(p, "", "", &error));
  REQUIRE(s->waitForSimFrame(20));
  REQUIRE(s->sync());
  const TimelineStatus& t = s->simFrame().timeline;
  CHECK(s->simFrame().frame == 20);
  CHECK(t.first == 0);
  CHECK(t.last == 20);
  const std::vector<glm::vec4> live20 = positionsShown(*s);

  // A recorded frame on show: its positions, the simulation still at 20.
  SimControls& c = s->controls();
  c.showRecorded(8);
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == 8);
  CHECK(s->simFrame().frame == 8);
  CHECK(s->simFrame().timeline.live == 20);
  const std::vector<glm::vec4> at8 = positionsShown(*s);
  CHECK(at8 != live20);
  c.showRecorded(20);
  REQUIRE(s->sync());
  CHECK(positionsShown(*s) == live20);

  // Resumed from 8 and run to the limit again: frame 20 to the bit.
  c.resumeFrom(8);
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == -1);
  CHECK(s->simFrame().frame == 8);
  CHECK(c.paused());
  CHECK(said(*s, "resumed from frame 8"));
  CHECK(positionsShown(*s) == at8);
  c.setPaused(false);
  REQUIRE(s->waitForSimFrame(20));
  REQUIRE(s->sync());
  CHECK(s->simFrame().frame == 20);
  CHECK(positionsShown(*s) == live20);

  // A bake of 5 frames from 10, then paused.
  c.resumeFrom(10);
  REQUIRE(s->sync());
  c.bake(5.0 / 60.0);
  REQUIRE(s->waitForSimFrame(15));
  REQUIRE(s->sync());
  CHECK(s->simFrame().frame == 15);
  CHECK(s->simFrame().timeline.last == 15);
  CHECK(s->simFrame().idle);

  // The recording out as cyHair, a file a frame.
  const fs::path seq = dir / "seq";
  c.exportRecorded(seq.string(), 0, 15);
  REQUIRE(s->sync());
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(seq)) files += e.path().extension() == ".hair";
  CHECK(files == 16);
  const io::GroomReadResult last = io::readCyHair((seq / "frame_00016.hair").string());
  REQUIRE(last.groom);
  CHECK(last.groom->strandCount() == 100);
  CHECK(said(*s, "wrote frames 0-15 as 16 cyHair files"));

  // A/B: A kept, B with a strong wind over A's frames, the toggle between the two.
  c.keepAsA();
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.aFirst == 0);
  CHECK(s->simFrame().timeline.aLast == 15);
  c.showRecorded(15);
  REQUIRE(s->sync());
  const std::vector<glm::vec4> a15 = positionsShown(*s);
  REQUIRE(s->setParam("wind.strength", "14", &error));
  CHECK(c.keysChangedSinceA() == std::vector<std::string_view>{"wind.strength"});
  c.rerunFromA();
  REQUIRE(s->waitForSimFrame(15));
  REQUIRE(s->sync());
  c.showRecorded(15);
  REQUIRE(s->sync());
  const std::vector<glm::vec4> b15 = positionsShown(*s);
  CHECK(b15 != a15);
  c.showA(true);
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.showingA);
  CHECK(positionsShown(*s) == a15);
  c.showA(false);
  REQUIRE(s->sync());
  CHECK(positionsShown(*s) == b15);
  fs::remove_all(dir);
}

TEST_CASE("Session: a shot's cache opens on the timeline and scrubs, its frames as baked",
          "[app][session][timeline][cache][quick]") {
  const fs::path dir = tempDir("shot");
  SceneSetup baked;
  baked.preset = smallPreset(60);
  baked.preset.scene.head.amplitude = 30.0f;
  baked.source = "<test>";
  Options bake;
  bake.headless = true;
  bake.quiet = true;
  bake.solver = "cpu";
  bake.frames = 10;
  bake.noRender = true;
  bake.bake = (dir / "cache").string();
  REQUIRE(runHeadless(bake, baked) == 0);

  Options open;
  open.fromCache = bake.bake;
  CacheManifest m;
  SceneSetup scene;
  std::string error;
  REQUIRE(sceneFromCache(open.fromCache, open, m, scene, &error));
  std::unique_ptr<ViewerSession> s = makeSession(2);
  REQUIRE(s->open(scene.preset, scene.baseDir, "", &error, scene.head));
  REQUIRE(s->waitForSimFrame(2));
  s->openShot(open.fromCache, shot_cache::completeFrames(open.fromCache, m), m.particles);
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shotFrames == 10);
  CHECK(s->simFrame().timeline.shown == 1);  // the shot's first frame on show
  CHECK(s->simFrame().timeline.first == 0);
  CHECK(s->simFrame().timeline.last == 10);
  // Scrubbed to frames the simulation never ran (it stopped at 2): the cache's positions.
  for (long f : {7L, 10L, 4L}) {
    s->controls().showRecorded(f);
    REQUIRE(s->sync());
    CHECK(s->simFrame().timeline.shown == f);
    FrameRecording::Shown cached;
    REQUIRE(
        cache::readFrame(shot_cache::framePath(open.fromCache, f), f, m.particles, cached, &error));
    const std::vector<glm::vec4> shown = positionsShown(*s);
    REQUIRE(shown.size() == cached.positions.size());
    bool same = true;
    for (size_t i = 0; i < shown.size(); ++i)
      same = same && glm::vec3(shown[i]) == cached.positions[i];
    CHECK(same);
  }
  // Frame 2 is the simulation's own recording: the same as baked (one solver, deterministic).
  s->controls().showRecorded(2);
  REQUIRE(s->sync());
  FrameRecording::Shown cached2;
  REQUIRE(
      cache::readFrame(shot_cache::framePath(open.fromCache, 2), 2, m.particles, cached2, &error));
  const std::vector<glm::vec4> at2 = positionsShown(*s);
  REQUIRE(at2.size() == cached2.positions.size());
  CHECK(glm::vec3(at2[100]) == cached2.positions[100]);
  // A frame beyond the shot: live again.
  s->controls().showRecorded(11);
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == -1);
  fs::remove_all(dir);
}

TEST_CASE("Session: NaN from the simulation pauses it and says so, a reset clears it",
          "[app][session][quick]") {
  std::unique_ptr<ViewerSession> s = makeSession(-1, [](const std::string&, std::string*) {
    return std::unique_ptr<Solver>(new test::NanAfter(4));
  });
  std::string error;
  REQUIRE(s->open(smallPreset(100), "", "", &error));
  REQUIRE(s->waitForSimFrame(40));
  CHECK(s->controls().nanStopped());
  CHECK(s->controls().paused());
  CHECK(s->simFrame().nanFrame >= 4);
  CHECK(said(*s, "the simulation produced NaN at frame"));
  const long frame = s->simFrame().frame;
  CHECK(frame < 40);
  REQUIRE(s->sync());
  CHECK(s->simFrame().frame == frame);  // stopped: no garbage steps
  s->controls().resetHair();
  REQUIRE(s->sync());
  CHECK_FALSE(s->controls().nanStopped());
}

TEST_CASE("Session: edits queue while a frame runs and land between frames",
          "[app][session][quick]") {
  auto gate = std::make_shared<test::GatedSolver::Gate>();
  struct Opener {  // lets the frames through at the end, or the thread would wait for good
    test::GatedSolver::Gate& g;
    ~Opener() { test::allow(g, 1000000); }
  };
  std::unique_ptr<ViewerSession> s = makeSession(-1, [gate](const std::string&, std::string*) {
    return std::unique_ptr<Solver>(new test::GatedSolver(gate));
  });
  const Opener opener{*gate};
  std::string error;
  REQUIRE(s->open(smallPreset(100), "", "", &error));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (gate->started < 1 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::yield();
  REQUIRE(gate->started == 1);
  // The thread is inside its first frame: the session still takes edits, the view's at once.
  REQUIRE(s->setParam("camera.yaw", "75"));
  REQUIRE(s->setParam("wind.strength", "3"));
  s->update();
  CHECK(s->document().current().view.camera.yaw == 75.0f);
  CHECK(s->simFrame().frame == 0);
  CHECK(s->simFrame().config.wind.strength != 3.0f);
  test::allow(*gate, 3);
  REQUIRE(s->waitForSimFrame(3));
  CHECK(s->simFrame().frame == 3);
  CHECK(s->simFrame().config.wind.strength == 3.0f);
}
