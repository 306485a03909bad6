// The GPU collision pass against the CPU reference, on the real GL driver (llvmpipe where
// there is no GPU): the hash grid finds exactly the pairs brute force finds, and collisions
// keep strands apart.
#include <algorithm>
#include <iterator>
#include <limits>
#include <memory>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "shaders/sim/bindings.glsl"
#include "sim/core/segment_pairs.h"
#include "sim/gpu/gpu_probe.h"
#include "sim/gpu/gpu_solver.h"
#include "sim/groom/hairstyle.h"
#include "sim/head/head_model.h"
#include "sim/verify/scenes.h"
#include "tests/cpu/test_scenes.h"
#include "tests/gpu/gl_fixture.h"
#include "tests/gpu/gpu_solver_fixture.h"
#include "sim/verify/solver_head.h"

using namespace csm;
using test::strandOf;
using test::toDouble;

namespace {

// Tangled strands in a 10 cm box: random walks with steps up to `step` (the longest segment
// sets the cell size, so a few long steps also exercise big cells).
Groom tangle(int strands, double step, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f), d(-1.0f, 1.0f);
  Groom g;
  for (int s = 0; s < strands; ++s) {
    std::vector<glm::vec3> points;
    glm::vec3 p(u(rng), u(rng), u(rng));
    const int n = 3 + s % 11;
    for (int i = 0; i < n; ++i) {
      points.push_back(p);
      p += glm::vec3(d(rng), d(rng), d(rng)) * float(step);
    }
    g.addStrand(points);
  }
  return g;
}

struct Compared {
  size_t brute = 0, gpu = 0, missing = 0, extra = 0, ambiguous = 0;
};

// Compares the GPU's pair list with brute force on the positions the GPU holds. The GPU
// decides d < 2r in float, brute force in double: a pair whose distance lies within float
// rounding of 2r (relative 1e-5 here, ~100 float ulps of the closest-point arithmetic on
// coordinates up to 0.1 m) may fall either way and is not counted as a difference.
Compared compare(GpuSolver& gpu, const Groom& g, double r) {
  std::vector<glm::vec4> x;
  gpu.readPositions(x);
  const std::vector<glm::dvec3> xd = toDouble(x);
  const std::vector<uint32_t> strand = strandOf(g);
  const auto brute = findContactsBruteForce(xd, strand, 2.0 * r * (1.0 + 1e-5));
  bool overflow = true;
  std::vector<std::pair<uint32_t, uint32_t>> found = GpuProbe(gpu).readContactPairs(&overflow);
  REQUIRE_FALSE(overflow);
  std::set<std::pair<uint32_t, uint32_t>> gpuSet(found.begin(), found.end());
  Compared c;
  c.gpu = found.size();
  CHECK(gpuSet.size() == found.size());  // no pair reported twice
  std::set<std::pair<uint32_t, uint32_t>> certain;
  for (const SegmentPair& p : brute) {
    const bool inside = p.distance < 2.0 * r * (1.0 - 1e-5);
    if (!inside) {
      ++c.ambiguous;
      gpuSet.erase({p.a, p.b});
      continue;
    }
    ++c.brute;
    certain.insert({p.a, p.b});
    if (!gpuSet.count({p.a, p.b})) ++c.missing;
  }
  for (const auto& p : gpuSet)
    if (!certain.count(p)) ++c.extra;
  return c;
}

// 15 x 15 parallel strands `apart` m from each other along z, 6 particles `along` m apart; the
// roots staggered along z by up to `stagger` mm (from strand to strand).
Groom strandBlock(float apart, float along, int stagger = 0) {
  Groom g;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) {
      const float z0 = 0.001f * float((i + 2 * j) % (stagger + 1));
      std::vector<glm::vec3> points;
      for (int k = 0; k < 6; ++k)
        points.push_back(glm::vec3(apart * float(i), apart * float(j), z0 + along * float(k)));
      g.addStrand(points);
    }
  return g;
}

// A bundle of strands 0.3 mm apart, 6 particles 4 mm apart; staggered so that strands side by
// side sag differently under gravity across them.
Groom packedBundle(int stagger) {
  return strandBlock(0.0003f, 0.004f, stagger);
}

