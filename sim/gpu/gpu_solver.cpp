#include "sim/gpu/gpu_solver.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gl/caps.h"
#include "gl/draw.h"
#include "gl/debug.h"
#include "gl/shader_source.h"
#include "sim/hair_state.h"
#include "shaders/sim/bindings.glsl"

namespace csm {
namespace {

constexpr const char* kStageNames[] = {"integrate", "shape_matching", "strain_limiting", "grid",
                                       "contacts"};
enum Stage { kIntegrate = 0, kShapeMatching, kStrainLimiting, kGrid, kContacts };

// The grid (DESIGN.md section 1.7). Boxes are padded by r (half the contact distance) and 1%,
// so that a pair the contact pass finds closer than 2r in float always has overlapping boxes.
constexpr float kPadSlack = 1.01f;
// A segment enters at most this many cells (4 x 4 x 4): a box of a strain-limited segment
// spans at most 3 cells per axis (cells are at least half a mean segment), so only a segment
// stretched to ~1.5 mean lengths or more misses it. Such a segment is in no cell this frame
// (counted; see gridStats), which keeps the pass bounded when a simulation explodes.
constexpr uint32_t kMaxSegmentCells = 64;
// Entry buffers start at this many entries per segment (Fig. 1 needs ~7); when a frame needs
// more, the pass skips that frame and the buffers grow (see growEntries).
constexpr uint32_t kEntriesPerSegment = 10;

// Strand lengths are rounded up to this step for MAX_N, so a regrown groom rarely recompiles.
constexpr int kMaxNStep = 8;

// Between passes: storage writes become visible to storage reads and to texel fetches.
constexpr gl::Barrier kPassBarrier = gl::Barrier::Storage | gl::Barrier::TextureFetch;

template <class T>
void fill(gl::Buffer& buffer, const std::vector<T>& data) {
  // At least one element: a zero-sized buffer cannot be bound to an SSBO point usefully.
  if (data.empty()) {
    std::vector<T> one(1);
    fill(buffer, one);
    return;
  }
  if (buffer.id() == 0)
    buffer = gl::Buffer(data);
  else
    buffer.upload(data);
}

template <class T>
void zeroed(gl::Buffer& buffer, size_t count) {
  fill(buffer, std::vector<T>(std::max<size_t>(count, 1)));
}

}  // namespace

std::unique_ptr<GpuSolver> GpuSolver::create(std::string* error) {
  std::unique_ptr<GpuSolver> solver(new GpuSolver());
  solver->cpuTiming_ = gl::queryCaps().software;
  if (!solver->build(32, error)) return nullptr;
  return solver;
}

GpuSolver::~GpuSolver() = default;

bool GpuSolver::build(int maxStrandSize, std::string* error) {
  const int maxN = std::max(kMaxNStep, (maxStrandSize + kMaxNStep - 1) / kMaxNStep * kMaxNStep);
  auto make = [&](gl::Program& out, const char* path, const std::vector<gl::Define>& defines = {}) {
    std::string log;
    std::optional<gl::Program> p =
        gl::buildProgram(path, {{GL_COMPUTE_SHADER, path}}, defines, &log);
    if (!p) {
      if (error) *error = std::string("GPU solver: ") + path + " does not build:\n" + log;
      return false;
    }
    out = std::move(*p);
    return true;
  };
  if (builtMaxN_ == 0) {
    if (!make(programs_.predict, "sim/predict.comp") ||
        !make(programs_.strainLimit, "sim/strain_limit.comp") ||
        !make(programs_.gridCount, "sim/grid_count.comp") ||
        !make(programs_.scanBlocks, "sim/scan_blocks.comp") ||
        !make(programs_.scanSums, "sim/scan_sums.comp") ||
        !make(programs_.scanAdd, "sim/scan_add.comp") ||
        !make(programs_.gridScatter, "sim/grid_scatter.comp") ||
        !make(programs_.contacts, "sim/contacts.comp") ||
        !make(programs_.segmentForces, "sim/segment_forces.comp") ||
        !make(programs_.measure, "sim/measure.comp"))
      return false;
  }
  if (maxN != builtMaxN_) {
    // The per-strand prefix arrays are private arrays sized by the longest strand.
    if (!make(programs_.shapeMatch, "sim/shape_match.comp", {{"MAX_N", std::to_string(maxN)}}))
      return false;
    builtMaxN_ = maxN;
  }
  return true;
}

void GpuSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  time_ = 0.0;
  head_ = head;
  state_ = makeHairState(groom, config.sim, head);
  const HairState& st = state_;
  particles_ = st.particleCount();
  strands_ = st.strandCount();

