// The GPU solver's two kernel paths (GpuKernels): the per-particle path's work groups (whole
// strands, none split), the path chosen by the context, and both paths stepping the same hair
// to the same place (the CPU reference's tolerance) in every collision mode and head shape,
// each path bit-identical with itself. The GPU tiers also run whole with the per-particle path
// forced on (tests/CMakeLists.txt, CSM_GPU_KERNELS=particle).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "gl/caps.h"
#include "sim/gpu/gpu_probe.h"
#include "sim/gpu/gpu_solver.h"
#include "sim/gpu/strand_groups.h"
#include "sim/solver/cpu_solver.h"
#include "tests/cpu/test_scenes.h"
#include "tests/gpu/gpu_solver_fixture.h"
#include "sim/verify/solver_head.h"

using namespace csm;

namespace {

std::vector<glm::vec4> run(GpuKernels kernels, const Config& c, const Groom& g, int frames) {
  auto gpu = test::gpuSolver();
  REQUIRE(GpuProbe(*gpu).setKernels(kernels));
  resetWithHead(*gpu, g, c, headPose(c.head, 0.0));
  double t = 0.0;
  for (int f = 0; f < frames; ++f, t += c.sim.dt)
    gpu->stepFrame(headPose(c.head, t), headPose(c.head, t + c.sim.dt));
  std::vector<glm::vec4> x;
  gpu->readPositions(x);
  return x;
}

}  // namespace

TEST_CASE("GPU kernels: whole strands to a work group, in order, none split",
          "[gpu][kernels][quick]") {
  CHECK(gpu::groupParticlesFor(1) == gpu::kMinGroupParticles);
  CHECK(gpu::groupParticlesFor(128) == 128);
  CHECK(gpu::groupParticlesFor(129) == 256);
  CHECK(gpu::groupParticlesFor(256) == 256);
  // Strands of 50, 50, 30, 128, 1, 100 particles in groups of 128.
  const std::vector<uint32_t> first = {0, 50, 100, 130, 258, 259, 359};
  const std::vector<uint32_t> groups = gpu::packStrandGroups(first, 128);
  // 50 + 50 fit, 30 more would not; 30 + 128 would not; 128; then 1 + 100.
  CHECK(groups == std::vector<uint32_t>{0, 100, 130, 258, 359});
  // Every group holds at most 128 particles and starts where a strand starts.
  for (size_t k = 0; k + 1 < groups.size(); ++k) {
    CHECK(groups[k + 1] - groups[k] <= 128);
    CHECK(std::find(first.begin(), first.end(), groups[k]) != first.end());
  }
  CHECK(gpu::packStrandGroups({0}, 128) == std::vector<uint32_t>{0});
  CHECK(gpu::packStrandGroups({0, 128}, 128) == std::vector<uint32_t>{0, 128});
}

TEST_CASE("GPU kernels: per strand on a software renderer, per particle on a GPU",
          "[gpu][kernels][quick]") {
  auto gpu = test::gpuSolver();
  const char* forced = std::getenv("CSM_GPU_KERNELS");
  if (forced && std::string(forced) == "particle") {
    CHECK(GpuProbe(*gpu).kernels() == GpuKernels::PerParticle);
  } else if (forced && std::string(forced) == "strand") {
    CHECK(GpuProbe(*gpu).kernels() == GpuKernels::PerStrand);
  } else {
    CHECK(GpuProbe(*gpu).kernels() ==
          (gl::queryCaps().software ? GpuKernels::PerStrand : GpuKernels::PerParticle));
  }
}

TEST_CASE("GPU kernels: both paths step the hair alike, each the same twice", "[gpu][kernels]") {
  struct Case {
    const char* name;
    CollisionMode mode;
    HeadShape head;
    int iterations;  // strand-contact iterations (contact_apply.comp between them)
  };
  const Case cases[] = {
      {"head, distance field", CollisionMode::Head, HeadShape::Sdf, 1},
      {"head, spheres", CollisionMode::Head, HeadShape::Spheres, 1},
      {"strands, distance field", CollisionMode::Strands, HeadShape::Sdf, 2},
      {"volume + strands, spheres", CollisionMode::VolumeStrands, HeadShape::Spheres, 1},
      {"off", CollisionMode::Off, HeadShape::Sdf, 1}};
  for (const Case& k : cases) {
    INFO(k.name);
    Config c = test::smallScene(60);
    c.hairstyle.maxParticles = 20;
    c.hairstyle.lengthMax = 0.30f;
    c.collision.mode = k.mode;
    c.collision.headShape = k.head;
    c.collision.iterations = k.iterations;
    c.wind.strength = 3.0f;
    const Groom g = test::growFor(c);
    const int frames = 12;
    const std::vector<glm::vec4> strand = run(GpuKernels::PerStrand, c, g, frames);
    const std::vector<glm::vec4> particle = run(GpuKernels::PerParticle, c, g, frames);
    const std::vector<glm::vec4> again = run(GpuKernels::PerParticle, c, g, frames);
    REQUIRE(strand.size() == particle.size());
    double worst = 0.0, squares = 0.0;
    size_t sameTwice = 0;
    for (size_t i = 0; i < strand.size(); ++i) {
      const double e = glm::length(glm::vec3(strand[i]) - glm::vec3(particle[i]));
      worst = std::max(worst, std::isfinite(e) ? e : 1e30);
      squares += e * e;
      sameTwice += std::memcmp(&particle[i], &again[i], sizeof(glm::vec4)) == 0;
    }
    const double rms = std::sqrt(squares / double(std::max<size_t>(strand.size(), 1)));
    INFO("largest difference " << worst << " m, rms " << rms << " m");
    // The paths differ only in the order of float sums: within the CPU reference's tolerance
    // for these strands (gpu_solver_test.cpp). A strand contact is an event: a pair a rounding
    // puts either side of its contact distance moves its two segments apart or not, by up to
    // a fraction of the radius (0.5 mm), so with strand contacts the largest difference may
    // reach 1 mm and the mean a tenth of the radius (an H100: 0.62 mm and 0.031 mm over 12
    // frames, volume + strands), where without them both stay at rounding's size. On the
    // sculpted mannequin (ears, jaw) a strand that a contact moves lands on another side of
    // a feature: llvmpipe 1.56 mm and 0.147 mm (strands, distance field); with the ends'
    // factor in the rates (stiffer short strands) 3.0 mm and 0.179 mm.
    const bool events = strandContacts(k.mode);
    CHECK(worst < (events ? 4e-3 : 1e-4));
    CHECK(rms < (events ? 2.5e-4 : 2e-5));
    CHECK(sameTwice == particle.size());
  }
}