// Strand contacts of radius 0.5 mm and no gravity (the bundle's strands 0.3 mm apart are then
// inside each other's contact distance), with or without the default head.
Config contactConfig(bool head) {
  Config c;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = 0.0005f;
  c.sim.gravity = glm::vec3(0.0f);
  if (!head) c.head.spheres.clear();
  return c;
}

}  // namespace

TEST_CASE("GPU grid: exactly the contact pairs brute force finds", "[gpu][collision]") {
  auto gpu = test::gpuSolver();
  for (double step : {0.004, 0.012}) {
    const Groom g = tangle(400, step, 7);
    for (double r : {0.0005, 0.002, 0.008}) {
      Config c;
      c.collision.mode = CollisionMode::Strands;
      c.collision.radius = float(r);
      resetWithHead(*gpu, g, c, Pose{});
      GpuProbe(*gpu).detectContacts();
      const Compared cmp = compare(*gpu, g, r);
      INFO("step " << step << " r " << r << ": brute force " << cmp.brute << ", GPU " << cmp.gpu
                   << ", missing " << cmp.missing << ", extra " << cmp.extra
                   << ", within rounding of 2r " << cmp.ambiguous);
      CHECK(cmp.brute > 50);
      CHECK(cmp.missing == 0);
      CHECK(cmp.extra == 0);
      // The stats count the same pairs.
      CHECK(GpuProbe(*gpu).readContactStats().contacts == cmp.gpu);

      // Each segment lists every pair within 2r + margin it is part of, in ascending order,
      // however many (r = 8 mm: over a hundred).
      const double reach = 2.0 * r + c.collision.margin;
      std::vector<glm::vec4> x;
      gpu->readPositions(x);
      const auto within = findContactsBruteForce(toDouble(x), strandOf(g), reach);
      std::vector<std::vector<uint32_t>> expected(g.pointCount());
      std::set<std::pair<uint32_t, uint32_t>> borderline;  // within float rounding of the reach
      for (const SegmentPair& p : within) {
        if (std::abs(p.distance - reach) < 1e-5 * reach) {
          borderline.insert({p.a, p.b});
          borderline.insert({p.b, p.a});
          continue;
        }
        expected[p.a].push_back(p.b);
        expected[p.b].push_back(p.a);
      }
      const auto lists = GpuProbe(*gpu).readCandidates();
      size_t wrong = 0, most = 0;
      for (size_t i = 0; i < lists.size(); ++i) {
        std::vector<uint32_t> e = expected[i], got;
        std::sort(e.begin(), e.end());
        for (const auto& [b, d0] : lists[i]) got.push_back(b);
        most = std::max(most, e.size());
        // Every pair expected, in ascending order; others only within rounding of the reach.
        std::vector<uint32_t> missing, extra;
        std::set_difference(e.begin(), e.end(), got.begin(), got.end(),
                            std::back_inserter(missing));
        std::set_difference(got.begin(), got.end(), e.begin(), e.end(), std::back_inserter(extra));
        const bool onlyBorderline = std::all_of(extra.begin(), extra.end(), [&](uint32_t b) {
          return borderline.count({uint32_t(i), b}) > 0;
        });
        if (!std::is_sorted(got.begin(), got.end()) || !missing.empty() || !onlyBorderline) ++wrong;
        // At rest, every pair's contact distance is its distance, up to 2r.
        for (const auto& [b, d0] : lists[i]) CHECK(d0 <= float(2.0 * r) * 1.0001f);
      }
      INFO("most candidates of a segment " << most);
      CHECK(wrong == 0);
      if (r > 0.005) CHECK(most > 64);
    }
  }
}

