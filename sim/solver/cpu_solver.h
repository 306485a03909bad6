// The reference Chain Shape Matching solver: the whole step of METHOD.md section 2 in double
// precision on the CPU. The GPU solver is tested against it; the benchmarks use it as the
// baseline. Its step is the free functions of sim/solver/cpu_steps.h, each the twin of the GLSL
// function of the same name, run here over the strands on the thread pool; for strand contacts,
// sim/solver/contacts.h's.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glm/vec3.hpp>

#include "sim/solver/contacts.h"
#include "sim/solver/cpu_steps.h"
#include "sim/core/hair_state.h"
#include "sim/head/head_model.h"
#include "sim/solver/host_solver.h"
#include "sim/solver/volume.h"

namespace csm {

class CpuSolver final : public HostSolver {
 public:
  // Region sums by prefix differences (O(1) per region, Rivers & James 2007), or summed
  // directly over each region (O(w) per region), for the benchmarks' comparison.
  enum class RegionSums { Prefix, Direct };

  explicit CpuSolver(RegionSums sums = RegionSums::Prefix)
      : prefixSums_(sums == RegionSums::Prefix) {}

  std::string_view name() const override { return "cpu"; }
  void reset(const Groom& groom, const Config& config, const Pose& head) override;
  void setConfig(const Config& config) override;
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override;

  // Measured at once: the state is on the CPU.
  void requestSample(long frame) override;
  std::vector<StageTime> stageTimes() override { return stages_; }
  void setContactMeasures(bool always) override;
  StiffnessInfo stiffness() const override {
    return describeStiffness(regions_, config_.sim, dftlOf(config_));
  }

 private:
  // Tests and tools read the double state and take single steps through it (cpu_probe.h).
  friend class CpuProbe;

  // One step of length h ending at head pose `head` and torso pose `torso`.
  void step(double h, const Pose& head, const Pose& torso);
  void saveMore(StateWriter& w) const override;
  bool readMore(StateReader& r) override;
  void restored() override;
  void carryMore(const Pose& by) override;

  void clearStages();
  void rebuildRegions();
  // The step's arrays, for the step functions (sim/solver/cpu_steps.h).
  StepHair hair();
  // Each step function over every particle or strand, on the thread pool.
  void predict(double h, const Pose& head);
  void shapeMatch(const Pose& head, double h);
  void limitStrain(double h, const std::vector<Sphere>& spheres, const Pose& head,
                   const Pose& headBefore, const Pose& torso, const Pose& torsoBefore);
  ContactSettings contactSettings() const;
  // A candidate list within the frame (collision.lists), from where the hair is now.
  void listAgain();
  VolumeSettings volumeSettings() const;
  void resetVolume();

  bool prefixSums_;
  SceneHead shape_;  // what it collides with, read every step

  HairState state_;              // the layout the regions are built from
  Regions regions_;              // shape-matching regions, per-region masses, rates
  std::vector<double> invMass_;  // 0 for the particles the head holds (strand contacts)
  std::vector<glm::dvec3> xOld_, xPred_, goal_;
  ContactCandidates candidates_;        // this frame's strand contacts (sim/solver/contacts.h)
  std::vector<glm::dvec4> correction_;  // their corrections of this step, 2 per segment
  std::vector<Eigen::Quaterniond> q_;   // rotation of each region, warm start
  std::vector<Eigen::Quaterniond> restoredQ_;  // read by readMore, taken by restored
  ContactStats contacts_;
  bool measureContacts_ = false;
  VolumeGrid volume_;  // the volume mode's grid, splatted at the start of each frame
  // With hair-hair off and the measures on: the list of the last measure search (crossings),
  // its measures, and the frames stepped since it (1: it is of where this frame started).
  ContactCandidates measured_;
  ContactStats measuredStats_;
  // The particles' strands as the measures search them: those outside the sample
  // (sim/core/measure_sample.h) each a strand of its own, so they have no segments.
  std::vector<uint32_t> measuredStrandOf_;
  uint32_t measureStride_ = 1;
  int framesSinceMeasure_ = 2;
  void measureNow();   // searches where the hair stands
  void measureAnew();  // after a reset, a restore or new settings: forgets, then measureNow
  std::vector<StageTime> stages_;

  // The prefix sums of shape matching, strand by strand (sim/solver/cpu_steps.h).
  ShapeMatchSums sums_;
};

}  // namespace csm
