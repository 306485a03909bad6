// The volume mode (sim/solver/volume.h): the grid's sums, the model's two terms, and what it does
// to a groom.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "sim/solver/cpu_probe.h"
#include "sim/solver/cpu_solver.h"
#include "sim/groom/hairstyle.h"
#include "sim/solver/volume.h"
#include "sim/head/head_model.h"
#include "sim/verify/solver_head.h"

using namespace csm;

namespace {

// A straight strand of n particles from `from` along `dir`, 1 cm apart.
void addStrand(std::vector<glm::dvec3>& x, std::vector<uint32_t>& first, glm::dvec3 from,
               glm::dvec3 dir, int n) {
  for (int i = 0; i < n; ++i) x.push_back(from + 0.01 * i * dir);
  first.push_back(uint32_t(x.size()));
}

}  // namespace

TEST_CASE("volume grid: the sums hold every particle's length and momentum", "[quick]") {
  std::vector<glm::dvec3> x;
  std::vector<uint32_t> first{0};
  for (int s = 0; s < 20; ++s)
    addStrand(x, first, {0.003 * s, 0.0, 0.001 * s}, glm::normalize(glm::dvec3(1, -2, 0.5)), 12);
  VolumeGrid grid;
  grid.reset(x, first, {}, 0.01, 0.0005);
  REQUIRE_FALSE(grid.empty());
  // Every particle carries half of each segment beside it: the strand's length in all.
  double total = 0.0;
  for (double l : grid.particleLength()) total += l;
  CHECK(total == Approx(20 * 11 * 0.01).epsilon(1e-9));
  std::vector<glm::dvec3> v(x.size());
  for (size_t i = 0; i < v.size(); ++i) v[i] = {0.1 * std::sin(double(i)), -0.3, 0.02 * i};
  grid.splat(x, v, Pose{}, 0.2);
  glm::dvec3 momentum(0.0), expected(0.0);
  double length = 0.0;
  const std::vector<int64_t>& q = grid.sums();
  for (size_t n = 0; n < grid.nodes(); ++n) {
    length += double(q[4 * n]) / kVolumeUnit;
    momentum += glm::dvec3(q[4 * n + 1], q[4 * n + 2], q[4 * n + 3]) / kVolumeUnit;
  }
  for (size_t i = 0; i < x.size(); ++i) expected += grid.particleLength()[i] * v[i];
  // Each of 8 contributions per particle rounds to the unit: at most 4 units each.
  const double rounding = 4.0 * 8.0 * double(x.size()) / kVolumeUnit;
  CHECK(std::abs(length - total) <= rounding);
  CHECK(glm::length(momentum - expected) <= 2.0 * rounding);
}

