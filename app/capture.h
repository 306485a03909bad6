// Frames out of the headless path: an offscreen RGBA8 target the renderer resolves into,
// read back as RGB rows top to bottom; PNG files (libpng); a pipe into ffmpeg for --video.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/framebuffer.h"
#include "gl/renderbuffer.h"

namespace csm {

// An RGBA8 framebuffer of a fixed size (polyscope's EGL backend renders to its own
// framebuffer the same way: headless has no window framebuffer).
class CaptureTarget {
 public:
  CaptureTarget(int width, int height);
  unsigned framebuffer() const { return framebuffer_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  // Waits for the GPU. Rows top to bottom, 3 bytes a pixel.
  std::vector<std::uint8_t> readRgb() const;
  // Blocks until the GPU has done everything issued (glFinish), for honest frame timings.
  static void waitForGpu();

 private:
  int width_, height_;
  gl::Renderbuffer color_;
  gl::Framebuffer framebuffer_;
};

// Writes 8-bit RGB rows (top to bottom), whole or not at all. False with the reason in `error`.
bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb,
              std::string* error);

// The first executable called `name` on PATH, or "" when there is none.
std::string findOnPath(const std::string& name);

// Raw RGB frames piped into ffmpeg, which encodes them to H.264 in `path`.
class VideoPipe {
 public:
  // Null with the reason when ffmpeg is not on PATH or cannot be started.
  static std::unique_ptr<VideoPipe> open(const std::string& path, int width, int height, double fps,
                                         std::string* error);
  ~VideoPipe();
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  bool write(const std::vector<std::uint8_t>& rgb);
  // Closes the pipe and waits for ffmpeg; false when it failed.
  bool close(std::string* error);

 private:
  VideoPipe() = default;
  int fd_ = -1;
  int pid_ = -1;
  std::string path_;
};

}  // namespace csm
