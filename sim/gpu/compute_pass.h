// One compute shader of the GPU solver and the work it covers: a pass is built for one kind
// of item (particles, strands, grid entries, scan blocks) with that kind's group size, so a
// dispatch names how many items it runs on, never a group count.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_source.h"

namespace csm::gpu {

// Between passes: storage and image writes become visible to storage reads, texel fetches and
// image loads.
constexpr gl::Barrier kPassBarrier =
    gl::Barrier::Storage | gl::Barrier::TextureFetch | gl::Barrier::ImageAccess;

class ComputePass {
 public:
  ComputePass() = default;

  // Compiles shaders/<path>; false, with the compiler's log in `error`, when it does not build.
  bool build(const char* path, uint32_t groupSize, const std::vector<gl::Define>& defines,
             std::string* error);

  // Enough groups for `items` invocations (gl::Program::dispatchItems: a 2D grid of groups
  // beyond 65,535, the layout dispatch_size.comp writes for runIndirect too).
  void run(uint32_t items) const;
  // As many groups as slot `slot` (a CSM_DISPATCH_*) of `args` says: a count of items only the
  // GPU knows, sized there by dispatch_size.comp (after a Command barrier).
  void runIndirect(const gl::Buffer& args, uint32_t slot) const;
  // The same pass for each step of a frame: its `substep` uniform, then run.
  void runSubstep(uint32_t items, unsigned substep);

  template <class T>
  ComputePass& set(const char* uniform, const T& value) {
    program_.setUniform(uniform, value);
    return *this;
  }

 private:
  gl::Program program_{gl::NoCreate};
  uint32_t groupSize_ = 1;
  std::string path_;  // shaders/<path_>, the program's name (the pass profile's row)
};

}  // namespace csm::gpu
