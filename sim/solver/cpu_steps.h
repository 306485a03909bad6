// The CPU solver's step as free functions over one strand's or one particle's data, each the
// double twin of the GLSL function of the same name that one invocation of a pass runs
// (shaders/sim/), the same steps in the same order (where they differ, as the integration's
// velocity, both say so):
//   predictParticle    predict.glsl          steps 1-2: roots follow the head, forces, x*
//   shapeMatchStrand   shape_match.comp      steps 3-5: regions, rotations, goals, integration
//   limitStrainStrand  strain_limit.comp     step 6: the sweep from root to tip (sweepParticle)
//                                            and, held at both ends, back and forth (limitToward)
//   sweepParticle      head_push.glsl        one particle of the sweep
//   limitToward        head_push.glsl        one segment of a strand held at both ends
//   pushOutOfHead      head_push.glsl        out of the head within reach of the parent
//                                            (pushOutOfFieldHead for a distance field)
//   pushHead, outsideHead, pushOutOfSphere   head_push.glsl
//   extractRotation    common.glsl           a region's rotation
// CpuSolver (sim/solver/cpu_solver.h) runs them over the strands on the thread pool;
// tests/gpu/twins_test.cpp runs each pair on the same inputs (the three of a pass together, over
// one substep of a scene).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "sim/head/distance_grid.h"
#include "sim/solver/stiffness.h"
#include "sim/solver/volume.h"

