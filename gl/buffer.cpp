#include "gl/buffer.h"

#include <utility>

#include "gl/debug.h"
#include "gl/fence.h"

namespace csm::gl {

Buffer::Buffer() {
  glGenBuffers(1, &id_);
  maybeCheckErrors("Buffer::Buffer");
}

Buffer::Buffer(GLsizeiptr size, const void* data, GLenum usage) : Buffer() {
  setData(size, data, usage);
}

Buffer::~Buffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

Buffer::Buffer(Buffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      size_(std::exchange(other.size_, 0)),
      usage_(other.usage_) {}

// Deletes what this held at once, so a moved-from object is always empty.
Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteBuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
    size_ = std::exchange(other.size_, 0);
    usage_ = other.usage_;
  }
  return *this;
}

Buffer Buffer::wrap(GLuint id) {
  Buffer b{NoCreate};
  b.id_ = id;
  glBindBuffer(GL_COPY_READ_BUFFER, id);
  GLint64 size = 0;
  glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
  GLint usage = GL_DYNAMIC_DRAW;
  glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_USAGE, &usage);
  b.size_ = GLsizeiptr(size);
  b.usage_ = GLenum(usage);
  maybeCheckErrors("Buffer::wrap");
  return b;
}

GLuint Buffer::release() noexcept {
  size_ = 0;
  return std::exchange(id_, 0);
}

void Buffer::setData(GLsizeiptr size, const void* data, GLenum usage) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, id_);
  glBufferData(GL_COPY_WRITE_BUFFER, size, data, usage);
  size_ = size;
  usage_ = usage;
  maybeCheckErrors("Buffer::setData");
}

void Buffer::setSubData(GLintptr offset, GLsizeiptr size, const void* data) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, id_);
  glBufferSubData(GL_COPY_WRITE_BUFFER, offset, size, data);
  maybeCheckErrors("Buffer::setSubData");
}

void Buffer::read(GLintptr offset, GLsizeiptr size, void* out) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_COPY_READ_BUFFER, id_);
  glGetBufferSubData(GL_COPY_READ_BUFFER, offset, size, out);
  countReadback(std::uint64_t(size));
  maybeCheckErrors("Buffer::read");
}

void Buffer::clearToZero() {
  glBindBuffer(GL_COPY_WRITE_BUFFER, id_);
  // R8UI with a null pointer fills with zeros and works for any buffer size.
  glClearBufferData(GL_COPY_WRITE_BUFFER, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
  maybeCheckErrors("Buffer::clearToZero");
}

void Buffer::clearToZero(GLintptr offset, GLsizeiptr size) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, id_);
  glClearBufferSubData(GL_COPY_WRITE_BUFFER, GL_R32UI, offset, size, GL_RED_INTEGER,
                       GL_UNSIGNED_INT, nullptr);
  maybeCheckErrors("Buffer::clearToZero");
}

void Buffer::copyTo(Buffer& dst, GLintptr srcOffset, GLintptr dstOffset, GLsizeiptr size) const {
  glBindBuffer(GL_COPY_READ_BUFFER, id_);
  glBindBuffer(GL_COPY_WRITE_BUFFER, dst.id_);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, srcOffset, dstOffset, size);
  maybeCheckErrors("Buffer::copyTo");
}

void copyBuffer(GLuint src, GLuint dst, GLsizeiptr bytes) {
  glBindBuffer(GL_COPY_READ_BUFFER, src);
  glBindBuffer(GL_COPY_WRITE_BUFFER, dst);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, bytes);
  maybeCheckErrors("copyBuffer");
}

void Buffer::bindBase(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id_);
  maybeCheckErrors("Buffer::bindBase");
}

void Buffer::bindRange(GLenum target, GLuint index, GLintptr offset, GLsizeiptr size) const {
  glBindBufferRange(target, index, id_, offset, size);
  maybeCheckErrors("Buffer::bindRange");
}

void Buffer::bind(GLenum target) const {
  glBindBuffer(target, id_);
  maybeCheckErrors("Buffer::bind");
}

}  // namespace csm::gl
