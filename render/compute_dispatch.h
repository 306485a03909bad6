// How the render's compute passes are dispatched: one invocation per item, in work groups of 64
// (shaders/render/hair_compute.glsl), through gl::Program::dispatchItems (the 2D grid past 65,535
// groups, the pass profile); the item count in uItems; what the pass wrote made visible to the
// passes after it.
#pragma once

#include <cstddef>

#include "gl/gl.h"
#include "gl/program.h"

namespace csm {

inline void dispatchOver(gl::Program& program, std::size_t items) {
  if (items == 0) return;
  program.setUniform("uItems", unsigned(items));
  program.dispatchItems(GLuint(items), 64);
  gl::memoryBarrier(gl::Barrier::Storage);
}

}  // namespace csm