TEST_CASE("GPU lists: each run of segments is taken longest list first",
          "[gpu][collision][quick]") {
  // The list pass and the contact solve take the segments of each run of CSM_PARTICLE_GROUP
  // by candidate count, most first, ties by index (segment_order.comp): within a run a
  // permutation, counts non-increasing. Run on a tangle whose lists range from none to
  // dozens, so that an order left by index would fail.
  auto gpu = test::gpuSolver();
  const Groom g = tangle(400, 0.012, 11);
  Config c;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = 0.002f;
  resetWithHead(*gpu, g, c, Pose{});
  GpuProbe(*gpu).detectContacts();
  const auto lists = GpuProbe(*gpu).readCandidates();
  const std::vector<uint32_t> order = GpuProbe(*gpu).readSegmentOrder();
  REQUIRE(order.size() == g.pointCount());
  const size_t run = CSM_PARTICLE_GROUP;
  size_t outOfRun = 0, repeated = 0, misordered = 0, reordered = 0;
  for (size_t first = 0; first < order.size(); first += run) {
    const size_t end = std::min(order.size(), first + run);
    std::vector<bool> seen(end - first, false);
    for (size_t i = first; i < end; ++i) {
      const uint32_t a = order[i];
      if (a < first || a >= end) {
        ++outOfRun;
        continue;
      }
      if (seen[a - first]) ++repeated;
      seen[a - first] = true;
      reordered += a != i;
      if (i > first && order[i - 1] >= first && order[i - 1] < end) {
        const uint32_t b = order[i - 1];
        const size_t nb = lists[b].size(), na = lists[a].size();
        if (nb < na || (nb == na && b > a)) ++misordered;
      }
    }
  }
  INFO("out of their run " << outOfRun << ", repeated " << repeated << ", misordered " << misordered
                           << ", moved " << reordered);
  CHECK(outOfRun == 0);
  CHECK(repeated == 0);
  CHECK(misordered == 0);
  CHECK(reordered > order.size() / 2);
}

TEST_CASE("GPU grid: pairs of a simulated head of hair match brute force",
          "[gpu][collision][one_path]") {
  // Hair fallen under gravity and wind: dense near the scalp, where most pairs are.
  auto gpu = test::gpuSolver();
  Config c;
  c.hairstyle.strands = 1500;
  c.hairstyle.particlesPerStrand = 12;
  c.wind.strength = 3.0f;
  c.collision.mode = CollisionMode::Strands;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  resetWithHead(*gpu, g, c, Pose{});
  for (int f = 0; f < 10; ++f) gpu->stepFrame(Pose{}, Pose{});
  GpuProbe(*gpu).detectContacts();
  const Compared cmp = compare(*gpu, g, c.collision.radius);
  INFO("brute force " << cmp.brute << ", GPU " << cmp.gpu << ", missing " << cmp.missing
                      << ", extra " << cmp.extra << ", within rounding of 2r " << cmp.ambiguous);
  CHECK(cmp.brute > 1000);
  CHECK(cmp.missing == 0);
  CHECK(cmp.extra == 0);
}

TEST_CASE("GPU hair-hair collision keeps strands apart", "[gpu][collision][one_path]") {
  // The CPU test's scene (tests/cpu/cpu_solver_test.cpp): strands shaken through each other.
  // Penetrations are segment pairs closer than the hair radius, counted by brute force on
  // the read-back positions.
  const Config c = shakenCurtainsConfig();
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  const std::vector<uint32_t> strand = strandOf(g);
  auto penetrations = [&](CollisionMode mode, ContactStats* stats) {
    Config m = c;
    m.collision.mode = mode;
    auto gpu = test::gpuSolver();
    resetWithHead(*gpu, g, m, headPose(m.head, 0.0));
    double t = 0.0;
    for (int f = 0; f < 90; ++f, t += m.sim.dt)
      gpu->stepFrame(headPose(m.head, t), headPose(m.head, t + m.sim.dt));
    *stats = GpuProbe(*gpu).readContactStats();
    std::vector<glm::vec4> x;
    gpu->readPositions(x);
    return findContactsBruteForce(toDouble(x), strand, m.collision.radius).size();
  };
  ContactStats off, on;
  const size_t without = penetrations(CollisionMode::Head, &off);
  const size_t with = penetrations(CollisionMode::Strands, &on);
  INFO("penetrating pairs without " << without << ", with " << with << "; GPU counted "
                                    << on.penetrations << " of " << on.contacts << " contacts");
  CHECK(without > 20);
  // At least 40 % fewer (measured 3,427 against 6,712 with the scalp a built-in end; the CPU
  // tier, the same scene in double, keeps under half).
  CHECK(double(with) < 0.6 * double(without));
  CHECK(off.contacts == 0);
  CHECK(on.contacts > 0);
}