TEST_CASE("volume grid: friction joins the mean velocity, the push leaves over-dense places",
          "[quick]") {
  // A bundle of 40 parallel strands along x, 5 mm apart in y and z at rest.
  std::vector<glm::dvec3> x;
  std::vector<uint32_t> first{0};
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 5; ++b)
      addStrand(x, first, {-0.05, 0.005 * (a - 3.5), 0.005 * (b - 2)}, {1, 0, 0}, 11);
  VolumeGrid grid;
  grid.reset(x, first, {}, 0.01, 0.0005);
  VolumeSettings s;
  s.friction = 10.0;
  s.stiffness = 2.0;
  const double allowed = 0.01;
  const double h = 1.0 / 240.0;
  const double cell = grid.cell();
  // The node nearest the bundle's middle.
  const glm::dvec3 node =
      grid.origin() + cell * glm::floor((glm::dvec3(0.0) - grid.origin()) / cell + 0.5);
  const glm::dvec3 up(0.0, 0.5 * cell, 0.0);

  // At rest the groom's own packing is allowed: no push, and friction has nothing to do.
  grid.splat(x, std::vector<glm::dvec3>(x.size(), glm::dvec3(0.0)), Pose{}, allowed);
  CHECK(glm::length(grid.velocityChange(node + up, {0, 0, 0}, h, s)) == 0.0);

  // The bundle gathered to a tenth of its width around that node, moving along z.
  std::vector<glm::dvec3> gathered = x;
  for (glm::dvec3& p : gathered) p = glm::dvec3(p.x, node.y + 0.1 * p.y, node.z + 0.1 * p.z);
  const glm::dvec3 v(0.0, 0.0, 0.2);
  grid.splat(gathered, std::vector<glm::dvec3>(x.size(), v), Pose{}, allowed);
  const glm::dvec3 above = grid.velocityChange(node + up, v, h, s);
  const glm::dvec3 below = grid.velocityChange(node - up, v, h, s);
  INFO("above " << above.y << " below " << below.y << " m/s");
  CHECK(above.y > 0.0);
  CHECK(below.y < 0.0);
  CHECK(above.y == Approx(-below.y).epsilon(1e-6));  // the bundle is symmetric about the node
  // A particle at rest in the bundle joins its velocity by 1 - exp(-c h) of the difference.
  VolumeSettings frictionOnly = s;
  frictionOnly.stiffness = 0.0;
  const glm::dvec3 still = grid.velocityChange(node, {0, 0, 0}, h, frictionOnly);
  // (to the rounding of the fixed-point sums)
  CHECK(still.z == Approx(0.2 * (1.0 - std::exp(-s.friction * h))).epsilon(1e-4));
  CHECK(std::abs(still.x) + std::abs(still.y) < 1e-12);
  // Where no hair is, nothing changes.
  CHECK(glm::length(grid.velocityChange(node + glm::dvec3(0.0, 0.1, 0.1), v, h, s)) == 0.0);
  // The push turns with the head: the same bundle in a head turned 90 degrees about z, where
  // the head's +y is world -x.
  const glm::dvec3 friction = grid.velocityChange(node + up, v, h, frictionOnly);
  const glm::dvec3 push = above - friction;
  Pose turned;
  turned.rotation = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 0, 1));
  for (glm::dvec3& p : gathered) p = turned.apply(p);
  grid.splat(gathered, std::vector<glm::dvec3>(x.size(), v), turned, allowed);
  const glm::dvec3 world = grid.velocityChange(turned.apply(node + up), v, h, s) - friction;
  CHECK(world.x == Approx(-push.y).epsilon(1e-9));
  CHECK(world.y == Approx(push.x).margin(1e-12));
}

TEST_CASE("volume mode: only a volume mode keeps a grid, built when the mode is chosen",
          "[quick]") {
  Config c;
  c.hairstyle.strands = 200;
  c.collision.mode = CollisionMode::Head;
  c.collision.volumeFraction = 0.02f;  // pushes where hair gathers
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  CpuSolver headOnly, switched;
  resetWithHead(headOnly, g, c, Pose{});
  resetWithHead(switched, g, c, Pose{});
  CHECK(CpuProbe(switched).volumeNodes() == 0);
  for (int f = 0; f < 5; ++f) {
    headOnly.stepFrame(Pose{}, Pose{});
    switched.stepFrame(Pose{}, Pose{});
  }
  Config volume = c;
  volume.collision.mode = CollisionMode::Volume;
  switched.setConfig(volume);
  CHECK(CpuProbe(switched).volumeNodes() > 1000);
  for (int f = 0; f < 20; ++f) {
    headOnly.stepFrame(Pose{}, Pose{});
    switched.stepFrame(Pose{}, Pose{});
  }
  // The grid built mid-run acts: the hair ends elsewhere than with the head alone.
  double apart = 0.0;
  for (size_t i = 0; i < CpuProbe(headOnly).positions().size(); ++i)
    apart = std::max(
        apart, glm::length(CpuProbe(headOnly).positions()[i] - CpuProbe(switched).positions()[i]));
  INFO("farthest particle apart " << apart * 1e3 << " mm");
  CHECK(apart > 1e-4);
  switched.setConfig(c);
  CHECK(CpuProbe(switched).volumeNodes() == 0);
}

