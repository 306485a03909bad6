#include "sim/simulation.h"

#include "sim/cpu/cpu_solver.h"
#include "sim/hairstyle.h"
#include "sim/params.h"
#include "sim/scene_checks.h"

namespace csm {

bool Simulation::load(const Config& config, const std::string& baseDir, std::string* error) {
  if (!regrow(config, baseDir, error)) return false;
  reset();
  return true;
}

bool Simulation::regrow(const Config& config, const std::string& baseDir, std::string* error) {
  std::string capacity = checkCapacity(config);
  if (!capacity.empty()) {
    if (error) *error = capacity;
    return false;
  }
  Groom groom;
  GroomReport report;
  if (!buildGroom(config, baseDir, groom, error, &report)) return false;
  groomReport_ = report;
  config_ = config;
  baseDir_ = baseDir;
  groom_ = std::make_shared<const Groom>(std::move(groom));
  ++generation_;
  return true;
}

bool Simulation::setConfig(const Config& config, std::string* error) {
  if (needsRegrow(config_, config)) {
    // Keep the clock and the camera: only the hair starts again from rest.
    if (!regrow(config, baseDir_, error)) return false;
    lastPose_ = headPoseAt(time_);
    solver_->reset(*groom_, config_, lastPose_);
    return true;
  }
  config_ = config;
  solver_->setConfig(config_);
  return true;
}

void Simulation::reset() {
  time_ = 0.0;
  frame_ = 0;
  lastPose_ = headPoseAt(0.0);
  solver_->reset(*groom_, config_, lastPose_);
}

Pose Simulation::headPoseAt(double t) const {
  return compose(userPose_, csm::headPose(config_.head, t));
}

void Simulation::stepFrame() {
  const double next = time_ + config_.sim.dt;
  const Pose to = headPoseAt(next);
  solver_->stepFrame(lastPose_, to);
  lastPose_ = to;
  time_ = next;
  ++frame_;
}

}  // namespace csm
