#include "gl/draw.h"

#include "gl/debug.h"

namespace csm::gl {
namespace {

void setEnabled(GLenum cap, bool on) {
  if (on)
    glEnable(cap);
  else
    glDisable(cap);
}

}  // namespace

void applyDrawState(const DrawState& s) {
  setEnabled(GL_DEPTH_TEST, s.depthTest);
  glDepthFunc(s.depthFunc);
  glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
  setEnabled(GL_BLEND, s.blend != Blend::None);
  if (s.blend == Blend::Additive) {
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  setEnabled(GL_CULL_FACE, s.cull != Cull::None);
  if (s.cull != Cull::None) {
    glCullFace(s.cull == Cull::Front ? GL_FRONT : GL_BACK);
    glFrontFace(GL_CCW);
  }
  setEnabled(GL_MULTISAMPLE, s.multisample);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_PRIMITIVE_RESTART);
  glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  maybeCheckErrors("applyDrawState");
}

void setViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  glViewport(x, y, width, height);
}

void drawElements(GLenum mode, std::size_t count, GLsizei instances, std::size_t first) {
  if (count == 0 || instances <= 0) return;
  glDrawElementsInstanced(mode, GLsizei(count), GL_UNSIGNED_INT,
                          reinterpret_cast<const void*>(first * sizeof(GLuint)), instances);
  maybeCheckErrors("drawElements");
}

void drawArrays(GLenum mode, GLint first, GLsizei count) {
  glDrawArrays(mode, first, count);
  maybeCheckErrors("drawArrays");
}

void bindStorageBuffer(GLuint index, GLuint buffer) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, buffer);
}

void finish() {
  glFinish();
}

const char* versionString() {
  return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

}  // namespace csm::gl
