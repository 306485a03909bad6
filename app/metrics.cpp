#include "app/metrics.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "app/scene_setup.h"
#include "app/sim_frame.h"

namespace csm {

namespace {

double percentile95(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(0.95 * double(v.size() - 1) + 0.5))];
}

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

// The mean without the first frame, which also pays for what runs once (program builds, the
// driver's first allocations): what a frame costs once the scene runs. The plain mean when
// there is only one frame.
double steadyMean(const std::vector<double>& v) {
  if (v.size() < 2) return mean(v);
  return mean(std::vector<double>(v.begin() + 1, v.end()));
}

}  // namespace

void MetricsLog::addFrame(double simMs, const std::vector<StageTime>& stages) {
  simMs_.push_back(simMs);
  for (const StageTime& s : stages) stageSum_[s.name] += s.ms;
}

void MetricsLog::addUiFrame(double ms) {
  uiMs_.push_back(ms);
}

void MetricsLog::addSample(const FrameSample& sample) {
  const Accuracy& a = sample.accuracy;
  const ContactStats& contacts = sample.contacts;
  const bool first = samples_ == 0;
  ++samples_;
  worst_.maxStrain = first ? a.maxStrain : std::max(worst_.maxStrain, a.maxStrain);
  worst_.maxSpeed = std::max(worst_.maxSpeed, a.maxSpeed);
  worst_.nanCount = std::max(worst_.nanCount, a.nanCount);
  worst_.headPenetrations += a.headPenetrations;
  worst_.torsoPenetrations += a.torsoPenetrations;
  meanStrainSum_ += a.meanStrain;
  if (!sample.contactsMeasured) return;
  contactsLast_ = contacts.contacts;
  penetrationsLast_ = contacts.penetrations;
  penetrationsMax_ = std::max(penetrationsMax_, contacts.penetrations);
  if (sample.frame == 1) restPenetrations_ = int64_t(contacts.penetrations);
  ++contactSamples_;
  contactSum_.add(contacts);
}

void MetricsLog::addRender(double renderMs, const std::vector<StageTime>& stages) {
  renderMs_.push_back(renderMs);
  for (const StageTime& s : stages) renderStageSum_[s.name] += s.ms;
}

double MetricsLog::simMean() const {
  return mean(simMs_);
}

double MetricsLog::simP95() const {
  return percentile95(simMs_);
}

nlohmann::json MetricsLog::toJson(nlohmann::json meta) const {
  nlohmann::json& j = meta;
  j["frames"] = frames();
  // The fastest frame too: on a shared machine other work only ever adds time.
  const double fastest = simMs_.empty() ? 0.0 : *std::min_element(simMs_.begin(), simMs_.end());
  nlohmann::json ms = {{"sim_mean", simMean()},
                       {"sim_steady", steadyMean(simMs_)},
                       {"sim_p95", simP95()},
                       {"sim_min", fastest}};
  if (!uiMs_.empty()) {
    ms["ui_mean"] = mean(uiMs_);
    ms["ui_p95"] = percentile95(uiMs_);
    ms["ui_frames"] = uiMs_.size();
  }
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [name, sum] : stageSum_)
    stages[name] = simMs_.empty() ? 0.0 : sum / simMs_.size();
  ms["stages"] = stages;
  if (!renderMs_.empty()) {
    ms["render_mean"] = mean(renderMs_);
    ms["render_steady"] = steadyMean(renderMs_);
    ms["render_first"] = renderMs_.front();
    nlohmann::json rs = nlohmann::json::object();
    for (const auto& [name, s] : renderStageSum_) rs[name] = s / renderMs_.size();
    ms["render_stages"] = rs;
  }
  j["ms"] = ms;
  j["accuracy"] = {
      {"max_strain", worst_.maxStrain},
      {"mean_strain", samples_ == 0 ? 0.0 : meanStrainSum_ / double(samples_)},
      {"samples", samples_},
      {"head_penetrations", worst_.headPenetrations},
      {"torso_penetrations", worst_.torsoPenetrations},
      {"max_speed", worst_.maxSpeed},
      {"nan_count", worst_.nanCount},
  };
  // Hair-hair measures only where a sample measured them (a mode without hair-hair measures
  // them only when asked: SolverDiagnostics::setContactMeasures), never zeros for "not measured".
  if (contactSamples_ > 0) {
    // Each sample's crossings are those of its frame (against the frame before): per second
    // over the sampled frames.
    const double dt = j.value("frame_dt", 0.0);
    const double seconds = dt * double(contactSamples_);
    // Measured on 1 strand in `stride` (sim/core/measure_sample.h): a pair is in the sample
    // when both its strands are, so the whole hair's pair counts are about stride^2 times the
    // sample's. Said, with the sample's own count of crossings.
    const uint64_t stride = contactSum_.measureStride, pairScale = stride * stride;
    const uint64_t crossings = contactSum_.crossings * pairScale;
    const uint64_t crossingsClose = contactSum_.crossingsClose * pairScale;
    nlohmann::json& a = j["accuracy"];
    a["hair_measure_stride"] = stride;
    if (stride > 1) {
      a["hair_pair_counts_scaled_by"] = pairScale;
      a["hair_crossings_in_sample"] = contactSum_.crossings;
    }
    a["hair_contacts"] = contactsLast_ * pairScale;
    a["hair_penetrations"] = penetrationsLast_ * pairScale;
    a["hair_penetrations_max"] = penetrationsMax_ * pairScale;
    a["hair_crossings"] = crossings;
    a["hair_crossings_per_s"] = seconds > 0.0 ? double(crossings) / seconds : 0.0;
    // Of those, the pairs the groom put closer than 2r (their contact distance is the rest
    // distance): what is left is hair passing through hair that was apart.
    a["hair_crossings_close_at_rest"] = crossingsClose;
    a["hair_crossings_close_at_rest_per_s"] =
        seconds > 0.0 ? double(crossingsClose) / seconds : 0.0;
    a["hair_depth_p50"] = contactSum_.depthQuantile(0.50);
    a["hair_depth_p99"] = contactSum_.depthQuantile(0.99);
    a["hair_depth_max"] = contactSum_.maxDepth;
    a["hair_candidates_mean"] =
        double(contactSum_.candidates * pairScale) / double(contactSamples_);
    // Never silent: frames whose candidates did not fit the solver's buffers (they kept the
    // lists before them), and the most segments a sampled list left out as too long for the
    // grid's cells.
    a["hair_list_overflows"] = contactSum_.overflows;
    a["hair_oversize_segments_max"] = contactSum_.oversize;
    a["hair_crowded_segments_max"] = contactSum_.crowded;
    if (restPenetrations_ >= 0)
      a["hair_penetrations_rest"] = restPenetrations_ * int64_t(pairScale);
  }
  return j;
}

