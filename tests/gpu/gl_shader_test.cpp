// Shader embedding, #include expansion, compile errors, and compute dispatch.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/shader.h"
#include "gl/shader_source.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::vector<float> runDouble(gl::Program& program, std::vector<float> values) {
  gl::Buffer buffer(values);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.setUniform("count", unsigned(values.size()));
  program.dispatch(gl::Program::groupsFor(GLuint(values.size()), 64));
  gl::memoryBarrier(gl::Barrier::BufferUpdate);
  return buffer.download<float>();
}

// A shader directory in the build's temporary space, removed afterwards.
struct TempShaderDir {
  std::filesystem::path path;
  TempShaderDir() {
    path = std::filesystem::temp_directory_path() /
           ("csm_gl_shader_test_" +
            std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::create_directories(path / "test");
    gl::setShaderDirectory(path);
  }
  ~TempShaderDir() {
    gl::setShaderDirectory({});
    std::filesystem::remove_all(path);
  }
  void write(const std::string& rel, const std::string& text) {
    std::ofstream(path / rel, std::ios::binary) << text;
  }
};

}  // namespace

TEST_CASE("GL: shader files are embedded", "[gl][shader][quick]") {
  std::vector<std::string> paths = gl::embeddedShaderPaths();
  CHECK(std::is_sorted(paths.begin(), paths.end()));
  CHECK(std::count(paths.begin(), paths.end(), "test/double.comp") == 1);
  CHECK(std::count(paths.begin(), paths.end(), "CMakeLists.txt") == 0);

  std::optional<std::string> text = gl::shaderSource("test/common.glsl");
  REQUIRE(text);
  CHECK(contains(*text, "float scale(float x)"));
  CHECK(gl::shaderSource("./test/../test/common.glsl") == text);  // normalized
  CHECK_FALSE(gl::shaderSource("test/no_such_file.glsl"));
}

