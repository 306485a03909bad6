// Strand contacts on the CPU reference (sim/solver/contacts.h): candidates, measures, and contacts
// that hold one strand on another.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "sim/solver/cpu_probe.h"
#include "sim/core/measure_sample.h"
#include "sim/core/segment_pairs.h"
#include "sim/solver/contacts.h"
#include "sim/solver/cpu_solver.h"
#include "sim/groom/hairstyle.h"
#include "sim/head/head_model.h"
#include "tests/cpu/test_scenes.h"
#include "tests/strand_contact_scenes.h"
#include "sim/verify/solver_head.h"

using namespace csm;

namespace {

std::vector<glm::vec4> positions(Solver& s) {
  std::vector<glm::vec4> x;
  s.state().readPositions(x);
  return x;
}

test::Drape drape(CollisionMode mode, double seconds) {
  Config c = test::drapeConfig();
  c.collision.mode = mode;
  CpuSolver solver;
  resetWithHead(solver, test::drapeGroom(), c, Pose{});
  for (int f = 0; f < int(std::lround(seconds / c.sim.dt)); ++f) solver.stepFrame(Pose{}, Pose{});
  return test::measureDrape(positions(solver));
}

// The hand-built scenes below: r = 1 mm, pairs listed within 1.5 mm of 2r.
ContactSettings millimetreContacts() {
  ContactSettings settings;
  settings.radius = 0.001;
  settings.margin = 0.0015;
  return settings;
}

// One substep's corrections (1/240 s) of particles x at rest (no velocity).
std::vector<glm::dvec4> solveStill(const ContactCandidates& c, const std::vector<glm::dvec3>& x,
                                   const std::vector<double>& invMass,
                                   const ContactSettings& settings) {
  const std::vector<glm::dvec3> v(x.size(), glm::dvec3(0.0));
  std::vector<glm::dvec4> correction;
  solveContacts(c, x, v, invMass, 1.0 / 240.0, settings, correction);
  return correction;
}

// Two segments of two strands crossing as an X, listed 2.5 mm apart (r = 1 mm: contact
// distance 2r = 2 mm), then the upper one moved down to 1.5 mm: 0.5 mm inside.
struct CrossedPair {
  ContactCandidates candidates;
  std::vector<glm::dvec3> x;
};
CrossedPair crossedPair(const ContactSettings& settings) {
  const std::vector<glm::dvec3> rest = {
      {-0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}, {0.0, 0.0025, -0.01}, {0.0, 0.0025, 0.01}};
  const std::vector<uint32_t> strand = {0, 0, 1, 1};
  ContactStats stats;
  CrossedPair out{findCandidates(rest, rest, strand, settings, {}, stats), rest};
  out.x[2].y = out.x[3].y = 0.0015;
  return out;
}

}  // namespace

