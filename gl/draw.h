#pragma once
// Draw calls and the fixed-function state a pass sets before them. A pass states the whole
// raster state it needs (DrawState) instead of toggling what the last pass left, so passes
// can be reordered without surprises (as in Vulkan's pipeline state objects).
#include <cstddef>

#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

enum class Cull { None, Front, Back };
enum class Blend { None, Additive };  // Additive: src + dst, for accumulation targets

struct DrawState {
  bool depthTest = false;
  GLenum depthFunc = GL_LESS;
  bool depthWrite = true;
  Blend blend = Blend::None;
  Cull cull = Cull::None;  // with counter-clockwise front faces
  bool multisample = true;
};

// Sets every field of `state`, plus what no pass here changes: no scissor, stencil,
// alpha-to-coverage or sRGB conversion, all colour channels written, and primitive restart
// at the all-ones index.
void applyDrawState(const DrawState& state);
void setViewport(GLint x, GLint y, GLsizei width, GLsizei height);

// glDrawElementsInstanced on the bound vertex array's uint index buffer, from index `first`.
void drawElements(GLenum mode, std::size_t count, GLsizei instances = 1, std::size_t first = 0);
inline void drawElements(Primitive mode, std::size_t count, GLsizei instances = 1,
                         std::size_t first = 0) {
  drawElements(GLenum(mode), count, instances, first);
}
// glDrawArrays with no vertex attributes (vertices from gl_VertexID).
void drawArrays(GLenum mode, GLint first, GLsizei count);
inline void drawArrays(Primitive mode, GLint first, GLsizei count) {
  drawArrays(GLenum(mode), first, count);
}

// Binds a buffer by name to an indexed SSBO binding (a buffer another module owns).
void bindStorageBuffer(GLuint index, GLuint buffer);

// Blocks until every command issued in the current context has run (glFinish): for honest
// wall-clock timing only; it stalls the pipeline.
void finish();
// GL_VERSION of the current context; null when no context is current.
const char* versionString();

}  // namespace csm::gl
