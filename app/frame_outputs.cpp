#include "app/frame_outputs.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "gl/caps.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/hair_sequence.h"

namespace csm {

bool ImageFiles::makeDirectory() const {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec || !std::filesystem::is_directory(dir_)) {
    std::fprintf(stderr, "csmhair: --out %s: cannot create the directory%s%s\n", dir_.c_str(),
                 ec ? ": " : "", ec ? ec.message().c_str() : "");
    return false;
  }
  return true;
}

bool ImageFiles::write(long index, int width, int height,
                       const std::vector<std::uint8_t>& rgb) const {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05ld.png", index);
  const std::string path = (std::filesystem::path(dir_) / name).string();
  std::string error;
  if (!writePng(path, width, height, rgb, &error)) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return false;
  }
  return true;
}

bool VideoOutput::open(double frameDt) {
  const double fps = 1.0 / (frameDt * options_.every);
  std::string error;
  pipe_ = VideoPipe::open(options_.video, options_.width, options_.height, fps, &error);
  if (!pipe_) std::fprintf(stderr, "csmhair: %s\n", error.c_str());
  return pipe_ != nullptr;
}

bool VideoOutput::write(const std::vector<std::uint8_t>& rgb) {
  if (pipe_->write(rgb)) return true;
  std::string error;
  pipe_->close(&error);
  std::fprintf(stderr, "csmhair: %s: ffmpeg stopped taking frames%s%s\n", options_.video.c_str(),
               error.empty() ? "" : ": ", error.c_str());
  return false;
}

bool VideoOutput::close(long frames) {
  std::string error;
  if (!pipe_->close(&error)) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return false;
  }
  if (!options_.quiet)
    std::fprintf(stderr, "csmhair: wrote %ld frames to %s\n", frames, options_.video.c_str());
  return true;
}

bool HairExport::prepare() const {
  std::string error;
  if (options_.exportSequence.empty() || io::prepareSequenceDir(options_.exportSequence, &error))
    return true;
  std::fprintf(stderr, "csmhair: --export-hair-sequence: %s\n", error.c_str());
  return false;
}

bool HairExport::writeFrame(long index, const GrownScene& scene,
                            const std::vector<glm::vec4>& simulated, const BodyPose& body) {
  if (options_.exportSequence.empty()) return true;
  const Groom& groom = strands(scene, simulated, body);
  ++exported_;
  std::string error;
  if (!io::writeSequenceFrame(options_.exportSequence, index, groom, x_, &error)) {
    std::fprintf(stderr, "csmhair: --export-hair-sequence: %s\n", error.c_str());
    return false;
  }
  return true;
}

bool HairExport::finish(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                        const BodyPose& body) {
  if (!options_.exportHair.empty()) {
    const Groom out = io::posedGroom(strands(scene, simulated, body), x_);
    std::string error;
    if (!io::writeGroom(options_.exportHair, out, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return false;
    }
    if (!options_.quiet)
      std::fprintf(stderr, "csmhair: wrote %zu strands to %s\n", out.strandCount(),
                   options_.exportHair.c_str());
    if (!options_.quiet && scene.followers && !options_.exportGuides)
      std::fprintf(stderr,
                   "csmhair: the followers: %zu points moved out of the head, the deepest "
                   "left inside %.2f mm\n",
                   last_.pushed, 1e3 * last_.deepest);
  }
  if (exported_ > 0 && !options_.quiet)
    std::fprintf(stderr, "csmhair: wrote %ld frames of %zu strands into %s\n", exported_,
                 (options_.exportGuides || !scene.followers ? *scene.groom : scene.followers->drawn)
                     .strandCount(),
                 options_.exportSequence.c_str());
  return true;
}

const Groom& HairExport::strands(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                                 const BodyPose& body) {
  if (options_.exportGuides || !scene.followers) {
    x_ = simulated;
    return *scene.groom;
  }
  last_ = drawnPositions(scene, simulated, body, x_);
  return scene.followers->drawn;
}

bool FrameOutputs::open(bool render, double frameDt) {
  if (render && !options.video.empty() && !video.open(frameDt)) return false;
  if (render && images.on() && !images.makeDirectory()) return false;
  return hair.prepare();
}

std::unique_ptr<gl::HeadlessContext> openContext(const Options& options, bool render) {
  std::string error;
  std::unique_ptr<gl::HeadlessContext> context = gl::HeadlessContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "csmhair: no OpenGL 4.3 context for %s: %s\n",
                 render ? "rendering (use --no-render to simulate only)" : "the GPU solver",
                 error.c_str());
    return nullptr;
  }
  if (gl::isSoftwareRenderer(context->renderer())) {
    if (options.requireGpu) {
      std::fprintf(stderr,
                   "csmhair: --require-gpu: the OpenGL context (%s) is a software renderer, "
                   "%s, not a GPU\n",
                   context->platform().c_str(), context->renderer().c_str());
      return nullptr;
    }
    if (!options.quiet)
      std::fprintf(stderr, "csmhair: warning: %s\n",
                   gl::softwareRendererWarning(context->renderer()).c_str());
  }
  return context;
}

std::unique_ptr<FrameCapture> FrameCapture::create(const Options& options) {
  std::string error;
  std::unique_ptr<HairRenderer> renderer = HairRenderer::create(&error);
  if (!renderer) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return nullptr;
  }
  return std::unique_ptr<FrameCapture>(
      new FrameCapture(std::move(renderer), options.width, options.height));
}

double FrameCapture::draw(const FrameView& frame, bool timed) {
  const auto start = std::chrono::steady_clock::now();
  renderer_->render(frame);
  if (!timed) return 0.0;
  CaptureTarget::waitForGpu();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

std::vector<std::uint8_t> FrameCapture::readBack() {
  ++readBack_;
  return target_.readRgb();
}

}  // namespace csm