TEST_CASE("GPU grid: a segment over the cell cap and a grid over its buffers degrade safely",
          "[gpu][collision]") {
  // An exploding strand: one segment 2 m long spans far more than the 64-cell cap, so it is
  // in no cell (counted) and finds no contacts; every other pair is still found exactly.
  // Long diagonal segments between short ones (cells follow the mean length) each pass
  // through several cells (4.5 entries a segment here, of the clipped pieces, in cells of
  // 0.75 mean segments): the entries still fit what reset reserved from the boxes.
  auto gpu = test::gpuSolver();
  Groom g;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.03f, 0.03f), d(-1.0f, 1.0f);
  for (int s = 0; s < 300; ++s) {
    std::vector<glm::vec3> points;
    glm::vec3 p(u(rng), u(rng), u(rng));
    for (int i = 0; i < 8; ++i) {
      points.push_back(p);
      p += i % 2 == 0 ? glm::vec3(d(rng) < 0 ? -1 : 1, 1, d(rng) < 0 ? -1 : 1) * 0.0115f
                      : glm::vec3(d(rng), d(rng), d(rng)) * 0.001f;
    }
    g.addStrand(points);
  }
  const uint32_t longFirst = uint32_t(g.pointCount());
  g.addStrand(
      {glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.01f, 0.01f), glm::vec3(1.0f, 0.03f, 0.01f)});
  const double r = 0.0005;
  Config c;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = float(r);
  resetWithHead(*gpu, g, c, Pose{});
  GpuProbe(*gpu).detectContacts();
  const GpuProbe::GridStats grid = GpuProbe(*gpu).gridStats();
  INFO("entries " << grid.entries << " capacity " << grid.capacity << " oversize " << grid.oversize
                  << " cell " << grid.cell);
  CHECK(grid.oversize == 1);
  CHECK(grid.entries <= grid.capacity);
  CHECK(grid.entries > 2100 * 4);  // several cells per segment

  std::vector<glm::vec4> x;
  gpu->readPositions(x);
  const auto brute = findContactsBruteForce(toDouble(x), strandOf(g), 2.0 * r);
  std::set<std::pair<uint32_t, uint32_t>> expected;
  for (const SegmentPair& p : brute)
    if (p.a != longFirst && p.b != longFirst && std::abs(p.distance - 2.0 * r) > 2e-5 * r)
      expected.insert({p.a, p.b});
  size_t missing = 0, extra = 0;
  std::set<std::pair<uint32_t, uint32_t>> found;
  for (const auto& p : GpuProbe(*gpu).readContactPairs()) {
    found.insert(p);
    CHECK(p.first != longFirst);
    CHECK(p.second != longFirst);
  }
  for (const auto& p : expected) missing += found.count(p) ? 0 : 1;
  for (const auto& p : found) {
    const bool borderline = std::any_of(brute.begin(), brute.end(), [&](const SegmentPair& q) {
      return q.a == p.first && q.b == p.second && std::abs(q.distance - 2.0 * r) <= 2e-5 * r;
    });
    if (!expected.count(p) && !borderline) ++extra;
  }
  CHECK(expected.size() > 50);
  CHECK(missing == 0);
  CHECK(extra == 0);

  // The buffers hold what this groom needs, so stepping finds the contacts with no growth.
  const uint32_t capacity = grid.capacity;
  gpu->stepFrame(Pose{}, Pose{});
  CHECK(GpuProbe(*gpu).readContactStats().contacts > 0);
  CHECK(GpuProbe(*gpu).gridStats().capacity == capacity);
}

