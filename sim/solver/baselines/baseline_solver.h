// Baselines for the benchmarks (docs/BENCHMARKS.md): the strand models CSM is usually compared
// with, behind the same Solver interface and on the same scenes. CPU, double precision, one
// thread. They share gravity, wind (sim/solver/wind.h), linear damping, kinematic roots and a
// simple projection out of the head spheres; none of them does hair-hair collision.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/solver/host_solver.h"

namespace csm {

// The knobs of the baselines. Spring stiffnesses are axial stiffnesses EA in newtons (force per
// unit strain), so a strand's stiffness does not change with its particle count.
struct BaselineParams {
  double stretchStiffness = 0.05;  // EA of the edge springs i - i+1, N
  double bendStiffness = 0.01;     // EA of the bending springs i - i+2, N (Selle et al. 2008)
  int iterations = 4;              // PBD: constraint passes per step
  double pbdStretch = 1.0;         // PBD: distance constraint stiffness k, 0..1 (Mueller 2007)
  double pbdBend = 0.5;            // PBD: bending constraint (i - i+2) stiffness, 0..1
  double ftlDamping = 0.9;         // DFTL velocity correction s_damping (Mueller 2012), 0..1
  double ftlBend = 0.0;            // FTL: bending constraint stiffness per 1/60 s; 0 = the paper
};

// What every baseline has in common: the strand layout, roots that follow the head, external
// accelerations, the head projection and the substep loop.
class BaselineSolver : public HostSolver {
 public:
  explicit BaselineSolver(const BaselineParams& params) : params_(params) {}

  void reset(const Groom& groom, const Config& config, const Pose& head) override;
  void setConfig(const Config& config) override {
    config_ = config;
    headSpheres_ = headModel_.collider().spheres;
    torsoSpheres_ = headModel_.collider().torsoSpheres;
  }
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override;

  // Measured at once: the state is on the CPU.
  void requestSample(long frame) override;
  std::vector<StageTime> stageTimes() override { return {{"integrate", lastMs_}}; }

  const BaselineParams& params() const { return params_; }
  void setParams(const BaselineParams& p) { params_ = p; }

 protected:
  // One step of length h ending at head pose `head`.
  virtual void step(double h, const Pose& head) = 0;
  virtual void onReset() {}

  // Kinematic: the first sim.pinned particles of a strand, and its tip when the head holds both
  // ends (Groom::tipHeld).
  bool pinned(uint32_t i) const {
    const uint32_t s = strandOf_[i];
    return int(i - first_[s]) < config_.sim.pinned ||
           (s < tipHeld_.size() && tipHeld_[s] != 0 && i + 1 == first_[s + 1]);
  }
  // Gravity, wind drag across the strand (as the CSM solver applies it: implicit in the
  // velocity over a step of h, c / (1 + h c)) and nothing else.
  glm::dvec3 externalAcceleration(uint32_t i, double h) const;
  // Moves p out of every head sphere (radius + hair radius) by radial projection.
  // Returns true when it moved. Does nothing when collisions are off.
  bool projectOutOfHead(glm::dvec3& p) const;
  // Kinematic root targets for the end of the step.
  glm::dvec3 rootTarget(uint32_t i, const Pose& head) const { return head.apply(rest_[i]); }
  // Sets spheres_ for the step's end pose: the head's at `head`, the torso's at torso_ (the
  // step's end, set by stepFrame).
  void prepareStep(const Pose& head);
  // v *= exp(-damping h), as the CSM solver damps.
  void damp(double h);

  BaselineParams params_;
  std::vector<Sphere> headSpheres_;   // its spheres, head frame
  std::vector<Sphere> torsoSpheres_;  // the torso's, torso frame
  std::vector<double> invMass_;
  std::vector<double> bendLength_;  // rest distance i -> i+2; 0 where there is none
  std::vector<Sphere> spheres_;     // world space, this step: the head's, then the torso's
  double lastMs_ = 0.0;
};

// Projects the distance constraint |p_i - p_j| = rest with stiffness k (0..1) and inverse
// masses wi, wj (0 = kinematic) (Mueller et al. 2007, section 3.3): PBD's constraints, and
// follow-the-leader's bending.
void projectDistance(glm::dvec3& pi, glm::dvec3& pj, double wi, double wj, double rest, double k);

}  // namespace csm
