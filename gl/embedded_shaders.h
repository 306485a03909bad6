#pragma once
// The table that cmake/EmbedShaders.cmake generates into the csm_shaders library.
// Use shaderSource() in shader_source.h rather than reading it directly.
#include <cstddef>

namespace csm::gl::embedded {

struct File {
  const char* path;           // relative to shaders/, with '/' separators
  const unsigned char* data;  // `size` bytes followed by a 0 (unsigned: UTF-8 comments)
  std::size_t size;
};

extern const File kFiles[];
extern const std::size_t kFileCount;

}  // namespace csm::gl::embedded
