#pragma once
#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

// A renderbuffer: an attachment that is drawn into but never sampled (the depth of the
// main pass, a multisample color target that is resolved by a blit). Move-only.
class Renderbuffer {
 public:
  explicit Renderbuffer(NoCreateT) noexcept {}
  // `samples` 0 makes a single-sample renderbuffer.
  Renderbuffer(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei samples = 0);
  Renderbuffer(TextureFormat format, GLsizei width, GLsizei height, GLsizei samples = 0)
      : Renderbuffer(GLenum(format), width, height, samples) {}
  ~Renderbuffer();
  Renderbuffer(const Renderbuffer&) = delete;
  Renderbuffer& operator=(const Renderbuffer&) = delete;
  Renderbuffer(Renderbuffer&& other) noexcept;
  Renderbuffer& operator=(Renderbuffer&& other) noexcept;

  // Takes ownership of an existing name; queries its size and format.
  static Renderbuffer wrap(GLuint id);
  GLuint release() noexcept;

  GLuint id() const { return id_; }
  GLenum internalFormat() const { return internalFormat_; }
  GLsizei width() const { return width_; }
  GLsizei height() const { return height_; }
  GLsizei samples() const { return samples_; }

 private:
  GLuint id_ = 0;
  GLenum internalFormat_ = 0;
  GLsizei width_ = 0, height_ = 0, samples_ = 0;
};

}  // namespace csm::gl
