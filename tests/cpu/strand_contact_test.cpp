// Strand contacts on the CPU reference (sim/contacts.h): candidates, measures, and contacts
// that hold one strand on another.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include <glm/geometric.hpp>

#include "sim/collision.h"
#include "sim/contacts.h"
#include "sim/cpu/cpu_solver.h"
#include "sim/hairstyle.h"
#include "tests/cpu/test_scenes.h"
#include "tests/strand_contact_scenes.h"

using namespace csm;

namespace {

std::vector<glm::vec4> positions(Solver& s) {
  std::vector<glm::vec4> x;
  s.readPositions(x);
  return x;
}

test::Drape drape(CollisionMode mode, double seconds) {
  Config c = test::drapeConfig();
  c.collision.mode = mode;
  CpuSolver solver;
  solver.reset(test::drapeGroom(), c, Pose{});
  for (int f = 0; f < int(std::lround(seconds / c.sim.dt)); ++f) solver.stepFrame(Pose{}, Pose{});
  return test::measureDrape(positions(solver));
}

}  // namespace

TEST_CASE("a strand dropped across another stays on top for 2 s") {
  const test::Drape on = drape(CollisionMode::Strands, 2.0);
  const test::Drape off = drape(CollisionMode::Head, 2.0);
  INFO("with contacts: " << on.distance * 1e3 << " mm apart, " << on.height * 1e3
                         << " mm above; without: " << off.distance * 1e3 << " mm apart, "
                         << off.height * 1e3 << " mm above");
  const double r = test::drapeConfig().collision.radius;
  CHECK(on.height > 1.5 * r);    // on top
  CHECK(on.distance > 1.5 * r);  // less than half r inside the contact distance
  // Without strand contacts it falls through.
  CHECK(off.height < 0.0);
}

TEST_CASE("with gravity off the rest groom stays still for 1 s with strand contacts") {
  Config c;
  c.hairstyle.strands = 300;
  c.sim.gravity = glm::vec3(0.0f);
  c.collision.mode = CollisionMode::Strands;
  const Groom g = growHairstyle(c);
  CpuSolver solver;
  solver.reset(g, c, Pose{});
  const std::vector<glm::vec4> rest = positions(solver);
  for (int f = 0; f < 60; ++f) solver.stepFrame(Pose{}, Pose{});
  const std::vector<glm::vec4> x = positions(solver);
  double moved = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
    moved = std::max(moved, double(glm::length(glm::vec3(x[i]) - glm::vec3(rest[i]))));
  INFO("farthest particle moved " << moved * 1e3 << " mm; " << solver.contactStats().candidates
                                  << " candidate pairs");
  CHECK(solver.contactStats().candidates > 0);
  CHECK(moved < 1e-4);
}

TEST_CASE("candidates: both sides listed, rest distance kept, crossings counted") {
  // Two segments of two strands crossing as an X 1 mm apart at rest (r = 1 mm: closer than
  // 2r), and a third strand 3 mm away from the first.
  std::vector<glm::dvec3> rest = {{-0.01, 0.0, 0.0},    {0.01, 0.0, 0.0},      // strand 0
                                  {0.0, 0.001, -0.01},  {0.0, 0.001, 0.01},    // strand 1
                                  {-0.01, -0.003, 0.0}, {0.01, -0.003, 0.0}};  // strand 2
  const std::vector<uint32_t> strand = {0, 0, 1, 1, 2, 2};
  ContactSettings settings;
  settings.radius = 0.001;
  settings.margin = 0.0015;
  ContactStats stats;
  const ContactCandidates first = findCandidates(rest, rest, strand, settings, {}, stats);
  REQUIRE(first.start.size() == 7);
  // Segment 0 has both others (1 mm and 3 mm < 2r + margin = 3.5 mm); 2 and 4 (4 mm apart)
  // have segment 0 only.
  CHECK(first.start[1] - first.start[0] == 2);
  CHECK(first.other[first.start[0]] == 2);
  CHECK(first.other[first.start[0] + 1] == 4);
  CHECK(first.distance[first.start[0]] == Approx(0.001));  // its rest distance, not 2r
  CHECK(first.distance[first.start[0] + 1] == Approx(0.002));
  CHECK(first.start[3] - first.start[2] == 1);
  CHECK(first.start[5] - first.start[4] == 1);
  CHECK(stats.candidates == 2);
  CHECK(stats.contacts == 1);  // 0-2 closer than 2r
  CHECK(stats.penetrations == 0);
  CHECK(stats.depthQuantile(0.5) == 0.0);  // at rest nothing is inside its contact distance
  CHECK(stats.crossings == 0);

  // Strand 1 passes through strand 0: the pair's orientation flips.
  std::vector<glm::dvec3> x = rest;
  x[2].y = x[3].y = -0.0005;
  ContactStats after;
  const ContactCandidates second = findCandidates(x, rest, strand, settings, first, after);
  CHECK(after.crossings == 1);
  CHECK(after.crossingsClose == 1);                   // its contact distance is its rest distance
  CHECK(after.penetrations == 1);                     // 0.5 mm < r
  CHECK(after.maxDepth == Approx(0.5).margin(0.01));  // 1 mm contact distance - 0.5 mm
  CHECK(after.depthQuantile(0.5) == Approx(0.5).margin(1.0 / kDepthBinsPerR));
  (void)second;
}