TEST_CASE(
    "GPU grid: a pair list over its capacity at the first frame lists nothing, says so, grows",
    "[gpu][collision]") {
  // A bundle of parallel strands packed closer than the candidate distance (~22,000 pairs),
  // its lists capped at reset at 8,192 pairs (the reset sizes them for the bundle otherwise),
  // as hair that packs tighter than it was at reset: the frame has no list before it to keep
  // (the reset's), so it lists no candidates (the counters say how many pairs it needed, and
  // count the frame as one over capacity). With
  // the cap lifted, the next frame grows the list to what that one needed, fits and lists
  // them.
  auto gpu = test::gpuSolver();
  const Groom g = packedBundle(0);
  const Config c = contactConfig(true);
  GpuProbe(*gpu).limitGridStorage(128 * 1024);
  resetWithHead(*gpu, g, c, Pose{});
  GpuProbe(*gpu).limitGridStorage(UINT64_MAX);
  const uint32_t capacity = GpuProbe(*gpu).gridStats().pairCapacity;
  CHECK(capacity == 128 * 1024 / 16);
  gpu->stepFrame(Pose{}, Pose{});
  const GpuProbe::GridStats over = GpuProbe(*gpu).gridStats();
  INFO("pairs " << over.pairs << " capacity " << over.pairCapacity);
  CHECK(over.pairs > capacity);
  CHECK(over.entries <= over.capacity);
  const auto empty = GpuProbe(*gpu).readCandidates();
  CHECK(std::all_of(empty.begin(), empty.end(), [](const auto& l) { return l.empty(); }));
  // The next frame grows the list and fits.
  const ContactStats overStats = GpuProbe(*gpu).readContactStats();
  CHECK(overStats.candidates == over.pairs);
  CHECK(overStats.overflows == 1);
  CHECK(overStats.oversize == 0);
  gpu->stepFrame(Pose{}, Pose{});
  const GpuProbe::GridStats fits = GpuProbe(*gpu).gridStats();
  CHECK(fits.pairCapacity > capacity);
  CHECK(fits.pairs <= fits.pairCapacity);
  size_t listed = 0;
  for (const auto& l : GpuProbe(*gpu).readCandidates()) listed += l.size();
  CHECK(listed > 0);
  // A sample that fits grows nothing.
  GpuProbe(*gpu).readContactStats();
  gpu->stepFrame(Pose{}, Pose{});
  // The count of frames over capacity runs on (still the one), until a reset.
  CHECK(GpuProbe(*gpu).readContactStats().overflows == 1);
  CHECK(GpuProbe(*gpu).gridStats().pairCapacity == fits.pairCapacity);
  resetWithHead(*gpu, g, c, Pose{});
  CHECK(GpuProbe(*gpu).readContactStats().overflows == 0);
}

// Two rows of strands held horizontally along +z at rest, 1.6 mm apart in each row: row A at
// y = 0, 5 cm long; row B 0.8 mm to the side and 6 mm above, 10 cm long. Under gravity B
// droops further, down between A's strands.
Groom hangingRows(int perRow) {
  Groom g;
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < perRow; ++i) {
      const glm::vec3 root(0.0016f * float(i) + 0.0008f * float(row), 0.006f * float(row), 0.0f);
      std::vector<glm::vec3> points;
      for (int k = 0; k < (row == 0 ? 6 : 11); ++k)
        points.push_back(root + glm::vec3(0, 0, 0.01f * float(k)));
      g.addStrand(points);
    }
  return g;
}

TEST_CASE("GPU grid: cells of three quarters of a segment in sparse hair and half in dense",
          "[gpu][collision][quick]") {
  // The cell size changes what the search costs, not what it finds: a reset sizes it from
  // its search of the hair (at most 20 candidate pairs a segment: three quarters of a mean
  // rest segment, else half). Segments 1 cm long, reach 1.5 mm here (3 mm cells at least).
  auto gpu = test::gpuSolver();
  const Config c = contactConfig(false);
  resetWithHead(*gpu, hangingRows(60), c, Pose{});  // two rows of strands 1.6 mm apart: few pairs
  gpu->stepFrame(Pose{}, Pose{});
  GpuProbe::GridStats grid = GpuProbe(*gpu).gridStats();
  INFO("sparse: " << grid.pairs << " pairs of 900 segments, cell " << grid.cell);
  CHECK(grid.pairs < 20 * 900);
  CHECK(grid.cell == Approx(0.0075));
  // 15 x 15 strands 0.3 mm apart, 5 segments each: ~100 pairs a segment.
  resetWithHead(*gpu, strandBlock(0.0003f, 0.01f), c, Pose{});
  gpu->stepFrame(Pose{}, Pose{});
  grid = GpuProbe(*gpu).gridStats();
  INFO("dense: " << grid.pairs << " pairs of 1125 segments, cell " << grid.cell);
  CHECK(grid.pairs > 20 * 1125);
  CHECK(grid.cell == Approx(0.005));
  CHECK(grid.entries <= grid.capacity);
  CHECK(GpuProbe(*gpu).readContactStats().overflows == 0);
}

