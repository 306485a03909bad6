#include "sim/gpu/gpu_solver.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/gl/caps.h"
#include "render/gl/debug.h"
#include "render/gl/shader_source.h"
#include "sim/hair_state.h"
#include "shaders/sim/bindings.glsl"

namespace csm {
namespace {

constexpr const char* kStageNames[] = {"integrate", "shape_matching", "strain_limiting", "grid",
                                       "contacts"};
enum Stage { kIntegrate = 0, kShapeMatching, kStrainLimiting, kGrid, kContacts };

// The cell edge and the contact prefilter get a little slack over their exact bounds, so that
// float rounding of midpoints never drops a pair closer than 2r (see contacts.comp).
constexpr float kCellSlack = 1.0f + 1e-5f;
constexpr float kPrefilterSlack = 1.0f + 1e-4f;

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

// The bucket offsets of the 9 runs of three x-neighbouring cells (dy, dz in -1..1) under the
// linear hash x + P1 y + P2 z (mod buckets): valid when the 27 buckets around any cell are
// distinct, i.e. the runs' bases are at least 3 apart around the table. Then every bucket is
// visited at most once, and no candidate is counted twice.
bool runsDistinct(uint32_t p1, uint32_t p2, uint32_t buckets, uint32_t runs[9]) {
  const uint32_t mask = buckets - 1;
  int k = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) runs[k++] = (uint32_t(dy) * p1 + uint32_t(dz) * p2) & mask;
  for (int i = 0; i < 9; ++i)
    for (int j = i + 1; j < 9; ++j) {
      const uint32_t d = (runs[i] - runs[j]) & mask;
      if (d < 3 || d > buckets - 3) return false;
    }
  return true;
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
        !make(programs_.segmentPrep, "sim/segment_prep.comp") ||
        !make(programs_.gridCount, "sim/grid_count.comp") ||
        !make(programs_.scanBlocks, "sim/scan_blocks.comp") ||
        !make(programs_.scanSums, "sim/scan_sums.comp") ||
        !make(programs_.scanAdd, "sim/scan_add.comp") ||
        !make(programs_.gridScatter, "sim/grid_scatter.comp") ||
        !make(programs_.gridRank, "sim/grid_rank.comp") ||
        !make(programs_.contacts, "sim/contacts.comp"))
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
  const HairState st = makeHairState(groom, config.sim, head);
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

  // One bucket per segment at least (a power of two, so the hash wraps with the integers).
  buckets_ = std::max<uint32_t>(64, std::bit_ceil(std::max<uint32_t>(segments_, 1)));
  scanBlocks_ = buckets_ / CSM_SCAN_LEAF;
  uint32_t runs[9] = {};
  uint32_t p1 = uint32_t(double(buckets_) * 0.6180339887) | 1u;
  uint32_t p2 = uint32_t(double(buckets_) * 0.7548776662) | 1u;
  for (int tries = 0; !runsDistinct(p1, p2, buckets_, runs); ++tries) {
    p1 += 2;
    if (tries % 64 == 63) p2 += 2;
  }
  params_.grid = glm::uvec4(buckets_ - 1, p1, p2, 0);
  for (int k = 0; k < 9; ++k) params_.runs[k / 4][k % 4] = runs[k];

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
  zeroed<glm::vec4>(segmentData_, particles_);
  zeroed<uint32_t>(segmentBucket_, particles_);
  zeroed<uint32_t>(gridCount_, buckets_);
  zeroed<uint32_t>(gridStart_, buckets_ + 4);  // + the total, as a uvec4
  zeroed<uint32_t>(scanBlockSums_, scanBlocks_ + 1);
  zeroed<glm::vec4>(unsorted_, segments_);
  zeroed<glm::vec4>(sortedData_, segments_);
  zeroed<uint32_t>(counters_, 4);
  zeroed<glm::uvec2>(pairs_, pairCapacity_);
  zeroed<uint32_t>(segmentContacts_, particles_);
  auto view = [](gl::BufferTexture& tex, const gl::Buffer& buffer, GLenum format) {
    if (tex.id() == 0)
      tex = gl::BufferTexture(buffer, format);
    else
      tex.attach(buffer, format);
  };
  view(positionTex_, position_, GL_RGBA32F);
  view(velocityTex_, velocity_, GL_RGBA32F);
  view(restTex_, rest_, GL_RGBA32F);
  view(sortedDataTex_, sortedData_, GL_RGBA32F);
  view(gridStartTex_, gridStart_, GL_R32UI);
  view(unsortedTex_, unsorted_, GL_RGBA32F);
  view(predictedTex_, predicted_, GL_RGBA32F);
  if (paramsBuffer_.id() == 0) paramsBuffer_ = gl::Buffer();
  if (spheres_.id() == 0) spheres_ = gl::Buffer();

