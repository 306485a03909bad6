#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

// A texture with immutable storage (glTexStorage*, GL 4.2/4.3): 2D, 2D array (deep opacity
// layers) or 2D multisample. Move-only. Edits bind it to the active texture unit.
class Texture {
 public:
  explicit Texture(NoCreateT) noexcept {}
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;

  static Texture create2D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei levels = 1);
  static Texture create2D(TextureFormat format, GLsizei width, GLsizei height, GLsizei levels = 1) {
    return create2D(GLenum(format), width, height, levels);
  }
  static Texture create2DArray(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei layers,
                               GLsizei levels = 1);
  static Texture create2DArray(TextureFormat format, GLsizei width, GLsizei height, GLsizei layers,
                               GLsizei levels = 1) {
    return create2DArray(GLenum(format), width, height, layers, levels);
  }
  static Texture create2DMultisample(GLenum internalFormat, GLsizei width, GLsizei height,
                                     GLsizei samples, bool fixedSampleLocations = true);
  static Texture create2DMultisample(TextureFormat format, GLsizei width, GLsizei height,
                                     GLsizei samples, bool fixedSampleLocations = true) {
    return create2DMultisample(GLenum(format), width, height, samples, fixedSampleLocations);
  }
  // Takes ownership of an existing name of the given target; queries its size and format.
  static Texture wrap(GLuint id, GLenum target);
  GLuint release() noexcept;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  GLenum internalFormat() const { return internalFormat_; }
  GLsizei width() const { return width_; }
  GLsizei height() const { return height_; }
  GLsizei layers() const { return layers_; }  // 1 unless a 2D array
  GLsizei levels() const { return levels_; }
  GLsizei samples() const { return samples_; }  // 0 unless multisample; what the driver made

  // Sampler state; not valid on multisample textures.
  Texture& setFilter(GLenum minFilter, GLenum magFilter);
  Texture& setWrap(GLenum wrap);
  Texture& setBorderColor(const std::array<float, 4>& rgba);
  Texture& setParameter(GLenum name, GLint value);
  Texture& setFilter(Filter minFilter, Filter magFilter) {
    return setFilter(GLenum(minFilter), GLenum(magFilter));
  }
  Texture& setWrap(Wrap wrap) { return setWrap(GLenum(wrap)); }
  // A depth texture sampled as a shadow map (sampler2DShadow): each fetch compares the
  // reference with the stored depth by `compare` and filters the results.
  Texture& setDepthCompare(DepthCompare compare) {
    return setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE)
        .setParameter(GL_TEXTURE_COMPARE_FUNC, GLint(compare));
  }

  // Uploads a region of one level; for a 2D array, `layer` picks the first of `depth`
  // layers.
  void setSubImage(GLint level, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                   GLenum type, const void* data);
  void setSubImage(GLint level, GLint x, GLint y, GLint layer, GLsizei width, GLsizei height,
                   GLsizei depth, GLenum format, GLenum type, const void* data);
  void setSubImage(GLint level, GLint x, GLint y, GLint layer, GLsizei width, GLsizei height,
                   GLsizei depth, PixelFormat format, PixelType type, const void* data) {
    setSubImage(level, x, y, layer, width, height, depth, GLenum(format), GLenum(type), data);
  }
  void generateMipmap();

  // Binds for sampling on texture unit `unit` (leaves `unit` active).
  void bind(GLuint unit) const;
  // Binds level `level` as an image for imageLoad/imageStore; a 2D array is bound
  // layered unless `layer` >= 0. `format` 0 means the texture's own internal format.
  void bindImage(GLuint unit, GLenum access, GLint level = 0, GLint layer = -1,
                 GLenum format = 0) const;

  // Reads back one whole level (every layer of an array, layer after layer) with rows
  // packed tightly. Waits for the GPU. Multisample textures cannot be read: resolve them
  // into a plain one with Framebuffer::blitTo first.
  void read(GLint level, GLenum format, GLenum type, void* out) const;
  // `components` per pixel of type T, e.g. read<float>(GL_RGBA, GL_FLOAT, 4).
  template <class T>
  std::vector<T> read(GLenum format, GLenum type, int components, GLint level = 0) const {
    std::size_t w = std::size_t(width_ >> level), h = std::size_t(height_ >> level);
    std::vector<T> out((w ? w : 1) * (h ? h : 1) * std::size_t(layers_) * std::size_t(components));
    read(level, format, type, out.data());
    return out;
  }

 private:
  explicit Texture(GLenum target);
  GLuint id_ = 0;
  GLenum target_ = GL_TEXTURE_2D;
  GLenum internalFormat_ = 0;
  GLsizei width_ = 0, height_ = 0, layers_ = 1, levels_ = 1, samples_ = 0;
};

}  // namespace csm::gl