TEST_CASE("volume mode: with gravity off the rest groom stays still", "[quick]") {
  Config c;
  c.hairstyle.strands = 300;
  c.sim.gravity = glm::vec3(0.0f);
  c.collision.mode = CollisionMode::Volume;
  c.collision.volumeFraction = 0.01f;  // everything the groom packed is allowed, not more
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  CpuSolver solver;
  resetWithHead(solver, g, c, Pose{});
  const std::vector<glm::dvec3> rest = CpuProbe(solver).positions();
  for (int f = 0; f < 60; ++f) solver.stepFrame(Pose{}, Pose{});
  double moved = 0.0;
  for (size_t i = 0; i < rest.size(); ++i)
    moved = std::max(moved, glm::length(CpuProbe(solver).positions()[i] - rest[i]));
  INFO("farthest particle moved " << moved * 1e3 << " mm");
  CHECK(moved < 1e-4);
}

TEST_CASE("volume mode: hair falling onto itself ends less dense than without it", "[quick]") {
  // Strands grown straight out of the scalp fall under gravity and pile up on the head.
  Config c;
  c.hairstyle.strands = 600;
  c.hairstyle.fall = 0.0f;
  c.collision.volumeFraction = 0.05f;
  c.collision.volumeStiffness = 5.0f;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  auto densest = [&](CollisionMode mode) {
    Config m = c;
    m.collision.mode = mode;
    CpuSolver solver;
    resetWithHead(solver, g, m, Pose{});
    for (int f = 0; f < 60; ++f) solver.stepFrame(Pose{}, Pose{});
    // The densest node over the last state, on a grid of the same geometry.
    VolumeGrid grid;
    std::vector<glm::dvec3> x0;
    for (const glm::vec3& p : g.points) x0.emplace_back(p);
    grid.reset(x0, g.first, {}, m.collision.volumeCell, m.collision.radius);
    grid.splat(CpuProbe(solver).positions(), std::vector<glm::dvec3>(x0.size(), glm::dvec3(0.0)),
               Pose{}, m.collision.volumeFraction);
    int64_t most = 0;
    for (size_t n = 0; n < grid.nodes(); ++n) most = std::max(most, grid.sums()[4 * n]);
    return double(most) * grid.fillPerUnit();
  };
  const double head = densest(CollisionMode::Head), volume = densest(CollisionMode::Volume);
  // Measured: 0.170 against 0.205 (0.83; the scalp a built-in end, the strands grown straight
  // out stand up longer before they fall).
  INFO("densest volume fraction: head only " << head << ", volume " << volume);
  CHECK(volume < 0.85 * head);
}

namespace {

// Strands of `g` listed `copies[s]` times over: the groom a guide of that weight stands for,
// its followers lying where it lies.
void repeatStrands(const std::vector<glm::dvec3>& x, const std::vector<uint32_t>& first,
                   const std::vector<int>& copies, std::vector<glm::dvec3>& outX,
                   std::vector<uint32_t>& outFirst) {
  outX.clear();
  outFirst.assign(1, 0);
  for (size_t s = 0; s + 1 < first.size(); ++s)
    for (int c = 0; c < copies[s]; ++c) {
      outX.insert(outX.end(), x.begin() + first[s], x.begin() + first[s + 1]);
      outFirst.push_back(uint32_t(outX.size()));
    }
}

// The velocity changes of every particle of `x` in a grid splatted with `x` at rest.
std::vector<glm::dvec3> pushes(const VolumeGrid& grid, const std::vector<glm::dvec3>& x,
                               const VolumeSettings& s) {
  std::vector<glm::dvec3> dv;
  for (const glm::dvec3& p : x) dv.push_back(grid.velocityChange(p, glm::dvec3(0.0), 1e-3, s));
  return dv;
}

}  // namespace

