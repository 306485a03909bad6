#include "gl/renderbuffer.h"

#include <utility>

#include "gl/debug.h"

namespace csm::gl {

Renderbuffer::Renderbuffer(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei samples)
    : internalFormat_(internalFormat), width_(width), height_(height), samples_(samples) {
  glGenRenderbuffers(1, &id_);
  glBindRenderbuffer(GL_RENDERBUFFER, id_);
  if (samples > 0)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internalFormat, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, internalFormat, width, height);
  maybeCheckErrors("Renderbuffer::Renderbuffer");
}

Renderbuffer::~Renderbuffer() {
  if (id_) glDeleteRenderbuffers(1, &id_);
}

Renderbuffer::Renderbuffer(Renderbuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      internalFormat_(other.internalFormat_),
      width_(other.width_),
      height_(other.height_),
      samples_(other.samples_) {}

Renderbuffer& Renderbuffer::operator=(Renderbuffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteRenderbuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
    internalFormat_ = other.internalFormat_;
    width_ = other.width_;
    height_ = other.height_;
    samples_ = other.samples_;
  }
  return *this;
}

Renderbuffer Renderbuffer::wrap(GLuint id) {
  Renderbuffer r{NoCreate};
  r.id_ = id;
  glBindRenderbuffer(GL_RENDERBUFFER, id);
  GLint format = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
  r.internalFormat_ = GLenum(format);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &r.width_);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &r.height_);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &r.samples_);
  maybeCheckErrors("Renderbuffer::wrap");
  return r;
}

GLuint Renderbuffer::release() noexcept {
  return std::exchange(id_, 0);
}

}  // namespace csm::gl
