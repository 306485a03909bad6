// Each CPU/GLSL twin of the step (sim/solver/cpu_steps.h lists them), the two same-named functions
// run on the same inputs: the GLSL one in float on the GL driver (shaders/test/twins.comp), the
// C++ one in double. They agree to float's precision; a change to either alone fails here. The
// step's passes as a whole (predictParticle, shapeMatchStrand, limitStrainStrand) are compared on
// one substep of a scene.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gl/buffer.h"
#include "gl/shader_source.h"
#include "sim/base/shared_functions.h"
#include "sim/core/measure_sample.h"
#include "sim/gpu/gpu_params.h"
#include "sim/gpu/gpu_probe.h"
#include "sim/gpu/gpu_solver.h"
#include "sim/head/distance_grid.h"
#include "sim/solver/cpu_probe.h"
#include "sim/solver/cpu_steps.h"
#include "sim/solver/wind.h"
#include "sim/verify/solver_head.h"
#include "shaders/sim/bindings.glsl"
#include "tests/cpu/test_scenes.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

// The parameter block the twins read (P, and S[0]): what each test sets, the rest zero.
struct Params {
  gpu::SimParams p{};
  gpu::Substep s{};
};

// Runs twins.comp with TWIN_<name> on `in`, `outPerItem` vec4s out an item, P from `params`, the
// spheres and the field bound where the passes bind them.
std::vector<glm::vec4> runTwin(const std::string& name, const std::vector<glm::vec4>& in,
                               size_t items, size_t outPerItem, const Params& params,
                               const std::vector<glm::vec4>& spheres = {glm::vec4(0.0f)},
                               const std::vector<glm::vec4>& field = {glm::vec4(0.0f)}) {
  test::glContext();
  std::string log;
  auto program = gl::buildProgram("twins " + name, {{GL_COMPUTE_SHADER, "test/twins.comp"}},
                                  {{"TWIN_" + name, ""}, {"CSM_STORAGE_READS", ""}}, &log);
  INFO(log);
  REQUIRE(program);
  gl::Buffer input(GLsizeiptr(in.size() * sizeof(glm::vec4)), in.data(),
                   gl::BufferUsage::StaticDraw);
  gl::Buffer output(GLsizeiptr(items * outPerItem * sizeof(glm::vec4)), nullptr,
                    gl::BufferUsage::StreamRead);
  gl::Buffer block(GLsizeiptr(sizeof(Params)), &params, gl::BufferUsage::StaticDraw);
  gl::Buffer sphereBuffer(GLsizeiptr(spheres.size() * sizeof(glm::vec4)), spheres.data(),
                          gl::BufferUsage::StaticDraw);
  gl::Buffer fieldBuffer(GLsizeiptr(field.size() * sizeof(glm::vec4)), field.data(),
                         gl::BufferUsage::StaticDraw);
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  input.bindBase(ssbo, 0);
  output.bindBase(ssbo, 1);
  block.bindBase(ssbo, CSM_BIND_PARAMS);
  sphereBuffer.bindBase(ssbo, CSM_BIND_SPHERES);
  fieldBuffer.bindBase(ssbo, CSM_BIND_HEAD_FIELD);
  program->setUniform("items", unsigned(items));
  program->dispatchItems(GLuint(items), 64);
  gl::memoryBarrier(gl::Barrier::All);
  return output.download<glm::vec4>(items * outPerItem);
}

glm::dvec3 d3(const glm::vec4& v) {
  return glm::dvec3(glm::vec3(v));
}

// Float's precision on a value of size `scale`: a few ulps of it, and of the sums before it.
double nearFloat(double scale) {
  return 2e-5 * std::max(1.0, scale);
}

// A field that is a signed distance to an ellipsoid (a head's size), sampled as heads are.
DistanceGrid ellipsoidField() {
  const glm::dvec3 radii(0.09, 0.12, 0.10);
  auto f = [radii](const glm::dvec3& p) {
    const glm::dvec3 q = p / radii;
    const double k = glm::length(q);
    return (k - 1.0) * std::min(radii.x, std::min(radii.y, radii.z));
  };
  return sampleDistance(f, glm::dvec3(-0.16), glm::dvec3(0.16), 0.008);
}

std::mt19937 rng(12345);
double uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
glm::dvec3 point(double r) {
  return {uniform(-r, r), uniform(-r, r), uniform(-r, r)};
}

