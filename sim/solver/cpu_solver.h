// The reference Chain Shape Matching solver: the whole step of METHOD.md section 2 in double
// precision on the CPU. The GPU solver is tested against it; the benchmarks use it as the
// baseline. Its GLSL twins, step by step: shaders/sim/predict.comp, shaders/sim/shape_match.comp,
// shaders/sim/strain_limit.comp (with the head's push, pushOutOfHead) and, for strand contacts,
// sim/solver/contacts.h's.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glm/vec3.hpp>

#include "sim/solver/contacts.h"
#include "sim/core/hair_state.h"
#include "sim/head/head_model.h"
#include "sim/core/solver.h"
#include "sim/solver/volume.h"

namespace csm {

// Rotational part of A (Mueller, Bender, Chentanez, Macklin 2016, "A Robust Method to Extract
// the Rotational Part of Deformations"): rotates q toward A's rotation a fixed number of times.
// Robust when A is rank-deficient, which a straight strand's regions are. Each iteration turns
// by the torque of R's columns toward A's over the region's rest moment J = sum m |r|^2 (the
// value of sum r.a at convergence): scale-free, so the masses' unit and size cancel, and
// bounded where sum r.a passes through zero. J <= 0 (a region with no extent) leaves q alone.
//
// The turn about `axis` (a rest-frame direction, e.g. the region's chord; zero: none) is taken
// at `twistStep` (0..1) of its size. For a nearly straight region that turn, the twist about
// the strand, is barely determined by the positions: each full iteration moves it only by the
// small share b / J of its error (b the region's moment across the strand), so it relaxes at
// a rate set by the iterations per second, and more substeps make the twist, and the goals,
// follow the curvature faster. The calibrated model passes twistStep = r h / iterations so that
// the twist relaxes at r iterations per second whatever the step.
void extractRotation(const Eigen::Matrix3d& A, double J, Eigen::Quaterniond& q, int iterations,
                     const Eigen::Vector3d& axis = Eigen::Vector3d::Zero(), double twistStep = 1.0);

class CpuSolver final : public Solver {
 public:
  // Region sums by prefix differences (O(1) per region, Rivers & James 2007), or summed
  // directly over each region (O(w) per region), for the benchmarks' comparison.
  enum class RegionSums { Prefix, Direct };

  explicit CpuSolver(RegionSums sums = RegionSums::Prefix) : sums_(sums) {}

  std::string_view name() const override { return "cpu"; }
  void reset(const Groom& groom, const Config& config, const Pose& head) override;
  void setHead(std::shared_ptr<const HeadModel> head) override { headModel_.hand(std::move(head)); }
  std::string failure() const override { return failure_; }
  void setConfig(const Config& config) override;
  void stepFrame(const Pose& from, const Pose& to) override;

  size_t strandCount() const override { return first_.size() - 1; }
  size_t particleCount() const override { return x_.size(); }
  double time() const override { return time_; }

  void readPositions(std::vector<glm::vec4>& out) override;
  void readVelocities(std::vector<glm::vec4>& out) override;
  void carry(const Pose& by) override;
  void saveState(SolverState& out) override;
  bool restoreState(const SolverState& in, std::string* error) override;
  void writeState(const std::vector<glm::vec4>& positions,
                  const std::vector<glm::vec4>& velocities) override;
  // Measured at once: the state is on the CPU.
  void requestSample(long frame) override;
  std::optional<FrameSample> takeSample(bool wait = false) override;
  void dropSamples() override { samples_.clear(); }
  std::vector<StageTime> stageTimes() override { return stages_; }
  ContactStats contactStats() override { return contacts_; }
  // Nodes of the volume mode's grid: none unless collision.mode is a volume mode (tests).
  size_t volumeNodes() const { return volume_.nodes(); }
  void setContactMeasures(bool always) override;
  StiffnessInfo stiffness() const override { return describeStiffness(regions_, config_.sim); }

  // One step of length h ending at head pose `head` (exposed for tests).
  void step(double h, const Pose& head);
  const std::vector<glm::dvec3>& positions() const { return x_; }
  const std::vector<glm::dvec3>& velocities() const { return v_; }
  // Rest length of the segment from particle i to i+1.
  double restLength(size_t i) const { return restLength_[i]; }

 private:
  // Sets a wave's positions in double, which writeState would round to float
  // (sim/verify/window_coefficient.h).
  friend double measureWindowCoefficient(int w);

  void clearStages();
  void rebuildRegions();
  void predict(double h, const Pose& head);
  glm::dvec3 windDrag(uint32_t i, uint32_t end, double h) const;
  void shapeMatch(const Pose& head, double h);
  void integrate(double h);
  // Shares out the stretch the sweep from the root leaves a strand held at both ends: its free
  // particles [first, tip), then its held tip.
  void tieStrain(uint32_t first, uint32_t tip, double h);
  void limitStrain(double h, const std::vector<Sphere>& spheres, const Pose& head,
                   const Pose& headBefore);
  ContactSettings contactSettings() const;
  // A candidate list within the frame (collision.lists), from where the hair is now.
  void listAgain();
  VolumeSettings volumeSettings() const;
  void resetVolume();

  RegionSums sums_;
  Config config_;
  SolverHead headModel_;  // the scene's head, handed before the reset
  std::string failure_;   // set by reset when no head was handed
  SceneHead shape_;       // what it collides with, read every step
  double time_ = 0.0;
  Pose head_;  // the head pose at the end of the last step

  std::vector<uint32_t> first_{0};
  std::vector<uint32_t> strandOf_;
  HairState state_;               // the layout the regions are built from
  Regions regions_;               // shape-matching regions, per-region masses, rates
  std::vector<glm::dvec3> rest_;  // head frame
  std::vector<double> mass_;
  std::vector<double> invMass_;     // 0 for the particles the head holds (strand contacts)
  std::vector<double> restLength_;  // segment i -> i+1; 0 for a strand's last particle
  std::vector<glm::dvec3> x_, v_, xOld_, xPred_, goal_;
  ContactCandidates candidates_;        // this frame's strand contacts (sim/solver/contacts.h)
  std::vector<glm::dvec4> correction_;  // their corrections of this step, 2 per segment
  std::vector<Eigen::Quaterniond> q_;   // rotation of each region, warm start
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
  std::deque<FrameSample> samples_;

  // Per strand s, prefix arrays have strand size + 1 entries starting at first_[s] + s. Sums
  // over regions weigh each particle by its per-region mass (regions_.mass).
  std::vector<double> prefMass_;
  std::vector<Eigen::Vector3d> prefMassRest_, prefMassX_;
  std::vector<Eigen::Matrix3d> prefA_, prefR_;
  std::vector<Eigen::Vector3d> prefT_;
  std::vector<Eigen::Vector3d> regionC_, regionCRest_;
};

}  // namespace csm
