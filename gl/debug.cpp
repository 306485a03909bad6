#include "gl/debug.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gl/gl.h"

namespace csm::gl {
namespace {

LogSink& sink() {
  static LogSink s;
  return s;
}

bool initialErrorChecks() {
  if (const char* env = std::getenv("CSM_GL_ERROR_CHECKS"); env && *env)
    return std::strcmp(env, "0") != 0;
#ifdef CSM_GL_ERROR_CHECKS_DEFAULT
  return true;
#else
  return false;
#endif
}

std::atomic<bool>& errorChecks() {
  static std::atomic<bool> enabled{initialErrorChecks()};
  return enabled;
}

const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    default:
      return "unknown GL error";
  }
}

const char* sourceName(GLenum s) {
  switch (s) {
    case GL_DEBUG_SOURCE_API:
      return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
      return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER:
      return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY:
      return "third party";
    case GL_DEBUG_SOURCE_APPLICATION:
      return "application";
    default:
      return "other";
  }
}

const char* typeName(GLenum t) {
  switch (t) {
    case GL_DEBUG_TYPE_ERROR:
      return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
      return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
      return "undefined behavior";
    case GL_DEBUG_TYPE_PORTABILITY:
      return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
      return "performance";
    default:
      return "other";
  }
}

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity,
                              GLsizei length, const GLchar* message, const void*) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  LogLevel level = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH
                       ? LogLevel::Error
                       : LogLevel::Warning;
  std::string text = "GL debug (";
  text += sourceName(source);
  text += ", ";
  text += typeName(type);
  text += ", id " + std::to_string(id) + "): ";
  text.append(message, length < 0 ? std::strlen(message) : std::size_t(length));
  logMessage(level, text);
}

}  // namespace

void setLogSink(LogSink s) {
  sink() = std::move(s);
}

void logMessage(LogLevel level, std::string_view message) {
  if (sink()) {
    sink()(level, message);
    return;
  }
  const char* prefix = level == LogLevel::Error     ? "error: "
                       : level == LogLevel::Warning ? "warning: "
                                                    : "";
  std::fprintf(stderr, "csm::gl: %s%.*s\n", prefix, int(message.size()), message.data());
}

void setErrorChecks(bool enabled) {
  errorChecks() = enabled;
}
bool errorChecksEnabled() {
  return errorChecks().load(std::memory_order_relaxed);
}

bool checkErrors(const char* where) {
  bool ok = true;
  // Bounded: without a current context glGetError may keep returning an error.
  for (int i = 0; i < 16; ++i) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    ok = false;
    logMessage(LogLevel::Error, std::string(errorName(e)) + " in " + where);
  }
  return ok;
}

bool enableDebugOutput(bool synchronous) {
  if (epoxy_gl_version() < 43 && !epoxy_has_gl_extension("GL_KHR_debug")) return false;
  glEnable(GL_DEBUG_OUTPUT);
  if (synchronous)
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  else
    glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debugCallback, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                        GL_FALSE);
  // Shader::compile logs compiler messages itself, with file names in place of numbers.
  glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                        GL_FALSE);
  return true;
}

void disableDebugOutput() {
  glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT);
}

}  // namespace csm::gl