// A particle the strain limit put at p, its parent at prev a centimetre or so away, and the reach
// of their segment (0: no strain limit, a third of the cases).
struct PushCase {
  glm::dvec3 p, prev;
  double maxLength;
};
// 256 of them around the head at `pose`, the parents `lift` higher.
std::vector<PushCase> pushCases(const Pose& pose, const glm::dvec3& lift) {
  std::vector<PushCase> cases;
  for (int k = 0; k < 256; ++k) {
    PushCase c;
    c.p = pose.apply(point(0.12));
    c.prev = c.p + 0.01 * glm::normalize(point(1.0)) + lift;
    c.maxLength = k % 3 == 0 ? 0.0 : uniform(0.004, 0.02);
    cases.push_back(c);
  }
  return cases;
}

}  // namespace

TEST_CASE("Twins: windVelocity, wind.glsl and csm::windVelocity", "[gpu][twins][quick]") {
  WindConfig wind;
  wind.direction = glm::vec3(1.0f, 0.2f, -0.4f);
  wind.strength = 3.0f;
  wind.gusts = 0.6f;
  wind.gustFrequency = 0.7f;
  wind.turbulence = 0.4f;
  wind.turbulenceScale = 0.3f;
  Params params;
  params.p.windDirection = glm::vec3(glm::normalize(glm::dvec3(wind.direction)));
  params.p.windStrength = wind.strength;
  params.p.gusts = wind.gusts;
  params.p.gustFrequency = wind.gustFrequency;
  params.p.turbulence = wind.turbulence;
  params.p.turbulenceScale = wind.turbulenceScale;
  std::vector<glm::vec4> in;
  for (int k = 0; k < 256; ++k) in.emplace_back(glm::vec3(point(0.3)), float(uniform(0.0, 4.0)));
  const std::vector<glm::vec4> out = runTwin("WIND", in, in.size(), 1, params);
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec3 cpu = windVelocity(wind, d3(in[k]), double(in[k].w));
    INFO("point " << k);
    CHECK(glm::length(d3(out[k]) - cpu) < nearFloat(20.0 * glm::length(cpu)));
  }
}

TEST_CASE("Twins: extractRotation, common.glsl and cpu_steps", "[gpu][twins][quick]") {
  std::vector<glm::vec4> in;
  struct Case {
    Eigen::Matrix3d A;
    double J;
    Eigen::Quaterniond q;
    int iterations;
    Eigen::Vector3d axis;
    double twistStep;
  };
  std::vector<Case> cases;
  for (int k = 0; k < 128; ++k) {
    Case c;
    // A region's A: a rotation times a stretch, its moment J about that size.
    const Eigen::Quaterniond turn =
        Eigen::Quaterniond(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))
            .normalized();
    Eigen::Matrix3d S = Eigen::Matrix3d::Identity() * 1e-4;
    S(0, 0) *= uniform(0.5, 3.0);
    S(1, 1) *= uniform(0.0, 1.0);  // rank-deficient, as a straight strand's region
    c.A = turn.toRotationMatrix() * S;
    c.J = S.trace();
    c.q = Eigen::Quaterniond(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))
              .normalized();
    c.iterations = 1 + k % 4;
    c.axis = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
    c.twistStep = k % 2 ? 1.0 : uniform(0.05, 1.0);
    cases.push_back(c);
    for (int col = 0; col < 3; ++col)
      in.emplace_back(float(c.A(0, col)), float(c.A(1, col)), float(c.A(2, col)), 0.0f);
    in.emplace_back(float(1.0 / c.J), float(c.iterations), float(c.twistStep), 0.0f);
    in.emplace_back(float(c.q.x()), float(c.q.y()), float(c.q.z()), float(c.q.w()));
    in.emplace_back(float(c.axis.x()), float(c.axis.y()), float(c.axis.z()), 0.0f);
  }
  const std::vector<glm::vec4> out = runTwin("ROTATION", in, cases.size(), 1, Params{});
  for (size_t k = 0; k < cases.size(); ++k) {
    Case c = cases[k];
    extractRotation(c.A, c.J, c.q, c.iterations, c.axis, c.twistStep);
    const Eigen::Quaterniond gpu(out[k].w, out[k].x, out[k].y, out[k].z);
    INFO("case " << k);
    CHECK(std::abs(std::abs(gpu.dot(c.q)) - 1.0) < 1e-5);
  }
}

