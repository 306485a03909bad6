// Strand contacts on the GPU, every substep (sim/solver/contacts.h's solveContacts is the CPU
// reference): contact_solve.comp gives each segment its corrections from the candidate lists the
// ContactSearch built this frame (sim/gpu/contact_search.h), collision.iterations times;
// contact_apply.comp moves the particles by each iteration but the last, whose corrections
// strain_limit.comp applies. With the paper's penalty model (collision.contact_model = penalty)
// contact_penalty.comp gives each segment's ends a change of velocity where the substep ends,
// and contact_apply.comp (CSM_PENALTY) adds it to the particles'.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "gl/buffer.h"
#include "sim/gpu/compute_pass.h"

namespace csm::gpu {

class ContactSolve {
 public:
  // `device`: defines every pass is built with too (CSM_STORAGE_READS).
  bool build(std::string* error, const std::vector<gl::Define>& device = {});
  // The texel where the lists' second view starts (ContactCapacity::listSplit).
  void setListSplit(uint32_t split);
  // Sizes the corrections for `particles` particles, zeroed.
  void reset(size_t particles, uint32_t segments);
  // The corrections at CSM_BIND_CORRECTION.
  void bind() const;
  // The bytes of its buffer.
  uint64_t bytes() const { return correction_.size(); }
  // One substep's corrections (the timer's stage is the caller's): `iterations` solves, each but
  // the last applied to the particles' positions and velocities here, the last left for the
  // strain-limit sweep. `splitViews`: the lists run past their first view.
  void run(unsigned substep, int iterations, bool splitViews);
  // The penalty model's passes, built on first use (false, with the log, when they do not).
  bool buildPenalty(std::string* error);
  // One substep's penalty forces, from where the substep ends, added to the velocities.
  void runPenalty(unsigned substep, bool splitViews);

 private:
  size_t particles_ = 0;
  uint32_t segments_ = 0;
  // Without the second view of the lists, and with it (CSM_SPLIT_VIEWS).
  ComputePass solve_[2], apply_;
  ComputePass penalty_[2], applyPenalty_;  // built by buildPenalty
  bool penaltyBuilt_ = false;
  uint32_t listSplit_ = 0;
  std::vector<gl::Define> device_;
  gl::Buffer correction_{gl::NoCreate};
};

}  // namespace csm::gpu
