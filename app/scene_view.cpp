#include "app/scene_view.h"

#include <array>
#include <cstdlib>
#include <filesystem>

#include "gl/shader_source.h"
#include "render/hair_renderer.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

// After the camera or the head last moved, the view counts as moving this long: a drag that
// pauses for a frame does not flip the quality back and forth.
constexpr double kStillSeconds = 0.3;

}  // namespace

SceneView::SceneView() {
  renderer_ = HairRenderer::create(&status_.rendererError);
  status_.hasRenderer = renderer_ != nullptr;
  status_.interactiveExtra = budget_.extra();
  // Pass timings by glFinish would stall every frame of the window.
  if (renderer_) renderer_->setSynchronousTiming(false);
}

SceneView::~SceneView() = default;

bool SceneView::moving() const {
  return std::chrono::duration<double>(Clock::now() - lastMotion_).count() < kStillSeconds;
}

unsigned SceneView::positions(const SimFrame& frame) {
  if (frame.positionBuffer != 0) return frame.positionBuffer;
  if (!frame.hostPositions) return 0;
  // A solver that keeps its state on the CPU: upload each new frame's positions.
  if (uploaded_.id() == 0) uploaded_ = gl::Buffer();
  if (uploadedSerial_ != frame.serial && !frame.hostPositions->empty()) {
    uploaded_.upload(*frame.hostPositions);
    uploadedSerial_ = frame.serial;
  }
  return uploaded_.id();
}

SceneView::Drawn SceneView::draw(const SimFrame& frame, const ViewConfig& look, WindowSize size,
                                 bool running, bool capture) {
  Drawn out;
  if (size.width <= 0 || size.height <= 0) return out;
  const DrawQuality quality = !capture && look.render.interactive && (moving() || running)
                                  ? DrawQuality::Interactive
                                  : DrawQuality::Full;
  const Key key{frame.serial, version_, size.width, size.height, quality};

  if (color_.id() == 0 || color_.width() != size.width || color_.height() != size.height) {
    color_ = gl::Texture::create2D(gl::TextureFormat::Rgba8, size.width, size.height);
    fbo_ = gl::Framebuffer();
    fbo_.attach(gl::Attachment::Color0, color_).setDrawBuffers({gl::Attachment::Color0});
    drawn_ = Key{};
  }
  if (!(key == drawn_) || capture) {
    if (renderer_ && frame.loaded && frame.groom) {
      FrameView view;
      view.scene = &frame.config;
      view.look = &look;
      view.groom = frame.groom.get();
      view.followers = frame.followers.get();
      view.generation = frame.generation;
      view.head = frame.head.get();
      view.headPose = frame.headPose;
      view.torsoPose = frame.torsoPose;
      view.positionBuffer = positions(frame);
      view.width = size.width;
      view.height = size.height;
      view.targetFramebuffer = fbo_.id();
      if (quality == DrawQuality::Interactive) {
        view.amount = interactiveAmount(look.render);
        view.amount.extra = budget_.extra();
      }
      renderer_->render(view);
      out.scene = true;
      out.stages = renderer_->stageTimes();
      out.strands = renderer_->drawnStrands();
      if (quality == DrawQuality::Interactive) {
        // The passes' measured times (a software renderer's at once; timer queries' a few
        // frames late) set the next interactive frame's share.
        double ms = 0.0;
        for (const StageTime& s : out.stages) ms += s.ms;
        budget_.measured(ms, double(look.render.interactiveBudgetMs));
        status_.interactiveExtra = budget_.extra();
      }
    } else {
      fbo_.clearColor(0, std::array<float, 4>{look.render.background.x, look.render.background.y,
                                              look.render.background.z, 1.0f});
    }
    drawn_ = key;
    status_.lastQuality = quality;
    ++scenesDrawn_;
  }
  fbo_.blitTo(0, {0, 0, size.width, size.height}, {0, 0, size.width, size.height});
  gl::Framebuffer::bindDefault();
  return out;
}

bool SceneView::reloadShaders(std::string* message) {
  if (!renderer_) {
    *message = "no renderer to reload: " + status_.rendererError;
    return false;
  }
  // From the source tree, unless a folder was chosen (CSM_SHADER_DIR, setShaderDirectory),
  // so edits to shaders/ show at once.
  if (!std::getenv("CSM_SHADER_DIR") && gl::shaderDirectory().empty()) {
#ifdef CSM_SOURCE_DIR
    const std::filesystem::path dir = std::filesystem::path(CSM_SOURCE_DIR) / "shaders";
    if (std::filesystem::is_directory(dir)) gl::setShaderDirectory(dir);
#endif
  }
  std::string buildLog;
  changed();
  if (renderer_->reloadShaders(&buildLog)) {
    status_.shaderReloadFailed = false;
    status_.shaderLog = buildLog;
    *message = "shaders reloaded from " + gl::shaderDirectory().string() +
               (buildLog.empty() ? "" : " (with warnings)");
    return true;
  }
  status_.shaderReloadFailed = true;
  status_.shaderLog = buildLog;
  *message = "shader reload failed; the old shaders are still in use";
  return false;
}

}  // namespace csm
