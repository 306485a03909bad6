#include "app/metrics.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "app/preset.h"

namespace csm {

void MetricsRecorder::addFrame(double simMs, const Accuracy& a,
                               const std::vector<StageTime>& stages, const ContactStats& contacts) {
  const bool first = simMs_.empty();
  simMs_.push_back(simMs);
  for (const StageTime& s : stages) stageSum_[s.name] += s.ms;
  worst_.maxStrain = first ? a.maxStrain : std::max(worst_.maxStrain, a.maxStrain);
  worst_.maxSpeed = std::max(worst_.maxSpeed, a.maxSpeed);
  worst_.nanCount = std::max(worst_.nanCount, a.nanCount);
  worst_.headPenetrations += a.headPenetrations;
  meanStrainSum_ += a.meanStrain;
  contactsLast_ = contacts.contacts;
  penetrationsLast_ = contacts.penetrations;
  penetrationsMax_ = std::max(penetrationsMax_, contacts.penetrations);
}

void MetricsRecorder::addRender(double renderMs, const std::vector<StageTime>& stages) {
  renderMs_.push_back(renderMs);
  for (const StageTime& s : stages) renderStageSum_[s.name] += s.ms;
}

double MetricsRecorder::simMean() const {
  if (simMs_.empty()) return 0.0;
  double sum = 0.0;
  for (double v : simMs_) sum += v;
  return sum / simMs_.size();
}

double MetricsRecorder::simP95() const {
  if (simMs_.empty()) return 0.0;
  std::vector<double> v = simMs_;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(0.95 * (v.size() - 1) + 0.5))];
}

nlohmann::json MetricsRecorder::toJson(nlohmann::json meta) const {
  nlohmann::json& j = meta;
  j["frames"] = frames();
  // The fastest frame too: on a shared machine other work only ever adds time.
  const double fastest = simMs_.empty() ? 0.0 : *std::min_element(simMs_.begin(), simMs_.end());
  nlohmann::json ms = {{"sim_mean", simMean()}, {"sim_p95", simP95()}, {"sim_min", fastest}};
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [name, sum] : stageSum_)
    stages[name] = simMs_.empty() ? 0.0 : sum / simMs_.size();
  ms["stages"] = stages;
  if (!renderMs_.empty()) {
    double sum = 0.0;
    for (double v : renderMs_) sum += v;
    ms["render_mean"] = sum / renderMs_.size();
    nlohmann::json rs = nlohmann::json::object();
    for (const auto& [name, s] : renderStageSum_) rs[name] = s / renderMs_.size();
    ms["render_stages"] = rs;
  }
  j["ms"] = ms;
  j["accuracy"] = {
      {"max_strain", worst_.maxStrain},
      {"mean_strain", simMs_.empty() ? 0.0 : meanStrainSum_ / simMs_.size()},
      {"head_penetrations", worst_.headPenetrations},
      {"max_speed", worst_.maxSpeed},
      {"nan_count", worst_.nanCount},
      {"hair_contacts", contactsLast_},
      {"hair_penetrations", penetrationsLast_},
      {"hair_penetrations_max", penetrationsMax_},
  };
  return j;
}

bool MetricsRecorder::write(const std::string& path, const nlohmann::json& meta,
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

}  // namespace csm
