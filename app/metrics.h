// Per-frame timings and accuracy, written as the --metrics JSON.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/metrics.h"
#include "sim/solver.h"

namespace csm {

class MetricsRecorder {
 public:
  void addFrame(double simMs, const Accuracy& accuracy, const std::vector<StageTime>& stages,
                const ContactStats& contacts);
  void addRender(double renderMs, const std::vector<StageTime>& stages);

  long frames() const { return long(simMs_.size()); }
  double simMean() const;
  double simP95() const;
  const Accuracy& worst() const { return worst_; }
  uint64_t nanCount() const { return worst_.nanCount; }

  // `meta` holds the scene's description (strands, particles, solver, device...); the
  // recorder adds "frames", "ms" and "accuracy".
  nlohmann::json toJson(nlohmann::json meta) const;
  bool write(const std::string& path, const nlohmann::json& meta, std::string* error) const;

 private:
  std::vector<double> simMs_, renderMs_;
  std::map<std::string, double> stageSum_, renderStageSum_;
  Accuracy worst_;  // max strain, max speed, max NaN count, summed head penetrations
  double meanStrainSum_ = 0.0;
  uint64_t contactsLast_ = 0, penetrationsLast_ = 0, penetrationsMax_ = 0;
};

}  // namespace csm