TEST_CASE("volume grid: a guide standing for N strands puts N strands' density in the grid",
          "[quick]") {
  std::vector<glm::dvec3> x;
  std::vector<uint32_t> first{0};
  std::vector<float> weight;
  std::vector<int> copies;
  for (int s = 0; s < 12; ++s) {
    addStrand(x, first, {0.004 * s, 0.0, 0.002 * s}, glm::normalize(glm::dvec3(1, -2, 0.5)), 10);
    copies.push_back(1 + s % 5);
    weight.push_back(float(copies.back()));
  }
  std::vector<glm::dvec3> all;
  std::vector<uint32_t> allFirst;
  repeatStrands(x, first, copies, all, allFirst);
  VolumeGrid guided, whole;
  guided.reset(x, first, weight, 0.01, 0.0005);
  whole.reset(all, allFirst, {}, 0.01, 0.0005);
  REQUIRE(guided.nodes() == whole.nodes());
  std::vector<glm::dvec3> v(x.size()), vAll;
  for (size_t i = 0; i < v.size(); ++i) v[i] = {0.05 * std::cos(double(i)), -0.2, 0.01 * i};
  for (size_t s = 0; s + 1 < first.size(); ++s)
    for (int c = 0; c < copies[s]; ++c)
      vAll.insert(vAll.end(), v.begin() + first[s], v.begin() + first[s + 1]);
  guided.splat(x, v, Pose{}, 0.2);
  whole.splat(all, vAll, Pose{}, 0.2);
  // Node by node, length and momentum as the whole groom's, to the sums' rounding (at most half
  // a unit a particle's contribution: once for a guide, once a copy for the groom).
  double worst = 0.0, most = 0.0;
  for (size_t k = 0; k < 4 * guided.nodes(); ++k) {
    worst = std::max(worst, std::abs(double(guided.sums()[k] - whole.sums()[k])));
    most = std::max(most, std::abs(double(whole.sums()[k])));
  }
  INFO("largest sum " << most << " units, largest difference " << worst);
  CHECK(most > 1e5);
  CHECK(worst <= 0.5 * double(all.size() + x.size()));
  // So the rest fraction too, and the fraction a guide's weight of 1 leaves as it was.
  for (size_t n = 0; n < guided.nodes(); ++n)
    CHECK(guided.restFraction()[n] == Approx(whole.restFraction()[n]).margin(1e-6));
  VolumeGrid unweighted;
  unweighted.reset(x, first, {}, 0.01, 0.0005);
  double less = 0.0, more = 0.0;
  for (size_t n = 0; n < guided.nodes(); ++n) {
    less += unweighted.restFraction()[n];
    more += guided.restFraction()[n];
  }
  CHECK(more == Approx(less * 33.0 / 12.0).epsilon(1e-3));  // weights 1..5 over 12 strands: 33
}