TEST_CASE("a skew pair keeps the side it was listed on: one passed through is pushed back") {
  // Segment 0 along x; segment 2 (another strand) along z 3 mm above it; segment 4 along x,
  // parallel to segment 0, 3 mm below it. r = 1 mm, margin 1.5 mm: both pairs are listed.
  const std::vector<glm::dvec3> rest = {{-0.01, 0.0, 0.0},    {0.01, 0.0, 0.0},
                                        {0.0, 0.003, -0.01},  {0.0, 0.003, 0.01},
                                        {-0.01, -0.003, 0.0}, {0.01, -0.003, 0.0}};
  const std::vector<uint32_t> strand = {0, 0, 1, 1, 2, 2};
  ContactSettings settings;
  settings.radius = 0.001;
  settings.margin = 0.0015;
  ContactStats stats;
  ContactCandidates c = findCandidates(rest, rest, strand, settings, {}, stats);
  REQUIRE(c.start[1] - c.start[0] == 2);
  REQUIRE(c.other[c.start[0]] == 2);
  // The sign of the pair's triple product (segment 0 below segment 2); the parallel pair has
  // no side to keep.
  CHECK(c.side[c.start[0]] == 1);
  CHECK(c.side[c.start[2]] == 1);  // the same pair from the other side
  CHECK(c.side[c.start[0] + 1] == 0);

  // Within the frame, segment 2 passes through segment 0 and ends 0.5 mm below it.
  std::vector<glm::dvec3> x = rest, v(rest.size(), glm::dvec3(0.0));
  x[2].y = x[3].y = -0.0005;
  const std::vector<double> invMass(rest.size(), 1.0);
  std::vector<glm::dvec4> correction;
  solveContacts(c, x, v, invMass, 1.0 / 240.0, settings, correction);
  // Pushed back: segment 0 down, segment 2 up, the whole way back to 2r apart (a hard
  // contact, four equal masses, both at the middle: each segment's particles move half of
  // the 2.5 mm).
  CHECK(correction[0].y == Approx(-0.5 * 2.5e-3));
  CHECK(correction[4].y == Approx(0.5 * 2.5e-3));
  // Along the closest points alone, the same pair would be pushed on through.
  std::fill(c.side.begin(), c.side.end(), int8_t(0));
  solveContacts(c, x, v, invMass, 1.0 / 240.0, settings, correction);
  CHECK(correction[0].y > 0.0);
  CHECK(correction[4].y < 0.0);
}

TEST_CASE("with hair-hair off, samples measure contacts only when asked, and then all of them") {
  Config c;
  c.hairstyle.strands = 400;
  c.collision.mode = CollisionMode::Head;
  const Groom g = growHairstyle(c);
  CpuSolver solver;
  solver.reset(g, c, Pose{});
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(1);
  const FrameSample off = solver.takeSample().value();
  CHECK_FALSE(off.contactsMeasured);
  CHECK(off.contacts.contacts == 0);

  solver.setContactMeasures(true);
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(2);
  const FrameSample on = solver.takeSample().value();
  const std::vector<uint32_t> strand = test::strandOf(g);
  const double r = c.collision.radius;
  const size_t within2r = findContactsGrid(solver.positions(), strand, 2.0 * r).size();
  const size_t withinR = findContactsGrid(solver.positions(), strand, r).size();
  INFO("pairs closer than 2r " << within2r << ", than r " << withinR);
  CHECK(on.contactsMeasured);
  CHECK(withinR > 0);
  CHECK(on.contacts.contacts == within2r);
  CHECK(on.contacts.penetrations == withinR);
  // The simulation is the same with the measures on: they change no state.
  CpuSolver plain;
  plain.reset(g, c, Pose{});
  plain.stepFrame(Pose{}, Pose{});
  plain.stepFrame(Pose{}, Pose{});
  const std::vector<glm::vec4> a = positions(solver), b = positions(plain);
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)) == 0);
}

