// The CPU and GPU solvers under a motion clip (sim/motion): a jerky Z-up dance at 60 fps (its head
// pops, the hips bounce) and a run that starts at 4.5 m/s, sampled at every substep, travel
// included, agree as they do under the procedural motions (tests/gpu/gpu_solver_test.cpp's
// tolerance: 1e-4 m, a tenth of the hair's radius).
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "sim/run/make_solver.h"
#include "sim/run/simulation.h"
#include "tests/cpu/test_scenes.h"
#include "tests/gpu/gl_fixture.h"

namespace csm {
namespace {

std::vector<glm::vec4> run(const std::string& solver, const Config& c, int frames) {
  std::string error;
  std::unique_ptr<Simulation> sim = makeSimulation(solver, &error);
  INFO(error);
  REQUIRE(sim);
  REQUIRE(sim->load(c, CSM_CLIP_DIR, &error));
  for (int f = 0; f < frames; ++f) sim->stepFrame();
  std::vector<glm::vec4> x;
  sim->readPositions(x);
  return x;
}

TEST_CASE("GPU and CPU solvers agree under a motion clip", "[gpu][solver][motion]") {
  test::glContext();
  for (const char* clip : {"dance_zup.bvh", "run_6ch.bvh"}) {
    Config c = test::smallScene(200);
    c.collision.mode = CollisionMode::Off;
    c.motion.clip = clip;
    const std::vector<glm::vec4> cpu = run("cpu", c, 30), gpu = run("gpu", c, 30);
    REQUIRE(cpu.size() == gpu.size());
    double worst = 0.0, travel = 0.0;
    for (size_t i = 0; i < cpu.size(); ++i) {
      worst = std::max(worst, double(glm::length(glm::vec3(cpu[i]) - glm::vec3(gpu[i]))));
      travel = std::max(travel, double(std::abs(cpu[i].x)) + std::abs(cpu[i].z));
    }
    INFO(clip << ": the largest difference " << worst << " m");
    CHECK(worst < 1e-4);
    // The clip moved the hair (the run 2 m forward in half a second).
    if (std::string(clip) == "run_6ch.bvh") CHECK(travel > 1.5);
  }
}

}  // namespace
}  // namespace csm