  int maxStrand = 0;
  segments_ = 0;
  std::vector<uint32_t> order(strands_);
  std::iota(order.begin(), order.end(), 0u);
  for (size_t s = 0; s < strands_; ++s) {
    const int size = int(st.strandFirst[s + 1] - st.strandFirst[s]);
    maxStrand = std::max(maxStrand, size);
    segments_ += uint32_t(std::max(0, size - 1));
  }
  // Strands of equal length side by side: a SIMD group of the per-strand passes then runs
  // loops of one length (the state itself keeps the groom's order).
  std::stable_sort(order.begin(), order.end(), [&](uint32_t l, uint32_t r) {
    return st.strandFirst[l + 1] - st.strandFirst[l] < st.strandFirst[r + 1] - st.strandFirst[r];
  });
  std::string error;
  if (!build(maxStrand, &error)) {
    // The shaders built at create() with MAX_N 32; a longer strand needs a recompile, which
    // only fails if the driver runs out of resources.
    gl::logMessage(gl::LogLevel::Error, error);
  }

  // Rest lengths set the cell edge (DESIGN.md section 1.7): strain limiting keeps the current
  // ones within a few percent, and a grid fixed per groom needs no reduction on the GPU.
  double restSum = 0.0;
  for (size_t i = 0; i + 1 < particles_; ++i)
    if (st.particleStrand[i] == st.particleStrand[i + 1])
      restSum += glm::length(glm::dvec3(st.rest[i + 1]) - glm::dvec3(st.rest[i]));
  meanSegment_ = segments_ > 0 ? restSum / segments_ : 0.0;
  // Two buckets per segment (a power of two, so the hash is masked): dense hair fills far
  // fewer cells than that, sparse hair about as many, so few buckets hold two cells.
  buckets_ = std::max<uint32_t>(64, std::bit_ceil(std::max<uint32_t>(2 * segments_, 1)));
  scanBlocks_ = buckets_ / CSM_SCAN_LEAF;
  // The per-segment scan (where each segment's partial forces start) runs on the same scan
  // passes, over one count per particle.
  segmentScan_ = std::max<uint32_t>(64, std::bit_ceil(uint32_t(particles_)));

  fill(rest_, st.rest);
  fill(position_, st.position);
  fill(velocity_, st.velocity);
  fill(strandFirst_, st.strandFirst);
  fill(particleStrand_, st.particleStrand);
  fill(predicted_, st.position);
  fill(strandOrder_, order);
  const glm::dquat q = head.rotation;
  fill(rotation_, std::vector<glm::vec4>(particles_, glm::vec4(q.x, q.y, q.z, q.w)));
  zeroed<glm::vec4>(segmentForce_, 2 * particles_);
  zeroed<uint32_t>(gridCount_, buckets_);
  zeroed<uint32_t>(gridStart_, buckets_ + 4);  // + the total, as a uvec4
  zeroed<uint32_t>(scanBlockSums_, scanBlocks_ + 1);
  zeroed<uint32_t>(counters_, CSM_COUNTERS);
  zeroed<uint32_t>(segmentCells_, segmentScan_);
  zeroed<uint32_t>(segmentBase_, segmentScan_ + 4);
  zeroed<uint32_t>(segmentScanBlocks_, segmentScan_ / CSM_SCAN_LEAF + 1);
  zeroed<glm::uvec2>(pairs_, pairCapacity_);
  zeroed<uint32_t>(segmentContacts_, particles_);
  entryCapacity_ = 0;
  growEntries(std::max<uint64_t>(1, uint64_t(segments_) * kEntriesPerSegment));
  view(positionTex_, position_, GL_RGBA32F);
  view(velocityTex_, velocity_, GL_RGBA32F);
  view(restTex_, rest_, GL_RGBA32F);
  view(gridStartTex_, gridStart_, GL_R32UI);
  view(predictedTex_, predicted_, GL_RGBA32F);
  uploadRegions();
  if (paramsBuffer_.id() == 0) paramsBuffer_ = gl::Buffer();
  if (spheres_.id() == 0) spheres_ = gl::Buffer();