TEST_CASE("more contact iterations hold dense hair in the wind apart better") {
  // Fig. 1's strands (0.4 mm radius, 22-30 cm, straight) in its wind, 800 of them: each
  // substep's one Jacobi iteration averages what a segment's contacts ask, so a crowded one
  // moves a fraction of the way; more iterations (collision.iterations) go further. Measured
  // on 2,000 strands of Fig. 1, 8 frames: 4 iterations cross 2.4x less than 1 and leave 40%
  // fewer pairs closer than r.
  Config c = test::smallScene(800);
  c.hairstyle.minParticles = c.hairstyle.maxParticles = 16;
  c.hairstyle.lengthMin = 0.22f;
  c.hairstyle.lengthMax = 0.30f;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = 0.0004f;
  c.wind.strength = 3.0f;
  c.wind.direction = glm::vec3(1.0f, 0.0f, -0.4f);
  const Groom g = growHairstyle(c);
  struct Run {
    uint64_t crossings = 0, penetrations = 0;
  };
  auto run = [&](int iterations) {
    Config ci = c;
    ci.collision.iterations = iterations;
    CpuSolver solver;
    solver.reset(g, ci, Pose{});
    Run out;
    for (int f = 0; f < 16; ++f) {
      solver.stepFrame(Pose{}, Pose{});
      out.crossings += solver.contactStats().crossings;
    }
    out.penetrations = solver.contactStats().penetrations;
    return out;
  };
  const Run one = run(1), four = run(4);
  INFO("crossings over 16 frames: " << one.crossings << " with 1 iteration, " << four.crossings
                                    << " with 4; pairs closer than r at the end: "
                                    << one.penetrations << ", " << four.penetrations);
  CHECK(one.crossings > 100);
  CHECK(double(four.crossings) < 0.7 * double(one.crossings));
  CHECK(four.penetrations < one.penetrations);
}

TEST_CASE("lists within the frame catch a strand that closes in faster than the margin") {
  // The thrown scene (tests/strand_contact_scenes.h): the strand swings down 2.4 mm in the
  // first frame from 3 mm above the bar, further than the margin (the pair is not listed
  // where the frame starts: 2r + margin is 1.5 mm), back up, and down again. One list a frame
  // catches it only once it is inside 2r (measured: 0.52 mm, then 0.02 mm apart, both deeper
  // than r); four (one a substep) list it within the frame and hold it at 2r.
  struct Thrown {
    double lowest = 1e30;   // the strand's lowest height over the bar where it crosses it
    double closest = 1e30;  // the closest the two came at a frame's end
  };
  auto thrown = [&](int lists) {
    CpuSolver solver;
    solver.reset(test::thrownGroom(), test::thrownConfig(lists), Pose{});
    REQUIRE(solver.stiffness().plan.substeps == 4);
    const std::vector<glm::vec4> x = positions(solver);
    solver.writeState(x, test::throwDown(x));
    Thrown out;
    for (int f = 0; f < 6; ++f) {
      solver.stepFrame(Pose{}, Pose{});
      const test::Drape d = test::measureDrape(positions(solver));
      out.lowest = std::min(out.lowest, d.height);
      out.closest = std::min(out.closest, d.distance);
    }
    return out;
  };
  const double twoR = 2.0 * double(test::thrownConfig(1).collision.radius);
  const Thrown one = thrown(1), four = thrown(4), sixteen = thrown(16);
  INFO("closest: " << one.closest << " m with 1 list a frame, " << four.closest << " m with 4, "
                   << sixteen.closest
                   << " m asking for 16; lowest over the bar with 4: " << four.lowest << " m");
  CHECK(one.closest < 0.5 * twoR);
  CHECK(four.closest > 0.95 * twoR);
  CHECK(four.lowest > 0.0);
  // More lists than substeps: one a substep.
  CHECK(sixteen.closest == four.closest);
}

TEST_CASE("lists within the frame: where they come, and what they measure") {
  // Spread over the substeps, the frame's own list before substep 0.
  auto before = [](int substeps, int lists) {
    std::vector<int> at;
    for (int k = 0; k < substeps; ++k)
      if (listsBefore(k, substeps, lists)) at.push_back(k);
    return at;
  };
  CHECK(before(4, 1).empty());
  CHECK(before(4, 2) == std::vector<int>{2});
  CHECK(before(4, 3) == std::vector<int>{1, 2});
  CHECK(before(4, 4) == std::vector<int>{1, 2, 3});
  CHECK(before(4, 16) == std::vector<int>{1, 2, 3});
  CHECK(before(1, 4).empty());
  CHECK(before(8, 3) == std::vector<int>{2, 5});
  // The frame's measures are of where it starts, whatever the lists within it: the same
  // candidates, contacts and depths as one list a frame after the first frame (which starts
  // from the same state), and crossings of the lists within the frame added.
  Config c = test::smallScene(300);
  c.collision.mode = CollisionMode::Strands;
  c.wind.strength = 3.0f;
  const Groom g = growHairstyle(c);
  auto first = [&](int lists) {
    Config cl = c;
    cl.collision.lists = lists;
    CpuSolver solver;
    solver.reset(g, cl, Pose{});
    solver.stepFrame(Pose{}, Pose{});
    return solver.contactStats();
  };
  const ContactStats one = first(1), four = first(4);
  CHECK(four.candidates == one.candidates);
  CHECK(four.contacts == one.contacts);
  CHECK(four.penetrations == one.penetrations);
  CHECK(four.depth == one.depth);
  CHECK(one.crossings == 0);  // no list before the first
  CHECK(four.crossings >= one.crossings);
}
