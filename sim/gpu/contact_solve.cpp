#include "sim/gpu/contact_solve.h"

#include <glm/vec4.hpp>

#include "shaders/sim/bindings.glsl"
#include "sim/gpu/buffer_fill.h"

namespace csm::gpu {

bool ContactSolve::build(std::string* error, const std::vector<gl::Define>& device) {
  device_ = device;
  penaltyBuilt_ = false;
  std::vector<gl::Define> split = device;
  split.push_back({"CSM_SPLIT_VIEWS", ""});
  return apply_.build("sim/contact_apply.comp", CSM_PARTICLE_GROUP, device, error) &&
         solve_[0].build("sim/contact_solve.comp", CSM_PARTICLE_GROUP, device, error) &&
         solve_[1].build("sim/contact_solve.comp", CSM_PARTICLE_GROUP, split, error);
}

void ContactSolve::setListSplit(uint32_t split) {
  listSplit_ = split;
  solve_[1].set("listSplit", split);
  if (penaltyBuilt_) penalty_[1].set("listSplit", split);
}

bool ContactSolve::buildPenalty(std::string* error) {
  if (penaltyBuilt_) return true;
  std::vector<gl::Define> split = device_, apply = device_;
  split.push_back({"CSM_SPLIT_VIEWS", ""});
  apply.push_back({"CSM_PENALTY", ""});
  penaltyBuilt_ =
      applyPenalty_.build("sim/contact_apply.comp", CSM_PARTICLE_GROUP, apply, error) &&
      penalty_[0].build("sim/contact_penalty.comp", CSM_PARTICLE_GROUP, device_, error) &&
      penalty_[1].build("sim/contact_penalty.comp", CSM_PARTICLE_GROUP, split, error);
  if (penaltyBuilt_) penalty_[1].set("listSplit", listSplit_);
  return penaltyBuilt_;
}

void ContactSolve::runPenalty(unsigned substep, bool splitViews) {
  if (segments_ == 0 || !penaltyBuilt_) return;
  penalty_[splitViews].runSubstep(uint32_t(particles_), substep);
  gl::memoryBarrier(kPassBarrier);
  applyPenalty_.runSubstep(uint32_t(particles_), substep);
  gl::memoryBarrier(kPassBarrier);
}

void ContactSolve::reset(size_t particles, uint32_t segments) {
  particles_ = particles;
  segments_ = segments;
  zeroed<glm::vec4>(correction_, 2 * particles);
}

void ContactSolve::bind() const {
  correction_.bindBase(gl::BufferTarget::ShaderStorage, CSM_BIND_CORRECTION);
}

void ContactSolve::run(unsigned substep, int iterations, bool splitViews) {
  if (segments_ == 0) return;
  ComputePass& solve = solve_[splitViews];
  for (int k = 1; k < iterations; ++k) {
    solve.runSubstep(uint32_t(particles_), substep);
    gl::memoryBarrier(kPassBarrier);
    apply_.runSubstep(uint32_t(particles_), substep);
    gl::memoryBarrier(kPassBarrier);
  }
  solve.runSubstep(uint32_t(particles_), substep);
  gl::memoryBarrier(kPassBarrier);
}

}  // namespace csm::gpu
