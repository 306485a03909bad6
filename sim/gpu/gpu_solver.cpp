#include "sim/gpu/gpu_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/draw.h"
#include "gl/fence.h"
#include "sim/gpu/buffer_fill.h"
#include "sim/gpu/strand_groups.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/base/state_bytes.h"
#include "sim/core/measure_sample.h"
#include "shaders/sim/bindings.glsl"
#include "sim/solver/contacts.h"

namespace csm {
namespace {

// Strand lengths are rounded up to this step for MAX_N, so a regrown groom rarely recompiles.
constexpr int kMaxNStep = 8;
// The parameter block read as a uniform block: the frame's parameters and CSM_MAX_SUBSTEPS
// steps, the size the shaders declare (common.glsl), used or not.
constexpr size_t kParamBlockBytes =
    sizeof(gpu::SimParams) + CSM_MAX_SUBSTEPS * sizeof(gpu::Substep);

}  // namespace

const char* gpuKernelsName(GpuKernels k) {
  return k == GpuKernels::PerParticle ? "per particle" : "per strand";
}

GpuSolver::GpuSolver(bool cpuClock, GpuKernels kernels, Reads reads)
    : kernels_(kernels),
      reads_(reads),
      timer_(cpuClock),
      samples_([this](const uint32_t* counters) {
        sampledContacts_ = gpu::contactStatsOf(counters);
        sampledContacts_.measureStride = contactSearch_.measureStride();
      }) {}

std::vector<gl::Define> GpuSolver::withReads(std::vector<gl::Define> defines) const {
  if (reads_.uniformParams) defines.push_back({"CSM_PARAMS_UNIFORM", ""});
  if (reads_.storage) defines.push_back({"CSM_STORAGE_READS", ""});
  return defines;
}

std::unique_ptr<GpuSolver> GpuSolver::create(std::string* error) {
  const gl::Caps caps = gl::queryCaps();
  const bool software = caps.software;
  Reads reads;
  reads.uniformParams = !software && size_t(caps.maxUniformBlockSize) >= kParamBlockBytes;
  reads.storage = !software;
  if (const char* env = std::getenv("CSM_GPU_READS"); env && *env) {
    const std::string want = env;
    if (want == "texture") {
      reads = Reads{};
    } else if (want == "storage") {
      reads.storage = true;
      reads.uniformParams = size_t(caps.maxUniformBlockSize) >= kParamBlockBytes;
    } else {
      if (error) *error = "CSM_GPU_READS=" + want + " is not one of texture, storage";
      return nullptr;
    }
  }
  GpuKernels kernels = software ? GpuKernels::PerStrand : GpuKernels::PerParticle;
  if (const char* env = std::getenv("CSM_GPU_KERNELS"); env && *env) {
    const std::string want = env;
    if (want == "strand") {
      kernels = GpuKernels::PerStrand;
    } else if (want == "particle") {
      kernels = GpuKernels::PerParticle;
    } else {
      if (error) *error = "CSM_GPU_KERNELS=" + want + " is not one of strand, particle";
      return nullptr;
    }
  }
  std::unique_ptr<GpuSolver> solver(new GpuSolver(software, kernels, reads));
  if (!solver->build(32, error)) return nullptr;
  return solver;
}

GpuSolver::~GpuSolver() = default;

bool GpuSolver::build(int maxStrandSize, std::string* error) {
  const int maxN = std::max(kMaxNStep, (maxStrandSize + kMaxNStep - 1) / kMaxNStep * kMaxNStep);
  if (maxStrandSize > int(kMaxStrandParticles)) {
    if (error)
      *error = "a strand of " + std::to_string(maxStrandSize) +
               " particles: the GPU solver takes at most " + std::to_string(kMaxStrandParticles);
    return false;
  }
  // Each path's passes are built when it is first used (a driver may warn about the other's).
  if (!builtCommon_) {
    if (!passes_.measure.build("sim/measure.comp", CSM_MEASURE_GROUP, withReads({}), error) ||
        !passes_.carry.build("sim/carry.comp", CSM_PARTICLE_GROUP, {}, error) ||
        !volume_.build(withReads({}), error) ||
        !contactSearch_.build(error, contactSolve_, withReads({})))
      return false;
    builtCommon_ = true;
  }
  if (kernels_ == GpuKernels::PerStrand && builtMaxN_ == 0) {
    if (!passes_.predict.build("sim/predict.comp", CSM_PARTICLE_GROUP, withReads({}), error) ||
        !passes_.strainLimit[0].build("sim/strain_limit.comp", CSM_STRAND_GROUP, withReads({}),
                                      error) ||
        !passes_.strainLimit[1].build("sim/strain_limit.comp", CSM_STRAND_GROUP,
                                      withReads({{"CSM_HEAD_FIELD", ""}}), error))
      return false;
  }
  if (kernels_ == GpuKernels::PerStrand && maxN != builtMaxN_) {
    // The per-strand prefix arrays are private arrays sized by the longest strand.
    if (!passes_.shapeMatch.build("sim/shape_match.comp", CSM_STRAND_GROUP,
                                  withReads({{"MAX_N", std::to_string(maxN)}}), error))
      return false;
    builtMaxN_ = maxN;
  }
  if (kernels_ == GpuKernels::PerParticle && maxN != builtParticleMaxN_) {
    // Shared arrays of one group's particles; the scans take log2(MAX_N) rounds.
    const uint32_t group = gpu::groupParticlesFor(maxN);
    const std::vector<gl::Define> defines = withReads(
        {{"MAX_N", std::to_string(maxN)}, {"CSM_GROUP_PARTICLES", std::to_string(group)}});
    std::vector<gl::Define> sweep = defines, sweepField = defines;
    sweep.push_back({"CSM_SWEEP", ""});
    sweepField.push_back({"CSM_SWEEP", ""});
    sweepField.push_back({"CSM_HEAD_FIELD", ""});
    std::vector<gl::Define> field = defines;
    field.push_back({"CSM_HEAD_FIELD", ""});
    if (!passes_.strandStep.build("sim/strand_step.comp", group, defines, error) ||
        !passes_.strandStepSweep[0].build("sim/strand_step.comp", group, sweep, error) ||
        !passes_.strandStepSweep[1].build("sim/strand_step.comp", group, sweepField, error) ||
        !passes_.strandStrain[0].build("sim/strand_strain.comp", group, defines, error) ||
        !passes_.strandStrain[1].build("sim/strand_strain.comp", group, field, error))
      return false;
    builtParticleMaxN_ = maxN;
  }
  if (config_.collision.model == ContactModel::Penalty && !contactSolve_.buildPenalty(error))
    return false;
  return true;
}

void GpuSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  shape_ = headModel_.collider();
  time_ = 0.0;
  head_ = head;
  state_ = makeHairState(groom, config.sim, head);
  hair_.upload(state_, head.rotation);
  // The shaders built at create() with MAX_N 32; a longer strand needs a recompile, which
  // fails past kMaxStrandParticles or if the driver runs out of resources. The solver then
  // steps nothing and says why (Simulation::load refuses the scene).
  failure_.clear();
  if (!build(hair_.longestStrand, &failure_)) {
    if (failure_.empty()) failure_ = "the GPU solver's shaders did not build";
    gl::logMessage(gl::LogLevel::Error, failure_);
  } else if (!headModel_.handed()) {
    failure_ = kNoHeadFailure;
  }
  // Rest lengths set the cell edge (METHOD.md section 3.6): strain limiting keeps the current
  // ones within a few percent, and a grid fixed per groom needs no reduction on the GPU.
  // The contact buffers are sized when a mode or the measures first list candidates
  // (sizeLists), from the reset's state.
  contactSearch_.reset(hair_.particles, hair_.segments, hair_.meanSegment);
  contactSolve_.reset(hair_.particles, hair_.segments);
  contactSearch_.setMemoryBudget(contactBudgetBytes(config.collision));
  resetOrigin_ = glm::vec3(head.translation);
  uploadRegions();
  volume_.reset(state_, config_.collision);
  uploadHeadField();
  if (paramsBuffer_.id() == 0) paramsBuffer_ = gl::Buffer();
  if (spheres_.id() == 0) spheres_ = gl::Buffer();

