#pragma once
#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

class Renderbuffer;
class Texture;

struct Rect {
  GLint x = 0, y = 0;
  GLsizei width = 0, height = 0;
};

// A framebuffer object. Headless rendering has no window framebuffer, so every pass draws
// into one of these (polyscope's EGL backend does the same). Move-only. Edits and clears
// bind it to GL_DRAW_FRAMEBUFFER, reads to GL_READ_FRAMEBUFFER.
class Framebuffer {
 public:
  explicit Framebuffer(NoCreateT) noexcept {}
  Framebuffer();
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;

  // Takes ownership of an existing name.
  static Framebuffer wrap(GLuint id);
  GLuint release() noexcept;
  GLuint id() const { return id_; }

  // Attaches a whole level. For a 2D array this is a layered attachment: a geometry
  // shader picks the layer with gl_Layer (one pass fills every deep opacity layer).
  Framebuffer& attach(GLenum attachment, const Texture& texture, GLint level = 0);
  // Attaches one layer of a 2D array.
  Framebuffer& attachLayer(GLenum attachment, const Texture& texture, GLint layer, GLint level = 0);
  Framebuffer& attach(GLenum attachment, const Renderbuffer& renderbuffer);
  Framebuffer& attach(Attachment attachment, const Texture& texture, GLint level = 0) {
    return attach(GLenum(attachment), texture, level);
  }
  Framebuffer& attach(Attachment attachment, const Renderbuffer& renderbuffer) {
    return attach(GLenum(attachment), renderbuffer);
  }
  Framebuffer& detach(GLenum attachment);
  // Which color attachments the fragment outputs 0, 1, ... write; GL_NONE skips one.
  Framebuffer& setDrawBuffers(std::initializer_list<GLenum> buffers);
  Framebuffer& setDrawBuffers(std::initializer_list<Attachment> buffers);

  // True when complete; otherwise `message` (if given) names the failing status.
  bool checkComplete(std::string* message = nullptr) const;

  void bind(GLenum target = GL_FRAMEBUFFER) const;
  // The window's framebuffer (or none, headless).
  static void bindDefault(GLenum target = GL_FRAMEBUFFER);
  // A framebuffer by name (0: the default one), e.g. one a caller passed down.
  static void bindRaw(GLenum target, GLuint id);
  static void bindRaw(FramebufferTarget target, GLuint id) { bindRaw(GLenum(target), id); }

  // Clear one draw buffer (index into setDrawBuffers) or the depth attachment. Scissor and
  // write masks apply as usual.
  void clearColor(GLint drawBuffer, const std::array<float, 4>& rgba);
  void clearColor(GLint drawBuffer, const std::array<GLuint, 4>& rgba);
  void clearDepth(float depth = 1.0f);

  // Reads a rectangle of one color attachment (GL_COLOR_ATTACHMENTn), rows bottom to top,
  // tightly packed. Waits for the GPU.
  void read(GLenum attachment, const Rect& rect, GLenum format, GLenum type, void* out) const;
  template <class T>
  std::vector<T> read(GLenum attachment, const Rect& rect, GLenum format, GLenum type,
                      int components) const {
    std::vector<T> out(std::size_t(rect.width) * std::size_t(rect.height) *
                       std::size_t(components));
    read(attachment, rect, format, type, out.data());
    return out;
  }
  void read(Attachment attachment, const Rect& rect, PixelFormat format, PixelType type,
            void* out) const {
    read(GLenum(attachment), rect, GLenum(format), GLenum(type), out);
  }
  template <class T>
  std::vector<T> read(Attachment attachment, const Rect& rect, PixelFormat format, PixelType type,
                      int components) const {
    return read<T>(GLenum(attachment), rect, GLenum(format), GLenum(type), components);
  }

  // Copies into framebuffer `dst` (0 = default); resolves multisampling when this one is
  // multisampled and `dst` is not.
  void blitTo(GLuint dst, const Rect& src, const Rect& dstRect,
              GLbitfield mask = GL_COLOR_BUFFER_BIT, GLenum filter = GL_NEAREST) const;

 private:
  GLuint id_ = 0;
};

}  // namespace csm::gl
