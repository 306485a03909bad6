// "Model no more than a scene needs" (METHOD.md section 5): on the default preset's scene,
// what particles per strand, collision modes and substeps each cost and what they buy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"
#include <glm/geometric.hpp>

#include "sim/groom/hairstyle.h"
#include "sim/core/pose.h"
#include "sim/solver/accuracy.h"
#include "sim/head/head_model.h"

namespace csm::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Outcome {
  size_t particles = 0;
  double msPerFrame = 0.0;
  double maxStrain = 0.0;
  uint64_t headPenetrations = 0;  // most particles inside the head in any frame
  double hairPairs = 0.0;         // segment pairs closer than r, mean over the sampled frames
  double hairPairsAtStart = 0.0;  // the same in the groom as it starts
  std::vector<glm::vec4> x;       // the state at the end
};

Outcome run(Scene scene, double duration) {
  Outcome out;
  Setting s;  // the CPU reference; the scene's config is used as it is
  SceneRunner runner(s.maker(), scene);
  const std::vector<double> rest = restLengths(scene.groom);
  std::vector<glm::vec4> v;
  const int frames = int(std::lround(duration / scene.config.sim.dt));
  runner.readPositions(out.x);
  out.hairPairsAtStart =
      double(closeSegmentPairs(out.x, scene.groom, scene.config.collision.radius));
  std::vector<double> frameMs;
  int samples = 0;
  for (int f = 0; f < frames; ++f) {
    const auto t0 = Clock::now();
    runner.frame();
    runner.diagnostics().finish();
    frameMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    runner.readPositions(out.x);
    runner.readVelocities(v);
    const auto spheres =
        worldSpheres(scene.config.head.spheres, headPose(scene.config.head, runner.time()));
    const Accuracy a =
        measureAccuracy(out.x, v, scene.groom, rest, spheres, scene.config.sim.pinned);
    out.maxStrain = std::max(out.maxStrain, a.maxStrain);
    out.headPenetrations = std::max(out.headPenetrations, a.headPenetrations);
    if ((f + 1) % std::max(1, frames / 3) == 0) {
      out.hairPairs += double(closeSegmentPairs(out.x, scene.groom, scene.config.collision.radius));
      ++samples;
    }
  }
  out.hairPairs /= std::max(1, samples);
  out.particles = scene.groom.pointCount();
  // The median frame: the machine is shared, and a busy moment only ever adds time.
  std::sort(frameMs.begin(), frameMs.end());
  out.msPerFrame = frameMs.empty() ? NAN : frameMs[frameMs.size() / 2];
  return out;
}

// RMS and max distance between the centrelines of two runs of the same strands (any particle
// counts), sampled at 16 points along each strand.
PositionError centrelineError(const Scene& a, const Outcome& ra, const Scene& b,
                              const Outcome& rb) {
  double sum = 0.0, mx = 0.0;
  size_t count = 0;
  for (size_t s = 0; s < a.groom.strandCount(); ++s) {
    const auto ca = sampleStrand(ra.x, a.groom.first[s], a.groom.first[s + 1], 16);
    const auto cb = sampleStrand(rb.x, b.groom.first[s], b.groom.first[s + 1], 16);
    for (size_t k = 0; k < ca.size(); ++k) {
      const double d = 1000.0 * glm::length(ca[k] - cb[k]);
      sum += d * d;
      mx = std::max(mx, d);
      ++count;
    }
  }
  return {std::sqrt(sum / std::max<size_t>(1, count)), mx};
}

}  // namespace

void runSceneChoices(const Options& o) {
  const int strands = o.quick ? 400 : 2000;
  const double duration = o.quick ? 0.25 : 0.5;
  Scene base = presetScene(o, "default", strands);
  base.config.collision.mode = CollisionMode::Head;
  Csv csv({"group", "variant", "strands", "particles", "ms_per_frame", "error_rms_mm",
           "error_max_mm", "max_strain", "head_penetrations", "hair_pairs_closer_than_r",
           "hair_pairs_at_start"});
  auto row = [&](const char* group, const std::string& variant, const Outcome& r, PositionError e) {
    csv.add(group).add(variant).add(strands).add(r.particles).add(r.msPerFrame);
    csv.add(e.rmsMm).add(e.maxMm).add(r.maxStrain).add(r.headPenetrations).add(r.hairPairs);
    csv.add(r.hairPairsAtStart);
    csv.endRow();
    std::fprintf(stderr, "  %-10s %-34s %8zu particles %8.1f ms/frame  error %.2f mm\n", group,
                 variant.c_str(), r.particles, r.msPerFrame, e.rmsMm);
  };
  std::fprintf(stderr, "scene choices: presets/default.json with %d strands, %.2f s\n", strands,
               duration);
  auto regrow = [](Scene s) {
    s.groom = growHairstyle(s.config, *HeadModel::require(s.config));
    return s;
  };

  // Particles per strand, against 32 particles on every strand.
  {
    Scene ref = base;
    ref.config.hairstyle.particlesPerStrand = 32;
    ref = regrow(ref);
    const Outcome refRun = run(ref, duration);
    struct V {
      std::string name;
      int fixed;
      float segment;
    };
    const HairstyleConfig& h = base.config.hairstyle;
    char preset[96];
    std::snprintf(preset, sizeof preset, "by length, %.1f cm segments, %d-%d (preset)",
                  100.0 * h.segmentLength, h.minParticles, h.maxParticles);
    std::vector<V> variants = {
        {preset, 0, h.segmentLength},           {"by length, 1.5 cm segments", 0, 0.015f},
        {"by length, 3 cm segments", 0, 0.03f}, {"fixed 8", 8, h.segmentLength},
        {"fixed 16", 16, h.segmentLength},      {"fixed 25", 25, h.segmentLength}};
    for (const V& v : variants) {
      Scene s = base;
      s.config.hairstyle.particlesPerStrand = v.fixed;
      s.config.hairstyle.segmentLength = v.segment;
      s.config.hairstyle.minParticles = std::min(h.minParticles, 6);
      s.config.hairstyle.maxParticles = 25;
      if (v.segment == h.segmentLength) {
        s.config.hairstyle.minParticles = h.minParticles;
        s.config.hairstyle.maxParticles = h.maxParticles;
      }
      s = regrow(s);
      const Outcome r = run(s, duration);
      row("particles", v.name, r, centrelineError(s, r, ref, refRun));
    }
    row("particles", "fixed 32 (reference)", refRun, {0.0, 0.0});
  }
  // Collision modes.
  for (CollisionMode m : {CollisionMode::Off, CollisionMode::Head, CollisionMode::Strands}) {
    Scene s = base;
    s.config.collision.mode = m;
    const Outcome r = run(s, duration);
    row("collisions", collisionModeName(m), r, {NAN, NAN});
  }
  // Substeps, against 32. The preset's calibrated stiffness needs 4: fewer are not asked for.
  {
    Scene ref = base;
    ref.config.sim.substeps = 32;
    const Outcome refRun = run(ref, duration);
    for (int n : {4, 8, 16}) {
      Scene s = base;
      s.config.sim.substeps = n;
      const Outcome r = run(s, duration);
      ErrorAccumulator e(s.groom, s.config.sim.pinned);
      e.add(r.x, refRun.x);
      row("substeps", std::to_string(n), r, e.result());
    }
    row("substeps", "32 (reference)", refRun, {0.0, 0.0});
  }
  csv.write(o.out + "/scene_choices.csv");
}

}  // namespace csm::bench