  if (listsCandidates()) sizeLists();
  sampledContacts_ = ContactStats{};
  samples_.drop();
  gpu::zeroed<glm::uvec4>(measure_,
                          2 * ((hair_.particles + CSM_MEASURE_GROUP - 1) / CSM_MEASURE_GROUP));
  timer_.clear();
  measureAnew();
}

void GpuSolver::uploadRegions() {
  regions_ = buildRegions(state_, config_.sim);
  hair_.uploadRegions(state_, regions_);
}

void GpuSolver::setConfig(const Config& config) {
  const bool remeasure = contactMeasuresChanged(config_.collision, config.collision);
  const bool rebuild = regionsChanged(config_.sim, config.sim);
  const bool regrid = volumeGridChanged(config_.collision, config.collision);
  const bool listed = listsCandidates();
  config_ = config;
  shape_ = headModel_.collider();
  if (config_.collision.model == ContactModel::Penalty && failure_.empty() &&
      !contactSolve_.buildPenalty(&failure_)) {
    if (failure_.empty()) failure_ = "the GPU solver's penalty contact shaders did not build";
    gl::logMessage(gl::LogLevel::Error, failure_);
  }
  if (rebuild && hair_.particles > 0) uploadRegions();
  if (regrid) volume_.reset(state_, config_.collision);
  if (shape_.field != uploadedField_) uploadHeadField();
  // Lists anew where they begin, or where they take other strands (a mode with strand
  // contacts lists every strand; the measures alone, a sample).
  const bool sized =
      listsCandidates() && (!listed || searchStride() != contactSearch_.measureStride());
  if (sized) sizeLists();
  if (remeasure) {
    // The last list measured other pairs: nothing to count crossings against.
    if (!sized && measureContacts_ && !strandContacts(config_.collision.mode)) sizeLists();
    measureAnew();
  }
}

