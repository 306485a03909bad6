// The body's two parts (sim/head/mannequin.h, HeadModel, the solvers' collider): each part moves
// only with its own pose, the neck shows no seam however the head turns on the torso (a particle
// pushed out of one part is not inside the other), a particle in the torso is counted there, and
// on a clip whose head turns 80 degrees the shoulders stay while the hair on them is kept out.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "sim/groom/followers.h"
#include "sim/head/head_model.h"
#include "sim/head/mannequin.h"
#include "sim/motion/clip.h"
#include "sim/run/simulation.h"
#include "sim/solver/accuracy.h"
#include "sim/solver/cpu_solver.h"
#include "sim/solver/cpu_steps.h"

namespace csm {
namespace {

const glm::dvec3 kPivot{0.0, -0.15, 0.0};

Config sdfConfig() {
  Config c;
  c.collision.headShape = HeadShape::Sdf;
  return c;
}

// The mannequin's parts as the CPU solver collides with them, at the given poses.
struct Body {
  std::shared_ptr<const HeadModel> model = HeadModel::require(sdfConfig());
  SceneHead shape = model->collider();
  std::vector<Sphere> spheres;
  Pose head, torso;
  HeadCollider collider(double radius = 0.0) const {
    return {shape.field, spheres, head, radius, shape.torsoField, &torso};
  }
};

double partDistance(const DistanceGrid& g, const Pose& pose, const glm::dvec3& world) {
  return g.sample(inverse(pose).apply(world));
}

TEST_CASE("the mannequin is two parts, each moving only with its own pose", "[quick]") {
  Body body;
  REQUIRE(body.model->articulated());
  REQUIRE(body.shape.field != nullptr);
  REQUIRE(body.shape.torsoField != nullptr);
  REQUIRE(body.model->torsoSurface() != nullptr);
  // At rest the parts' union is the whole (the field hair grows on).
  for (const glm::dvec3& p : {glm::dvec3(0.0, 0.05, 0.0), glm::dvec3(0.15, -0.30, 0.0),
                              glm::dvec3(0.0, -0.15, 0.0), glm::dvec3(0.0, 0.2, 0.0)})
    CHECK(bodySample(body.collider(), p) ==
          Approx(body.model->shapeField().sample(p)).margin(2e-3));
  const glm::dvec3 cranium(0.0, 0.05, 0.0), shoulder(0.15, -0.30, 0.0), nose(0.0, -0.045, 0.104);
  // The head turns 80 degrees about the neck: the cranium and the nose go with it, the shoulder
  // stays where it was.
  body.head = rotationAbout(kPivot, {0, 1, 0}, 80.0);
  CHECK(bodySample(body.collider(), body.head.apply(cranium)) < -0.03);
  CHECK(bodySample(body.collider(), body.head.apply(nose)) < 0.0);
  CHECK(bodySample(body.collider(), nose) > 0.01);  // the face is no longer there
  CHECK(bodySample(body.collider(), shoulder) < -0.01);
  CHECK(partDistance(*body.shape.torsoField, body.torso, shoulder) < -0.01);
  // The torso leans and walks on: the shoulder goes with it, the cranium stays with the head.
  body.torso =
      compose(Pose{{1, 0, 0, 0}, {0.3, 0.0, 0.5}}, rotationAbout({0, -0.4, 0}, {1, 0, 0}, 15));
  CHECK(bodySample(body.collider(), body.torso.apply(shoulder)) < -0.01);
  CHECK(bodySample(body.collider(), shoulder) > 0.0);
  CHECK(bodySample(body.collider(), body.head.apply(cranium)) < -0.03);
  // The spheres split the same way: the neck's sphere (below the pivot) is the torso's.
  Config c;
  c.collision.headShape = HeadShape::Spheres;
  auto spheres = HeadModel::require(c);
  CHECK(spheres->headSphereCount() == 2);
  CHECK(spheres->collider().torsoSpheres.size() == 1);
  CHECK(spheres->collider().torsoField == nullptr);
}

TEST_CASE("no seam at the neck: a particle pushed out of one part is not inside the other",
          "[quick]") {
  Body body;
  const double radius = 1e-4;
  // The head nods, shakes and sways on the torso, which turns and leans too.
  const std::vector<Pose> heads = {
      rotationAbout(kPivot, {1, 0, 0}, 35.0), rotationAbout(kPivot, {1, 0, 0}, -30.0),
      rotationAbout(kPivot, {0, 1, 0}, 80.0), rotationAbout(kPivot, {0, 0, 1}, 25.0)};
  const std::vector<Pose> torsos = {Pose{}, rotationAbout({0, -0.4, 0}, {0, 1, 0}, -20.0)};
  int pushed = 0, inside = 0, holes = 0, insideReach = 0;
  double worst = 0.0;
  for (const Pose& torso : torsos)
    for (const Pose& headLocal : heads) {
      body.torso = torso;
      body.head = compose(torso, headLocal);
      const HeadCollider h = body.collider(radius);
      // Points on a lattice about the neck, where the parts meet.
      for (double y = -0.21; y <= -0.06; y += 0.01)
        for (double a = 0.0; a < 2.0 * M_PI; a += M_PI / 12.0)
          for (double r : {0.03, 0.05, 0.06, 0.07}) {
            const glm::dvec3 dir(std::sin(a), 0.0, std::cos(a));
            const glm::dvec3 at = torso.apply(glm::dvec3(0.0, y, -0.02) + r * dir);
            // Its parent outside the body, as in the sweep (within reach, the strain limit's
            // passes and bisection, from any depth), and without one (the push alone: no
            // strain limit).
            const glm::dvec3 parent = torso.apply(glm::dvec3(0.0, y + 0.01, -0.02) + 0.13 * dir);
            if (bodySample(h, parent) < radius) continue;  // under the jaw: not a parent here
            for (double reach : {glm::length(at - parent) + 0.02, 0.0}) {
              // The push alone, from within a centimetre of the surface (a step's worth).
              if (reach == 0.0 && bodySample(h, at) < -0.01) continue;
              glm::dvec3 p = at, normal(0.0);
              if (!pushOutOfHead(h, p, parent, reach, normal)) continue;
              ++pushed;
              const double dh = partDistance(*body.shape.field, body.head, p);
              const double dt = partDistance(*body.shape.torsoField, body.torso, p);
              inside += (dh < 0.0 || dt < 0.0) ? 1 : 0;
              if ((dh < 0.0 || dt < 0.0) && reach > 0.0) ++insideReach;
              if (dh < 0.0 || dt < 0.0) worst = std::min(worst, std::min(dh, dt));
            }
          }
      // The neck's axis stays inside the body between the parts: no hole opens there.
      for (double y = -0.22; y <= -0.08; y += 0.005) {
        const glm::dvec3 axisPoint =
            interpolate(torso, body.head, 0.5).apply(glm::dvec3(0.0, y, -0.02));
        holes += bodySample(h, axisPoint) > -0.02 ? 1 : 0;
      }
    }
  INFO("with reach " << insideReach << " worst " << worst);
  CHECK(pushed > 500);
  CHECK(inside == 0);
  CHECK(holes == 0);
}

TEST_CASE("a particle inside the torso is counted there, one inside the head there", "[quick]") {
  Body body;
  body.head = rotationAbout(kPivot, {0, 1, 0}, 45.0);
  // A strand of four free particles: one in the cranium, one in the shoulder, two outside.
  const std::vector<glm::dvec3> x = {
      body.head.apply({0.0, 0.05, 0.0}), {0.15, -0.30, 0.0}, {0.0, 0.5, 0.0}, {0.0, 0.6, 0.0}};
  const std::vector<glm::dvec3> v(4, glm::dvec3(0.0));
  const std::vector<uint32_t> first = {0, 4};
  const std::vector<double> rest = {0.1, 0.1, 0.1, 0.0};
  const std::vector<int> pinned = {0};
  const Accuracy a =
      measureAccuracy(x, v, first, rest, {}, pinned, PosedField{body.shape.field, body.head},
                      BodyParts{PosedField{body.shape.torsoField, body.torso}});
  CHECK(a.headPenetrations == 1);
  CHECK(a.torsoPenetrations == 1);
}

TEST_CASE("without a clip the head turns alone within the neck's reach, the body past it",
          "[quick]") {
  const glm::dvec3 pivot(HeadConfig{}.pivot);
  auto degrees = [](const Pose& p) { return glm::degrees(glm::angle(p.rotation)); };
  // Within reach the torso stays where the body is.
  CHECK(degrees(torsoUnder(rotationAbout(pivot, {1, 0, 0}, 30.0), Pose{}, pivot)) < 1e-9);
  CHECK(degrees(torsoUnder(rotationAbout(pivot, {0, 1, 0}, -65.0), Pose{}, pivot)) < 1e-9);
  // Past it the torso takes the rest, about the neck, which stays joined to the head's.
  const Pose nod = rotationAbout(pivot, {1, 0, 0}, 100.0);
  const Pose down = torsoUnder(nod, Pose{}, pivot);
  CHECK(std::abs(degrees(down) - (100.0 - kNeckSwingDegrees)) < 1e-6);
  CHECK(glm::length(down.apply(pivot) - nod.apply(pivot)) < 1e-9);
  const Pose shake = rotationAbout(pivot, {0, 1, 0}, -120.0);
  CHECK(std::abs(degrees(torsoUnder(shake, Pose{}, pivot)) - (120.0 - kNeckTwistDegrees)) < 1e-6);
  // A spinning body carries the head: a shake over it is measured from the torso's facing.
  const Pose body = rotationAbout(pivot, {0, 1, 0}, 150.0);
  const Pose over = compose(rotationAbout(pivot, {0, 1, 0}, 20.0), body);
  CHECK(std::abs(glm::dot(torsoUnder(over, body, pivot).rotation, body.rotation)) > 1.0 - 1e-12);

  // In a Simulation: the preset's nod turns the head, the torso stands; spin moves both.
  Config c = sdfConfig();
  c.hairstyle.strands = 20;
  c.head.motion = HeadMotion::Nod;
  c.head.amplitude = 30.0f;
  c.head.frequency = 1.0f;
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim.load(c, ".", &error));
  CHECK(std::abs(degrees(sim.bodyPoseAt(0.25).head) - 30.0) < 1e-3);
  CHECK(degrees(sim.bodyPoseAt(0.25).torso) < 1e-9);
  c.head.motion = HeadMotion::Spin;
  REQUIRE(sim.load(c, ".", &error));
  const BodyPose spun = sim.bodyPoseAt(0.25);
  CHECK(std::abs(degrees(spun.torso) - 90.0) < 1e-3);
  CHECK(std::abs(glm::dot(spun.torso.rotation, spun.head.rotation)) > 1.0 - 1e-12);
}

TEST_CASE("a clip turns the head 80 degrees on still shoulders, the hair kept out of both") {
  Config c = sdfConfig();
  c.hairstyle.strands = 200;
  c.motion.clip = "turn_mixed.bvh";
  Simulation sim(std::make_unique<CpuSolver>(), Sampling{.every = 1});
  std::string error;
  REQUIRE(sim.load(c, CSM_CLIP_DIR, &error));
  const MotionClip& clip = *sim.clip();
  // The torso's pose is the clip's chest: it hardly turns while the head turns 80 degrees.
  const BodyPose turned = sim.bodyPoseAt(2.0);
  CHECK(std::abs(glm::degrees(glm::angle(turned.head.rotation))) > 70.0);
  CHECK(std::abs(glm::degrees(glm::angle(turned.torso.rotation))) < 3.0);
  CHECK(clip.sample(2.0, true, false).torso.rotation == turned.torso.rotation);
  for (int f = 0; f < 150; ++f) sim.stepFrame();
  sim.drainSamples();
  REQUIRE(sim.latestSample());
  const Accuracy& a = sim.latestSample()->accuracy;
  CHECK(a.nanCount == 0);
  CHECK(a.headPenetrations == 0);
  CHECK(a.torsoPenetrations == 0);
  CHECK(a.maxStrain < 0.11);
}

TEST_CASE("drawn strands are kept out of each part at its own pose as the head turns") {
  // Long hair drawn about 40 guides under the clip's 80-degree turn: the followers made on the
  // CPU stay out of the torso where it stands, not where it would be had it turned with the
  // head.
  Config c = sdfConfig();
  c.hairstyle.strands = 400;
  c.hairstyle.guides = 40;
  c.hairstyle.lengthMin = 0.35f;
  c.hairstyle.lengthMax = 0.45f;
  c.motion.clip = "turn_mixed.bvh";
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim.load(c, CSM_CLIP_DIR, &error));
  REQUIRE(sim.followers());
  for (int f = 0; f < 150; ++f) sim.stepFrame();
  const BodyPose body{sim.headPose(), sim.torsoPose()};
  REQUIRE(glm::degrees(glm::angle(compose(body.head, inverse(body.torso)).rotation)) > 70.0);
  std::vector<glm::vec4> guides, drawn;
  sim.readPositions(guides);
  const FollowerStats stats = sim.drawnPositions(guides, drawn);
  const SceneHead parts = sim.head().collider();
  REQUIRE(parts.torsoField);
  const Groom& g = sim.followers()->drawn;
  size_t inTorso = 0, nearTorso = 0;
  for (size_t s = 0; s < g.strandCount(); ++s)
    for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i) {
      const double d = partDistance(*parts.torsoField, body.torso, glm::dvec3(glm::vec3(drawn[i])));
      inTorso += d < -1e-4;
      nearTorso += d < 0.01;
    }
  INFO(stats.pushed << " pushed, " << nearTorso << " drawn points within 1 cm of the torso, "
                    << inTorso << " inside it");
  CHECK(nearTorso > 100);  // the hair lies on the shoulders
  CHECK(inTorso == 0);
  CHECK(stats.deepest < 1e-4);
}

}  // namespace
}  // namespace csm
