#include "gl/texture.h"

#include <utility>

#include "gl/debug.h"
#include "gl/fence.h"

namespace csm::gl {

Texture::Texture(GLenum target) : target_(target) {
  glGenTextures(1, &id_);
}

Texture::~Texture() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      target_(other.target_),
      internalFormat_(other.internalFormat_),
      width_(other.width_),
      height_(other.height_),
      layers_(other.layers_),
      levels_(other.levels_),
      samples_(other.samples_) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
    target_ = other.target_;
    internalFormat_ = other.internalFormat_;
    width_ = other.width_;
    height_ = other.height_;
    layers_ = other.layers_;
    levels_ = other.levels_;
    samples_ = other.samples_;
  }
  return *this;
}

Texture Texture::create2D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei levels) {
  Texture t(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, t.id_);
  glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
  // The default min filter samples mipmaps, which makes a one-level texture incomplete.
  if (levels == 1) glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  t.internalFormat_ = internalFormat;
  t.width_ = width;
  t.height_ = height;
  t.levels_ = levels;
  maybeCheckErrors("Texture::create2D");
  return t;
}

Texture Texture::create2DArray(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei layers,
                               GLsizei levels) {
  Texture t(GL_TEXTURE_2D_ARRAY);
  glBindTexture(GL_TEXTURE_2D_ARRAY, t.id_);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, levels, internalFormat, width, height, layers);
  if (levels == 1) glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  t.internalFormat_ = internalFormat;
  t.width_ = width;
  t.height_ = height;
  t.layers_ = layers;
  t.levels_ = levels;
  maybeCheckErrors("Texture::create2DArray");
  return t;
}

Texture Texture::create2DMultisample(GLenum internalFormat, GLsizei width, GLsizei height,
                                     GLsizei samples, bool fixedSampleLocations) {
  Texture t(GL_TEXTURE_2D_MULTISAMPLE);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.id_);
  glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internalFormat, width, height,
                            fixedSampleLocations ? GL_TRUE : GL_FALSE);
  t.internalFormat_ = internalFormat;
  t.width_ = width;
  t.height_ = height;
  // The driver may round the count up: keep what it made.
  GLint made = samples;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &made);
  t.samples_ = made > 0 ? made : samples;
  maybeCheckErrors("Texture::create2DMultisample");
  return t;
}

Texture Texture::wrap(GLuint id, GLenum target) {
  Texture t{NoCreate};
  t.id_ = id;
  t.target_ = target;
  glBindTexture(target, id);
  GLint v = 0;
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
  t.internalFormat_ = GLenum(v);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &t.width_);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &t.height_);
  if (target == GL_TEXTURE_2D_ARRAY)
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_DEPTH, &t.layers_);
  if (target == GL_TEXTURE_2D_MULTISAMPLE)
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_SAMPLES, &t.samples_);
  else
    glGetTexParameteriv(target, GL_TEXTURE_IMMUTABLE_LEVELS, &t.levels_);
  if (t.levels_ < 1) t.levels_ = 1;
  maybeCheckErrors("Texture::wrap");
  return t;
}

GLuint Texture::release() noexcept {
  return std::exchange(id_, 0);
}

Texture& Texture::setFilter(GLenum minFilter, GLenum magFilter) {
  glBindTexture(target_, id_);
  glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
  glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
  maybeCheckErrors("Texture::setFilter");
  return *this;
}

Texture& Texture::setWrap(GLenum wrap) {
  glBindTexture(target_, id_);
  glTexParameteri(target_, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(target_, GL_TEXTURE_WRAP_T, GLint(wrap));
  glTexParameteri(target_, GL_TEXTURE_WRAP_R, GLint(wrap));
  maybeCheckErrors("Texture::setWrap");
  return *this;
}

Texture& Texture::setBorderColor(const std::array<float, 4>& rgba) {
  glBindTexture(target_, id_);
  glTexParameterfv(target_, GL_TEXTURE_BORDER_COLOR, rgba.data());
  maybeCheckErrors("Texture::setBorderColor");
  return *this;
}

Texture& Texture::setParameter(GLenum name, GLint value) {
  glBindTexture(target_, id_);
  glTexParameteri(target_, name, value);
  maybeCheckErrors("Texture::setParameter");
  return *this;
}

void Texture::setSubImage(GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                          GLenum format, GLenum type, const void* data) {
  glBindTexture(target_, id_);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(target_, level, x, y, width, height, format, type, data);
  maybeCheckErrors("Texture::setSubImage");
}

void Texture::setSubImage(GLint level, GLint x, GLint y, GLint layer, GLsizei width, GLsizei height,
                          GLsizei depth, GLenum format, GLenum type, const void* data) {
  glBindTexture(target_, id_);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage3D(target_, level, x, y, layer, width, height, depth, format, type, data);
  maybeCheckErrors("Texture::setSubImage");
}

void Texture::generateMipmap() {
  glBindTexture(target_, id_);
  glGenerateMipmap(target_);
  maybeCheckErrors("Texture::generateMipmap");
}

void Texture::bind(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(target_, id_);
  maybeCheckErrors("Texture::bind");
}

void Texture::bindImage(GLuint unit, GLenum access, GLint level, GLint layer, GLenum format) const {
  bool layered = target_ == GL_TEXTURE_2D_ARRAY && layer < 0;
  glBindImageTexture(unit, id_, level, layered ? GL_TRUE : GL_FALSE, layer < 0 ? 0 : layer, access,
                     format ? format : internalFormat_);
  maybeCheckErrors("Texture::bindImage");
}

void Texture::read(GLint level, GLenum format, GLenum type, void* out) const {
  // Image stores from shaders are not visible to glGetTexImage without this barrier.
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindTexture(target_, id_);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(target_, level, format, type, out);
  countReadback(1);
  maybeCheckErrors("Texture::read");
}

}  // namespace csm::gl