MemoryUse GpuSolver::memoryUse() const {
  MemoryUse m;
  m.bytes = {{"strands", hair_.bytes()},
             {"contacts", contactSearch_.bytes() + contactSolve_.bytes()},
             {"volume", volume_.bytes()},
             {"head and parameters", uint64_t(headField_.size() + paramsBuffer_.size() +
                                              spheres_.size() + measure_.size())},
             {"samples", samples_.bytes()}};
  return m;
}

void GpuSolver::setContactMeasures(bool always) {
  const bool listed = listsCandidates(), was = measureContacts_;
  measureContacts_ = always;
  if (!listed && listsCandidates()) sizeLists();
  if (always && !was) measureAnew();
}

void GpuSolver::measureAnew() {
  framesSinceMeasure_ = 2;
  if (measureContacts_ && !strandContacts(config_.collision.mode)) measureNow();
}

void GpuSolver::measureNow() {
  if (hair_.particles == 0 || !failure_.empty()) return;
  listCandidatesNow(nullptr);
  gl::memoryBarrier(gl::Barrier::All);
  framesSinceMeasure_ = 0;
}

bool GpuSolver::listsCandidates() const {
  return strandContacts(config_.collision.mode) || measureContacts_;
}

uint32_t GpuSolver::searchStride() const {
  return strandContacts(config_.collision.mode) ? 1u : measureStride(hair_.particles);
}

void GpuSolver::reserveLists() {
  // Buffers for the strands searched, estimated from the reset's state (they only grow).
  const uint32_t stride = searchStride();
  if (contactSearch_.reserved() && stride == contactSearch_.measureStride()) return;
  contactSearch_.setMeasureStride(stride);
  contactSearch_.reserveFor(state_.position, state_.particleStrand,
                            2.0f * config_.collision.radius + config_.collision.margin,
                            resetOrigin_);
}