  forcesValid_ = false;
  collidedThisFrame_ = false;
  sampledContacts_ = ContactStats{};
  dropSamples();
  zeroed<glm::uvec4>(measure_, 2 * ((particles_ + CSM_MEASURE_GROUP - 1) / CSM_MEASURE_GROUP));
  for (FrameTimers& f : timers_) f.issued = false;
  lastStages_.clear();
}

void GpuSolver::uploadRegions() {
  regions_ = buildRegions(state_, config_.sim);
  std::vector<glm::vec4> region(particles_);
  for (size_t i = 0; i < particles_; ++i) {
    const double J = regions_.inertia[i];
    region[i] = glm::vec4(float(regions_.mass[i]), J > 0.0 ? float(1.0 / J) : 0.0f,
                          float(regions_.lo[i]), float(regions_.hi[i]));
  }
  fill(region_, region);
  std::vector<glm::vec4> strand(strands_);
  for (size_t s = 0; s < strands_; ++s)
    strand[s] = glm::vec4(float(regions_.rate[s]), float(regions_.ghostMass[s]),
                          float(regions_.pinned[s]), 0.0f);
  fill(strandStiffness_, strand);
  view(regionTex_, region_, GL_RGBA32F);
}

void GpuSolver::setConfig(const Config& config) {
  const bool rebuild = regionsChanged(config_.sim, config.sim);
  config_ = config;
  if (rebuild && particles_ > 0) uploadRegions();
}

void GpuSolver::view(gl::BufferTexture& tex, const gl::Buffer& buffer, GLenum format) {
  if (tex.id() == 0)
    tex = gl::BufferTexture(buffer, format);
  else
    tex.attach(buffer, format);
}

void GpuSolver::growEntries(uint64_t needed) {
  // A quarter more than asked, so a growing tangle does not reallocate every frame; never
  // beyond what a 32-bit index and one buffer can hold.
  const uint64_t limit = uint64_t(1) << 27;  // 2 GiB of 16-byte entries
  const uint64_t want = std::min(limit, needed + needed / 4);
  if (want <= entryCapacity_) return;
  entryCapacity_ = uint32_t(want);
  zeroed<glm::uvec4>(entryLow_, entryCapacity_);
  zeroed<glm::uvec4>(entryHigh_, entryCapacity_);
  zeroed<glm::vec4>(partialForce_, 2 * size_t(entryCapacity_));
  view(entryLowTex_, entryLow_, GL_RGBA32UI);
  view(entryHighTex_, entryHigh_, GL_RGBA32UI);
}

GpuSolver::GridStats GpuSolver::gridStats() {
  const std::vector<uint32_t> c = counters_.download<uint32_t>(CSM_COUNTERS);
  GridStats g;
  g.entries = c[CSM_COUNTER_ENTRIES];
  g.capacity = entryCapacity_;
  g.oversize = c[CSM_COUNTER_OVERSIZE];
  g.buckets = buckets_;
  g.cell = params_.cells.x;
  return g;
}

void GpuSolver::setPairCapacity(size_t capacity) {
  pairCapacity_ = capacity;
  zeroed<glm::uvec2>(pairs_, pairCapacity_);
}

