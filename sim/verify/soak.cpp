#include "sim/verify/soak.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "sim/verify/points.h"
#include "sim/run/simulation.h"
#include "sim/solver/accuracy.h"
#include "sim/verify/torture.h"

namespace csm {

namespace {

long statusKb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(in, line))
    if (line.rfind(k, 0) == 0) return std::atol(line.c_str() + k.size());
  return 0;
}

}  // namespace

long residentKb() {
  return statusKb("VmRSS");
}

long peakResidentKb() {
  return statusKb("VmHWM");
}

Config soakScene(const Config& preset, int strands) {
  Config c = preset;
  c.hairstyle.strands = strands;
  c.collision.mode = CollisionMode::Strands;
  c.wind.strength = 0.0f;
  c.head.motion = HeadMotion::Shake;
  c.head.amplitude = 40.0f;
  c.head.frequency = 1.5f;
  return c;
}

double StrandDistances::quantile(double q) const {
  if (mm.empty()) return 0.0;
  const size_t i = std::min(mm.size() - 1, size_t(std::ceil(q * double(mm.size()))) - (q > 0));
  return mm[i];
}

size_t StrandDistances::beyond(double limit) const {
  return size_t(mm.end() - std::upper_bound(mm.begin(), mm.end(), limit));
}

StrandDistances strandDistances(const Groom& groom, int pinned, const std::vector<glm::vec4>& a,
                                const std::vector<glm::vec4>& b) {
  StrandDistances out;
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    double sum = 0.0;
    int n = 0;
    for (uint32_t i = groom.first[s] + uint32_t(pinned); i < groom.first[s + 1]; ++i, ++n) {
      const glm::dvec3 d = d3(a[i]) - d3(b[i]);
      sum += glm::dot(d, d);
    }
    if (n > 0) out.mm.push_back(1000.0 * std::sqrt(sum / n));
  }
  std::sort(out.mm.begin(), out.mm.end());
  return out;
}

SoakResult runSoak(const SolverMaker& make, const Config& base, const SoakOptions& o,
                   const std::function<void(long, const SoakResult&)>& progress) {
  using Clock = std::chrono::steady_clock;
  SoakResult r;
  Config still = base;
  still.head.motion = HeadMotion::None;
  std::string error;

  // The rest the hair should come back to: the same scene, the head never moving, settled
  // for as long as the soak's still part.
  std::vector<glm::vec4> settled;
  const long stillFrames = o.frames - o.movingFrames;
  {
    const auto t0 = Clock::now();
    Simulation rest(make());
    if (!rest.load(still, "", &error)) {
      std::fprintf(stderr, "soak: %s\n", error.c_str());
      r.finite = false;
      return r;
    }
    for (long f = 0; f < stillFrames; ++f) rest.stepFrame();
    rest.readPositions(settled);
    r.restWallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
  }

  Simulation sim(make());
  if (!sim.load(base, "", &error)) {
    std::fprintf(stderr, "soak: %s\n", error.c_str());
    r.finite = false;
    return r;
  }
  const Groom& groom = sim.groom();
  const std::vector<double> rest = restLengths(groom);
  const long every = std::max(1L, o.frames / std::max(1, o.memorySamples));
  const long warm = std::lround(o.warmUpFraction * double(o.frames));
  std::vector<glm::vec4> x, v, halfway;
  r.rssStartKb = residentKb();
  r.rss.emplace_back(0, r.rssStartKb);
  const auto start = Clock::now();
  for (long f = 0; f < o.frames; ++f) {
    if (f == o.movingFrames) sim.setConfig(still, nullptr);
    sim.stepFrame();
    sim.readPositions(x);
    sim.readVelocities(v);
    r.frames = f + 1;
    double strain = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
      if (!finite(x[i]) || !finite(v[i])) {
        r.finite = false;
        r.nonFiniteFrame = r.frames;
        break;
      }
      if (i + 1 < x.size() && rest[i] > 0.0)
        strain = std::max(strain, glm::length(d3(x[i + 1]) - d3(x[i])) / rest[i] - 1.0);
    }
    if (!r.finite) break;
    if (strain > r.maxStrain) r.maxStrain = strain, r.maxStrainFrame = r.frames;
    r.strainedFrames += strain > base.sim.strainLimit + TortureCriteria{}.strainTolerance;
    if (r.frames == o.movingFrames + stillFrames / 2) halfway = x;
    if (r.frames == o.movingFrames + std::lround(1.0 / base.sim.dt)) {
      ErrorAccumulator at(groom, base.sim.pinned);
      at.add(x, settled);
      r.atStop = at.result();
    }
    if (r.frames % every == 0 || r.frames == o.frames) {
      const long kb = residentKb();
      r.rss.emplace_back(r.frames, kb);
      if (r.frames <= warm) r.rssWarmKb = kb;
      r.rssMaxKb = std::max(r.rssMaxKb, kb);
      if (progress) progress(r.frames, r);
    }
  }
  sim.diagnostics().finish();
  r.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.framesPerSecond = r.frames / std::max(1e-9, r.wallSeconds);
  r.rssEndKb = residentKb();
  r.rssMaxKb = std::max({r.rssMaxKb, r.rssStartKb, r.rssEndKb});
  if (r.rssWarmKb == 0) r.rssWarmKb = r.rssStartKb;
  r.hwmEndKb = peakResidentKb();
  if (r.finite) {
    ErrorAccumulator acc(groom, base.sim.pinned);
    acc.add(x, settled);
    r.toRest = acc.result();
    r.strandsToRest = strandDistances(groom, base.sim.pinned, x, settled);
    if (!halfway.empty()) {
      ErrorAccumulator drift(groom, base.sim.pinned);
      drift.add(x, halfway);
      r.stillDrift = drift.result();
    }
  }
  return r;
}

}  // namespace csm