void GpuSolver::sizeLists() {
  if (hair_.particles == 0 || !failure_.empty()) return;
  reserveLists();
  listCandidatesNow(nullptr);
  contactSearch_.sizeForLastSearch();
  gl::memoryBarrier(gl::Barrier::All);
}

void GpuSolver::uploadHeadField() {
  const DistanceGrid* field = shape_.field;
  if (field == uploadedField_ && headField_.id() != 0) return;
  gpu::fill(headField_, field ? field->nodes : std::vector<glm::vec4>(1));
  gpu::view(headFieldTex_, headField_, gl::TextureFormat::Rgba32f);
  uploadedField_ = field;
  uploadedHead_ = headModel_.shared();  // keeps the field uploaded alive, so its address names it
}

void GpuSolver::writeParams(const std::vector<Pose>& poses, const std::vector<Pose>& before) {
  writeStepParams(params_);
  writeHeadParams(params_);
  writeContactParams(params_, poses.back());
  volume_.writeParams(params_, config_.collision, head_);
  uploadParams(poses, before);
}

void GpuSolver::writeStepParams(gpu::SimParams& p) const {
  const SimConfig& sim = config_.sim;
  const WindConfig& wind = config_.wind;
  p.gravity = sim.gravity;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  p.windDirection = glm::vec3(dir);
  p.windStrength = wind.strength;
  p.gusts = wind.gusts;
  p.gustFrequency = wind.gustFrequency;
  p.turbulence = wind.turbulence;
  p.turbulenceScale = wind.turbulenceScale;
  p.alpha = sim.stiffness;
  p.strainLimit = sim.strainLimit;
  p.dftl = sim.dftl;
  p.windDrag = wind.drag;
  static_assert(int(StiffnessModel::Paper) == CSM_STIFFNESS_PAPER &&
                int(StiffnessModel::Calibrated) == CSM_STIFFNESS_CALIBRATED);
  p.stiffnessModel = int(sim.stiffnessModel);
  p.rotationIterations = sim.rotationIterations;
  p.strainLimiting = sim.strainLimiting;
  p.windOn = wind.strength > 0.0f && wind.drag > 0.0f;
  p.particles = hair_.particles;
  p.strands = hair_.strands;
  p.segments = hair_.segments;
}

void GpuSolver::writeHeadParams(gpu::SimParams& p) const {
  const CollisionConfig& col = config_.collision;
  p.radius = col.radius;
  p.headFriction = col.headFriction;
  p.headSpheres = int(shape_.spheres.size());
  p.headCollision = collidesWithHead(col.mode);
  if (const DistanceGrid* field = uploadedField_) {
    p.headFieldOrigin = field->origin;
    p.headFieldCell = field->cell;
    p.headFieldDims = glm::uvec3(field->dims);
    p.headIsField = 1u;
  } else {
    p.headFieldOrigin = glm::vec3(0.0f);
    p.headFieldCell = 1.0f;
    p.headFieldDims = glm::uvec3(2u);
    p.headIsField = 0u;
  }
}

void GpuSolver::writeContactParams(gpu::SimParams& p, const Pose& frameEnd) const {
  const CollisionConfig& col = config_.collision;
  const float reach = 2.0f * col.radius + col.margin;
  p.candidateDistance = reach;
  p.compliance = col.compliance;
  p.friction = col.friction;
  p.sweepSolve = col.solve == ContactSolve::Sweep ? 1.0f : 0.0f;
  // The strain limit's sweep applies the constraints' corrections; penalties go to velocities.
  p.strandContacts = strandContacts(col.mode) && col.model == ContactModel::Constraints;
  p.penaltyStiffness = col.penaltyStiffness;
  p.penaltyDamping = col.penaltyDamping;
  contactSearch_.writeParams(p, reach);
  // Cells count from the head, so the clamped 10-bit cell coordinates (common.glsl) cover
  // +-512 cells around it wherever it moves.
  p.gridOrigin = glm::vec3(frameEnd.translation);
}