TEST_CASE("GPU grid: a search over the pair list's capacity keeps the list before it",
          "[gpu][collision][quick]") {
  // Row B droops between row A's strands: with a 6 mm margin the candidate pairs go from
  // 12,734 at rest to ~14,700 (llvmpipe). With the buffers capped at 13,500 pairs, a frame
  // whose search needs more keeps each segment's list from the frame before (not an empty
  // one: the hair would pass through itself for a frame), says so, and counts no crossings.
  auto gpu = test::gpuSolver();
  Config c = contactConfig(false);
  c.sim.gravity = glm::vec3(0.0f, -9.81f, 0.0f);
  c.collision.margin = 0.006f;
  const uint32_t cap = 13500;
  GpuProbe(*gpu).limitGridStorage(uint64_t(cap) * 16);
  resetWithHead(*gpu, hangingRows(60), c, Pose{});
  REQUIRE(GpuProbe(*gpu).gridStats().pairCapacity == cap);
  std::vector<std::vector<std::pair<uint32_t, float>>> before;
  int fitted = 0;
  for (int f = 0; f < 20 && GpuProbe(*gpu).readContactStats().overflows == 0; ++f) {
    before = GpuProbe(*gpu).readCandidates();
    gpu->stepFrame(Pose{}, Pose{});
    if (GpuProbe(*gpu).readContactStats().overflows == 0) ++fitted;
  }
  const GpuProbe::GridStats over = GpuProbe(*gpu).gridStats();
  const ContactStats stats = GpuProbe(*gpu).readContactStats();
  INFO("frames that fit " << fitted << ", pairs " << over.pairs << " entries " << over.entries
                          << " of " << over.capacity);
  REQUIRE(stats.overflows == 1);
  CHECK(fitted >= 1);  // a list before it
  CHECK(over.pairs > cap);
  CHECK(over.entries <= over.capacity);
  CHECK(stats.crossings == 0);
  const auto kept = GpuProbe(*gpu).readCandidates();
  size_t listed = 0;
  for (const auto& l : kept) listed += l.size();
  CHECK(listed > 20000);
  CHECK(kept == before);
  // The next frame, over the cap too (the cap stops the growth), keeps the same lists.
  gpu->stepFrame(Pose{}, Pose{});
  REQUIRE(GpuProbe(*gpu).gridStats().pairs > cap);
  CHECK(GpuProbe(*gpu).readContactStats().overflows == 2);
  CHECK(GpuProbe(*gpu).readCandidates() == before);
}

// One segment 6 cm along x (particles 0 and 1) and `crossing` segments 1 cm along z, each a
// strand of its own, crossing it 0.2 mm away at even steps along it: every one is a candidate
// of the first segment.
Groom crowd(int crossing) {
  Groom g;
  // Inside one cell (7.5 mm cells here), so the box is one cell thick.
  const float y = 0.0025f, z = 0.0025f;
  g.addStrand({glm::vec3(0.0f, y, z), glm::vec3(0.06f, y, z)});
  for (int i = 0; i < crossing; ++i) {
    const float x = 0.06f * (float(i) + 0.5f) / float(crossing);
    g.addStrand({glm::vec3(x, y + 0.0002f, z - 0.005f), glm::vec3(x, y + 0.0002f, z + 0.005f)});
  }
  return g;
}

TEST_CASE("GPU lists: a segment lists all of 1500 candidates and none of 2500",
          "[gpu][collision][quick]") {
  // An insertion sort of 1,500 candidates takes ~560,000 loop iterations, past the 65,535 that
  // llvmpipe allows an invocation (it cuts the loops short, silently): the list came out cut
  // short and unsorted. The heapsort takes ~35,000. Over CSM_MAX_CANDIDATES the segment is in
  // no pair, on either side, and counted as crowded.
  const Config c = contactConfig(false);
  for (int crossing : {1500, 2500}) {
    INFO(crossing << " crossing segments");
    const Groom g = crowd(crossing);
    auto gpu = test::gpuSolver();
    resetWithHead(*gpu, g, c, Pose{});
    GpuProbe(*gpu).detectContacts();
    const auto lists = GpuProbe(*gpu).readCandidates();
    const ContactStats stats = GpuProbe(*gpu).readContactStats();
    CHECK(stats.oversize == 0);
    CHECK(GpuProbe(*gpu).gridStats().pairs <=
          GpuProbe(*gpu).gridStats().pairCapacity);  // this pass fitted
    size_t listing = 0;                              // crossing segments that list the first
    for (size_t i = 2; i < lists.size(); ++i)
      for (const auto& cand : lists[i]) listing += cand.first == 0 ? 1 : 0;
    if (crossing <= 2048) {
      REQUIRE(lists[0].size() == size_t(crossing));
      for (size_t k = 0; k < lists[0].size(); ++k) CHECK(lists[0][k].first == 2 * (k + 1));
      CHECK(listing == size_t(crossing));
      CHECK(stats.crowded == 0);
    } else {
      CHECK(lists[0].empty());
      CHECK(listing == 0);
      CHECK(stats.crowded == 1);
      // The crossing segments still list each other.
      size_t others = 0;
      for (size_t i = 2; i < lists.size(); ++i) others += lists[i].size();
      CHECK(others > size_t(crossing));
    }
  }
}

