// Guards of the CPU side against non-finite and runaway values: each test fails without its
// guard (the solvers' own guards, on both solvers, are in tests/gpu/guards_test.cpp).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "sim/core/segment_pairs.h"
#include "sim/solver/cpu_solver.h"
#include "sim/groom/groom_file.h"
#include "sim/run/simulation.h"
#include "tests/cpu/test_scenes.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

// A loose tangle of short strands in a 10 cm box.
void tangle(std::vector<glm::dvec3>& x, std::vector<uint32_t>& strand) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05), d(-0.01, 0.01);
  for (uint32_t s = 0; s < 200; ++s) {
    glm::dvec3 p(u(rng), u(rng), u(rng));
    for (int i = 0; i < 8; ++i) {
      x.push_back(p);
      strand.push_back(s);
      p += glm::dvec3(d(rng), d(rng), d(rng));
    }
  }
}

}  // namespace

TEST_CASE("Guard: the CPU grid leaves out non-finite and runaway segments, and counts them",
          "[guard][quick]") {
  std::vector<glm::dvec3> x;
  std::vector<uint32_t> strand;
  tangle(x, strand);
  const double r = 0.002;
  uint64_t oversize = 99;
  const std::vector<SegmentPair> clean = findContactsGrid(x, strand, r, &oversize);
  CHECK(oversize == 0);
  REQUIRE(!clean.empty());

  // Strand 0 blows up: a NaN end, then a segment a thousand kilometres long. Before the guard
  // the NaN's cell was floor(NaN) cast to an integer (undefined), and the long segment was
  // entered in each of the ~10^24 cells of its box: the search never ended.
  std::vector<glm::dvec3> broken = x;
  broken[1] = glm::dvec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  broken[4] = glm::dvec3(1e6, -1e6, 1e6);
  broken[6] = glm::dvec3(std::numeric_limits<double>::infinity(), 0.0, 0.0);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SegmentPair> pairs = findContactsGrid(broken, strand, r, &oversize);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(seconds << " s");
  // Segments 0-1, 1-2 (NaN), 3-4, 4-5 (long), 5-6, 6-7 (infinite) are left out and counted.
  CHECK(oversize == 6);
  // Every pair of the other strands is still found.
  std::vector<SegmentPair> others;
  for (const SegmentPair& p : clean)
    if (p.a >= 7 && p.b >= 7) others.push_back(p);
  CHECK(pairs == others);
  CHECK(seconds < 10.0);

  // The contact search of the solvers reports them in its stats.
  ContactSettings settings;
  settings.radius = r;
  ContactStats stats;
  findCandidates(broken, x, strand, settings, {}, stats);
  CHECK(stats.oversize == 6);
}

TEST_CASE("Guard: a region's rotation recovers from a NaN warm start and ignores a NaN matrix",
          "[guard][quick]") {
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.0, 1.0, 0.0)).toRotationMatrix();
  const Eigen::Vector3d axis(1.0, 0.0, 0.0);
  // A NaN matrix (a particle gone non-finite) leaves the rotation as it was.
  Eigen::Quaterniond q(Eigen::AngleAxisd(0.1, Eigen::Vector3d(0.0, 0.0, 1.0)));
  const Eigen::Quaterniond kept = q;
  Eigen::Matrix3d nan = turned;
  nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
  extractRotation(nan, 3.0, q, 8, axis, 1.0);
  CHECK(q.coeffs() == kept.coeffs());
  // A NaN rotation (stored before the guard) starts again and finds the matrix's rotation.
  q.coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());
  // (J = 3: sum r.a of a rotation matrix's columns against its own.)
  for (int step = 0; step < 10; ++step) extractRotation(turned, 3.0, q, 8, axis, 1.0);
  REQUIRE(q.coeffs().allFinite());
  CHECK((q.matrix() - turned).norm() < 1e-6);
}

TEST_CASE("Guard: an imported strand longer than the solvers take is refused with its index",
          "[guard][quick]") {
  const fs::path dir = fs::temp_directory_path() / "csm_guard_long_strand";
  fs::create_directories(dir);
  Groom g;
  for (int s = 0; s < 3; ++s) {
    std::vector<glm::vec3> points;
    const uint32_t n = s == 2 ? kMaxStrandParticles + 1 : 20;
    for (uint32_t i = 0; i < n; ++i)
      points.emplace_back(0.01f * float(s), 0.1f - 0.001f * float(i), 0.1f);
    g.addStrand(points);
  }
  const std::string file = (dir / "long.hair").string();
  REQUIRE(io::writeGroom(file, g));
  Config c = test::smallScene();
  c.hairstyle.file = file;
  c.hairstyle.resampleTolerance = 0.0f;  // keep the file's points
  c.hairstyle.importScale = 1.0f;
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  CHECK_FALSE(sim.load(c, dir.string(), &error));
  INFO(error);
  CHECK(error.find("strand 2 has 257 points") != std::string::npos);
  CHECK(error.find("hairstyle.resample_tolerance") != std::string::npos);
  // Thinned by the resampler it loads.
  c.hairstyle.resampleTolerance = 0.002f;
  CHECK(sim.load(c, dir.string(), &error));
  fs::remove_all(dir);
}