void GpuSolver::uploadParams(const std::vector<Pose>& poses, const std::vector<Pose>& before) {
  const SimConfig& sim = config_.sim;
  const gpu::SimParams& p = params_;
  const int substeps = int(poses.size());
  substepsWritten_ = substeps;
  const double h = double(sim.dt) / substeps;
  const double keep = std::exp(-double(sim.damping) * h);
  std::vector<unsigned char> blob(sizeof(gpu::SimParams) + substeps * sizeof(gpu::Substep));
  std::memcpy(blob.data(), &p, sizeof(p));
  std::vector<glm::vec4> spheres;
  double t = time_;
  for (int k = 0; k < substeps; ++k) {
    gpu::Substep s;
    s.head = poses[k].matrix();
    // Where a point on the head at the end of the step was at its start (head friction),
    // composed in double: before * inverse(now).
    glm::dmat4 now = glm::mat4_cast(poses[k].rotation), was = glm::mat4_cast(before[k].rotation);
    now[3] = glm::dvec4(poses[k].translation, 1.0);
    was[3] = glm::dvec4(before[k].translation, 1.0);
    s.headDelta = glm::mat4(was * glm::inverse(now));
    s.stepStart = float(t);
    s.h = float(h);
    s.twistStep = float(twistStepOf(sim, h, sim.rotationIterations));
    s.velocityKept = float(keep);
    std::memcpy(blob.data() + sizeof(p) + k * sizeof(s), &s, sizeof(s));
    for (const Sphere& sp : worldSpheres(shape_.spheres, poses[k]))
      spheres.emplace_back(sp.center, sp.radius);
    t += h;  // as CpuSolver advances its clock, step by step
  }
  if (reads_.uniformParams) {
    // A uniform block is read whole: the buffer holds CSM_MAX_SUBSTEPS steps, used or not.
    if (size_t(paramsBuffer_.size()) < kParamBlockBytes)
      paramsBuffer_.setData(GLsizeiptr(kParamBlockBytes), nullptr, gl::BufferUsage::DynamicDraw);
    paramsBuffer_.setSubData(0, GLsizeiptr(blob.size()), blob.data());
  } else {
    paramsBuffer_.upload(blob);
  }
  gpu::fill(spheres_, spheres);
}

void GpuSolver::bindAll() {
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  hair_.bind();
  contactSearch_.bind();
  contactSolve_.bind();
  paramsBuffer_.bindBase(ssbo, CSM_BIND_PARAMS);
  if (reads_.uniformParams) paramsBuffer_.bindBase(gl::BufferTarget::Uniform, CSM_UNIFORM_PARAMS);
  volume_.bind();
  headFieldTex_.bind(CSM_TEX_HEAD_FIELD);
  headField_.bindBase(ssbo, CSM_BIND_HEAD_FIELD);
  spheres_.bindBase(ssbo, CSM_BIND_SPHERES);
  measure_.bindBase(ssbo, CSM_BIND_MEASURE);
}

