#include "gl/state_backup.h"

namespace csm::gl {
namespace {

constexpr std::array<GLenum, 10> kCapabilities = {GL_BLEND,
                                                  GL_DEPTH_TEST,
                                                  GL_CULL_FACE,
                                                  GL_SCISSOR_TEST,
                                                  GL_STENCIL_TEST,
                                                  GL_PRIMITIVE_RESTART_FIXED_INDEX,
                                                  GL_MULTISAMPLE,
                                                  GL_SAMPLE_ALPHA_TO_COVERAGE,
                                                  GL_FRAMEBUFFER_SRGB,
                                                  GL_PRIMITIVE_RESTART};

void setEnabled(GLenum cap, GLboolean on) {
  if (on)
    glEnable(cap);
  else
    glDisable(cap);
}

}  // namespace

StateBackup::StateBackup() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  for (int i = 0; i < kUnits; ++i) {
    glActiveTexture(GLenum(GL_TEXTURE0 + i));
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture2D_[i]);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &texture2DMultisample_[i]);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &texture2DArray_[i]);
  }
  glActiveTexture(GLenum(activeTexture_));
  glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb_);
  glGetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb_);
  glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcAlpha_);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstAlpha_);
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEquationRgb_);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEquationAlpha_);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
  glGetIntegerv(GL_CULL_FACE_MODE, &cullFaceMode_);
  glGetIntegerv(GL_FRONT_FACE, &frontFace_);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_.data());
  for (std::size_t i = 0; i < kCapabilities.size(); ++i)
    enabled_[i] = glIsEnabled(kCapabilities[i]);
}

StateBackup::~StateBackup() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  // A program current when the backup was made but deleted since (its owner destroyed while it
  // was current, then unbound by the passes in between) is no longer a name to restore.
  glUseProgram(program_ != 0 && glIsProgram(GLuint(program_)) ? GLuint(program_) : 0u);
  glBindVertexArray(GLuint(vertexArray_));
  glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
  for (int i = 0; i < kUnits; ++i) {
    glActiveTexture(GLenum(GL_TEXTURE0 + i));
    glBindTexture(GL_TEXTURE_2D, GLuint(texture2D_[i]));
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, GLuint(texture2DMultisample_[i]));
    glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(texture2DArray_[i]));
  }
  glActiveTexture(GLenum(activeTexture_));
  glBlendFuncSeparate(GLenum(blendSrcRgb_), GLenum(blendDstRgb_), GLenum(blendSrcAlpha_),
                      GLenum(blendDstAlpha_));
  glBlendEquationSeparate(GLenum(blendEquationRgb_), GLenum(blendEquationAlpha_));
  glDepthFunc(GLenum(depthFunc_));
  glCullFace(GLenum(cullFaceMode_));
  glFrontFace(GLenum(frontFace_));
  glDepthMask(depthMask_);
  glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
  for (std::size_t i = 0; i < kCapabilities.size(); ++i) setEnabled(kCapabilities[i], enabled_[i]);
}

}  // namespace csm::gl
