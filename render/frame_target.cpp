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
    color_ = gl::Texture::create2DMultisample(GL_RGBA16F, width, height, samples);
    samples_ = std::max(1, int(color_.samples()));
    depth_ = gl::Renderbuffer(GL_DEPTH_COMPONENT24, width, height, samples_);
  } else {
    color_ = gl::Texture::create2D(GL_RGBA16F, width, height);
    color_.setFilter(GL_NEAREST, GL_NEAREST);
    samples_ = 1;
    depth_ = gl::Renderbuffer(GL_DEPTH_COMPONENT24, width, height, 0);
  }
  fbo_ = gl::Framebuffer();
  fbo_.attach(GL_COLOR_ATTACHMENT0, color_)
      .attach(GL_DEPTH_ATTACHMENT, depth_)
      .setDrawBuffers({GL_COLOR_ATTACHMENT0});
  std::string message;
  if (!fbo_.checkComplete(&message))
    gl::logMessage(gl::LogLevel::Error, "frame target: " + message);
}

}  // namespace csm