void GpuSolver::stepFrame(const Pose& from, const Pose& to) {
  const FramePlan plan = planFrame(config_.sim, regions_.planRate);
  const int substeps = plan.substeps;
  const double h = plan.h;
  std::vector<Pose> poses(substeps), before(substeps);
  ++framesSinceMeasure_;
  for (int k = 0; k < substeps; ++k) {
    poses[k] = interpolate(from, to, double(k + 1) / substeps);
    before[k] = k == 0 ? head_ : poses[k - 1];
  }
  if (hair_.particles == 0 || !failure_.empty()) {
    time_ += substeps * h;
    head_ = poses.back();
    return;
  }
  const bool contacts = strandContacts(config_.collision.mode);
  // Constraints solved every substep, whose last corrections the strain limit applies; or the
  // paper's penalty forces where each substep ends (collision.contact_model).
  const bool penalty = contacts && config_.collision.model == ContactModel::Penalty;
  const bool constraints = contacts && !penalty;
  // Measuring contacts with hair-hair off, the grid keeps the last sample's list (crossings).
  if (contacts || !measureContacts_) contactSearch_.beginFrame(contacts);
  writeParams(poses, before);
  bindAll();
  timer_.beginFrame();
  // The frame's candidates, from where it starts (METHOD.md section 3.3).
  if (contacts) contactSearch_.findCandidates(&timer_);

  const uint32_t particles = uint32_t(hair_.particles), strands = uint32_t(hair_.strands);

  // The volume mode's grid, from where the frame starts (sim/solver/volume.h).
  if (params_.volumeForces != 0u) {
    timer_.stage(gpu::kVolume);
    volume_.run(particles, contactSearch_.dispatch());
  }
  const int head = uploadedField_ ? 1 : 0;
  for (int k = 0; k < substeps && kernels_ == GpuKernels::PerParticle; ++k) {
    // Predict, shape matching and integration in one pass; the sweep in it too, or after the
    // contacts.
    if (contacts && listsBefore(k, substeps, config_.collision.lists)) listAgain();
    const uint32_t groups = hair_.groups, items = groups * hair_.groupParticles;
    timer_.stage(gpu::kShapeMatching);
    (constraints ? passes_.strandStep : passes_.strandStepSweep[head])
        .set("groups", groups)
        .runSubstep(items, unsigned(k));
    gl::memoryBarrier(gpu::kPassBarrier);
    if (penalty) {
      timer_.stage(gpu::kContacts);
      contactSolve_.runPenalty(unsigned(k), contactSearch_.splitViews());
    }
    if (constraints) {
      timer_.stage(gpu::kContacts);
      contactSolve_.run(unsigned(k), config_.collision.iterations, contactSearch_.splitViews());
      timer_.stage(gpu::kStrainLimiting);
      passes_.strandStrain[head].set("groups", groups).runSubstep(items, unsigned(k));
      gl::memoryBarrier(gpu::kPassBarrier);
    }
    time_ += h;
  }
  for (int k = 0; k < substeps && kernels_ == GpuKernels::PerStrand; ++k) {
    if (contacts && listsBefore(k, substeps, config_.collision.lists)) listAgain();
    timer_.stage(gpu::kIntegrate);
    passes_.predict.runSubstep(particles, unsigned(k));
    gl::memoryBarrier(gpu::kPassBarrier);
    timer_.stage(gpu::kShapeMatching);
    passes_.shapeMatch.runSubstep(strands, unsigned(k));
    gl::memoryBarrier(gpu::kPassBarrier);
    if (constraints) {
      timer_.stage(gpu::kContacts);
      contactSolve_.run(unsigned(k), config_.collision.iterations, contactSearch_.splitViews());
    }
    timer_.stage(gpu::kStrainLimiting);
    passes_.strainLimit[head].runSubstep(strands, unsigned(k));
    gl::memoryBarrier(gpu::kPassBarrier);
    if (penalty) {
      timer_.stage(gpu::kContacts);
      contactSolve_.runPenalty(unsigned(k), contactSearch_.splitViews());
    }
    time_ += h;
  }
  timer_.endStage();
  head_ = poses.back();
  timer_.endFrame();
  // The renderer reads the positions as vertex data or storage; read-backs and clears follow.
  gl::memoryBarrier(gl::Barrier::All);
}

void GpuSolver::listAgain() {
  // The lists swap, so the parameters' grid half changes: only that field is written again.
  contactSearch_.swapLists();
  contactSearch_.writeParams(params_, params_.candidateDistance);
  const glm::uvec4 grid(params_.bucketMask, params_.entryCapacity, params_.pairListCapacity,
                        params_.listHalf);
  paramsBuffer_.setSubData(offsetof(gpu::SimParams, bucketMask), sizeof(grid), &grid);
  contactSearch_.bind();
  contactSolve_.bind();
  contactSearch_.findCandidates(&timer_, false);
}

void GpuSolver::listCandidatesNow(gpu::StageTimer* timer) {
  // Parameters as they stand, at the current time (no step is taken).
  contactSearch_.beginFrame(true);
  writeParams({head_}, {head_});
  bindAll();
  contactSearch_.findCandidates(timer);
}