bool MetricsLog::write(const std::string& path, const nlohmann::json& meta,
                       std::string* error) const {
  const std::string text = toJson(meta).dump(2) + "\n";
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out.flush()) {
      if (error) *error = path + ": cannot write the metrics file";
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    if (error) *error = path + ": cannot write the metrics file";
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

RunDescription runDescription(const SceneSetup& scene, const SimFrame& figures,
                              const std::string& device) {
  RunDescription d;
  d.preset = scene.preset.name;
  d.source = scene.source;
  d.config = figures.config;
  d.stiffness = figures.stiffness;
  d.memory = figures.memory;
  d.strands = figures.strands;
  d.particles = figures.particles;
  d.groomStrands = figures.drawnStrands;
  d.solver = figures.solver;
  d.solverVariant = figures.solverVariant;
  d.groom = figures.groomReport;
  d.device = device;
  return d;
}

uint64_t peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0)
      return uint64_t(std::strtoull(line.c_str() + 6, nullptr, 10)) << 10;
  return 0;
}

nlohmann::json describeMemory(const MemoryUse& memory, std::size_t particles) {
  nlohmann::json kinds = nlohmann::json::object();
  for (const auto& [kind, bytes] : memory.bytes) kinds[kind] = bytes;
  const uint64_t total = memory.total();
  return {{"peak_rss_bytes", peakResidentBytes()},
          {"solver_buffers_bytes", kinds},
          {"solver_buffers_total_bytes", total},
          {"solver_bytes_per_particle", particles > 0 ? double(total) / double(particles) : 0.0}};
}

nlohmann::json describeRun(const RunDescription& r) {
  const Config& c = r.config;
  const bool paper = c.sim.stiffnessModel == StiffnessModel::Paper;
  nlohmann::json j = {
      {"preset", r.preset},
      {"source", r.source},
      {"strands", r.strands},
      {"particles", r.particles},
      {"groom_strands", r.groomStrands},
      {"guides", r.config.hairstyle.guides},
      {"frame_dt", c.sim.dt},
      {"substeps", r.stiffness.plan.substeps},
      {"stiffness",
       {{"model", paper ? "paper" : "calibrated"},
        {"window", paper ? double(c.sim.stiffnessWindow) : double(c.sim.windowLength)},
        {"window_unit", paper ? "particles" : "m"},
        {"bending_stiffness", c.sim.bendingStiffness},
        {"substeps_wanted", r.stiffness.plan.wanted},
        {"substeps_capped", r.stiffness.plan.capped},
        {"alpha", {r.stiffness.alphaMin, r.stiffness.alphaMax}},
        {"particles_per_side", {r.stiffness.windowMin, r.stiffness.windowMax}},
        {"rate", {r.stiffness.rateMin, r.stiffness.rateMax}},
        {"strands_at_alpha_1", r.stiffness.stifferStrands}}},
      {"stiffness_window", c.sim.stiffnessWindow},
      {"collision_mode", collisionModeName(c.collision.mode)},
      {"solver", r.solver},
      {"solver_variant", r.solverVariant},
      {"groom",
       {{"file_strands", r.groom.fileStrands},
        {"file_points", r.groom.filePoints},
        {"simulated_particles", r.groom.simulatedPoints},
        {"resample_saved_particles", r.groom.savedPoints()},
        {"dropped_strands", r.groom.repair.droppedStrands},
        {"merged_points", r.groom.repair.mergedPoints},
        {"turned_strands", r.groom.turnedStrands},
        {"pushed_particles", r.groom.pushedParticles},
        {"held_tips", r.groom.heldTips},
        {"kept_on_head", r.groom.keptOnHead},
        {"file_guides", r.groom.fileGuides.size()},
        {"follow_hairs", r.groom.followHairs},
        {"file_spheres", r.groom.fileSpheres.size()},
        {"repairs", r.groom.repair.notes}}},
      {"device", r.device},
  };
  j["memory"] = describeMemory(r.memory, r.particles);
  return j;
}

}  // namespace csm
