#pragma once
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

// A GL buffer object. Move-only; the destructor deletes the GL name (Magnum's
// GL/Buffer.h). Edits bind it to GL_COPY_WRITE_BUFFER / GL_COPY_READ_BUFFER, targets that
// no draw or dispatch reads, so array and indexed bindings stay as the caller left them.
class Buffer {
 public:
  explicit Buffer(NoCreateT) noexcept {}
  // A buffer name with no storage yet.
  Buffer();
  explicit Buffer(GLsizeiptr size, const void* data = nullptr, GLenum usage = GL_DYNAMIC_DRAW);
  template <class T>
  explicit Buffer(const std::vector<T>& data, GLenum usage = GL_DYNAMIC_DRAW)
      : Buffer(GLsizeiptr(data.size() * sizeof(T)), data.data(), usage) {}
  Buffer(GLsizeiptr size, const void* data, BufferUsage usage)
      : Buffer(size, data, GLenum(usage)) {}
  template <class T>
  Buffer(const std::vector<T>& data, BufferUsage usage) : Buffer(data, GLenum(usage)) {}
  ~Buffer();

  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  // Takes ownership of an existing name (the destructor deletes it); queries its size.
  static Buffer wrap(GLuint id);
  // Gives up ownership: returns the name and leaves this object empty.
  GLuint release() noexcept;

  GLuint id() const { return id_; }
  GLsizeiptr size() const { return size_; }

  // Reallocates (glBufferData). `usage` is a hint; the last one given is kept for upload().
  void setData(GLsizeiptr size, const void* data, GLenum usage);
  void setData(GLsizeiptr size, const void* data, BufferUsage usage) {
    setData(size, data, GLenum(usage));
  }
  void setData(GLsizeiptr size, const void* data) { setData(size, data, usage_); }
  void setSubData(GLintptr offset, GLsizeiptr size, const void* data);
  // Reads back into `out`. Waits for the GPU. Issues the buffer-update barrier itself, since
  // a compute shader's SSBO writes are not otherwise visible to glGetBufferSubData.
  void read(GLintptr offset, GLsizeiptr size, void* out) const;
  // Sets every byte to zero on the GPU (glClearBufferData, GL 4.3).
  void clearToZero();
  // The same for `size` bytes from `offset` (glClearBufferSubData; both multiples of 4).
  void clearToZero(GLintptr offset, GLsizeiptr size);
  // GPU-side copy into `dst` (glCopyBufferSubData).
  void copyTo(Buffer& dst, GLintptr srcOffset, GLintptr dstOffset, GLsizeiptr size) const;

  // Replaces the contents with `data`; reallocates only when the byte size changes.
  template <class T>
  void upload(const std::vector<T>& data) {
    static_assert(std::is_trivially_copyable_v<T>);
    auto bytes = GLsizeiptr(data.size() * sizeof(T));
    if (bytes == size_ && bytes > 0)
      setSubData(0, bytes, data.data());
    else
      setData(bytes, data.data());
  }
  // Reads `count` elements of T starting at element `first`; by default all that fit.
  template <class T>
  std::vector<T> download(std::size_t count = SIZE_MAX, std::size_t first = 0) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::size_t available = std::size_t(size_) / sizeof(T);
    if (first > available) first = available;
    if (count > available - first) count = available - first;
    std::vector<T> out(count);
    if (count > 0) read(GLintptr(first * sizeof(T)), GLsizeiptr(count * sizeof(T)), out.data());
    return out;
  }

  // Indexed binding for GL_SHADER_STORAGE_BUFFER / GL_UNIFORM_BUFFER / atomic counters.
  void bindBase(GLenum target, GLuint index) const;
  void bindBase(BufferTarget target, GLuint index) const { bindBase(GLenum(target), index); }
  void bindRange(GLenum target, GLuint index, GLintptr offset, GLsizeiptr size) const;
  void bind(GLenum target) const;

 private:
  GLuint id_ = 0;
  GLsizeiptr size_ = 0;
  GLenum usage_ = GL_DYNAMIC_DRAW;
};

// GPU-side copy of `bytes` from the start of buffer `src` to the start of `dst`, by name: for
// a buffer another module owns (a solver's positions).
void copyBuffer(GLuint src, GLuint dst, GLsizeiptr bytes);

}  // namespace csm::gl
