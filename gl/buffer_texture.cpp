#include "gl/buffer_texture.h"

#include <utility>

#include "gl/debug.h"

namespace csm::gl {

BufferTexture::BufferTexture(const Buffer& buffer, GLenum internalFormat) {
  glGenTextures(1, &id_);
  attach(buffer, internalFormat);
}

BufferTexture::BufferTexture(const Buffer& buffer, GLenum internalFormat, GLintptr offset,
                             GLsizeiptr size) {
  glGenTextures(1, &id_);
  attachRange(buffer, internalFormat, offset, size);
}

BufferTexture::~BufferTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

BufferTexture::BufferTexture(BufferTexture&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

// Deletes what this held at once, so a moved-from object is always empty.
BufferTexture& BufferTexture::operator=(BufferTexture&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

BufferTexture BufferTexture::wrap(GLuint id) {
  BufferTexture t{NoCreate};
  t.id_ = id;
  return t;
}

GLuint BufferTexture::release() noexcept {
  return std::exchange(id_, 0);
}

void BufferTexture::attach(const Buffer& buffer, GLenum internalFormat) {
  // Texture unit 0 is borrowed for the edit; bind() sets the unit it needs.
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, id_);
  glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer.id());
  maybeCheckErrors("BufferTexture::attach");
}

void BufferTexture::attachRange(const Buffer& buffer, GLenum internalFormat, GLintptr offset,
                                GLsizeiptr size) {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, id_);
  glTexBufferRange(GL_TEXTURE_BUFFER, internalFormat, buffer.id(), offset, size);
  maybeCheckErrors("BufferTexture::attachRange");
}

void BufferTexture::bind(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, id_);
  maybeCheckErrors("BufferTexture::bind");
}

void BufferTexture::bindImage(GLuint unit, GLenum access, GLenum format) const {
  glBindImageTexture(unit, id_, 0, GL_FALSE, 0, access, format);
  maybeCheckErrors("BufferTexture::bindImage");
}

}  // namespace csm::gl
