#include "gl/shader.h"

#include <cctype>
#include <utility>

#include "gl/debug.h"

namespace csm::gl {

Shader::Shader(GLenum stage, std::string name) : stage_(stage), name_(std::move(name)) {
  id_ = glCreateShader(stage);
  maybeCheckErrors("Shader::Shader");
}

Shader::~Shader() {
  if (id_) glDeleteShader(id_);
}

Shader::Shader(Shader&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      stage_(other.stage_),
      name_(std::move(other.name_)),
      sources_(std::move(other.sources_)),
      fileNames_(std::move(other.fileNames_)),
      log_(std::move(other.log_)) {}

Shader& Shader::operator=(Shader&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteShader(id_);
    id_ = std::exchange(other.id_, 0);
    stage_ = other.stage_;
    name_ = std::move(other.name_);
    sources_ = std::move(other.sources_);
    fileNames_ = std::move(other.fileNames_);
    log_ = std::move(other.log_);
  }
  return *this;
}

Shader Shader::wrap(GLuint id, std::string name) {
  Shader s{NoCreate};
  s.id_ = id;
  GLint type = 0;
  glGetShaderiv(id, GL_SHADER_TYPE, &type);
  s.stage_ = GLenum(type);
  s.name_ = std::move(name);
  return s;
}

GLuint Shader::release() noexcept {
  return std::exchange(id_, 0);
}

Shader& Shader::addSource(std::string source) {
  sources_.push_back(std::move(source));
  return *this;
}

Shader& Shader::setFileNames(std::vector<std::string> names) {
  fileNames_ = std::move(names);
  return *this;
}

bool Shader::compile() {
  std::vector<const GLchar*> strings;
  std::vector<GLint> lengths;
  for (const std::string& s : sources_) {
    strings.push_back(s.data());
    lengths.push_back(GLint(s.size()));
  }
  glShaderSource(id_, GLsizei(strings.size()), strings.data(), lengths.data());
  glCompileShader(id_);

  GLint ok = GL_FALSE, length = 0;
  glGetShaderiv(id_, GL_COMPILE_STATUS, &ok);
  glGetShaderiv(id_, GL_INFO_LOG_LENGTH, &length);
  std::string info(std::size_t(length > 0 ? length : 0), '\0');
  if (length > 0) glGetShaderInfoLog(id_, length, nullptr, info.data());
  while (!info.empty() && (info.back() == '\0' || info.back() == '\n')) info.pop_back();
  info = nameSourceStrings(info, fileNames_);
  if (saysNothing(info)) info.clear();

  std::string header = "shader \"" + name_ + "\" (" + stageName(stage_) + ")";
  if (!ok) {
    log_ = header + " failed to compile:\n" + info;
    logMessage(LogLevel::Error, log_);
  } else if (!info.empty()) {
    log_ = header + " compiled with warnings:\n" + info;
    logMessage(LogLevel::Warning, log_);
  } else {
    log_.clear();
  }
  maybeCheckErrors("Shader::compile");
  return ok == GL_TRUE;
}

const char* Shader::stageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    case GL_TESS_CONTROL_SHADER:
      return "tessellation control";
    case GL_TESS_EVALUATION_SHADER:
      return "tessellation evaluation";
    case GL_COMPUTE_SHADER:
      return "compute";
    default:
      return "unknown stage";
  }
}

bool saysNothing(const std::string& infoLog) {
  // NVIDIA's log of a clean compile: "Compute info\n------------\n" and nothing else.
  std::size_t pos = 0;
  while (pos < infoLog.size()) {
    std::size_t end = infoLog.find('\n', pos);
    if (end == std::string::npos) end = infoLog.size();
    const std::string line = infoLog.substr(pos, end - pos);
    const bool rule = line.find_first_not_of("- \r") == std::string::npos;
    const bool heading = line.size() > 5 && line.compare(line.size() - 5, 5, " info") == 0 &&
                         line.find(' ') == line.size() - 5;
    if (!rule && !heading) return false;
    pos = end + 1;
  }
  return true;
}

std::string nameSourceStrings(const std::string& infoLog, const std::vector<std::string>& names) {
  if (names.empty()) return infoLog;
  auto digitsEnd = [](const std::string& s, std::size_t i) {
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i;
  };
  std::string out;
  std::size_t pos = 0;
  while (pos < infoLog.size()) {
    std::size_t end = infoLog.find('\n', pos);
    if (end == std::string::npos) end = infoLog.size();
    std::string line = infoLog.substr(pos, end - pos);
    std::size_t start = 0;
    for (const char* prefix : {"ERROR: ", "WARNING: "})
      if (line.rfind(prefix, 0) == 0) start = std::char_traits<char>::length(prefix);
    // "N:L" or "N(L", then the line number's own end.
    std::size_t sourceEnd = digitsEnd(line, start);
    if (sourceEnd > start && sourceEnd < line.size() &&
        (line[sourceEnd] == ':' || line[sourceEnd] == '(')) {
      std::size_t lineEnd = digitsEnd(line, sourceEnd + 1);
      if (lineEnd > sourceEnd + 1 && lineEnd - sourceEnd < 10) {
        long l = std::stol(line.substr(sourceEnd + 1, lineEnd - sourceEnd - 1));
        std::size_t file = std::size_t(l / kLinesPerFile);
        // Always "name:line", the form editors jump to: NVIDIA's "N(L)" loses its brackets.
        std::size_t rest = lineEnd;
        if (line[sourceEnd] == '(' && rest < line.size() && line[rest] == ')') ++rest;
        if (file < names.size())
          line = line.substr(0, start) + names[file] + ':' + std::to_string(l % kLinesPerFile) +
                 line.substr(rest);
      }
    }
    out += line;
    if (end < infoLog.size()) out += '\n';
    pos = end + 1;
  }
  return out;
}

}  // namespace csm::gl