TEST_CASE("Twins: pushOutOfSphere and pushOutOfHead on spheres, head_push.glsl and cpu_steps",
          "[gpu][twins][quick]") {
  const std::vector<Sphere> spheres = {{glm::vec3(0.0f, 0.0f, 0.0f), 0.09f},
                                       {glm::vec3(0.0f, -0.1f, 0.02f), 0.05f}};
  const double r = 5e-4;
  std::vector<glm::vec4> one, head;
  const std::vector<PushCase> cases = pushCases(Pose{}, glm::dvec3(0.0, 0.0, 0.005));
  for (const PushCase& c : cases) {
    one.emplace_back(glm::vec3(c.p), 0.0f);
    one.emplace_back(glm::vec3(c.prev), 0.0f);
    one.emplace_back(spheres[0].center, spheres[0].radius + float(r));
    one.emplace_back(float(c.maxLength), 0.0f, 0.0f, 0.0f);
    head.emplace_back(glm::vec3(c.p), 0.0f);
    head.emplace_back(glm::vec3(c.prev), 0.0f);
    head.emplace_back(float(r), float(c.maxLength), 0.0f, 0.0f);
  }
  const std::vector<glm::vec4> outOne = runTwin("SPHERE", one, cases.size(), 2, Params{});
  Params params;
  params.p.headSpheres = int(spheres.size());
  std::vector<glm::vec4> sphereData;
  for (const Sphere& s : spheres) sphereData.emplace_back(s.center, s.radius);
  const std::vector<glm::vec4> outHead =
      runTwin("HEAD_SPHERES", head, cases.size(), 3, params, sphereData);
  const Pose pose;
  const HeadCollider collider{nullptr, spheres, pose, r};
  int moved = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    INFO("case " << k);
    glm::dvec3 p = cases[k].p;
    const bool hit = pushOutOfSphere(p, cases[k].prev, glm::dvec3(spheres[0].center),
                                     spheres[0].radius + r, cases[k].maxLength);
    CHECK(hit == (outOne[2 * k + 1].x != 0.0f));
    CHECK(glm::length(d3(outOne[2 * k]) - p) < nearFloat(0.1));
    glm::dvec3 q = cases[k].p, normal(0.0);
    const bool touching = pushOutOfHead(collider, q, cases[k].prev, cases[k].maxLength, normal);
    CHECK(touching == (outHead[3 * k + 1].x != 0.0f));
    CHECK(glm::length(d3(outHead[3 * k]) - q) < nearFloat(0.1));
    moved += touching;
  }
  CHECK(moved > 40);  // the cases do reach into the head
}

TEST_CASE(
    "Twins: headFieldSample and pushOutOfFieldHead, head_field_sample.glsl, head_push.glsl "
    "and DistanceGrid::sample, cpu_steps' pushOutOfHead",
    "[gpu][twins][quick]") {
  const DistanceGrid grid = ellipsoidField();
  Params params;
  params.p.headFieldOrigin = grid.origin;
  params.p.headFieldCell = grid.cell;
  params.p.headFieldDims = glm::uvec3(grid.dims);
  params.p.headIsField = 1u;
  // The head turned and moved: the push reads the field in its frame.
  Pose pose;
  pose.rotation = glm::normalize(glm::dquat(0.97, 0.1, 0.2, -0.05));
  pose.translation = glm::dvec3(0.01, 1.6, -0.02);
  params.s.head = pose.matrix();

  std::vector<glm::vec4> samples;
  for (int k = 0; k < 512; ++k) samples.emplace_back(glm::vec3(point(0.2)), 0.0f);
  const std::vector<glm::vec4> sampled =
      runTwin("FIELD_SAMPLE", samples, samples.size(), 1, params, {glm::vec4(0.0f)}, grid.nodes);
  for (size_t k = 0; k < samples.size(); ++k) {
    glm::dvec3 gradient;
    const double d = grid.sample(d3(samples[k]), &gradient);
    INFO("point " << k);
    CHECK(std::abs(double(sampled[k].w) - d) < nearFloat(0.2));
    CHECK(glm::length(d3(sampled[k]) - gradient) < nearFloat(1.0));
  }

  const double r = 5e-4;
  std::vector<glm::vec4> in;
  const std::vector<PushCase> cases = pushCases(pose, glm::dvec3(0.0));
  for (const PushCase& c : cases) {
    in.emplace_back(glm::vec3(c.p), 0.0f);
    in.emplace_back(glm::vec3(c.prev), 0.0f);
    in.emplace_back(float(r), float(c.maxLength), 0.0f, 0.0f);
  }
  const std::vector<glm::vec4> pushed =
      runTwin("FIELD_PUSH", in, cases.size(), 3, params, {glm::vec4(0.0f)}, grid.nodes);
  const HeadCollider collider{&grid, {}, pose, r};
  int touched = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    INFO("case " << k);
    glm::dvec3 q = cases[k].p, normal(0.0);
    const bool touching = pushOutOfHead(collider, q, cases[k].prev, cases[k].maxLength, normal);
    CHECK(touching == (pushed[3 * k + 1].x != 0.0f));
    CHECK(glm::length(d3(pushed[3 * k]) - q) < nearFloat(1.6));
    if (touching) CHECK(glm::length(d3(pushed[3 * k + 2]) - normal) < 1e-3);
    touched += touching;
  }
  CHECK(touched > 40);
}

