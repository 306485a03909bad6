// The window's picture of the scene: the renderer drawing the simulation's latest frame into a
// texture of the window's size, in the preset's interactive quality while the camera moves or
// the hair simulates and in full when still and for screenshots; a picture nothing has changed
// since is shown again, not drawn. Lives on the window's thread, its context current.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "app/sim_frame.h"
#include "app/window.h"
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "render/interactive_budget.h"
#include "render/view_config.h"

namespace csm {

class HairRenderer;

// How the last scene picture was drawn.
enum class DrawQuality { Full, Interactive };

// What the panels show of the picture (PanelView): whether there is a renderer and why not,
// the quality and share of the last picture, the shader log of the last reload. Plain values, so
// that the panels run without a window or a renderer (tests/app/panels_test.cpp).
struct PictureStatus {
  bool hasRenderer = false;
  std::string rendererError;
  DrawQuality lastQuality = DrawQuality::Full;
  // The share of children and followers interactive quality draws now
  // (render.interactive_budget_ms).
  float interactiveExtra = 1.0f;
  std::string shaderLog;
  bool shaderReloadFailed = false;
};

class SceneView {
 public:
  // Starts the renderer; without one (rendererError() says why) the hair is simulated, not drawn.
  SceneView();
  ~SceneView();
  SceneView(const SceneView&) = delete;
  SceneView& operator=(const SceneView&) = delete;

  // Something the picture depends on changed other than the frame (the look, the camera).
  void changed() { ++version_; }
  // The camera or the head moved: interactive quality for a moment.
  void moved() { lastMotion_ = std::chrono::steady_clock::now(); }
  // Whether the view counts as moving (it moved within the last moment).
  bool moving() const;

  struct Drawn {
    bool scene = false;  // the renderer drew the frame's positions (the caller says so to the
                         // simulation, which may then write that buffer again)
    std::vector<StageTime> stages;
    size_t strands = 0;
  };
  // Draws `frame` as `look` says into the picture (unless nothing changed since the last one,
  // or with `capture` at full quality whatever the motion) and shows it in the window's
  // framebuffer. `running`: the hair simulates (interactive quality).
  Drawn draw(const SimFrame& frame, const ViewConfig& look, WindowSize size, bool running,
             bool capture);
  // Builds the renderer's shaders again from the source tree (or CSM_SHADER_DIR); the old ones
  // stay when that fails. *message says which and where.
  bool reloadShaders(std::string* message);

  const PictureStatus& status() const { return status_; }
  bool hasRenderer() const { return status_.hasRenderer; }
  long scenesDrawn() const { return scenesDrawn_; }  // pictures drawn (not shown again)
  DrawQuality lastQuality() const { return status_.lastQuality; }
  const std::string& shaderLog() const { return status_.shaderLog; }
  bool shaderReloadFailed() const { return status_.shaderReloadFailed; }
  void dismissShaderLog() {
    status_.shaderLog.clear();
    status_.shaderReloadFailed = false;
  }

 private:
  // What a picture depends on: when none of it changed, the last one is shown again.
  struct Key {
    long serial = -1, version = -1;
    int width = 0, height = 0;
    DrawQuality quality = DrawQuality::Full;
    bool operator==(const Key&) const = default;
  };
  unsigned positions(const SimFrame& frame);

  std::unique_ptr<HairRenderer> renderer_;
  PictureStatus status_;
  gl::Buffer uploaded_{gl::NoCreate};  // a CPU solver's positions
  long uploadedSerial_ = -1;
  gl::Texture color_{gl::NoCreate};
  gl::Framebuffer fbo_{gl::NoCreate};
  Key drawn_;
  long version_ = 0;
  std::chrono::steady_clock::time_point lastMotion_{};
  InteractiveBudget budget_;
  long scenesDrawn_ = 0;
};

}  // namespace csm
