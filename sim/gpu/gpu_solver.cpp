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
#include "sim/gpu/buffer_fill.h"
#include "sim/gpu/strand_groups.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/core/measure_sample.h"
#include "shaders/sim/bindings.glsl"
#include "sim/solver/contacts.h"

namespace csm {
namespace {

// Strand lengths are rounded up to this step for MAX_N, so a regrown groom rarely recompiles.
constexpr int kMaxNStep = 8;

}  // namespace

const char* gpuKernelsName(GpuKernels k) {
  return k == GpuKernels::PerParticle ? "per particle" : "per strand";
}

GpuSolver::GpuSolver(bool cpuClock, GpuKernels kernels, Reads reads)
    : kernels_(kernels), reads_(reads), timer_(cpuClock) {}

std::vector<gl::Define> GpuSolver::withReads(std::vector<gl::Define> defines) const {
  if (reads_.uniformParams) defines.push_back({"CSM_PARAMS_UNIFORM", ""});
  if (reads_.storage) defines.push_back({"CSM_STORAGE_READS", ""});
  return defines;
}

std::unique_ptr<GpuSolver> GpuSolver::create(std::string* error) {
  const gl::Caps caps = gl::queryCaps();
  const bool software = caps.software;
  Reads reads;
  reads.uniformParams = !software && size_t(caps.maxUniformBlockSize) >= gpu::kParamBlockBytes;
  reads.storage = !software;
  if (const char* env = std::getenv("CSM_GPU_READS"); env && *env) {
    const std::string want = env;
    if (want == "texture") {
      reads = Reads{};
    } else if (want == "storage") {
      reads.storage = true;
      reads.uniformParams = size_t(caps.maxUniformBlockSize) >= gpu::kParamBlockBytes;
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
  torso_ = head;  // the body as one until a path says otherwise
  state_ = makeHairState(groom, config.sim, head);
  meanWeight_ = meanWeight(state_.weight);
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
  if (shape_.field != uploadedField_ || shape_.torsoField != uploadedTorso_) uploadHeadField();
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
  contactSearch_.reserveFor(
      state_.position, state_.particleStrand,
      2.0f * float(contactRadius(config_.collision, meanWeight_)) + config_.collision.margin,
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
  const DistanceGrid* torso = field ? shape_.torsoField : nullptr;
  if (field == uploadedField_ && torso == uploadedTorso_ && headField_.id() != 0) return;
  // The head's nodes, then the torso's (SimParams::torsoFieldOffset).
  std::vector<glm::vec4> nodes = field ? field->nodes : std::vector<glm::vec4>(1);
  if (torso) nodes.insert(nodes.end(), torso->nodes.begin(), torso->nodes.end());
  gpu::fill(headField_, nodes);
  gpu::view(headFieldTex_, headField_, gl::TextureFormat::Rgba32f);
  uploadedField_ = field;
  uploadedTorso_ = torso;
  uploadedHead_ = headModel_.shared();  // keeps the field uploaded alive, so its address names it
}

void GpuSolver::stepFrame(const FramePath& path) {
  const FramePlan plan = planFrame(config_.sim, regions_.planRate);
  const int substeps = plan.substeps;
  const double h = plan.h;
  std::vector<Pose> poses(substeps), before(substeps), torso(substeps), torsoBefore(substeps);
  ++framesSinceMeasure_;
  for (int k = 0; k < substeps; ++k) {
    poses[k] = path.at(double(k + 1) / substeps);
    before[k] = k == 0 ? head_ : poses[k - 1];
    torso[k] = path.torsoAt(double(k + 1) / substeps);
    torsoBefore[k] = k == 0 ? path.torsoAt(0.0) : torso[k - 1];
  }
  if (hair_.particles == 0 || !failure_.empty()) {
    time_ += substeps * h;
    head_ = poses.back();
    torso_ = torso.back();
    return;
  }
  const bool contacts = strandContacts(config_.collision.mode);
  // Constraints solved every substep, whose last corrections the strain limit applies; or the
  // paper's penalty forces where each substep ends (collision.contact_model).
  const bool penalty = contacts && config_.collision.model == ContactModel::Penalty;
  const bool constraints = contacts && !penalty;
  // Measuring contacts with hair-hair off, the grid keeps the last sample's list (crossings).
  if (contacts || !measureContacts_) contactSearch_.beginFrame(contacts);
  writeParams(poses, before, torso, torsoBefore);
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
  torso_ = torso.back();
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
