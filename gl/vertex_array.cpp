#include "gl/vertex_array.h"

#include <utility>

#include "gl/buffer.h"
#include "gl/debug.h"

namespace csm::gl {

VertexArray::VertexArray() {
  glGenVertexArrays(1, &id_);
  maybeCheckErrors("VertexArray::VertexArray");
}

VertexArray::~VertexArray() {
  if (id_) glDeleteVertexArrays(1, &id_);
}

VertexArray::VertexArray(VertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteVertexArrays(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

VertexArray VertexArray::wrap(GLuint id) {
  VertexArray v{NoCreate};
  v.id_ = id;
  return v;
}

GLuint VertexArray::release() noexcept {
  return std::exchange(id_, 0);
}

void VertexArray::bind() const {
  glBindVertexArray(id_);
  maybeCheckErrors("VertexArray::bind");
}

void VertexArray::unbind() {
  glBindVertexArray(0);
}

VertexArray& VertexArray::setAttribute(GLuint location, const Buffer& buffer, GLint components,
                                       GLenum type, GLsizei stride, GLintptr offset,
                                       bool normalized, GLuint divisor) {
  glBindVertexArray(id_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, type, normalized ? GL_TRUE : GL_FALSE, stride,
                        reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(location, divisor);
  maybeCheckErrors("VertexArray::setAttribute");
  return *this;
}

VertexArray& VertexArray::setIntegerAttribute(GLuint location, const Buffer& buffer,
                                              GLint components, GLenum type, GLsizei stride,
                                              GLintptr offset, GLuint divisor) {
  glBindVertexArray(id_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribIPointer(location, components, type, stride, reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(location, divisor);
  maybeCheckErrors("VertexArray::setIntegerAttribute");
  return *this;
}

VertexArray& VertexArray::setIndexBuffer(const Buffer& buffer) {
  glBindVertexArray(id_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());  // recorded in the VAO
  maybeCheckErrors("VertexArray::setIndexBuffer");
  return *this;
}

}  // namespace csm::gl
