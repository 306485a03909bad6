// Filling the GPU solver's storage buffers: created on first use, at least one element (a
// zero-sized buffer cannot be bound to a storage point usefully), texel views kept attached.
#pragma once

#include <algorithm>
#include <vector>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "gl/enums.h"

namespace csm::gpu {

template <class T>
void fill(gl::Buffer& buffer, const std::vector<T>& data) {
  if (data.empty()) {
    fill(buffer, std::vector<T>(1));
    return;
  }
  if (buffer.id() == 0)
    buffer = gl::Buffer(data);
  else
    buffer.upload(data);
}

// `count` zero elements (at least one), cleared on the GPU: no copy of the buffer in process
// memory, which the largest of them (the contact search's, hundreds of MB in dense hair) would
// double at their peak.
template <class T>
void zeroed(gl::Buffer& buffer, size_t count) {
  const auto bytes = GLsizeiptr(std::max<size_t>(count, 1) * sizeof(T));
  if (buffer.id() == 0)
    buffer = gl::Buffer(bytes);
  else if (buffer.size() != bytes)
    buffer.setData(bytes, nullptr);
  buffer.clearToZero();
}

// A texelFetch view of `buffer` (see gl/buffer_texture.h).
inline void view(gl::BufferTexture& tex, const gl::Buffer& buffer, gl::TextureFormat format) {
  if (tex.id() == 0)
    tex = gl::BufferTexture(buffer, format);
  else
    tex.attach(buffer, format);
}

// A view of `size` bytes of `buffer` from `offset` (see BufferTexture::attachRange).
inline void viewRange(gl::BufferTexture& tex, const gl::Buffer& buffer, gl::TextureFormat format,
                      GLintptr offset, GLsizeiptr size) {
  if (tex.id() == 0)
    tex = gl::BufferTexture(buffer, format, offset, size);
  else
    tex.attachRange(buffer, format, offset, size);
}

}  // namespace csm::gpu
