// The render passes' per-frame block in C++: FrameUniforms expanded from the one list in
// shaders/render/frame_uniforms.glsl, which shaders/render/frame.glsl expands for GLSL, so the two
// cannot drift apart (std140; tests/gpu/render_uniforms_test.cpp checks every field's offset
// against the linked program's).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shaders/render/frame_uniforms.glsl"

namespace csm::render_block {

// GLSL's names for the types the list uses.
using mat4 = glm::mat4;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;

struct FrameUniforms {
  CSM_FRAME_UNIFORMS(CSM_CPP_FIELD)
};
static_assert(sizeof(FrameUniforms) == 3 * 64 + 21 * 16);

}  // namespace csm::render_block
