// How the render's compute passes are dispatched: one invocation per item, in work groups of 64
// (shaders/render/hair_compute.glsl), over two dimensions where one would pass the 65,535 groups
// a dimension may have; the item count in uItems; what the pass wrote made visible to the passes
// after it.
#pragma once

#include <algorithm>
#include <cstddef>

#include "gl/gl.h"
#include "gl/program.h"

namespace csm {

inline void dispatchOver(gl::Program& program, std::size_t items) {
  const std::size_t groups = (items + 63) / 64;
  if (groups == 0) return;
  program.use();
  program.setUniform("uItems", unsigned(items));
  const std::size_t wide = std::min<std::size_t>(groups, 65535);
  program.dispatch(GLuint(wide), GLuint((groups + wide - 1) / wide));
  gl::memoryBarrier(gl::Barrier::Storage);
}

}  // namespace csm