void GpuSolver::finish() {
  gl::finish();
}

void GpuSolver::readPositions(std::vector<glm::vec4>& out) {
  out = hair_.position.download<glm::vec4>(hair_.particles);
}

void GpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  out = hair_.velocity.download<glm::vec4>(hair_.particles);
}

void GpuSolver::writeState(const std::vector<glm::vec4>& positions,
                           const std::vector<glm::vec4>& velocities) {
  if (hair_.particles == 0) return;
  std::vector<glm::vec4> x(positions), v(velocities);
  x.resize(hair_.particles, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  v.resize(hair_.particles, glm::vec4(0.0f));
  for (glm::vec4& p : x) p.w = 1.0f;
  hair_.position.upload(x);
  hair_.velocity.upload(v);
}

namespace {

// The GPU solver's state (saveState, and a frame copy's): the particle count, the positions,
// velocities and rotations the passes step, as the GPU holds them (float, bit for bit), the
// time and the head. restoreState reads it.
void writeGpuState(std::vector<std::byte>& bytes, const std::vector<glm::vec4>& position,
                   const std::vector<glm::vec4>& velocity, const std::vector<glm::vec4>& rotation,
                   double time, const Pose& head) {
  StateWriter w(bytes);
  w.put(position.size());
  w.putVector(position);
  w.putVector(velocity);
  w.putVector(rotation);
  w.put(time);
  w.put(head);
}

}  // namespace

void GpuSolver::saveState(SolverState& out) {
  const size_t n = hair_.particles;
  auto all = [n](const gl::Buffer& b) {
    return n ? b.download<glm::vec4>(n) : std::vector<glm::vec4>{};
  };
  writeGpuState(out.bytes, all(hair_.position), all(hair_.velocity), all(hair_.rotation), time_,
                head_);
}

namespace {

class GpuFrameCopy final : public FrameCopy {
 public:
  gl::Buffer staging{gl::NoCreate};
  gl::Fence fence;
  size_t particles = 0;
  bool withState = false;
  double time = 0.0;
  Pose head;

  bool ready() const override { return fence.passed(); }
  void read(std::vector<glm::vec3>& positions, SolverState* state) override {
    fence.wait();
    const size_t n = particles;
    const std::vector<glm::vec4> all =
        n ? staging.download<glm::vec4>(n * (withState ? 3 : 1)) : std::vector<glm::vec4>{};
    positions.assign(all.begin(), all.begin() + std::ptrdiff_t(n));
    if (!state || !withState) return;
    auto part = [&](size_t k) {
      return std::vector<glm::vec4>(all.begin() + std::ptrdiff_t(k * n),
                                    all.begin() + std::ptrdiff_t((k + 1) * n));
    };
    writeGpuState(state->bytes, part(0), part(1), part(2), time, head);
  }
};

}  // namespace

std::unique_ptr<FrameCopy> GpuSolver::copyFrame(bool withState) {
  auto copy = std::make_unique<GpuFrameCopy>();
  const size_t n = hair_.particles;
  const GLsizeiptr bytes = GLsizeiptr(n * sizeof(glm::vec4));
  copy->particles = n;
  copy->withState = withState;
  copy->time = time_;
  copy->head = head_;
  if (n > 0) {
    copy->staging = gl::Buffer(bytes * (withState ? 3 : 1), nullptr, gl::BufferUsage::StreamRead);
    gl::memoryBarrier(gl::Barrier::BufferUpdate);
    hair_.position.copyTo(copy->staging, 0, 0, bytes);
    if (withState) {
      hair_.velocity.copyTo(copy->staging, 0, bytes, bytes);
      hair_.rotation.copyTo(copy->staging, 0, 2 * bytes, bytes);
    }
  }
  copy->fence = gl::Fence::insert();
  return copy;
}

bool GpuSolver::restoreState(const SolverState& in, std::string* error) {
  const size_t n = hair_.particles;
  StateReader r(in.bytes);
  std::vector<glm::vec4> x, v, q;
  double time = 0.0;
  Pose head;
  if (!r.expectCount(n, "particles", error)) return false;
  if (!r.getVector(x, n) || !r.getVector(v, n) || !r.getVector(q, n) || !r.get(time) ||
      !r.get(head) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another solver";
    return false;
  }
  if (n > 0) {
    hair_.position.upload(x);
    hair_.velocity.upload(v);
    hair_.rotation.upload(q);
  }
  time_ = time;
  head_ = head;
  // Lists sized for the hair restored (a denser state than the reset's overflowed its first
  // frame), and no last list: the one kept is of another state, nothing to count crossings
  // against (as after a reset).
  if (listsCandidates()) sizeLists();
  measureAnew();
  return true;
}

void GpuSolver::carry(const Pose& by) {
  if (hair_.particles == 0) return;
  // Positions, velocities and each region's rotation (the warm start of its next extraction)
  // turn with the hair, on the GPU (carry.comp).
  const glm::dquat q = glm::normalize(by.rotation);
  hair_.bind();
  gl::memoryBarrier(gpu::kPassBarrier);
  passes_.carry.set("turn", glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w)))
      .set("shift", glm::vec3(by.translation))
      .set("count", uint32_t(hair_.particles))
      .run(uint32_t(hair_.particles));
  gl::memoryBarrier(gl::Barrier::All);
  head_ = compose(by, head_);
}

