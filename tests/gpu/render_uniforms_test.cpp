// The render passes' per-frame block has the same layout in C++ and GLSL: every field of the one
// list (shaders/render/frame_uniforms.glsl) at the offset the linked program gives it, and the
// block as large as the struct.
#include <string>

#include "gl/shader_source.h"
#include "render/frame_uniforms.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

TEST_CASE("Render: FrameUniforms has the same layout in C++ and GLSL", "[gpu][render][quick]") {
  test::glContext();
  std::string log;
  // A pass that reads the block (std140: all its fields are active when it is).
  auto program = gl::buildProgram("shade", {{GL_COMPUTE_SHADER, "render/hair_shade.comp"}},
                                  {{"SAMPLES", "1"}}, &log);
  INFO(log);
  REQUIRE(program);
  using render_block::FrameUniforms;
  size_t checked = 0;
  const auto check = [&](const char* name, size_t expected) {
    INFO(name);
    const GLuint index = glGetProgramResourceIndex(program->id(), GL_UNIFORM, name);
    REQUIRE(index != GL_INVALID_INDEX);
    const GLenum prop = GL_OFFSET;
    GLint offset = -1;
    glGetProgramResourceiv(program->id(), GL_UNIFORM, index, 1, &prop, 1, nullptr, &offset);
    CHECK(size_t(offset) == expected);
    ++checked;
  };
#define CSM_CHECK_FIELD(type, cppName, glslName) check(#glslName, offsetof(FrameUniforms, cppName));
  CSM_FRAME_UNIFORMS(CSM_CHECK_FIELD)
#undef CSM_CHECK_FIELD
  CHECK(checked == 24);
  const GLuint block = glGetProgramResourceIndex(program->id(), GL_UNIFORM_BLOCK, "FrameUniforms");
  REQUIRE(block != GL_INVALID_INDEX);
  const GLenum prop = GL_BUFFER_DATA_SIZE;
  GLint size = 0;
  glGetProgramResourceiv(program->id(), GL_UNIFORM_BLOCK, block, 1, &prop, 1, nullptr, &size);
  CHECK(size_t(size) == sizeof(FrameUniforms));
}
