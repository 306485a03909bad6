#pragma once
#include <string>
#include <vector>

#include "gl/gl.h"

namespace csm::gl {

// One shader stage, compiled from several source strings: typically the `#version` line,
// the `#define`s, then the file's text, each a separate string (Dear ImGui's
// imgui_impl_opengl3.cpp does the same), so the file never needs editing per variant.
// Move-only.
class Shader {
 public:
  explicit Shader(NoCreateT) noexcept {}
  // `name` (usually the file path) prefixes every log line about this shader.
  Shader(GLenum stage, std::string name);
  ~Shader();
  Shader(const Shader&) = delete;
  Shader& operator=(const Shader&) = delete;
  Shader(Shader&& other) noexcept;
  Shader& operator=(Shader&& other) noexcept;

  static Shader wrap(GLuint id, std::string name = {});  // takes ownership
  GLuint release() noexcept;

  Shader& addSource(std::string source);
  // Names of the files in an include expansion (ExpandedSource::files), so the info log's
  // "N:line" becomes "file:line"; see kLinesPerFile.
  Shader& setFileNames(std::vector<std::string> names);

  // Compiles the sources added so far. On failure logs, and keeps in log(), the whole info
  // log prefixed with the shader's name and stage (Magnum's Shader::checkCompile()).
  bool compile();
  const std::string& log() const { return log_; }

  GLuint id() const { return id_; }
  GLenum stage() const { return stage_; }
  const std::string& name() const { return name_; }

  static const char* stageName(GLenum stage);

 private:
  GLuint id_ = 0;
  GLenum stage_ = 0;
  std::string name_;
  std::vector<std::string> sources_;
  std::vector<std::string> fileNames_;
  std::string log_;
};

// How included files are told apart in compiler messages. GLSL's `#line line source` takes a
// number, not a name (GLSL 4.60 §3.4), and Mesa drops the source number from many messages
// while keeping the line right. So file k of an expansion is numbered from line
// k * kLinesPerFile + 1 (and source k): the line alone says which file it was.
inline constexpr int kLinesPerFile = 100000;

// Rewrites "N:L" (Mesa, AMD, Intel) and "N(L)" (NVIDIA) at the start of info-log lines into
// "names[k]:line", with k = L / kLinesPerFile and line = L % kLinesPerFile: one form whatever
// the driver, for editors and for tests that look for "file:line".
// Exposed for tests.
// Whether a compile's info log holds nothing but headings and rules (NVIDIA's "Compute info"
// over a line of dashes after a clean compile): not a warning. Exposed for tests.
bool saysNothing(const std::string& infoLog);

std::string nameSourceStrings(const std::string& infoLog, const std::vector<std::string>& names);

}  // namespace csm::gl
