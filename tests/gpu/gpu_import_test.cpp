// The flawed import of tests/import_cases.h on the GPU solver (float positions, the strain
// measured on the GPU), and a fur of tens of thousands of strands through the whole program's
// path: the file read, the scene loaded, simulated and drawn.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include "tests/gpu/gpu_solver_fixture.h"
#include "tests/gpu/render_test_scene.h"
#include "tests/import_cases.h"

TEST_CASE("GPU: the flawed groom's 30 frames", "[gpu][import]") {
  auto gpu = csm::test::gpuSolver();
  csm::test::checkImportedRun(*gpu, 1e-4);
}

TEST_CASE("GPU: TressFX 3.x and 4.x strands tied at both ends keep both with the nodding head",
          "[gpu][import][quick]") {
  for (int version : {3, 4}) {
    auto gpu = csm::test::gpuSolver();
    csm::test::checkHeldEnds(*gpu, 1e-6, version);
  }
}

TEST_CASE(
    "GPU: a ponytail's back tied at both ends, fitted through a larger head, stays within the "
    "strain limit while nodding",
    "[gpu][import][quick]") {
  auto gpu = csm::test::gpuSolver();
  csm::test::checkTiedPonytail(*gpu, 1e-4, 1e-6);
}

namespace {

// A fur-like TressFX 3.x file, as the bear fur of AMD's samples has it: `strands` short strands
// of 4 points on the upper cap of a 9 cm sphere, in centimetres, 1.5 to 2.5 cm long; then three
// degenerate strands: 7.5 um long, one point four times, a coordinate that is not a number.
std::string writeFur(const std::filesystem::path& path, uint32_t strands) {
  std::vector<float> pos;
  const double golden = 2.399963229728653;
  for (uint32_t s = 0; s < strands; ++s) {
    const double z = 1.0 - 1.1 * (s + 0.5) / strands;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = golden * s;
    const glm::dvec3 n(r * std::cos(phi), z, r * std::sin(phi));
    const double length = 1.5 + (s % 11) / 10.0;
    const glm::dvec3 root = glm::dvec3(0.0, 150.0, 0.0) + 9.0 * n;
    const glm::dvec3 dir = glm::normalize(n + glm::dvec3(0.0, -0.6, 0.0));
    for (int i = 0; i < 4; ++i) {
      const glm::dvec3 p = root + (length * i / 3.0) * dir;
      pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
    }
  }
  const float root[3] = {pos[0], pos[1], pos[2]};
  for (int i = 0; i < 4; ++i)  // 7.5 um
    pos.insert(pos.end(), {root[0] + 2.5e-4f * float(i), root[1], root[2]});
  for (int i = 0; i < 4; ++i) pos.insert(pos.end(), {root[0], root[1], root[2]});
  for (int i = 0; i < 4; ++i)
    pos.insert(pos.end(), {i == 2 ? std::nanf("") : root[0], root[1] + float(i), root[2]});
  const uint32_t total = strands + 3;
  std::vector<std::byte> bytes(296 + 4 * pos.size());
  auto u32 = [&](size_t at, uint32_t v) { std::memcpy(bytes.data() + at, &v, 4); };
  const float version = 3.0f;
  std::memcpy(bytes.data(), &version, 4);
  u32(4, total);
  u32(8, 4);
  u32(144, 296);
  std::memcpy(bytes.data() + 296, pos.data(), 4 * pos.size());
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return path.string();
}

}  // namespace

TEST_CASE(
    "Import: a fur of 30,000 four-point strands fits, simulates and draws, the degenerate "
    "strands counted",
    "[gpu][import][render]") {
  const auto dir = std::filesystem::temp_directory_path() / "csm_fur";
  std::filesystem::create_directories(dir);
  csm::Preset p = csm::defaultPreset();
  p.scene.hairstyle.file = writeFur(dir / "fur.tfx", 30000);
  p.scene.hairstyle.strands = 1000000;  // every strand, as a groom opened directly
  p.scene.hairstyle.maxParticles = 32;
  csm::test::RenderScene scene(p, 2);
  const csm::GroomReport& report = scene.sim().groomReport();
  INFO(csm::groomReportText(report));
  CHECK(report.fileStrands == 30000 + 3);
  CHECK(report.repair.droppedStrands == 3);
  // Past 20,000 strands the default (hairstyle.guides -1) simulates 4,000 of them as guides and
  // draws all 30,000.
  CHECK(scene.sim().counts().strands == csm::kAutoGuides);
  CHECK(scene.sim().drawnStrands() == 30000);
  // Four points a strand, resampled to the scene's fewest particles a strand.
  CHECK(scene.sim().counts().particles ==
        csm::kAutoGuides * size_t(std::max(4, p.scene.hairstyle.minParticles)));
  std::vector<glm::vec4> x;
  scene.sim().readPositions(x);
  size_t bad = 0;
  for (const glm::vec4& q : x) bad += !std::isfinite(q.x + q.y + q.z);
  CHECK(bad == 0);
  const csm::test::Image hair = scene.render(320, 180);
  CHECK(scene.renderer().drawnStrands() == drawnStrandCount(30000, p.view.render));
  const csm::test::Image bare = scene.render(320, 180, nullptr, false);
  csm::test::dumpImage(hair, "fur");
  const std::vector<bool> mask = csm::test::hairMask(hair, bare);
  const double share = double(std::count(mask.begin(), mask.end(), true)) / double(mask.size());
  INFO("fur covers " << share << " of the frame");
  CHECK(share > 0.01);
  std::filesystem::remove_all(dir);
}
