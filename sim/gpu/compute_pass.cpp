#include "sim/gpu/compute_pass.h"

#include <optional>

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
  program_.dispatchItems(items, groupSize_);
}

void ComputePass::runIndirect(const gl::Buffer& args, uint32_t slot) const {
  program_.dispatchIndirect(args.id(), GLintptr(slot) * 4 * sizeof(GLuint));
}

void ComputePass::runSubstep(uint32_t items, unsigned substep) {
  program_.setUniform("substep", substep);
  program_.dispatchItems(items, groupSize_);
}

}  // namespace csm::gpu
