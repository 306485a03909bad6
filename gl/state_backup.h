// The GL state the render passes change, saved on construction and put back on destruction,
// so the UI drawn after the hair (Dear ImGui) finds the context as it left it
// (imgui_impl_opengl3.cpp's "Backup GL state" does the same).
#pragma once

#include <array>

#include "gl/gl.h"

namespace csm::gl {

class StateBackup {
 public:
  StateBackup();
  ~StateBackup();
  StateBackup(const StateBackup&) = delete;
  StateBackup& operator=(const StateBackup&) = delete;

 private:
  static constexpr int kUnits = 8;  // texture units saved: the first eight
  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
  std::array<GLint, 4> viewport_{};
  GLint program_ = 0, vertexArray_ = 0, arrayBuffer_ = 0, activeTexture_ = 0;
  std::array<GLint, kUnits> texture2D_{}, texture2DMultisample_{}, texture2DArray_{};
  GLint blendSrcRgb_ = 0, blendDstRgb_ = 0, blendSrcAlpha_ = 0, blendDstAlpha_ = 0;
  GLint blendEquationRgb_ = 0, blendEquationAlpha_ = 0;
  GLint depthFunc_ = 0, cullFaceMode_ = 0, frontFace_ = 0;
  GLboolean depthMask_ = GL_TRUE;
  std::array<GLboolean, 4> colorMask_{};
  std::array<GLboolean, 10> enabled_{};
};

}  // namespace csm::gl
