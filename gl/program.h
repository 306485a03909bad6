#pragma once
#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "gl/gl.h"

namespace csm::gl {

class Shader;

// A linked program. Uniform setters use glProgramUniform* (GL 4.1), so they work without
// use(); a name that the linker removed has location -1, which GL ignores. Move-only.
class Program {
 public:
  explicit Program(NoCreateT) noexcept {}
  explicit Program(std::string name = {});
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;

  static Program wrap(GLuint id, std::string name = {});  // takes ownership
  GLuint release() noexcept;

  Program& attach(const Shader& shader);
  // Links and detaches the shaders (they may be deleted now). On failure logs, and keeps in
  // log(), the whole info log prefixed with the program's name.
  bool link();
  const std::string& log() const { return log_; }

  GLuint id() const { return id_; }
  const std::string& name() const { return name_; }
  void use() const;

  // Cached per name; -1 when the program has no such active uniform.
  GLint uniformLocation(std::string_view name) const;

  Program& setUniform(GLint location, float v);
  Program& setUniform(GLint location, int v);
  Program& setUniform(GLint location, unsigned v);
  Program& setUniform(GLint location, bool v) { return setUniform(location, int(v)); }
  Program& setUniform(GLint location, const glm::vec2& v);
  Program& setUniform(GLint location, const glm::vec3& v);
  Program& setUniform(GLint location, const glm::vec4& v);
  Program& setUniform(GLint location, const glm::ivec2& v);
  Program& setUniform(GLint location, const glm::ivec3& v);
  Program& setUniform(GLint location, const glm::ivec4& v);
  Program& setUniform(GLint location, const glm::uvec2& v);
  Program& setUniform(GLint location, const glm::uvec3& v);
  Program& setUniform(GLint location, const glm::uvec4& v);
  Program& setUniform(GLint location, const glm::mat3& v);
  Program& setUniform(GLint location, const glm::mat4& v);
  template <class T>
  Program& setUniform(std::string_view name, const T& v) {
    return setUniform(uniformLocation(name), v);
  }

  // use() and glDispatchCompute. Counts are work groups, not invocations; see groupsFor().
  void dispatch(GLuint x, GLuint y = 1, GLuint z = 1) const;
  // Enough groups of `groupSize` for `items` invocations (none for 0): beyond GL 4.3's 65,535
  // groups a dimension, a 2D grid of groups that the shader flattens (globalIndex in
  // shaders/sim/common.glsl, invocationIndex in shaders/render/hair_compute.glsl). The one
  // dispatch of a count of items, the solver's and the renderer's; timed under the program's
  // name by the pass profile (gl/pass_profile.h).
  void dispatchItems(GLuint items, GLuint groupSize) const;
  // use() and glDispatchComputeIndirect with the work group counts (three GLuints) at
  // `offset` in buffer `args`; timed by the pass profile as dispatchItems is.
  void dispatchIndirect(GLuint args, GLintptr offset) const;
  // local_size_x/y/z of a compute program.
  std::array<GLint, 3> workGroupSize() const;
  // Work groups needed to cover `count` items with groups of `groupSize`.
  static GLuint groupsFor(GLuint count, GLuint groupSize) {
    return (count + groupSize - 1) / groupSize;
  }

 private:
  GLuint id_ = 0;
  std::string name_;
  std::string log_;
  mutable std::map<std::string, GLint, std::less<>> locations_;
};

}  // namespace csm::gl