void GpuSolver::writeParams(const std::vector<Pose>& poses, const std::vector<Pose>& before) {
  const SimConfig& sim = config_.sim;
  const CollisionConfig& col = config_.collision;
  const WindConfig& wind = config_.wind;
  gpu::SimParams& p = params_;
  p.gravity = glm::vec4(sim.gravity, 0.0f);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  p.windDir = glm::vec4(glm::vec3(dir), wind.strength);
  p.windShape = glm::vec4(wind.gusts, wind.gustFrequency, wind.turbulence, wind.turbulenceScale);
  p.stepping = glm::vec4(sim.stiffness, sim.strainLimit, col.radius, col.headFriction);
  p.contact = glm::vec4(col.stiffness, col.damping, col.friction, sim.dt);
  p.misc = glm::vec4(sim.dftl, wind.drag, 0.0f, 0.0f);
  p.ints = glm::ivec4(0, int(sim.stiffnessModel), sim.rotationIterations,
                      int(config_.head.spheres.size()));
  const bool windOn = wind.strength > 0.0f && wind.drag > 0.0f;
  p.flags = glm::uvec4(sim.strainLimiting, col.mode != CollisionMode::Off, windOn, forcesValid_);
  p.counts = glm::uvec4(particles_, strands_, segments_, pairCapacity_);
  p.grid = glm::uvec4(buckets_ - 1, entryCapacity_, kMaxSegmentCells, 0);
  // Cells of at least twice the contact distance and half a mean segment, as the CPU
  // reference (findContactsGrid): a segment then enters ~2-12 cells, and a cell holds about a
  // sixteenth of what a cell as long as a segment holds.
  const double cell = std::max({4.0 * double(col.radius), 0.5 * meanSegment_, 1e-6});
  p.cells = glm::vec4(float(cell), float(1.0 / cell), col.radius * kPadSlack + 1e-7f, 0.0f);
  // Cells count from the head, so the clamped 10-bit cell coordinates (common.glsl) cover
  // +-512 cells around it wherever it moves.
  p.origin = glm::vec4(glm::vec3(poses.back().translation), 0.0f);

  const int substeps = int(poses.size());
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
    s.time = glm::vec4(float(t), float(h), float(twistStepOf(sim, h, sim.rotationIterations)),
                       float(keep));
    std::memcpy(blob.data() + sizeof(p) + k * sizeof(s), &s, sizeof(s));
    for (const Sphere& sp : worldSpheres(config_.head.spheres, poses[k]))
      spheres.emplace_back(sp.center, sp.radius);
    t += h;  // as CpuSolver advances its clock, step by step
  }
  paramsBuffer_.upload(blob);
  fill(spheres_, spheres);
}

void GpuSolver::bindAll() {
  const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
  rest_.bindBase(ssbo, CSM_BIND_REST);
  position_.bindBase(ssbo, CSM_BIND_POSITION);
  velocity_.bindBase(ssbo, CSM_BIND_VELOCITY);
  strandFirst_.bindBase(ssbo, CSM_BIND_STRAND_FIRST);
  particleStrand_.bindBase(ssbo, CSM_BIND_PARTICLE_STRAND);
  predicted_.bindBase(ssbo, CSM_BIND_PREDICTED);
  rotation_.bindBase(ssbo, CSM_BIND_ROTATION);
  strandOrder_.bindBase(ssbo, CSM_BIND_STRAND_ORDER);
  region_.bindBase(ssbo, CSM_BIND_REGION);
  strandStiffness_.bindBase(ssbo, CSM_BIND_STRAND_STIFFNESS);
  paramsBuffer_.bindBase(ssbo, CSM_BIND_PARAMS);
  spheres_.bindBase(ssbo, CSM_BIND_SPHERES);
  segmentForce_.bindBase(ssbo, CSM_BIND_SEGMENT_FORCE);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  entryHigh_.bindBase(ssbo, CSM_BIND_ENTRY_HIGH);
  entryLow_.bindBase(ssbo, CSM_BIND_ENTRY_LOW);
  counters_.bindBase(ssbo, CSM_BIND_COUNTERS);
  pairs_.bindBase(ssbo, CSM_BIND_PAIRS);
  segmentContacts_.bindBase(ssbo, CSM_BIND_SEGMENT_CONTACTS);
  segmentCells_.bindBase(ssbo, CSM_BIND_SEGMENT_CELLS);
  segmentBase_.bindBase(ssbo, CSM_BIND_SEGMENT_BASE);
  partialForce_.bindBase(ssbo, CSM_BIND_PARTIAL_FORCE);
  measure_.bindBase(ssbo, CSM_BIND_MEASURE);
  positionTex_.bind(CSM_TEX_POSITION);
  velocityTex_.bind(CSM_TEX_VELOCITY);
  restTex_.bind(CSM_TEX_REST);
  entryLowTex_.bind(CSM_TEX_ENTRY_LOW);
  gridStartTex_.bind(CSM_TEX_GRID_START);
  entryHighTex_.bind(CSM_TEX_ENTRY_HIGH);
  predictedTex_.bind(CSM_TEX_PREDICTED);
  regionTex_.bind(CSM_TEX_REGION);
}

void GpuSolver::dispatchItems(const gl::Program& program, uint32_t items, uint32_t groupSize) {
  const uint32_t groups = (items + groupSize - 1) / groupSize;
  if (groups == 0) return;
  // GL 4.3 guarantees 65535 groups per dimension; beyond that, a 2D grid of groups
  // (globalIndex() in common.glsl flattens it).
  const uint32_t x = std::min<uint32_t>(groups, 65535u);
  program.dispatch(x, (groups + x - 1) / x);
}

