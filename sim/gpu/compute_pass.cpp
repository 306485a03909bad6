#include "sim/gpu/compute_pass.h"

#include <algorithm>
#include <optional>

#include "sim/gpu/pass_profile.h"

namespace csm::gpu {

bool ComputePass::build(const char* path, uint32_t groupSize,
                        const std::vector<gl::Define>& defines, std::string* error) {
  std::string log;
  std::optional<gl::Program> p =
      gl::buildProgram(path, {{gl::ShaderStage::Compute, path}}, defines, &log);
  if (!p) {
    if (error) *error = std::string("GPU solver: ") + path + " does not build:\n" + log;
    return false;
  }
  program_ = std::move(*p);
  groupSize_ = groupSize;
  path_ = path;
  return true;
}

void ComputePass::run(uint32_t items) const {
  const uint32_t groups = gl::Program::groupsFor(items, groupSize_);
  if (groups == 0) return;
  const uint32_t x = std::min<uint32_t>(groups, 65535u);
  pass_profile::run(path_, [&] { program_.dispatch(x, (groups + x - 1) / x); });
}

void ComputePass::runIndirect(const gl::Buffer& args, uint32_t slot) const {
  pass_profile::run(
      path_, [&] { program_.dispatchIndirect(args.id(), GLintptr(slot) * 4 * sizeof(GLuint)); });
}

void ComputePass::runSubstep(uint32_t items, unsigned substep) {
  program_.setUniform("substep", substep);
  run(items);
}

}  // namespace csm::gpu