#ifdef CSM_SOURCE_DIR
TEST_CASE("GL: embedded shaders are byte for byte the files under shaders/",
          "[gl][shader][quick]") {
  REQUIRE(gl::shaderDirectory().empty());  // else shaderSource reads the disk
  for (const std::string& path : gl::embeddedShaderPaths()) {
    INFO(path);
    std::ifstream file(std::filesystem::path(CSM_SOURCE_DIR) / "shaders" / path, std::ios::binary);
    REQUIRE(file);
    std::string disk((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    CHECK(gl::shaderSource(path) == disk);
  }
}
#endif

TEST_CASE("GL: a compute shader from shaders/test doubles a buffer",
          "[gl][shader][compute][quick]") {
  test::glContext();
  std::string log;
  std::optional<gl::Program> program =
      gl::buildProgram("double", {{GL_COMPUTE_SHADER, "test/double.comp"}}, {}, &log);
  INFO(log);
  REQUIRE(program);
  CHECK(program->workGroupSize() == std::array<GLint, 3>{64, 1, 1});

  std::vector<float> values(1000);  // not a multiple of the group size
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = float(i) - 300.5f;
  std::vector<float> doubled = runDouble(*program, values);
  REQUIRE(doubled.size() == values.size());
  for (std::size_t i = 0; i < values.size(); ++i) REQUIRE(doubled[i] == 2.0f * values[i]);

  SECTION("defines are prepended as their own source strings") {
    std::optional<gl::Program> triple = gl::buildProgram(
        "triple", {{GL_COMPUTE_SHADER, "test/double.comp"}}, {{"FACTOR", "3.0"}}, &log);
    REQUIRE(triple);
    CHECK(runDouble(*triple, {1.0f, -2.0f}) == std::vector<float>{3.0f, -6.0f});
  }
  CHECK(gl::checkErrors("compute test"));
}

TEST_CASE("GL: a shader with a syntax error fails and the log names the file",
          "[gl][shader][quick]") {
  test::glContext();
  test::LogCapture captured;

  SECTION("Shader::compile") {
    gl::Shader shader(GL_COMPUTE_SHADER, "test/syntax_error.comp");
    shader.addSource("#version 430 core\n").addSource(*gl::shaderSource("test/syntax_error.comp"));
    CHECK_FALSE(shader.compile());
    INFO(shader.log());
    CHECK(contains(shader.log(), "shader \"test/syntax_error.comp\" (compute) failed to compile"));
    CHECK(contains(shader.log(), "error"));
    CHECK(contains(captured.text(), shader.log()));  // and it was logged
  }
  SECTION("buildProgram") {
    std::string log;
    CHECK_FALSE(gl::buildProgram("bad", {{GL_COMPUTE_SHADER, "test/syntax_error.comp"}}, {}, &log));
    INFO(log);
    // The include expansion's #line makes the compiler's line that of the file: 5.
    CHECK(contains(log, "test/syntax_error.comp:5"));
    CHECK(contains(log, "(compute) failed to compile"));
  }
  CHECK(captured.errors() >= 1);
}

TEST_CASE("GL: #include expansion", "[gl][shader][include][quick]") {
  SECTION("files are numbered for #line, the main file first") {
    std::string error;
    auto expanded = gl::expandIncludes("test/double.comp", &error);
    REQUIRE(expanded);
    CHECK(expanded->files == std::vector<std::string>{"test/double.comp", "test/common.glsl"});
    CHECK(expanded->text.rfind("#line 1 0\n", 0) == 0);
    CHECK(contains(expanded->text, "#line 100001 1\n"));  // test/common.glsl from its line 1
    CHECK(contains(expanded->text, "float scale(float x)"));
    CHECK(contains(expanded->text, "#line 4 0\n"));  // back in double.comp after line 3
    CHECK_FALSE(contains(expanded->text, "#include"));
    CHECK(expanded->version.empty());
  }
  SECTION("a #version line is hoisted, keeping the line count") {
    auto expanded = gl::expandIncludes("test/solid.frag");
    REQUIRE(expanded);
    CHECK(expanded->version == "#version 430 core");
    CHECK(expanded->text.rfind("#line 1 0\n\n//", 0) == 0);
  }
  SECTION("cycles are rejected") {
    std::string error;
    CHECK_FALSE(gl::expandIncludes("test/cycle_a.glsl", &error));
    CHECK(contains(error,
                   "include cycle: test/cycle_a.glsl -> test/cycle_b.glsl -> test/cycle_a.glsl"));
  }
  SECTION("a missing file is an error naming the including line") {
    TempShaderDir dir;
    dir.write("test/missing_include.comp", "// x\n#include \"test/nope.glsl\"\n");
    std::string error;
    CHECK_FALSE(gl::expandIncludes("test/missing_include.comp", &error));
    CHECK(contains(error,
                   "test/missing_include.comp:2: cannot find included file \"test/nope.glsl\""));
  }
  SECTION("errors report the included file's line") {
    test::glContext();
    std::string log;
    CHECK_FALSE(
        gl::buildProgram("inc", {{GL_COMPUTE_SHADER, "test/include_error.comp"}}, {}, &log));
    INFO(log);
    // Mesa: "test/broken.glsl:4(13): error: `undefined_variable' undeclared"; NVIDIA:
    // "test/broken.glsl:4 : error C1503: undefined variable "undefined_variable"".
    CHECK(contains(log, "test/broken.glsl:4"));
    CHECK(contains(log, "undefined_variable"));
    CHECK_FALSE(contains(log, "test/include_error.comp:4"));
  }
  SECTION("and the including file's line after the include") {
    test::glContext();
    std::string log;
    CHECK_FALSE(gl::buildProgram("after", {{GL_COMPUTE_SHADER, "test/error_after_include.comp"}},
                                 {}, &log));
    INFO(log);
    CHECK(contains(log, "test/error_after_include.comp:7"));
  }
}

TEST_CASE("GL: info-log source numbers become file names for each vendor's format",
          "[gl][shader][quick]") {
  std::vector<std::string> names{"main.comp", "common.glsl"};
  CHECK(gl::nameSourceStrings("1:100004(12): error: x", names) == "common.glsl:4(12): error: x");
  // The line decides, as Mesa reports some errors with source 0.
  CHECK(gl::nameSourceStrings("0:100004(12): error: x", names) == "common.glsl:4(12): error: x");
  CHECK(gl::nameSourceStrings("0(7) : error C1008: y", names) == "main.comp:7 : error C1008: y");
  CHECK(gl::nameSourceStrings("1(100002) : warning C7050: v", names) ==
        "common.glsl:2 : warning C7050: v");
  CHECK(gl::nameSourceStrings("ERROR: 1:100003: z\nWARNING: 0:2: w", names) ==
        "ERROR: common.glsl:3: z\nWARNING: main.comp:2: w");
  CHECK(gl::nameSourceStrings("0:700001(1): out of range", names) == "0:700001(1): out of range");
  CHECK(gl::nameSourceStrings("no numbers", names) == "no numbers");
  CHECK(gl::saysNothing("Compute info\n------------\n"));
  CHECK(gl::saysNothing(""));
  CHECK_FALSE(gl::saysNothing("Compute info\n------------\n0(3) : warning C7050: x"));
  CHECK_FALSE(gl::saysNothing("main.comp:3: warning: unused"));
}

TEST_CASE(
    "GL: shaders load from a directory for hot reload and a failed reload keeps the old program",
    "[gl][shader][reload][quick]") {
  test::glContext();
  TempShaderDir dir;
  CHECK(gl::shaderDirectory() == dir.path);
  // Not on disk: falls back to the embedded copy.
  CHECK(gl::shaderSource("test/common.glsl") == gl::shaderSource("test/common.glsl"));
  REQUIRE(gl::shaderSource("test/common.glsl"));

  dir.write("test/common.glsl", "float scale(float x) { return 5.0 * x; }\n");
  CHECK(contains(*gl::shaderSource("test/common.glsl"), "5.0 * x"));
  std::string log;
  std::optional<gl::Program> program =
      gl::buildProgram("reload", {{GL_COMPUTE_SHADER, "test/double.comp"}}, {}, &log);
  REQUIRE(program);
  CHECK(runDouble(*program, {1.0f}) == std::vector<float>{5.0f});

  dir.write("test/common.glsl", "float scale(float x) { return 5.0 * ; }\n");
  std::optional<gl::Program> reloaded =
      gl::buildProgram("reload", {{GL_COMPUTE_SHADER, "test/double.comp"}}, {}, &log);
  CHECK_FALSE(reloaded);
  CHECK(contains(log, "test/common.glsl:1"));
  CHECK(runDouble(*program, {1.0f}) == std::vector<float>{5.0f});  // the old one still runs
}