TEST_CASE("volume grid: two guides' groups of unequal weight are pushed apart as their weights say",
          "[quick]") {
  // Two bundles of 12 strands along x, 0.3 cells either side of a row of nodes in y (each
  // 0.3 mm across), far denser than allowed; the lower one's guides stand for 1 strand each,
  // the upper one's for 4. At rest the strands lay 10 cm away, so the grid allows nothing more
  // there than collision.volume_fraction.
  const double cell = 0.01, allowed = 0.001;
  std::vector<glm::dvec3> rest;
  std::vector<uint32_t> first{0};
  std::vector<float> weight;
  std::vector<int> copies;
  for (int group = 0; group < 2; ++group)
    for (int k = 0; k < 12; ++k) {
      addStrand(rest, first, {-0.05, 0.0, 0.1}, {1, 0, 0}, 11);
      copies.push_back(group ? 4 : 1);
      weight.push_back(float(copies.back()));
    }
  VolumeGrid probe;
  probe.reset(rest, first, {}, cell, 0.0005);
  const glm::dvec3 node =
      probe.origin() + cell * glm::floor((glm::dvec3(0.0) - probe.origin()) / cell + 0.5);
  std::vector<glm::dvec3> x = rest;
  for (size_t s = 0; s + 1 < first.size(); ++s) {
    const double side = s < 12 ? -1.0 : 1.0;
    const double dy = 0.0001 * double(s % 4) - 0.00015, dz = 0.0001 * double((s / 4) % 3) - 0.0001;
    for (uint32_t i = first[s]; i < first[s + 1]; ++i)
      x[i] = {x[i].x, node.y + side * 0.3 * cell + dy, node.z + dz};
  }
  std::vector<glm::dvec3> all, allRest;
  std::vector<uint32_t> allFirst;
  repeatStrands(x, first, copies, all, allFirst);
  repeatStrands(rest, first, copies, allRest, allFirst);
  VolumeSettings s;
  s.friction = 0.0;
  s.stiffness = 2.0;
  const size_t half = x.size() / 2;  // the lower group's particles come first
  auto groupPush = [&](const std::vector<glm::dvec3>& dv, size_t begin, size_t end) {
    double sum = 0.0;
    for (size_t i = begin; i < end; ++i) sum += dv[i].y;
    return sum / double(end - begin);
  };

  VolumeGrid guided, whole, equal;
  guided.reset(rest, first, weight, cell, 0.0005);
  whole.reset(allRest, allFirst, {}, cell, 0.0005);
  equal.reset(rest, first, {}, cell, 0.0005);
  REQUIRE(guided.origin() == probe.origin());
  guided.splat(x, std::vector<glm::dvec3>(x.size(), glm::dvec3(0.0)), Pose{}, allowed);
  whole.splat(all, std::vector<glm::dvec3>(all.size(), glm::dvec3(0.0)), Pose{}, allowed);
  equal.splat(x, std::vector<glm::dvec3>(x.size(), glm::dvec3(0.0)), Pose{}, allowed);
  const std::vector<glm::dvec3> dvGuided = pushes(guided, x, s), dvWhole = pushes(whole, x, s),
                                dvEqual = pushes(equal, x, s);
  const double lower = groupPush(dvGuided, 0, half), upper = groupPush(dvGuided, half, x.size());
  const double lowerEqual = groupPush(dvEqual, 0, half),
               upperEqual = groupPush(dvEqual, half, x.size());
  INFO("weights 1 and 4: lower " << lower << ", upper " << upper
                                 << " m/s; weights 1 and 1: " << lowerEqual << ", " << upperEqual);
  // Apart: the lower group down, the upper up.
  CHECK(lower < 0.0);
  CHECK(upper > 0.0);
  // Each particle pushed as the strands it stands for would be: the guided grid's push is the
  // whole groom's, to the sums' rounding.
  for (size_t i = 0; i < x.size(); ++i)
    CHECK(glm::length(dvGuided[i] - dvWhole[i]) <= 1e-4 * glm::length(dvWhole[i]) + 1e-9);
  // Of equal weights the two give way alike; of weights 1 and 4 each gives way in inverse
  // proportion to its weight, as a pressure between them would move them (equal and opposite
  // momentum: 1 x the light group's change against 4 x the heavy one's).
  CHECK(-lowerEqual == Approx(upperEqual).epsilon(1e-4));
  CHECK(-lower == Approx(4.0 * upper).epsilon(0.1));
  CHECK(-lower > 2.0 * -lowerEqual);
}

TEST_CASE("volume mode: a groom whose every weight is 1 steps as one with none, to the byte",
          "[quick]") {
  Config c;
  c.hairstyle.strands = 200;
  c.collision.mode = CollisionMode::Volume;
  c.collision.volumeFraction = 0.02f;  // pushes where hair gathers
  c.head.motion = HeadMotion::Nod;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  Groom ones = g, heavy = g;
  ones.weight.assign(g.strandCount(), 1.0f);
  heavy.weight.assign(g.strandCount(), 6.0f);
  auto run = [&](const Groom& groom) {
    CpuSolver solver;
    resetWithHead(solver, groom, c, headPose(c.head, 0.0));
    for (int f = 0; f < 20; ++f)
      solver.stepFrame(headPose(c.head, f * c.sim.dt), headPose(c.head, (f + 1) * c.sim.dt));
    return CpuProbe(solver).positions();
  };
  const std::vector<glm::dvec3> none = run(g), one = run(ones), six = run(heavy);
  REQUIRE(none.size() == one.size());
  CHECK(std::memcmp(none.data(), one.data(), none.size() * sizeof(glm::dvec3)) == 0);
  // And a weight does act: six strands' density a guide pushes the hair elsewhere.
  double apart = 0.0;
  for (size_t i = 0; i < none.size(); ++i) apart = std::max(apart, glm::length(six[i] - none[i]));
  INFO("farthest particle apart " << apart * 1e3 << " mm");
  CHECK(apart > 1e-4);
}
