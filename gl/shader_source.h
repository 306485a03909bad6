#pragma once
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gl/enums.h"
#include "gl/program.h"

namespace csm::gl {

// The text of a shader file, by its path relative to shaders/ ("sim/predict.comp").
// When a shader directory is set (setShaderDirectory, or the CSM_SHADER_DIR environment
// variable) and holds the file, it is read from disk, for hot reload; otherwise the copy
// compiled into the binary is used. nullopt when neither has it.
std::optional<std::string> shaderSource(std::string_view relPath);

// An empty path goes back to embedded files only (unless CSM_SHADER_DIR is set).
void setShaderDirectory(const std::filesystem::path& dir);
std::filesystem::path shaderDirectory();

// Every embedded path, sorted.
std::vector<std::string> embeddedShaderPaths();

// A file with its `#include "x.glsl"` lines (paths relative to shaders/) replaced by the
// files' text, recursively.
struct ExpandedSource {
  std::string text;
  // The files in order of first inclusion, files[0] the one asked for; file k's lines are
  // numbered from k * kLinesPerFile + 1 by `#line`. Pass to Shader::setFileNames so
  // compile errors name the file and its line.
  std::vector<std::string> files;
  // A `#version` line at the top of the main file is moved here (without it, "") so the
  // caller can put it first, before the defines.
  std::string version;
};
// nullopt, with the reason in `error`, when a file is missing or includes itself.
std::optional<ExpandedSource> expandIncludes(std::string_view relPath,
                                             std::string* error = nullptr);

struct StageSource {
  StageSource(GLenum stage, std::string path) : stage(stage), path(std::move(path)) {}
  StageSource(ShaderStage stage, std::string path) : stage(GLenum(stage)), path(std::move(path)) {}
  GLenum stage;      // GL_COMPUTE_SHADER, GL_VERTEX_SHADER, ...
  std::string path;  // relative to shaders/
};
struct Define {
  std::string name;
  std::string value;  // may be empty
};

// Used when a file has no `#version` line of its own.
inline constexpr std::string_view kDefaultGlslVersion = "#version 430 core";

// Loads, expands, compiles and links. Each stage gets the `#version` line, then one string
// per define, then the expanded file. On failure returns nullopt and leaves the full log
// in `log` (and logs it), so a hot reload can keep its old program and show why; on success
// `log` holds any warnings.
std::optional<Program> buildProgram(std::string_view name, const std::vector<StageSource>& stages,
                                    const std::vector<Define>& defines = {},
                                    std::string* log = nullptr);
inline std::optional<Program> buildProgram(std::string_view name,
                                           std::initializer_list<StageSource> stages,
                                           const std::vector<Define>& defines = {},
                                           std::string* log = nullptr) {
  return buildProgram(name, std::vector<StageSource>(stages), defines, log);
}

}  // namespace csm::gl