namespace csm {

// Rotational part of A (Mueller, Bender, Chentanez, Macklin 2016, "A Robust Method to Extract
// the Rotational Part of Deformations"): rotates q toward A's rotation a fixed number of times.
// Robust when A is rank-deficient, which a straight strand's regions are. Each iteration turns
// by the torque of R's columns toward A's over the region's rest moment J = sum m |r|^2 (the
// value of sum r.a at convergence): scale-free, so the masses' unit and size cancel, and
// bounded where sum r.a passes through zero. J <= 0 (a region with no extent) leaves q alone.
//
// The turn about `axis` (a rest-frame direction, e.g. the region's chord; zero: none) is taken
// at `twistStep` (0..1) of its size. For a nearly straight region that turn, the twist about
// the strand, is barely determined by the positions: each full iteration moves it only by the
// small share b / J of its error (b the region's moment across the strand), so it relaxes at
// a rate set by the iterations per second, and more substeps make the twist, and the goals,
// follow the curvature faster. The calibrated model passes twistStep = r h / iterations so that
// the twist relaxes at r iterations per second whatever the step.
void extractRotation(const Eigen::Matrix3d& A, double J, Eigen::Quaterniond& q, int iterations,
                     const Eigen::Vector3d& axis = Eigen::Vector3d::Zero(), double twistStep = 1.0);

// The hair's arrays a step reads and writes, as CpuSolver holds them: a particle each, in
// particle order, strand s's particles [first[s], first[s + 1]).
struct StepHair {
  const std::vector<uint32_t>& first;
  const std::vector<glm::dvec3>& rest;    // head frame
  const std::vector<double>& restLength;  // segment i -> i+1; 0 after a strand's last particle
  const Regions& regions;
  std::vector<glm::dvec3>& x;  // where the step started; where it ends
  std::vector<glm::dvec3>& v;
  std::vector<glm::dvec3>& xOld;   // where the step started
  std::vector<glm::dvec3>& xPred;  // x*
  std::vector<glm::dvec3>& goal;
};

// ---- Steps 1-2 ------------------------------------------------------------------------------

// The forces of a step: gravity, the wind's drag across the strand (none when null) at the
// step's start `time`, and the volume's push and friction (none when null).
struct StepForces {
  glm::dvec3 gravity{0.0};
  const WindConfig* wind = nullptr;
  double time = 0.0;
  const VolumeGrid* volume = nullptr;
  VolumeSettings volumeSettings;
};

// Particle i of a strand that ends before b, held by the head or not: xOld = x; a held
// particle's x* is where the head at `head` puts it; a free one's velocity takes the forces over
// h and its x* = x + h v.
void predictParticle(StepHair& hair, const StepForces& forces, uint32_t i, uint32_t b, bool held,
                     const Pose& head, double h);

// ---- Steps 3-5 ------------------------------------------------------------------------------

// The prefix sums shape matching keeps, strand s's from first[s] + s on (a strand of n particles
// has n + 1 entries), and each region's centroids (a particle each). The static ones (mass,
// massRest) are made once for the regions (prepareRegionSums).
struct ShapeMatchSums {
  std::vector<double> mass;
  std::vector<Eigen::Vector3d> massRest, massX, T;
  std::vector<Eigen::Matrix3d> A, R;
  std::vector<Eigen::Vector3d> c, cRest;
  // Sized for the hair, the static sums of its regions.
  void prepare(const StepHair& hair);
};

struct ShapeMatchSettings {
  int iterations = 1;      // of extractRotation
  double twistStep = 1.0;  // twistStepOf
  bool prefixSums = true;  // else summed directly over each region (the benchmarks' comparison)
  double keep = 1.0;       // the velocity kept by damping over the step, exp(-c h)
};

// Strand s: every region's sums, rotation (warm-started from q) and goal contribution, each
// particle's goal (paper eq. 1), and integration: x = x* + alpha (g - x*), v = (x - xOld) / h,
// damped (eq. 2-3; in double the positions' difference is exact enough, where the GLSL twin takes
// the step's own displacement).
void shapeMatchStrand(StepHair& hair, ShapeMatchSums& sums, std::vector<Eigen::Quaterniond>& q,
                      const SimConfig& sim, const ShapeMatchSettings& settings, size_t s,
                      const Pose& head, double h);

// ---- Step 6 ---------------------------------------------------------------------------------

// The body as the strain limit's sweep collides with it, the surface inflated by the hair's
// radius: the head's distance field (head frame) at the head's pose and, where the body has a
// torso, the torso's field at its own; or their spheres (world), the head's first.
struct HeadCollider {
  const DistanceGrid* field;
  const std::vector<Sphere>& spheres;
  const Pose& head;
  double radius;
  const DistanceGrid* torsoField = nullptr;  // with `torso`
  const Pose* torso = nullptr;
  size_t headSpheres = SIZE_MAX;  // spheres beyond these are the torso's
};

// The body's field at world point q, the union of its parts: the nearer part's distance, its
// outward gradient (world, not normalised) and the part (0 the head, 1 the torso).
double bodySample(const HeadCollider& head, const glm::dvec3& q, glm::dvec3* gradient = nullptr,
                  int* part = nullptr);
// The part nearest q (0 the head, 1 the torso): the field's nearer part, or the nearest sphere's.
int partAt(const HeadCollider& head, const glm::dvec3& q);

// Pushes p out of one sphere onto its surface. With a strain limit, the push keeps the
// segment from `prev` no longer than maxLength: when the radial projection is out of reach,
// take the nearest point of the circle where the sphere meets the ball of reach around prev.
// (Moving along the chord toward prev instead would jump: a chord between two points on the
// sphere always cuts through it.)
bool pushOutOfSphere(glm::dvec3& p, const glm::dvec3& prev, const glm::dvec3& c, double radius,
                     double maxLength);
// How far q lies outside the head's surface (not inflated).
double outsideHead(const HeadCollider& head, const glm::dvec3& q);
// One push of p out of the inflated surface, within reach of prev where it can. `normal` gets
// the field's outward normal (spheres: left as it is); `clearance` how far the point it leaves
// lies outside the head, where the push read it, else NaN.
bool pushHead(const HeadCollider& head, glm::dvec3& p, const glm::dvec3& prev, double maxLength,
              glm::dvec3& normal, double& clearance);
// Pushes p (where the strain limit put it, within maxLength of prev) out of the head and
// keeps it within reach of prev: the push, and where that is out of reach or still in the
// head (p went deep, where the surface nearest is another part of the head than the one
// prev lies over; a concave part, where the tangent plane cuts into the head) the push again
// from the nearest point of reach, twice; the last resort, the point where the segment from
// prev enters the head, found by bisection. "In the head": deeper than the surface and than
// prev (a root on the scalp lies within the radius). Returns whether p touched the head.
bool pushOutOfHead(const HeadCollider& head, glm::dvec3& p, const glm::dvec3& prev,
                   double maxLength, glm::dvec3& normal);

// One segment of a strand held at both ends limited against its neighbour `anchor`, already
// final: x moves toward it to (1 + strainLimit) restLength, v with it. Whether x moved.
bool limitToward(glm::dvec3& x, glm::dvec3& v, const glm::dvec3& anchor, double restLength,
                 double strainLimit, double h);

// What the sweep does beyond the strain limit, and the head where the step started (friction).
struct SweepSettings {
  bool limit = true;  // sim.strain_limiting
  double strainLimit = 0.0;
  bool headCollide = true;  // collidesWithHead(collision.mode)
  double friction = 0.0;    // collision.head_friction
  double dftl = 0.0;
  const Pose* before = nullptr;       // the head where the step started
  const Pose* torsoBefore = nullptr;  // the torso there (with HeadCollider::torso)
};

// Particle i after its parent i - 1 (final): with `contacts` the strand contacts' correction
// `moved` (a change of velocity too), the strain limit against the parent, the push out of the
// head, Coulomb friction against the moving head, and DFTL on the parent's velocity (when
// `parentFree`).
void sweepParticle(StepHair& hair, const HeadCollider& head, const SweepSettings& settings,
                   uint32_t i, bool contacts, const glm::dvec3& moved, bool parentFree, double h);

// The point nearest x in both balls (centre a, radius ra) and (b, rb); where they do not meet,
// the point between their centres that divides the gap in their radii's ratio.
glm::dvec3 intoBothBalls(const glm::dvec3& x, const glm::dvec3& a, double ra, const glm::dvec3& b,
                         double rb);

// Strand s: the sweep from its first free particle to its tip (a held tip stays), then, held
// at both ends, the stretch shared out by sweeps back from the tip and forth from the root
// (CSM_TIED_SWEEPS pairs at most, until one moves nothing), and a last sweep from the root that
// keeps each particle within reach of its parent and of the tip (intoBothBalls): every segment
// within the limit. `correction`: the strand contacts' corrections of this step, 2 per segment
// (empty: none).
void limitStrainStrand(StepHair& hair, const std::vector<glm::dvec4>& correction,
                       const HeadCollider& head, const SweepSettings& settings, size_t s, double h);

}  // namespace csm
