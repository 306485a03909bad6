#pragma once
#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

class Buffer;

// A vertex array object. Core profile needs one bound for any draw, even one that fetches
// nothing: the hair pass reads positions from the simulation's SSBO by gl_VertexID, so an
// empty VAO is all it needs. Move-only. Edits bind it (and GL_ARRAY_BUFFER).
class VertexArray {
 public:
  explicit VertexArray(NoCreateT) noexcept {}
  VertexArray();
  ~VertexArray();
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;
  VertexArray(VertexArray&& other) noexcept;
  VertexArray& operator=(VertexArray&& other) noexcept;

  static VertexArray wrap(GLuint id);  // takes ownership
  GLuint release() noexcept;
  GLuint id() const { return id_; }

  void bind() const;
  static void unbind();

  // A float attribute read from `buffer` (integers are converted; `normalized` maps them to
  // [0,1] / [-1,1]). `divisor` > 0 advances it per instance instead of per vertex.
  VertexArray& setAttribute(GLuint location, const Buffer& buffer, GLint components, GLenum type,
                            GLsizei stride, GLintptr offset, bool normalized = false,
                            GLuint divisor = 0);
  VertexArray& setAttribute(GLuint location, const Buffer& buffer, GLint components,
                            AttributeType type, GLsizei stride, GLintptr offset,
                            bool normalized = false, GLuint divisor = 0) {
    return setAttribute(location, buffer, components, GLenum(type), stride, offset, normalized,
                        divisor);
  }
  // An integer attribute (ivec/uvec in GLSL), not converted.
  VertexArray& setIntegerAttribute(GLuint location, const Buffer& buffer, GLint components,
                                   GLenum type, GLsizei stride, GLintptr offset,
                                   GLuint divisor = 0);
  VertexArray& setIndexBuffer(const Buffer& buffer);

 private:
  GLuint id_ = 0;
};

}  // namespace csm::gl
