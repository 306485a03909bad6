#include "render/frame_target.h"

#include <algorithm>
#include <string>

#include "gl/debug.h"

namespace csm {

void FrameTarget::resize(int width, int height, int samples) {
  if (width == width_ && height == height_ && samples == asked_) return;
  width_ = width;
  height_ = height;
  asked_ = samples;
  if (samples > 1) {
    color_ = gl::Texture::create2DMultisample(gl::TextureFormat::Rgba16f, width, height, samples);
    samples_ = std::max(1, int(color_.samples()));
    depth_ = gl::Renderbuffer(gl::TextureFormat::Depth24, width, height, samples_);
  } else {
    color_ = gl::Texture::create2D(gl::TextureFormat::Rgba16f, width, height);
    color_.setFilter(gl::Filter::Nearest, gl::Filter::Nearest);
    samples_ = 1;
    depth_ = gl::Renderbuffer(gl::TextureFormat::Depth24, width, height, 0);
  }
  fbo_ = gl::Framebuffer();
  fbo_.attach(gl::Attachment::Color0, color_)
      .attach(gl::Attachment::Depth, depth_)
      .setDrawBuffers({gl::Attachment::Color0});
  std::string message;
  if (!fbo_.checkComplete(&message))
    gl::logMessage(gl::LogLevel::Error, "frame target: " + message);
}

}  // namespace csm
