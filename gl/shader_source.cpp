#include "gl/shader_source.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

#include "gl/debug.h"
#include "gl/embedded_shaders.h"
#include "gl/shader.h"

namespace csm::gl {
namespace {

std::mutex& dirMutex() {
  static std::mutex m;
  return m;
}
std::filesystem::path& explicitDir() {
  static std::filesystem::path dir;
  return dir;
}

std::string normalize(std::string_view path) {
  return std::filesystem::path(path).lexically_normal().generic_string();
}

std::optional<std::string> embeddedSource(std::string_view relPath) {
  for (std::size_t i = 0; i < embedded::kFileCount; ++i)
    if (relPath == embedded::kFiles[i].path)
      return std::string(reinterpret_cast<const char*>(embedded::kFiles[i].data),
                         embedded::kFiles[i].size);
  return std::nullopt;
}

std::string_view trimLeft(std::string_view s) {
  std::size_t i = s.find_first_not_of(" \t\r");
  return i == std::string_view::npos ? std::string_view{} : s.substr(i);
}

// If `line` is `#<directive> ...`, returns what follows the directive name.
std::optional<std::string_view> directive(std::string_view line, std::string_view name) {
  line = trimLeft(line);
  if (line.empty() || line[0] != '#') return std::nullopt;
  line = trimLeft(line.substr(1));
  if (line.substr(0, name.size()) != name) return std::nullopt;
  std::string_view rest = line.substr(name.size());
  if (!rest.empty() && rest[0] != ' ' && rest[0] != '\t' && rest[0] != '"') return std::nullopt;
  return trimLeft(rest);
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(text.substr(pos, end - pos));
    pos = end + 1;
  }
  return lines;
}

// Include expansion with a `#line` before and after every inserted file, so compiler
// messages can be traced to the file and line on disk (numbering: see kLinesPerFile).
struct Expander {
  ExpandedSource result;
  std::map<std::string, int> ids;
  std::vector<std::string> stack;
  std::string error;

  int idOf(const std::string& path) {
    auto [it, inserted] = ids.emplace(path, int(result.files.size()));
    if (inserted) result.files.push_back(path);
    return it->second;
  }

  bool expand(const std::string& path, const std::string& text, bool isMain) {
    int id = idOf(path);
    if (id >= std::numeric_limits<int>::max() / kLinesPerFile - 1) {
      error = path + ": too many included files";
      return false;
    }
    int base = id * kLinesPerFile;
    stack.push_back(path);
    result.text += "#line " + std::to_string(base + 1) + " " + std::to_string(id) + "\n";
    bool beforeCode = isMain;
    int lineNumber = 0;
    for (std::string_view line : splitLines(text)) {
      if (++lineNumber >= kLinesPerFile) {
        error = path + ": longer than " + std::to_string(kLinesPerFile) + " lines";
        return false;
      }
      if (beforeCode) {
        std::string_view t = trimLeft(line);
        if (directive(line, "version")) {
          // Hoisted; an empty line keeps the numbering.
          result.version = std::string(t);
          while (!result.version.empty() && result.version.back() == '\r')
            result.version.pop_back();
          result.text += "\n";
          beforeCode = false;
          continue;
        }
        if (!t.empty() && t.substr(0, 2) != "//") beforeCode = false;
      }
      std::optional<std::string_view> include = directive(line, "include");
      if (!include) {
        result.text.append(line);
        result.text += '\n';
        continue;
      }
      std::string where = path + ":" + std::to_string(lineNumber) + ": ";
      std::string_view arg = *include;
      std::size_t close = arg.size() > 1 && arg[0] == '"' ? arg.find('"', 1) : std::string::npos;
      if (close == std::string_view::npos) {
        error = where + "expected #include \"file\"";
        return false;
      }
      std::string child = normalize(arg.substr(1, close - 1));
      if (std::find(stack.begin(), stack.end(), child) != stack.end()) {
        error = where + "include cycle: ";
        for (const std::string& s : stack) error += s + " -> ";
        error += child;
        return false;
      }
      std::optional<std::string> childText = shaderSource(child);
      if (!childText) {
        error = where + "cannot find included file \"" + child + "\" under shaders/";
        return false;
      }
      if (!expand(child, *childText, false)) return false;
      result.text +=
          "#line " + std::to_string(base + lineNumber + 1) + " " + std::to_string(id) + "\n";
    }
    stack.pop_back();
    return true;
  }
};

}  // namespace

std::filesystem::path shaderDirectory() {
  {
    std::lock_guard lock(dirMutex());
    if (!explicitDir().empty()) return explicitDir();
  }
  if (const char* env = std::getenv("CSM_SHADER_DIR"); env && *env) return env;
  return {};
}

void setShaderDirectory(const std::filesystem::path& dir) {
  std::lock_guard lock(dirMutex());
  explicitDir() = dir;
}

std::optional<std::string> shaderSource(std::string_view relPath) {
  std::string path = normalize(relPath);
  if (std::filesystem::path dir = shaderDirectory(); !dir.empty()) {
    std::ifstream file(dir / path, std::ios::binary);
    if (file) {
      std::ostringstream text;
      text << file.rdbuf();
      return text.str();
    }
  }
  return embeddedSource(path);
}

std::vector<std::string> embeddedShaderPaths() {
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < embedded::kFileCount; ++i)
    paths.emplace_back(embedded::kFiles[i].path);
  std::sort(paths.begin(), paths.end());
  return paths;
}

std::optional<ExpandedSource> expandIncludes(std::string_view relPath, std::string* error) {
  std::string path = normalize(relPath);
  std::optional<std::string> text = shaderSource(path);
  if (!text) {
    if (error) *error = "cannot find shader \"" + path + "\" under shaders/";
    return std::nullopt;
  }
  Expander expander;
  if (!expander.expand(path, *text, true)) {
    if (error) *error = expander.error;
    return std::nullopt;
  }
  return std::move(expander.result);
}

std::optional<Program> buildProgram(std::string_view name, const std::vector<StageSource>& stages,
                                    const std::vector<Define>& defines, std::string* log) {
  std::string messages;
  auto fail = [&](std::string message) -> std::optional<Program> {
    if (!messages.empty()) messages += '\n';
    messages += message;
    if (log) *log = messages;
    return std::nullopt;
  };

  std::vector<Shader> shaders;
  for (const StageSource& stage : stages) {
    std::string error;
    std::optional<ExpandedSource> source = expandIncludes(stage.path, &error);
    if (!source) {
      std::string message = "program \"" + std::string(name) + "\": " + error;
      logMessage(LogLevel::Error, message);
      return fail(message);
    }
    Shader shader(stage.stage, stage.path);
    shader.setFileNames(source->files);
    shader.addSource(
        (source->version.empty() ? std::string(kDefaultGlslVersion) : source->version) + "\n");
    for (const Define& d : defines) shader.addSource("#define " + d.name + " " + d.value + "\n");
    shader.addSource(std::move(source->text));
    bool ok = shader.compile();
    if (!ok) return fail(shader.log());
    if (!shader.log().empty()) messages += shader.log() + "\n";
    shaders.push_back(std::move(shader));
  }

  Program program{std::string(name)};
  for (const Shader& s : shaders) program.attach(s);
  if (!program.link()) return fail(program.log());
  if (!program.log().empty()) messages += program.log();
  while (!messages.empty() && messages.back() == '\n') messages.pop_back();
  if (log) *log = messages;
  return program;
}

}  // namespace csm::gl
