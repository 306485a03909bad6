// The frame the scene passes draw into: HDR colour (RGBA16F) and depth, multisampled when
// asked, resolved and tone mapped by the post pass into the caller's framebuffer.
#pragma once

#include "gl/framebuffer.h"
#include "gl/renderbuffer.h"
#include "gl/texture.h"

namespace csm {

class FrameTarget {
 public:
  // Reallocates when the size or the sample count changes.
  void resize(int width, int height, int samples);
  int width() const { return width_; }
  int height() const { return height_; }
  // The samples the driver made (it may round up); 1 without multisampling.
  int samples() const { return samples_; }

  gl::Framebuffer& framebuffer() { return fbo_; }
  const gl::Texture& color() const { return color_; }

 private:
  int width_ = 0, height_ = 0, asked_ = 0, samples_ = 0;
  gl::Texture color_{gl::NoCreate};
  gl::Renderbuffer depth_{gl::NoCreate};
  gl::Framebuffer fbo_{gl::NoCreate};
};

}  // namespace csm