  forcesValid_ = false;
  collidedThisFrame_ = false;
  contactStats_ = ContactStats{};
  for (FrameTimers& f : timers_) f.issued = false;
  lastStages_.clear();
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
  p.misc = glm::vec4(sim.dftl, wind.drag, kCellSlack, kPrefilterSlack);
  p.ints = glm::ivec4(sim.pinned, sim.stiffnessWindow, sim.rotationIterations,
                      int(config_.head.spheres.size()));
  const bool windOn = wind.strength > 0.0f && wind.drag > 0.0f;
  p.flags = glm::uvec4(sim.strainLimiting, col.mode != CollisionMode::Off, windOn, forcesValid_);
  p.counts = glm::uvec4(particles_, strands_, segments_, pairCapacity_);

  const int substeps = int(poses.size());
  const double h = double(sim.dt) / substeps;
  const double keep = std::max(0.0, 1.0 - double(sim.damping) * h);
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
    s.time = glm::vec4(float(t), float(h), 0.0f, float(keep));
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
  paramsBuffer_.bindBase(ssbo, CSM_BIND_PARAMS);
  spheres_.bindBase(ssbo, CSM_BIND_SPHERES);
  segmentForce_.bindBase(ssbo, CSM_BIND_SEGMENT_FORCE);
  segmentData_.bindBase(ssbo, CSM_BIND_SEGMENT_DATA);
  segmentBucket_.bindBase(ssbo, CSM_BIND_SEGMENT_BUCKET);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  unsorted_.bindBase(ssbo, CSM_BIND_UNSORTED);
  sortedData_.bindBase(ssbo, CSM_BIND_SORTED_DATA);
  counters_.bindBase(ssbo, CSM_BIND_COUNTERS);
  pairs_.bindBase(ssbo, CSM_BIND_PAIRS);
  segmentContacts_.bindBase(ssbo, CSM_BIND_SEGMENT_CONTACTS);
  positionTex_.bind(CSM_TEX_POSITION);
  velocityTex_.bind(CSM_TEX_VELOCITY);
  restTex_.bind(CSM_TEX_REST);
  sortedDataTex_.bind(CSM_TEX_SORTED_DATA);
  gridStartTex_.bind(CSM_TEX_GRID_START);
  unsortedTex_.bind(CSM_TEX_UNSORTED);
  predictedTex_.bind(CSM_TEX_PREDICTED);
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
    glFinish();  // a no-op on llvmpipe, whose dispatches have already run
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
  const int substeps = std::max(1, config_.sim.substeps);
  const double h = double(config_.sim.dt) / substeps;
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
    forcesValid_ = false;
    contactStats_ = ContactStats{};
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
  endStage();
  timers_[timerFrame_].issued = true;
  forcesValid_ = true;
  gl::memoryBarrier(gl::Barrier::All);
}

void GpuSolver::collide() {
  contactStats_.reset();
  if (segments_ == 0) {
    contactStats_ = ContactStats{};
    return;
  }
  timeStage(kGrid);
  counters_.clearToZero();
  dispatchItems(programs_.segmentPrep, uint32_t(strands_), CSM_STRAND_GROUP);
  gl::memoryBarrier(kPassBarrier);
  dispatchItems(programs_.gridCount, uint32_t(particles_), CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  // Counting sort, exclusive scan of the bucket counts: block sums, their scan, each block
  // rescanned from its offset.
  programs_.scanBlocks.setUniform("blocks", scanBlocks_);
  dispatchItems(programs_.scanBlocks, scanBlocks_, CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  programs_.scanSums.setUniform("count", scanBlocks_);
  programs_.scanSums.dispatch(1);
  gl::memoryBarrier(kPassBarrier);
  programs_.scanAdd.setUniform("blocks", scanBlocks_);
  dispatchItems(programs_.scanAdd, scanBlocks_, CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  dispatchItems(programs_.gridScatter, uint32_t(particles_), CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  dispatchItems(programs_.gridRank, segments_, CSM_PARTICLE_GROUP);
  gl::memoryBarrier(kPassBarrier);
  timeStage(kContacts);
  dispatchItems(programs_.contacts, segments_, CSM_CONTACT_GROUP);
  gl::memoryBarrier(kPassBarrier);
}

void GpuSolver::finish() {
  glFinish();
}

void GpuSolver::readPositions(std::vector<glm::vec4>& out) {
  out = position_.download<glm::vec4>(particles_);
}

void GpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  out = velocity_.download<glm::vec4>(particles_);
}

std::vector<StageTime> GpuSolver::stageTimes() {
  // The newest frame whose queries have all finished; if none has, wait for the newest.
  const int n = int(timers_.size());
  int pick = -1;
  for (int k = 0; k < n && pick < 0; ++k) {
    const int f = (timerFrame_ - k + n) % n;
    const FrameTimers& t = timers_[f];
    if (t.issued && (t.used == 0 || t.queries[t.used - 1].second.resultAvailable())) pick = f;
  }
  if (pick < 0 && timers_[timerFrame_].issued) pick = timerFrame_;
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

ContactStats GpuSolver::contactStats() {
  if (!contactStats_) {
    const std::vector<uint32_t> c = counters_.download<uint32_t>(4);
    contactStats_ = ContactStats{c[CSM_COUNTER_CONTACTS], c[CSM_COUNTER_PENETRATIONS]};
  }
  return *contactStats_;
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