void GpuSolver::timeStage(int stage) {
  endStage();
  FrameTimers& f = timers_[timerFrame_];
  if (cpuTiming_) {
    stageStart_ = std::chrono::steady_clock::now();
  } else {
    if (f.used == f.queries.size()) f.queries.emplace_back(stage, gl::Query(GL_TIME_ELAPSED));
    f.queries[f.used].first = stage;
    f.queries[f.used].second.begin();
    ++f.used;
  }
  openStage_ = stage;
}

void GpuSolver::endStage() {
  if (openStage_ < 0) return;
  FrameTimers& f = timers_[timerFrame_];
  if (cpuTiming_) {
    gl::finish();  // a no-op on llvmpipe, whose dispatches have already run
    f.cpuMs[openStage_] +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stageStart_)
            .count();
  } else {
    f.queries[f.used - 1].second.end();
  }
  openStage_ = -1;
}

void GpuSolver::beginTimerFrame() {
  timerFrame_ = (timerFrame_ + 1) % int(timers_.size());
  FrameTimers& f = timers_[timerFrame_];
  f.used = 0;
  f.issued = false;
  f.cpuMs.fill(0.0);
}

void GpuSolver::stepFrame(const Pose& from, const Pose& to) {
  const FramePlan plan = planFrame(config_.sim, regions_.maxRate);
  const int substeps = plan.substeps;
  lastSubsteps_ = substeps;
  const double h = plan.h;
  std::vector<Pose> poses(substeps), before(substeps);
  for (int k = 0; k < substeps; ++k) {
    poses[k] = interpolate(from, to, double(k + 1) / substeps);
    before[k] = k == 0 ? head_ : poses[k - 1];
  }
  if (particles_ == 0) {
    time_ += substeps * h;
    head_ = poses.back();
    return;
  }
  writeParams(poses, before);
  bindAll();
  beginTimerFrame();

  for (int k = 0; k < substeps; ++k) {
    timeStage(kIntegrate);
    programs_.predict.setUniform("substep", unsigned(k));
    dispatchItems(programs_.predict, uint32_t(particles_), CSM_PARTICLE_GROUP);
    gl::memoryBarrier(kPassBarrier);
    timeStage(kShapeMatching);
    programs_.shapeMatch.setUniform("substep", unsigned(k));
    dispatchItems(programs_.shapeMatch, uint32_t(strands_), CSM_STRAND_GROUP);
    gl::memoryBarrier(kPassBarrier);
    timeStage(kStrainLimiting);
    programs_.strainLimit.setUniform("substep", unsigned(k));
    dispatchItems(programs_.strainLimit, uint32_t(strands_), CSM_STRAND_GROUP);
    gl::memoryBarrier(kPassBarrier);
    time_ += h;
  }
  endStage();
  head_ = poses.back();
  if (config_.collision.mode == CollisionMode::Full) {
    collide();
    forcesValid_ = true;
  } else {
    // No collision pass: nothing to report either (the counters of a last pass are cleared
    // once, on the GPU).
    if (forcesValid_) counters_.clearToZero();
    forcesValid_ = false;
  }
  endStage();
  timers_[timerFrame_].issued = true;
  // The renderer reads the positions as vertex data or storage; read-backs and clears follow.
  gl::memoryBarrier(gl::Barrier::All);
}

void GpuSolver::detectContacts() {
  if (particles_ == 0) return;
  // Parameters as they stand, at the current time (no step is taken); timed as a frame of
  // its own.
  writeParams({head_}, {head_});
  bindAll();
  beginTimerFrame();
  collide();
  // A tool asks for this pass's contacts: when the grid did not fit, grow it and run again
  // (stepFrame instead grows it when a sample sees the total).
  const uint32_t needed = counters_.download<uint32_t>(1)[CSM_COUNTER_ENTRIES];
  if (needed > entryCapacity_) {
    growEntries(needed);
    writeParams({head_}, {head_});
    bindAll();
    collide();
  }
  endStage();
  timers_[timerFrame_].issued = true;
  forcesValid_ = true;
  gl::memoryBarrier(gl::Barrier::All);
}