unsigned GpuSolver::lastSubstepSpheres() const {
  // The spheres buffer holds the head's spheres for each step of the last writeParams: the
  // measures use the last step's.
  if (shape_.spheres.empty()) return 0;
  const size_t uploaded = size_t(spheres_.size()) / sizeof(glm::vec4);
  return unsigned(uploaded - std::min(uploaded, shape_.spheres.size()));
}

void GpuSolver::requestSample(long frame) {
  const bool listed = strandContacts(config_.collision.mode);
  // With hair-hair off, the contact measures are of where this frame started, as a strand
  // mode's list measures it: the search made when the last frame ended (after its sample, or
  // when the measures or the settings changed). With frames stepped since and no sample
  // between, of where this one ends (the crossings of the frames before it that no sample
  // reported are lost).
  const bool measuring = !listed && measureContacts_ && hair_.particles > 0;
  if (measuring && framesSinceMeasure_ > 1) measureNow();
  const uint32_t groups = uint32_t((hair_.particles + CSM_MEASURE_GROUP - 1) / CSM_MEASURE_GROUP);
  samples_.request(
      frame, groups,
      [&] {
        bindAll();
        passes_.measure.set("sphereBase", lastSubstepSpheres())
            .set("lastStep", unsigned(std::max(substepsWritten_ - 1, 0)))
            .run(uint32_t(hair_.particles));
      },
      measure_, contactSearch_.counters(), listed || measureContacts_);
  // The next frame's start, searched here, outside its timing (the sample has its copy).
  if (measuring && framesSinceMeasure_ != 0) measureNow();
}

std::optional<FrameSample> GpuSolver::takeSample(bool wait) {
  std::optional<FrameSample> sample = samples_.take(wait);
  if (sample && sample->contactsMeasured)
    sample->contacts.measureStride = contactSearch_.measureStride();
  return sample;
}

std::unique_ptr<GpuSolver> GpuSolver::start(std::string* error) {
  // Without a current context GL calls go to the dispatcher's no-op stubs: the version string is
  // null.
  if (gl::versionString() == nullptr) {
    if (error)
      *error =
          "the GPU solver needs a current OpenGL 4.3 context and none is current "
          "(headless runs make one through EGL; or use --solver cpu)";
    return nullptr;
  }
  const gl::Caps caps = gl::queryCaps();
  if (caps.major * 10 + caps.minor < 43) {
    if (error)
      *error = "the GPU solver needs OpenGL 4.3 compute shaders; the context is " + caps.version +
               " on " + caps.renderer + " (use --solver cpu)";
    return nullptr;
  }
  return create(error);
}

}  // namespace csm
