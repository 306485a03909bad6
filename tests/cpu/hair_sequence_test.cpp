// The hair sequence export (sim/groom/hair_sequence.h): each frame written reopens with the
// points the solver had then, the same strands in every frame.
#include <filesystem>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/solver/cpu_solver.h"
#include "sim/groom/cyhair.h"
#include "sim/groom/hair_sequence.h"
#include "sim/run/simulation.h"
#include "tests/cpu/test_scenes.h"

using namespace csm;

TEST_CASE("Hair sequence: every frame reopens with the solver's points of that frame",
          "[io][sequence][quick]") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "csm_hair_sequence_test";
  std::filesystem::remove_all(dir);
  std::string error;
  REQUIRE(io::prepareSequenceDir(dir.string(), &error));

  Config c = test::smallScene(40);
  c.head.motion = HeadMotion::Nod;
  Simulation sim(std::make_unique<CpuSolver>());
  REQUIRE(sim.load(c, ".", &error));
  std::vector<std::vector<glm::vec4>> frames;
  for (long f = 1; f <= 4; ++f) {
    sim.stepFrame();
    std::vector<glm::vec4> x;
    sim.readPositions(x);
    INFO(error);
    REQUIRE(io::writeSequenceFrame(dir.string(), f, sim.groom(), x, &error));
    frames.push_back(std::move(x));
  }
  for (long f = 1; f <= 4; ++f) {
    const std::filesystem::path path = dir / io::sequenceFrameName(f);
    INFO(path.string());
    const io::GroomReadResult r = io::readCyHair(path.string());
    REQUIRE(r.groom);
    CHECK(r.groom->first == sim.groom().first);
    const std::vector<glm::vec4>& x = frames[size_t(f - 1)];
    REQUIRE(r.groom->points.size() == x.size());
    size_t differ = 0;
    for (size_t i = 0; i < x.size(); ++i) differ += r.groom->points[i] != glm::vec3(x[i]);
    CHECK(differ == 0);
  }
  // The frames differ: the head nods.
  CHECK(frames.front() != frames.back());
  CHECK(io::sequenceFrameName(12345) == "frame_12345.hair");

  // A frame that does not match the groom is refused, and nothing is written.
  std::vector<glm::vec4> wrong(frames[0].begin(), frames[0].end() - 1);
  CHECK_FALSE(io::writeSequenceFrame(dir.string(), 9, sim.groom(), wrong, &error));
  CHECK_THAT(error, Catch::Contains("frame 9 has"));
  CHECK_FALSE(std::filesystem::exists(dir / io::sequenceFrameName(9)));
  std::filesystem::remove_all(dir);
}