TEST_CASE("GPU grid: its buffers stay within the cap on what the device's views hold",
          "[gpu][collision][quick]") {
  // A buffer read past what a binding holds is read and written as the driver pleases
  // (llvmpipe's 128 MiB storage blocks, before the lists moved to buffer textures: 30,000
  // strands of Fig. 1 counted different crossings from run to run). Capped at 128 KiB (8,192 pairs
  // or entries), the packed bundle (~4,500 entries, ~22,000 pairs) never fits its pairs: every
  // frame says so and keeps the list before it (none: no search ever fit), and nothing grows
  // past the cap.
  const Groom g = packedBundle(0);
  const Config c = contactConfig(true);
  const uint64_t cap = 128 * 1024;
  auto gpu = test::gpuSolver();
  GpuProbe(*gpu).limitGridStorage(cap);
  resetWithHead(*gpu, g, c, Pose{});
  for (int f = 0; f < 3; ++f) gpu->stepFrame(Pose{}, Pose{});
  const GpuProbe::GridStats grid = GpuProbe(*gpu).gridStats();
  INFO("pairs " << grid.pairs << " capacity " << grid.pairCapacity << " entries " << grid.entries
                << " capacity " << grid.capacity);
  CHECK(grid.pairs > cap / 16);
  CHECK(grid.pairCapacity == cap / 16);
  CHECK(grid.capacity <= cap / 16);
  CHECK(GpuProbe(*gpu).readContactStats().overflows == 3);
  const auto lists = GpuProbe(*gpu).readCandidates();
  CHECK(std::all_of(lists.begin(), lists.end(), [](const auto& l) { return l.empty(); }));
  // Uncapped, the reset sizes the lists for the bundle: every frame fits.
  auto free = test::gpuSolver();
  resetWithHead(*free, g, c, Pose{});
  for (int f = 0; f < 3; ++f) free->stepFrame(Pose{}, Pose{});
  CHECK(GpuProbe(*free).readContactStats().overflows == 0);
  CHECK(GpuProbe(*free).gridStats().pairCapacity > cap / 16);
}

TEST_CASE("GPU grid: a reset or a switch to a strand mode sizes the lists for the hair as it is",
          "[gpu][collision][quick]") {
  // The packed bundle needs ~40 pairs a segment against ~4 grid entries: more than the
  // reserve from the entries holds (its first frame overflowed when that was all). The reset
  // in a strand mode, and a switch to one from head only, search the hair as it stands and
  // size the lists for it: the first frame fits, and the sizing search counts as no frame.
  const Groom g = packedBundle(0);
  Config c = contactConfig(true);
  auto reset = test::gpuSolver(), switched = test::gpuSolver();
  resetWithHead(*reset, g, c, Pose{});
  c.collision.mode = CollisionMode::Head;
  resetWithHead(*switched, g, c, Pose{});
  const uint32_t reserved = GpuProbe(*switched).gridStats().pairCapacity;
  c.collision.mode = CollisionMode::Strands;
  switched->setConfig(c);
  for (GpuSolver* s : {reset.get(), switched.get()}) {
    s->stepFrame(Pose{}, Pose{});
    const GpuProbe::GridStats grid = GpuProbe(*s).gridStats();
    INFO("pairs " << grid.pairs << " capacity " << grid.pairCapacity << " reserved " << reserved);
    CHECK(grid.pairs > reserved);
    CHECK(grid.pairs <= grid.pairCapacity);
    CHECK(GpuProbe(*s).readContactStats().overflows == 0);
    CHECK(GpuProbe(*s).readContactStats().crossings == 0);
    size_t listed = 0;
    for (const auto& l : GpuProbe(*s).readCandidates()) listed += l.size();
    CHECK(listed == 2 * size_t(grid.pairs));
  }
}

