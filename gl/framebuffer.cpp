#include "gl/framebuffer.h"

#include <utility>

#include "gl/debug.h"
#include "gl/fence.h"
#include "gl/renderbuffer.h"
#include "gl/texture.h"

namespace csm::gl {
namespace {

const char* statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
      return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (an attachment is not renderable or has "
             "zero size)";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing attached)";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
      return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER (a draw buffer names an empty attachment)";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
      return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER (the read buffer names an empty "
             "attachment)";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED (this combination of formats is not supported)";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE (attachments differ in sample count)";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
      return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS (layered and non-layered attachments "
             "mixed)";
    default:
      return "unknown framebuffer status";
  }
}

}  // namespace

Framebuffer::Framebuffer() {
  glGenFramebuffers(1, &id_);
  maybeCheckErrors("Framebuffer::Framebuffer");
}

Framebuffer::~Framebuffer() {
  if (id_) glDeleteFramebuffers(1, &id_);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteFramebuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

Framebuffer Framebuffer::wrap(GLuint id) {
  Framebuffer f{NoCreate};
  f.id_ = id;
  return f;
}

GLuint Framebuffer::release() noexcept {
  return std::exchange(id_, 0);
}

Framebuffer& Framebuffer::attach(GLenum attachment, const Texture& texture, GLint level) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glFramebufferTexture(GL_DRAW_FRAMEBUFFER, attachment, texture.id(), level);
  maybeCheckErrors("Framebuffer::attach(texture)");
  return *this;
}

Framebuffer& Framebuffer::attachLayer(GLenum attachment, const Texture& texture, GLint layer,
                                      GLint level) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, attachment, texture.id(), level, layer);
  maybeCheckErrors("Framebuffer::attachLayer");
  return *this;
}

Framebuffer& Framebuffer::attach(GLenum attachment, const Renderbuffer& renderbuffer) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer.id());
  maybeCheckErrors("Framebuffer::attach(renderbuffer)");
  return *this;
}

Framebuffer& Framebuffer::detach(GLenum attachment) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, GL_RENDERBUFFER, 0);
  maybeCheckErrors("Framebuffer::detach");
  return *this;
}

Framebuffer& Framebuffer::setDrawBuffers(std::initializer_list<GLenum> buffers) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glDrawBuffers(GLsizei(buffers.size()), buffers.begin());
  maybeCheckErrors("Framebuffer::setDrawBuffers");
  return *this;
}

Framebuffer& Framebuffer::setDrawBuffers(std::initializer_list<Attachment> buffers) {
  std::vector<GLenum> names;
  for (Attachment a : buffers) names.push_back(GLenum(a));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glDrawBuffers(GLsizei(names.size()), names.data());
  maybeCheckErrors("Framebuffer::setDrawBuffers");
  return *this;
}

bool Framebuffer::checkComplete(std::string* message) const {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) {
    if (message) message->clear();
    return true;
  }
  if (message)
    *message = "framebuffer " + std::to_string(id_) + " is incomplete: " + statusName(status);
  return false;
}

void Framebuffer::bind(GLenum target) const {
  glBindFramebuffer(target, id_);
  maybeCheckErrors("Framebuffer::bind");
}

void Framebuffer::bindDefault(GLenum target) {
  glBindFramebuffer(target, 0);
}

void Framebuffer::bindRaw(GLenum target, GLuint id) {
  glBindFramebuffer(target, id);
}

void Framebuffer::clearColor(GLint drawBuffer, const std::array<float, 4>& rgba) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glClearBufferfv(GL_COLOR, drawBuffer, rgba.data());
  maybeCheckErrors("Framebuffer::clearColor");
}

void Framebuffer::clearColor(GLint drawBuffer, const std::array<GLuint, 4>& rgba) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  glClearBufferuiv(GL_COLOR, drawBuffer, rgba.data());
  maybeCheckErrors("Framebuffer::clearColor");
}

void Framebuffer::clearDepth(float depth) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id_);
  // glClearBuffer* honours the depth mask; a pass that left it off would clear nothing.
  GLboolean mask = GL_TRUE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
  glDepthMask(GL_TRUE);
  glClearBufferfv(GL_DEPTH, 0, &depth);
  glDepthMask(mask);
  maybeCheckErrors("Framebuffer::clearDepth");
}

void Framebuffer::read(GLenum attachment, const Rect& rect, GLenum format, GLenum type,
                       void* out) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, id_);
  glReadBuffer(attachment);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(rect.x, rect.y, rect.width, rect.height, format, type, out);
  countReadback(std::uint64_t(rect.width) * std::uint64_t(rect.height) * 4);
  maybeCheckErrors("Framebuffer::read");
}

void Framebuffer::blitTo(GLuint dst, const Rect& src, const Rect& dstRect, GLbitfield mask,
                         GLenum filter) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, id_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst);
  glBlitFramebuffer(src.x, src.y, src.x + src.width, src.y + src.height, dstRect.x, dstRect.y,
                    dstRect.x + dstRect.width, dstRect.y + dstRect.height, mask, filter);
  maybeCheckErrors("Framebuffer::blitTo");
}

}  // namespace csm::gl