TEST_CASE("a strand dropped across another stays on top for 2 s", "[quick]") {
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

TEST_CASE("with gravity off the rest groom stays still for 1 s with strand contacts", "[quick]") {
  Config c;
  c.hairstyle.strands = 300;
  c.sim.gravity = glm::vec3(0.0f);
  c.collision.mode = CollisionMode::Strands;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  CpuSolver solver;
  resetWithHead(solver, g, c, Pose{});
  const std::vector<glm::vec4> rest = positions(solver);
  for (int f = 0; f < 60; ++f) solver.stepFrame(Pose{}, Pose{});
  const std::vector<glm::vec4> x = positions(solver);
  double moved = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
    moved = std::max(moved, double(glm::length(glm::vec3(x[i]) - glm::vec3(rest[i]))));
  INFO("farthest particle moved " << moved * 1e3 << " mm; "
                                  << CpuProbe(solver).contactStats().candidates
                                  << " candidate pairs");
  CHECK(CpuProbe(solver).contactStats().candidates > 0);
  CHECK(moved < 1e-4);
}

TEST_CASE("candidates: both sides listed, rest distance kept, crossings counted", "[quick]") {
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

TEST_CASE("a skew pair keeps the side it was listed on: one passed through is pushed back",
          "[quick]") {
  // Segment 0 along x; segment 2 (another strand) along z 3 mm above it; segment 4 along x,
  // parallel to segment 0, 3 mm below it. r = 1 mm, margin 1.5 mm: both pairs are listed.
  const std::vector<glm::dvec3> rest = {{-0.01, 0.0, 0.0},    {0.01, 0.0, 0.0},
                                        {0.0, 0.003, -0.01},  {0.0, 0.003, 0.01},
                                        {-0.01, -0.003, 0.0}, {0.01, -0.003, 0.0}};
  const std::vector<uint32_t> strand = {0, 0, 1, 1, 2, 2};
  const ContactSettings settings = millimetreContacts();
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
  std::vector<glm::dvec3> x = rest;
  x[2].y = x[3].y = -0.0005;
  const std::vector<double> invMass(rest.size(), 1.0);
  std::vector<glm::dvec4> correction = solveStill(c, x, invMass, settings);
  // Pushed back: segment 0 down, segment 2 up, the whole way back to 2r apart (a hard
  // contact, four equal masses, both at the middle: each segment's particles move half of
  // the 2.5 mm).
  CHECK(correction[4].y == Approx(0.5 * 2.5e-3));
  // Segment 0 sweeps its list in order: pushed 1.25 mm down, it is 1.75 mm from segment 4,
  // the next in its list, which sends it back up by half of the 0.25 mm.
  CHECK(correction[0].y == Approx(-0.5 * 2.5e-3 + 0.5 * 0.25e-3));
  CHECK(correction[0].w == 1.0);
  // Along the closest points alone, the same pair would be pushed on through.
  std::fill(c.side.begin(), c.side.end(), int8_t(0));
  correction = solveStill(c, x, invMass, settings);
  CHECK(correction[0].y > 0.0);
  CHECK(correction[4].y < 0.0);
}

TEST_CASE("a segment sweeps its list: one deep pair among shallow ones is resolved at once",
          "[quick]") {
  // Segment 0 along x; three segments of other strands across it along z: one 1 mm inside 2r
  // at its middle, two 0.1 mm inside at 6 mm either side. r = 1 mm, a hard contact, equal
  // masses. Each segment moves its own ends by each pair's share in list order, so segment 0
  // moves 0.5 mm out of the deep pair first and the shallow ones are met on the way; a mean
  // of what its three pairs ask would move its ends 0.2 mm and leave the deep pair 0.3 mm
  // inside after the iteration.
  auto across = [](double x, double y) {
    return std::array{glm::dvec3(x, y, -0.01), glm::dvec3(x, y, 0.01)};
  };
  std::vector<glm::dvec3> x = {{-0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}};
  for (auto [at, height] :
       {std::pair(0.0, 0.001), std::pair(-0.006, 0.0019), std::pair(0.006, 0.0019)})
    for (const glm::dvec3& p : across(at, height)) x.push_back(p);
  std::vector<glm::dvec3> rest = x;  // at rest the three lay 5 mm higher: contact distance 2r
  for (size_t i = 2; i < rest.size(); ++i) rest[i].y += 0.005;
  const std::vector<uint32_t> strand = {0, 0, 1, 1, 2, 2, 3, 3};
  ContactSettings settings = millimetreContacts();
  ContactStats stats;
  const ContactCandidates c = findCandidates(x, rest, strand, settings, {}, stats);
  REQUIRE(c.start[1] - c.start[0] == 3);
  const std::vector<double> invMass(x.size(), 1.0);
  std::vector<glm::dvec4> correction = solveStill(c, x, invMass, settings);
  // Each segment is a strand of its own here: its ends take what it sent.
  std::vector<glm::dvec3> moved = x;
  for (size_t a = 0; a < x.size(); a += 2) {
    moved[a] += glm::dvec3(correction[2 * a]);
    moved[a + 1] += glm::dvec3(correction[2 * a + 1]);
  }
  CHECK(correction[0].w == 1.0);
  CHECK(correction[0].y == Approx(-0.5e-3));
  CHECK(correction[1].y == Approx(-0.5e-3));
  for (uint32_t b : {2u, 4u, 6u}) {
    double s, t;
    const double d =
        std::sqrt(closestSegmentPoints(moved[0], moved[1], moved[b], moved[b + 1], s, t));
    INFO("segment " << b << " is " << d * 1e3 << " mm from segment 0");
    CHECK(d > 0.999 * 2.0 * settings.radius);
  }
  // collision.solve = jacobi: the sum of the three pairs' shares from where segment 0 began,
  // sent as three (0.5 mm for the deep one, 0.0847 mm for each shallow one at its lever).
  settings.solve = ContactSolve::Jacobi;
  correction = solveStill(c, x, invMass, settings);
  CHECK(correction[0].w == 3.0);
  CHECK(correction[0].y / correction[0].w == Approx(-0.195e-3).epsilon(0.01));
}

TEST_CASE("a sweep moves no end further than 2.5 times the pair's depth, whatever the lever",
          "[quick]") {
  // Segment 0's first particle is held; a held segment crosses it 2 mm from that end (s = 0.1)
  // 0.5 mm inside 2r. To move the contact point 0.5 mm the free end would move 5 mm (W =
  // s^2): jacobi does, the sweep moves it at most 2.5 times the depth, 1.25 mm.
  const std::vector<glm::dvec3> x = {
      {-0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}, {-0.008, 0.0015, -0.01}, {-0.008, 0.0015, 0.01}};
  std::vector<glm::dvec3> rest = x;
  rest[2].y = rest[3].y = 0.006;
  const std::vector<uint32_t> strand = {0, 0, 1, 1};
  ContactSettings settings = millimetreContacts();
  ContactStats stats;
  const ContactCandidates c = findCandidates(x, rest, strand, settings, {}, stats);
  REQUIRE(c.start[1] - c.start[0] == 1);
  const std::vector<double> invMass = {0.0, 1.0, 0.0, 0.0};
  std::vector<glm::dvec4> correction = solveStill(c, x, invMass, settings);
  CHECK(correction[0].y == 0.0);
  CHECK(correction[1].y == Approx(-1.25e-3));
  settings.solve = ContactSolve::Jacobi;
  correction = solveStill(c, x, invMass, settings);
  CHECK(correction[1].y == Approx(-5e-3));
}

TEST_CASE("a listed pair whose other segment is no longer finite moves nothing", "[quick]") {
  // Segment 0 along x, segment 2 across it 1 mm inside 2r; then segment 2 goes NaN (or to
  // infinity) after the list was made, as a segment of an exploding strand kept in a list.
  // The pair asks nothing of segment 0 and the NaN stays where it is.
  std::vector<glm::dvec3> x = {
      {-0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}, {0.0, 0.001, -0.01}, {0.0, 0.001, 0.01}};
  std::vector<glm::dvec3> rest = x;
  rest[2].y = rest[3].y = 0.006;
  const std::vector<uint32_t> strand = {0, 0, 1, 1};
  const ContactSettings settings = millimetreContacts();
  ContactStats stats;
  const ContactCandidates c = findCandidates(x, rest, strand, settings, {}, stats);
  REQUIRE(c.start[1] - c.start[0] == 1);
  const std::vector<double> invMass(x.size(), 1.0);
  REQUIRE(solveStill(c, x, invMass, settings)[0].y < 0.0);  // listed and pushed while finite
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    std::vector<glm::dvec3> broken = x;
    broken[2].y = broken[3].y = bad;
    for (ContactSolve solve : {ContactSolve::Sweep, ContactSolve::Jacobi}) {
      ContactSettings s = settings;
      s.solve = solve;
      const std::vector<glm::dvec4> correction = solveStill(c, broken, invMass, s);
      INFO("other segment at y = " << bad << ", solve " << int(solve));
      CHECK(glm::dvec3(correction[0]) == glm::dvec3(0.0));
      CHECK(glm::dvec3(correction[1]) == glm::dvec3(0.0));
      CHECK(correction[0].w == 0.0);
    }
  }
}

TEST_CASE("the contact measures' strand sample: whole up to the budget, 1 in n beyond, by hash",
          "[quick]") {
  CHECK(measureStride(0) == 1);
  CHECK(measureStride(CSM_MEASURED_PARTICLES) == 1);
  CHECK(measureStride(CSM_MEASURED_PARTICLES + 1) == 2);
  CHECK(measureStride(10 * CSM_MEASURED_PARTICLES) == 10);
  for (uint32_t s = 0; s < 1000; ++s) CHECK(inMeasureSample(s, 1));
  // About 1 strand in n, and neighbours in the strands' order (which follows the scalp) as
  // often both in the sample as any two: a pair is in it with chance 1/n^2, not 0 or 1/n.
  const uint32_t n = 5, strands = 200000;
  uint32_t in = 0, pairs = 0;
  for (uint32_t s = 0; s < strands; ++s) {
    in += inMeasureSample(s, n);
    pairs += inMeasureSample(s, n) && inMeasureSample(s + 1, n);
  }
  CHECK(double(in) == Approx(strands / n).epsilon(0.03));
  CHECK(double(pairs) == Approx(strands / (n * n)).epsilon(0.1));
}

TEST_CASE("with hair-hair off, a hair over the budget is measured on its strand sample",
          "[quick]") {
  Config c;
  c.hairstyle.strands = 4000;
  c.collision.mode = CollisionMode::Head;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  REQUIRE(g.pointCount() > CSM_MEASURED_PARTICLES);
  const uint32_t stride = measureStride(g.pointCount());
  REQUIRE(stride >= 2);
  CpuSolver solver;
  resetWithHead(solver, g, c, Pose{});
  solver.setContactMeasures(true);
  const std::vector<glm::dvec3> start(CpuProbe(solver).positions().begin(),
                                      CpuProbe(solver).positions().end());
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(1);
  const FrameSample on = solver.takeSample(false).value();
  // The strands outside the sample as strands of one particle each: no segments.
  const std::vector<uint32_t> strand = test::strandOf(g), sampled = sampledStrands(strand, stride);
  const double r = c.collision.radius;
  const size_t sample = findContactsGrid(start, sampled, r).size();
  const size_t whole = findContactsGrid(start, strand, r).size();
  INFO("pairs closer than r: " << whole << ", in the sample of 1 strand in " << stride << ": "
                               << sample << "; measured " << on.contacts.penetrations);
  CHECK(on.contactsMeasured);
  CHECK(on.contacts.measureStride == stride);
  CHECK(sample > 0);
  CHECK(on.contacts.penetrations == sample);
  CHECK(on.contacts.contacts == findContactsGrid(start, sampled, 2.0 * r).size());
  // A pair is in the sample when both its strands are: about 1 in stride^2 of the whole's.
  CHECK(double(sample) * stride * stride == Approx(double(whole)).epsilon(0.25));
}

TEST_CASE("with hair-hair off, samples measure contacts only when asked, and then all of them",
          "[quick]") {
  Config c;
  c.hairstyle.strands = 400;
  c.collision.mode = CollisionMode::Head;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  CpuSolver solver;
  resetWithHead(solver, g, c, Pose{});
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(1);
  const FrameSample off = solver.takeSample(false).value();
  CHECK_FALSE(off.contactsMeasured);
  CHECK(off.contacts.contacts == 0);

  // Measured where the frame starts, as a strand mode's list is: every mode the same state.
  solver.setContactMeasures(true);
  const std::vector<glm::dvec3> start(CpuProbe(solver).positions().begin(),
                                      CpuProbe(solver).positions().end());
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(2);
  const FrameSample on = solver.takeSample(false).value();
  const std::vector<uint32_t> strand = test::strandOf(g);
  const double r = c.collision.radius;
  const size_t within2r = findContactsGrid(start, strand, 2.0 * r).size();
  const size_t withinR = findContactsGrid(start, strand, r).size();
  const size_t endWithinR = findContactsGrid(CpuProbe(solver).positions(), strand, r).size();
  INFO("pairs closer than 2r " << within2r << ", than r " << withinR << " where the frame "
                               << "starts; closer than r where it ends " << endWithinR);
  CHECK(on.contactsMeasured);
  CHECK(withinR > 0);
  CHECK(endWithinR != withinR);  // the two states tell apart
  CHECK(on.contacts.contacts == within2r);
  CHECK(on.contacts.penetrations == withinR);
  // The simulation is the same with the measures on: they change no state.
  CpuSolver plain;
  resetWithHead(plain, g, c, Pose{});
  plain.stepFrame(Pose{}, Pose{});
  plain.stepFrame(Pose{}, Pose{});
  const std::vector<glm::vec4> a = positions(solver), b = positions(plain);
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)) == 0);

  // The next frame: measured by the search its sample before made of where it starts.
  const std::vector<glm::dvec3> start3 = CpuProbe(solver).positions();
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(3);
  const FrameSample third = solver.takeSample(false).value();
  CHECK(third.contacts.penetrations == findContactsGrid(start3, strand, r).size());
  CHECK(third.contacts.contacts == findContactsGrid(start3, strand, 2.0 * r).size());
  // Frames stepped with no sample between: the sample measures where its frame ends.
  solver.stepFrame(Pose{}, Pose{});
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(5);
  const FrameSample fifth = solver.takeSample(false).value();
  CHECK(fifth.contacts.penetrations ==
        findContactsGrid(CpuProbe(solver).positions(), strand, r).size());
  // A new radius measures other pairs: the next sample, of where its frame starts, with them.
  c.collision.radius *= 1.5f;
  solver.setConfig(c);
  const std::vector<glm::dvec3> start6 = CpuProbe(solver).positions();
  solver.stepFrame(Pose{}, Pose{});
  solver.requestSample(6);
  const FrameSample sixth = solver.takeSample(false).value();
  CHECK(sixth.contacts.penetrations == findContactsGrid(start6, strand, c.collision.radius).size());
  CHECK(sixth.contacts.crossings == 0);  // nothing measured before it with this radius
}