TEST_CASE("GPU grid: a restored state sizes the lists for the hair it restores",
          "[gpu][collision][quick]") {
  // A solver reset on the bundle's strands 5 cm apart (no pairs: the lists hold the least
  // they reserve) restores the packed bundle's state: the lists are sized for it there, so
  // its first frame fits (it overflowed when a restore left them as they were).
  const Groom packed = packedBundle(0);
  const Groom spread = strandBlock(0.05f, 0.004f);
  const Config c = contactConfig(true);
  auto source = test::gpuSolver(), restored = test::gpuSolver();
  resetWithHead(*source, packed, c, Pose{});
  SavedState state;
  source->save(state);
  resetWithHead(*restored, spread, c, Pose{});
  const uint32_t reserved = GpuProbe(*restored).gridStats().pairCapacity;
  std::string error;
  REQUIRE(restored->restore(state, &error));
  restored->stepFrame(Pose{}, Pose{});
  source->stepFrame(Pose{}, Pose{});
  const GpuProbe::GridStats grid = GpuProbe(*restored).gridStats();
  INFO("pairs " << grid.pairs << " capacity " << grid.pairCapacity << " reserved " << reserved);
  CHECK(grid.pairs > reserved);
  CHECK(grid.pairs <= grid.pairCapacity);
  CHECK(GpuProbe(*restored).readContactStats().overflows == 0);
  CHECK(grid.pairs == GpuProbe(*source).gridStats().pairs);
}

TEST_CASE("GPU grid: the buffers grow at the same frame whoever reads the counters",
          "[gpu][collision][quick]") {
  // The packed bundle, its lists capped at reset, overflows its pair list on the first frame.
  // One solver reads every frame's sample at once (as a headless run writing frames does),
  // the other reads nothing (as a viewer whose samples arrive late): both grow as the second
  // frame begins and end bit-identical. Growing when a sample's read-back arrived made the
  // frame of growth, and so the motion, depend on who read and when.
  const Groom g = packedBundle(3);
  Config c = contactConfig(false);
  c.sim.gravity = glm::vec3(0.0f, -9.81f, 0.0f);
  c.sim.rootLength = 0.004f;  // the head holds the first segment; the rest sags
  auto eager = test::gpuSolver(), never = test::gpuSolver();
  for (GpuSolver* s : {eager.get(), never.get()}) {
    GpuProbe(*s).limitGridStorage(128 * 1024);
    resetWithHead(*s, g, c, Pose{});
    GpuProbe(*s).limitGridStorage(UINT64_MAX);
  }
  const uint32_t capacity = GpuProbe(*eager).gridStats().pairCapacity;
  for (long f = 0; f < 4; ++f) {
    eager->stepFrame(Pose{}, Pose{});
    eager->requestSample(f);
    while (eager->takeSample(true)) {
    }
    never->stepFrame(Pose{}, Pose{});
  }
  std::vector<glm::vec4> a, b;
  eager->readPositions(a);
  never->readPositions(b);
  CHECK(a == b);
  for (GpuSolver* s : {eager.get(), never.get()}) {
    CHECK(GpuProbe(*s).readContactStats().overflows == 1);
    CHECK(GpuProbe(*s).gridStats().pairCapacity > capacity);
  }
  // The contacts change this motion, so a frame without them would show.
  auto headOnly = test::gpuSolver();
  c.collision.mode = CollisionMode::Head;
  resetWithHead(*headOnly, g, c, Pose{});
  for (int f = 0; f < 4; ++f) headOnly->stepFrame(Pose{}, Pose{});
  std::vector<glm::vec4> h;
  headOnly->readPositions(h);
  CHECK(h != a);
}

TEST_CASE("GPU grid: positions that are not finite stay out of the grid",
          "[gpu][collision][quick]") {
  auto gpu = test::gpuSolver();
  Groom g = tangle(200, 0.004, 5);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  g.addStrand({glm::vec3(0.0f), glm::vec3(nan, 0.0f, 0.0f), glm::vec3(0.0f, 1e35f, 0.0f)});
  Config c;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = 0.002f;
  resetWithHead(*gpu, g, c, Pose{});
  GpuProbe(*gpu).detectContacts();
  CHECK(GpuProbe(*gpu).gridStats().oversize == 2);  // both segments of the broken strand
  CHECK(GpuProbe(*gpu).readContactStats().contacts > 0);
  CHECK(GpuProbe(*gpu).readContactStats().contacts == GpuProbe(*gpu).readContactPairs().size());
}
