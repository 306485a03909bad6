#include "gl/program.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gl/debug.h"
#include "gl/pass_profile.h"
#include "gl/shader.h"

namespace csm::gl {

Program::Program(std::string name) : name_(std::move(name)) {
  id_ = glCreateProgram();
  maybeCheckErrors("Program::Program");
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      name_(std::move(other.name_)),
      log_(std::move(other.log_)),
      locations_(std::move(other.locations_)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
    name_ = std::move(other.name_);
    log_ = std::move(other.log_);
    locations_ = std::move(other.locations_);
  }
  return *this;
}

Program Program::wrap(GLuint id, std::string name) {
  Program p{NoCreate};
  p.id_ = id;
  p.name_ = std::move(name);
  return p;
}

GLuint Program::release() noexcept {
  locations_.clear();
  return std::exchange(id_, 0);
}

Program& Program::attach(const Shader& shader) {
  glAttachShader(id_, shader.id());
  maybeCheckErrors("Program::attach");
  return *this;
}

bool Program::link() {
  glLinkProgram(id_);
  locations_.clear();

  GLint ok = GL_FALSE, length = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
  std::string info(std::size_t(length > 0 ? length : 0), '\0');
  if (length > 0) glGetProgramInfoLog(id_, length, nullptr, info.data());
  while (!info.empty() && (info.back() == '\0' || info.back() == '\n')) info.pop_back();

  GLint count = 0;
  glGetProgramiv(id_, GL_ATTACHED_SHADERS, &count);
  std::vector<GLuint> shaders(std::size_t(count > 0 ? count : 0));
  if (count > 0) glGetAttachedShaders(id_, count, nullptr, shaders.data());
  for (GLuint s : shaders) glDetachShader(id_, s);

  std::string header = "program \"" + name_ + "\"";
  if (!ok) {
    log_ = header + " failed to link:\n" + info;
    logMessage(LogLevel::Error, log_);
  } else if (!info.empty()) {
    log_ = header + " linked with warnings:\n" + info;
    logMessage(LogLevel::Warning, log_);
  } else {
    log_.clear();
  }
  maybeCheckErrors("Program::link");
  return ok == GL_TRUE;
}

void Program::use() const {
  glUseProgram(id_);
  maybeCheckErrors("Program::use");
}

GLint Program::uniformLocation(std::string_view name) const {
  if (auto it = locations_.find(name); it != locations_.end()) return it->second;
  std::string key(name);
  GLint location = glGetUniformLocation(id_, key.c_str());
  locations_.emplace(std::move(key), location);
  return location;
}

Program& Program::setUniform(GLint location, float v) {
  glProgramUniform1f(id_, location, v);
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, int v) {
  glProgramUniform1i(id_, location, v);
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, unsigned v) {
  glProgramUniform1ui(id_, location, v);
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::vec2& v) {
  glProgramUniform2fv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::vec3& v) {
  glProgramUniform3fv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::vec4& v) {
  glProgramUniform4fv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::ivec2& v) {
  glProgramUniform2iv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::ivec3& v) {
  glProgramUniform3iv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::ivec4& v) {
  glProgramUniform4iv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::uvec2& v) {
  glProgramUniform2uiv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::uvec3& v) {
  glProgramUniform3uiv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::uvec4& v) {
  glProgramUniform4uiv(id_, location, 1, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::mat3& v) {
  glProgramUniformMatrix3fv(id_, location, 1, GL_FALSE, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

Program& Program::setUniform(GLint location, const glm::mat4& v) {
  glProgramUniformMatrix4fv(id_, location, 1, GL_FALSE, glm::value_ptr(v));
  maybeCheckErrors("Program::setUniform");
  return *this;
}

void Program::dispatch(GLuint x, GLuint y, GLuint z) const {
  glUseProgram(id_);
  glDispatchCompute(x, y, z);
  maybeCheckErrors("Program::dispatch");
}

void Program::dispatchItems(GLuint items, GLuint groupSize) const {
  const GLuint groups = groupsFor(items, groupSize);
  if (groups == 0) return;
  const GLuint x = std::min<GLuint>(groups, 65535u), y = (groups + x - 1) / x;
  if (!pass_profile::enabled()) {
    glUseProgram(id_);
    glDispatchCompute(x, y, 1);
    maybeCheckErrors("Program::dispatchItems");
    return;
  }
  pass_profile::run(name_, [&] { dispatch(x, y); });
}

void Program::dispatchIndirect(GLuint args, GLintptr offset) const {
  pass_profile::run(name_, [&] {
    glUseProgram(id_);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, args);
    glDispatchComputeIndirect(offset);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    maybeCheckErrors("Program::dispatchIndirect");
  });
}

std::array<GLint, 3> Program::workGroupSize() const {
  std::array<GLint, 3> size{0, 0, 0};
  glGetProgramiv(id_, GL_COMPUTE_WORK_GROUP_SIZE, size.data());
  maybeCheckErrors("Program::workGroupSize");
  return size;
}

}  // namespace csm::gl