TEST_CASE("more contact iterations hold dense hair in the wind apart better") {
  // Fig. 1's strands (0.4 mm radius, 22-30 cm, straight) in its wind, 800 of them: within an
  // iteration a segment's neighbours stay where it began, so a crowd is held apart a part of
  // the way; more iterations (collision.iterations) go further. Measured on 2,000 strands of
  // Fig. 1, 8 frames, with the mean of the pairs (collision.solve = jacobi): 4 iterations
  // cross 2.4x less than 1 and leave 40% fewer pairs closer than r.
  Config c = test::smallScene(800);
  c.hairstyle.minParticles = c.hairstyle.maxParticles = 16;
  c.hairstyle.lengthMin = 0.22f;
  c.hairstyle.lengthMax = 0.30f;
  c.collision.mode = CollisionMode::Strands;
  c.collision.radius = 0.0004f;
  c.wind.strength = 3.0f;
  c.wind.direction = glm::vec3(1.0f, 0.0f, -0.4f);
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  struct Run {
    uint64_t crossings = 0, penetrations = 0;
  };
  auto run = [&](int iterations) {
    Config ci = c;
    ci.collision.iterations = iterations;
    CpuSolver solver;
    resetWithHead(solver, g, ci, Pose{});
    Run out;
    for (int f = 0; f < 16; ++f) {
      solver.stepFrame(Pose{}, Pose{});
      out.crossings += CpuProbe(solver).contactStats().crossings;
    }
    out.penetrations = CpuProbe(solver).contactStats().penetrations;
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

TEST_CASE("lists within the frame catch a strand that closes in faster than the margin",
          "[quick]") {
  // The thrown scene (tests/strand_contact_scenes.h): the strand swings down 2.4 mm in the
  // first frame from 3 mm above the bar, further than the margin (the pair is not listed
  // where the frame starts: 2r + margin is 1.5 mm), back up, and down again. One list a frame
  // catches it only once it is well inside 2r (measured: 0.53 mm apart at a frame's end, about
  // r); four (one a substep) list it within the frame and hold it at 2r.
  struct Thrown {
    double lowest = 1e30;   // the strand's lowest height over the bar where it crosses it
    double closest = 1e30;  // the closest the two came at a frame's end
  };
  auto thrown = [&](int lists) {
    CpuSolver solver;
    resetWithHead(solver, test::thrownGroom(), test::thrownConfig(lists), Pose{});
    REQUIRE(solver.stiffness().plan.substeps == 4);
    const std::vector<glm::vec4> x = positions(solver);
    solver.write(x, test::throwDown(x));
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
  CHECK(one.closest < 0.6 * twoR);
  CHECK(four.closest > 0.95 * twoR);
  CHECK(four.lowest > 0.0);
  // More lists than substeps: one a substep.
  CHECK(sixteen.closest == four.closest);
}

TEST_CASE("lists within the frame: where they come, and what they measure", "[quick]") {
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
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  auto first = [&](int lists) {
    Config cl = c;
    cl.collision.lists = lists;
    CpuSolver solver;
    resetWithHead(solver, g, cl, Pose{});
    solver.stepFrame(Pose{}, Pose{});
    return CpuProbe(solver).contactStats();
  };
  const ContactStats one = first(1), four = first(4);
  CHECK(four.candidates == one.candidates);
  CHECK(four.contacts == one.contacts);
  CHECK(four.penetrations == one.penetrations);
  CHECK(four.depth == one.depth);
  CHECK(one.crossings == 0);  // no list before the first
  CHECK(four.crossings >= one.crossings);
}

TEST_CASE("the penalty model pushes an overlapping pair apart by h k depth, damped, never pulls",
          "[quick]") {
  // The crossed pair 0.5 mm inside: each end takes half (closest points at the middles); the
  // upper segment is pushed up (+y), the lower down.
  const std::vector<uint32_t> first = {0, 2, 4};
  ContactSettings settings = millimetreContacts();
  settings.penaltyStiffness = 1e4;
  settings.penaltyDamping = 50.0;
  settings.friction = 0.0;
  auto [c, x] = crossedPair(settings);
  REQUIRE(c.start[1] - c.start[0] == 1);
  const std::vector<double> invMass = {1.0, 1.0, 1.0, 1.0};
  const double h = 1.0 / 240.0;
  std::vector<glm::dvec4> dv;
  std::vector<glm::dvec3> v(4, glm::dvec3(0.0));
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  const double push = h * 1e4 * 0.0005;  // 0.0208 m/s for the pair, half to each end
  CHECK(dv[0].y == Approx(-0.5 * push));
  CHECK(dv[1].y == Approx(-0.5 * push));
  CHECK(dv[4].y == Approx(0.5 * push));
  CHECK(dv[5].y == Approx(0.5 * push));
  CHECK(std::abs(dv[0].x) + std::abs(dv[0].z) < 1e-12);
  std::vector<glm::dvec3> w = v;
  applyPenalty(dv, first, w);
  CHECK(w[3].y == Approx(0.5 * push));  // particle 3: segment 2's second end
  CHECK(w[1].y == Approx(-0.5 * push));

  // Closing at 0.1 m/s: the damping adds 50 x 0.1 m/s^2.
  v[2].y = v[3].y = -0.1;
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  CHECK(dv[4].y == Approx(0.5 * h * (1e4 * 0.0005 + 50.0 * 0.1)));
  // Parting fast enough, no pull.
  v[2].y = v[3].y = 1.0;
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  CHECK(dv[4] == glm::dvec4(0.0));
  // Apart: nothing.
  v.assign(4, glm::dvec3(0.0));
  x[2].y = x[3].y = 0.0021;
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  for (const glm::dvec4& d : dv) CHECK(d == glm::dvec4(0.0));
  // A held end takes none.
  x[2].y = x[3].y = 0.0015;
  const std::vector<double> held = {0.0, 1.0, 1.0, 1.0};
  penaltyVelocities(c, x, v, held, h, settings, dv);
  CHECK(dv[0] == glm::dvec4(0.0));
  CHECK(dv[1].y == Approx(-0.5 * push));
}

TEST_CASE("penalty friction takes at most mu times the push, and at most half the sliding",
          "[quick]") {
  ContactSettings settings = millimetreContacts();
  settings.penaltyStiffness = 1e4;
  settings.penaltyDamping = 0.0;
  settings.friction = 0.5;
  const auto [c, x] = crossedPair(settings);
  const std::vector<double> invMass(4, 1.0);
  const double h = 1.0 / 240.0, push = h * 1e4 * 0.0005;
  std::vector<glm::dvec4> dv;
  // The upper segment slides along z at 1 m/s: friction mu x push against it.
  std::vector<glm::dvec3> v(4, glm::dvec3(0.0));
  v[2].z = v[3].z = 1.0;
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  CHECK(dv[4].z == Approx(-0.5 * 0.5 * push));
  CHECK(dv[0].z == Approx(0.5 * 0.5 * push));
  // Sliding slower than that: half of it each side, so the pair stops sliding.
  v[2].z = v[3].z = 0.004;
  penaltyVelocities(c, x, v, invMass, h, settings, dv);
  CHECK(dv[4].z == Approx(-0.5 * 0.5 * 0.004));
  CHECK(dv[0].z == Approx(0.5 * 0.5 * 0.004));
}

TEST_CASE("penalty contacts slow a strand dropped across another, constraints hold it") {
  Config c = test::softDrapeConfig();
  auto run = [&](CollisionMode mode, ContactModel model) {
    c.collision.mode = mode;
    c.collision.model = model;
    CpuSolver solver;
    resetWithHead(solver, test::drapeGroom(), c, Pose{});
    for (int f = 0; f < 30; ++f) solver.stepFrame(Pose{}, Pose{});
    return test::measureDrape(positions(solver));
  };
  const test::Drape penalty = run(CollisionMode::Strands, ContactModel::Penalty);
  const test::Drape held = run(CollisionMode::Strands, ContactModel::Constraints);
  const test::Drape off = run(CollisionMode::Head, ContactModel::Constraints);
  INFO("heights after 0.5 s (mm): penalty " << penalty.height * 1e3 << ", constraints "
                                            << held.height * 1e3 << ", none " << off.height * 1e3);
  CHECK(held.height > penalty.height);
  CHECK(penalty.height > off.height);
}

TEST_CASE("contact radius: a strand's, or with collision.wisps a guide's wisp's", "[quick]") {
  CollisionConfig c;
  c.radius = 0.001f;
  c.wisps = false;
  const std::vector<float> weights{4.0f, 16.0f, 10.0f, 10.0f};  // a mean of 10
  CHECK(contactRadius(c, weights) == double(c.radius));
  c.wisps = true;
  CHECK(contactRadius(c, {}) == double(c.radius));  // every strand simulated
  CHECK(contactRadius(c, weights) == Approx(double(c.radius) * std::sqrt(10.0)));
  // A groom of guides standing for themselves alone is not thicker than its strands.
  CHECK(contactRadius(c, std::vector<float>(5, 1.0f)) == double(c.radius));
}