TEST_CASE("Twins: limitToward, head_push.glsl and cpu_steps", "[gpu][twins][quick]") {
  Params params;
  params.p.strainLimit = 0.05f;
  std::vector<glm::vec4> in;
  struct Case {
    glm::dvec3 x, v, anchor;
    double rest, h;
  };
  std::vector<Case> cases;
  for (int k = 0; k < 256; ++k) {
    Case c{point(0.02), point(1.0), point(0.02), uniform(0.001, 0.02), 1.0 / 960.0};
    cases.push_back(c);
    in.emplace_back(glm::vec3(c.x), 0.0f);
    in.emplace_back(glm::vec3(c.v), 0.0f);
    in.emplace_back(glm::vec3(c.anchor), 0.0f);
    in.emplace_back(float(c.rest), float(c.h), 0.0f, 0.0f);
  }
  const std::vector<glm::vec4> out = runTwin("LIMIT", in, cases.size(), 3, params);
  for (size_t k = 0; k < cases.size(); ++k) {
    Case c = cases[k];
    const bool moved = limitToward(c.x, c.v, c.anchor, c.rest, params.p.strainLimit, c.h);
    INFO("case " << k);
    CHECK(moved == (out[3 * k + 2].x != 0.0f));
    CHECK(glm::length(d3(out[3 * k]) - c.x) < nearFloat(0.04));
    // The velocity takes the move over h: float's error on the positions, times 1 / h.
    CHECK(glm::length(d3(out[3 * k + 1]) - c.v) < nearFloat(0.04) / c.h + nearFloat(1.0));
  }
}

TEST_CASE("Twins: inMeasureSample, one text in both languages", "[gpu][twins][quick]") {
  std::vector<glm::vec4> in;
  for (uint32_t s = 0; s < 4096; s += 7) in.emplace_back(float(s), float(1 + s % 5), 0.0f, 0.0f);
  const std::vector<glm::vec4> out = runTwin("HASH", in, in.size(), 1, Params{});
  int sampled = 0;
  for (size_t k = 0; k < in.size(); ++k) {
    const bool cpu = inMeasureSample(uint32_t(in[k].x), uint32_t(in[k].y));
    CHECK(cpu == (out[k].x != 0.0f));
    sampled += cpu;
  }
  CHECK(sampled > 100);
  CHECK(sampled < int(in.size()));
}

TEST_CASE(
    "Twins: one substep of predictParticle, shapeMatchStrand and limitStrainStrand, the "
    "per-strand passes and cpu_steps",
    "[gpu][twins][quick]") {
  // One substep from rest under gravity, the head turning: every particle's predict, its
  // strand's shape matching and integration, and the sweep with the head's push. Both solvers
  // from the same state; the per-strand passes are the GLSL functions one invocation at a time.
  Config c = test::smallScene(40);
  c.sim.stiffnessModel = StiffnessModel::Paper;
  c.sim.substeps = 1;
  c.sim.maxSubsteps = 1;
  c.wind.strength = 2.0f;
  c.collision.mode = CollisionMode::Head;
  const Groom g = test::growFor(c);
  test::glContext();
  std::string error;
  std::unique_ptr<GpuSolver> gpu = GpuSolver::create(&error);
  INFO(error);
  REQUIRE(gpu);
  REQUIRE(GpuProbe(*gpu).setKernels(GpuKernels::PerStrand, &error));
  CpuSolver cpu;
  resetWithHead(cpu, g, c);
  resetWithHead(*gpu, g, c);
  Pose to;
  to.rotation = glm::angleAxis(0.05, glm::dvec3(1.0, 0.0, 0.0));
  cpu.stepFrame(Pose{}, to);
  gpu->stepFrame(Pose{}, to);
  std::vector<glm::vec4> x;
  gpu->readPositions(x);
  const std::vector<glm::dvec3>& reference = CpuProbe(cpu).positions();
  REQUIRE(x.size() == reference.size());
  double worst = 0.0, moved = 0.0;
  std::vector<glm::vec4> rest;
  for (size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, glm::length(d3(x[i]) - reference[i]));
    moved = std::max(moved, glm::length(reference[i] - glm::dvec3(g.points[i])));
  }
  INFO("farthest from the CPU's " << worst << " m; farthest moved " << moved << " m");
  CHECK(moved > 1e-4);
  CHECK(worst < 1e-6);
}
