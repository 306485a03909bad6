// What a headless run makes of its frames, whether it simulates them or draws them from a shot's
// cache (app/shot_cache.h): the PNG files, the video, the strands exported, the offscreen
// context and the capture that draws them. Frames count from 1 (the frame after the first step);
// a kept frame (every --every) is named by its number over --every, so a run that draws frames
// 31-45 alone names them as the run that drew 1-60 did.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "app/capture.h"
#include "app/cli.h"
#include "gl/context.h"
#include "render/hair_renderer.h"
#include "render/position_source.h"
#include "sim/core/pose.h"
#include "sim/run/grown_scene.h"

namespace csm {

// Frame `frame` (from 1) is kept (drawn, written) by a run of these options: within
// --frames A-B and on --every.
inline bool keptFrame(const Options& options, long frame) {
  return frame >= options.firstFrame && frame % options.every == 0;
}
// Its number among the kept frames of a run from frame 1: frame_00007.png.
inline long keptIndex(const Options& options, long frame) {
  return frame / options.every;
}

// --out: the frames as frame_00001.png, frame_00002.png, ... in a directory made before the
// run, so that an unwritable one fails before anything is simulated.
class ImageFiles {
 public:
  explicit ImageFiles(const Options& options) : dir_(options.outDir) {}
  bool on() const { return !dir_.empty(); }
  bool makeDirectory() const;
  // The kept frame numbered `index`, whole or not at all.
  bool write(long index, int width, int height, const std::vector<std::uint8_t>& rgb) const;

 private:
  std::string dir_;
};

// --video: the frames piped into ffmpeg, started before the run so that a missing one fails
// before anything is simulated.
class VideoOutput {
 public:
  explicit VideoOutput(const Options& options) : options_(options) {}
  bool on() const { return pipe_ != nullptr; }
  // One video frame a kept frame: every --every frames of `frameDt` seconds.
  bool open(double frameDt);
  bool write(const std::vector<std::uint8_t>& rgb);
  // Waits for ffmpeg to finish the file of `frames` frames.
  bool close(long frames);

 private:
  const Options& options_;
  std::unique_ptr<VideoPipe> pipe_;
};

// --export-hair-sequence (the strands of every kept frame) and --export-hair (the last frame's):
// every strand as drawn (a groom simulated through guides: the followers made on the CPU), or
// with --export-guides the simulated ones alone, in world space.
class HairExport {
 public:
  explicit HairExport(const Options& options) : options_(options) {}
  // The sequence's directory, before anything is simulated.
  bool prepare() const;
  // The kept frame numbered `index`: `simulated` the simulated strands' positions, the body at
  // `body` (the drawn strands made about the guides, kept out of its parts).
  bool writeFrame(long index, const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                  const BodyPose& body);
  // The final strands as a cyHair file (OBJ curves when the name ends in .obj); then what was
  // written.
  bool finish(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
              const BodyPose& body);
  bool on() const { return !options_.exportSequence.empty() || !options_.exportHair.empty(); }

 private:
  const Groom& strands(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                       const BodyPose& body);

  const Options& options_;
  std::vector<glm::vec4> x_;
  FollowerStats last_;  // of the last frame exported
  long exported_ = 0;
};

// Every output of a run's kept frames, opened before anything is simulated or drawn, so that a
// missing ffmpeg or an unwritable folder fails at once.
struct FrameOutputs {
  explicit FrameOutputs(const Options& options)
      : options(options), video(options), images(options), hair(options) {}
  // With `render`, the video (of frames `frameDt` apart) and the PNGs' folder; the sequence's
  // folder in any case. False, having said why.
  bool open(bool render, double frameDt);
  const Options& options;
  VideoOutput video;
  ImageFiles images;
  HairExport hair;
};

// The offscreen GL context for both the GPU solver and the renderer; null, having said why,
// when there is none or --require-gpu refuses it. `render`: it is wanted for drawing.
std::unique_ptr<gl::HeadlessContext> openContext(const Options& options, bool render);

// The drawn frames: the renderer, the offscreen target it draws into and, for positions that are
// not in a GPU buffer already (the CPU solvers', a cache's), the buffer they are uploaded into.
class FrameCapture {
 public:
  // Null, having said why, when the renderer does not start.
  static std::unique_ptr<FrameCapture> create(const Options& options);
  const HairRenderer& renderer() const { return *renderer_; }
  HairRenderer& renderer() { return *renderer_; }
  int width() const { return target_.width(); }
  int height() const { return target_.height(); }
  unsigned framebuffer() const { return target_.framebuffer(); }
  PositionSource& upload() { return positions_; }
  // Draws `frame`; with `timed`, waits for it and returns its ms (else 0).
  double draw(const FrameView& frame, bool timed);
  // The frame drawn last, rows top to bottom; counts the frames read back.
  std::vector<std::uint8_t> readBack();
  long framesReadBack() const { return readBack_; }

 private:
  FrameCapture(std::unique_ptr<HairRenderer> renderer, int width, int height)
      : renderer_(std::move(renderer)), target_(width, height) {}
  std::unique_ptr<HairRenderer> renderer_;
  CaptureTarget target_;
  PositionSource positions_;
  long readBack_ = 0;
};

}  // namespace csm