void GpuSolver::collide() {
  if (segments_ == 0) return;
  timeStage(kGrid);
  counters_.clearToZero();
  dispatchItems(programs_.gridCount, uint32_t(particles_), CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  // Counting sort, exclusive scan of the bucket counts; then the same scan over the
  // segments' cell counts, its buffers bound in the grid's place for the while.
  scan(scanBlocks_);
  const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
  segmentCells_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  segmentBase_.bindBase(ssbo, CSM_BIND_GRID_START);
  segmentScanBlocks_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  scan(segmentScan_ / CSM_SCAN_LEAF);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  dispatchItems(programs_.gridScatter, uint32_t(particles_), CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  timeStage(kContacts);
  // One invocation per entry slot: how many are used is known on the GPU only (no read-back
  // inside a frame); the others return at once.
  dispatchItems(programs_.contacts, entryCapacity_, CSM_CONTACT_GROUP);
  gl::memoryBarrier(kPassBarrier);
  dispatchItems(programs_.segmentForces, uint32_t(particles_), CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
}

void GpuSolver::scan(uint32_t blocks) {
  // Block sums, their scan, each block rescanned from its offset (scan_*.comp).
  programs_.scanBlocks.setUniform("blocks", blocks);
  dispatchItems(programs_.scanBlocks, blocks, CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  programs_.scanSums.setUniform("count", blocks);
  programs_.scanSums.dispatch(1);
  gl::memoryBarrier(kPassBarrier);
  programs_.scanAdd.setUniform("blocks", blocks);
  dispatchItems(programs_.scanAdd, blocks, CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
}

void GpuSolver::finish() {
  gl::finish();
}

void GpuSolver::readPositions(std::vector<glm::vec4>& out) {
  out = position_.download<glm::vec4>(particles_);
}

void GpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  out = velocity_.download<glm::vec4>(particles_);
}

void GpuSolver::writeState(const std::vector<glm::vec4>& positions,
                           const std::vector<glm::vec4>& velocities) {
  if (particles_ == 0) return;
  std::vector<glm::vec4> x(positions), v(velocities);
  x.resize(particles_, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  v.resize(particles_, glm::vec4(0.0f));
  for (glm::vec4& p : x) p.w = 1.0f;
  position_.upload(x);
  velocity_.upload(v);
}

std::vector<StageTime> GpuSolver::stageTimes() {
  // The newest frame whose queries have all finished; none yet: the last known (no waiting).
  const int n = int(timers_.size());
  int pick = -1;
  for (int k = 0; k < n && pick < 0; ++k) {
    const int f = (timerFrame_ - k + n) % n;
    const FrameTimers& t = timers_[f];
    if (t.issued && (t.used == 0 || t.queries[t.used - 1].second.resultAvailable())) pick = f;
  }
  if (pick < 0) return lastStages_;
  std::vector<StageTime> out;
  for (const char* name : kStageNames) out.push_back({name, 0.0});
  const FrameTimers& t = timers_[pick];
  for (int k = 0; k < kStages; ++k) out[k].ms += t.cpuMs[k];
  for (size_t i = 0; i < t.used; ++i)
    out[t.queries[i].first].ms += double(t.queries[i].second.result()) * 1e-6;
  lastStages_ = out;
  return out;
}

ContactStats GpuSolver::readContactStats() {
  const std::vector<uint32_t> c = counters_.download<uint32_t>(CSM_COUNTERS);
  afterCounters(c.data());
  return ContactStats{c[CSM_COUNTER_CONTACTS], c[CSM_COUNTER_PENETRATIONS]};
}

void GpuSolver::afterCounters(const uint32_t* c) {
  // The grid did not fit that frame (it applied no hair-hair forces): room for the next.
  if (c[CSM_COUNTER_ENTRIES] > entryCapacity_) growEntries(c[CSM_COUNTER_ENTRIES]);
}

void GpuSolver::requestSample(long frame) {
  // A full ring: its oldest sample is read now (waiting for it) and kept until taken.
  if (pendingSlots_.size() == slots_.size()) {
    slots_[pendingSlots_.front()].fence.wait();
    ready_.push_back(readSlot());
  }
  int index = 0;
  while (std::find(pendingSlots_.begin(), pendingSlots_.end(), index) != pendingSlots_.end())
    ++index;
  SampleSlot& slot = slots_[index];
  slot.frame = frame;
  slot.groups = uint32_t((particles_ + CSM_MEASURE_GROUP - 1) / CSM_MEASURE_GROUP);
  const GLsizeiptr recordBytes = GLsizeiptr(slot.groups) * 2 * sizeof(glm::uvec4);
  const GLsizeiptr bytes = recordBytes + CSM_COUNTERS * sizeof(uint32_t);
  if (slot.staging.id() == 0) slot.staging = gl::Buffer();
  if (slot.staging.size() < bytes) slot.staging.setData(bytes, nullptr, GL_STREAM_READ);
  if (slot.groups > 0) {
    bindAll();
    programs_.measure.setUniform("sphereBase",
                                 unsigned((lastSubsteps_ - 1) * int(config_.head.spheres.size())));
    dispatchItems(programs_.measure, uint32_t(particles_), CSM_MEASURE_GROUP);
    gl::memoryBarrier(gl::Barrier::BufferUpdate);
    measure_.copyTo(slot.staging, 0, 0, recordBytes);
  }
  counters_.copyTo(slot.staging, 0, recordBytes, CSM_COUNTERS * sizeof(uint32_t));
  slot.fence = gl::Fence::insert();
  pendingSlots_.push_back(index);
}

std::optional<FrameSample> GpuSolver::takeSample(bool wait) {
  if (!ready_.empty()) {
    FrameSample s = ready_.front();
    ready_.pop_front();
    return s;
  }
  if (pendingSlots_.empty()) return std::nullopt;
  const SampleSlot& slot = slots_[pendingSlots_.front()];
  if (!slot.fence.passed()) {
    if (!wait) return std::nullopt;
    slot.fence.wait();
  }
  return readSlot();
}

FrameSample GpuSolver::readSlot() {
  SampleSlot& slot = slots_[pendingSlots_.front()];
  pendingSlots_.pop_front();
  std::vector<glm::uvec4> data(size_t(slot.groups) * 2 + CSM_COUNTERS / 4);
  slot.staging.read(0, GLsizeiptr(data.size() * sizeof(glm::uvec4)), data.data());
  // The records in order (measure.comp), as measureAccuracy adds them.
  FrameSample sample;
  sample.frame = slot.frame;
  Accuracy& a = sample.accuracy;
  uint32_t strainKey = 0;
  uint64_t segments = 0;
  double strainSum = 0.0;
  for (uint32_t g = 0; g < slot.groups; ++g) {
    const glm::uvec4 r0 = data[2 * g], r1 = data[2 * g + 1];
    strainKey = std::max(strainKey, r0.x);
    segments += r0.y;
    a.headPenetrations += r0.z;
    a.nanCount += r0.w;
    strainSum += double(std::bit_cast<float>(r1.x));
    a.maxSpeed = std::max(a.maxSpeed, double(std::bit_cast<float>(r1.y)));
  }
  if (segments > 0) {
    // measure.comp's orderedKey, inverted.
    const uint32_t bits = (strainKey & 0x80000000u) ? (strainKey & 0x7fffffffu) : ~strainKey;
    a.maxStrain = double(std::bit_cast<float>(bits));
    a.meanStrain = strainSum / double(segments);
  }
  const uint32_t* c = reinterpret_cast<const uint32_t*>(&data[size_t(slot.groups) * 2]);
  sample.contacts = ContactStats{c[CSM_COUNTER_CONTACTS], c[CSM_COUNTER_PENETRATIONS]};
  sampledContacts_ = sample.contacts;
  afterCounters(c);
  return sample;
}

void GpuSolver::dropSamples() {
  pendingSlots_.clear();
  ready_.clear();
  for (SampleSlot& slot : slots_) slot.fence = gl::Fence();
}

std::vector<std::pair<uint32_t, uint32_t>> GpuSolver::readContactPairs(bool* overflow) {
  const std::vector<uint32_t> c = counters_.download<uint32_t>(4);
  const size_t found = c[CSM_COUNTER_PAIRS];
  if (overflow) *overflow = found > pairCapacity_;
  const size_t n = std::min(found, pairCapacity_);
  std::vector<std::pair<uint32_t, uint32_t>> out;
  out.reserve(n);
  for (const glm::uvec2& p : pairs_.download<glm::uvec2>(n)) out.emplace_back(p.x, p.y);
  return out;
}

std::vector<uint32_t> GpuSolver::readSegmentContactCounts() {
  return segmentContacts_.download<uint32_t>(particles_);
}

}  // namespace csm
