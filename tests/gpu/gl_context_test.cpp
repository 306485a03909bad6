// The headless context, capabilities, error checks and debug output.
#include <cstdlib>
#include <string>

#include "gl/caps.h"
#include "gl/debug.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, hadOld_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (hadOld_)
      setenv(name_, old_.c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::string old_;
  bool hadOld_ = false;
};

}  // namespace

TEST_CASE("GL: the shared headless context is GL 4.3+ core with compute", "[gl][context][quick]") {
  gl::HeadlessContext& context = test::glContext();
  INFO("platform: " << context.platform() << ", renderer: " << context.renderer());
  CHECK_FALSE(context.renderer().empty());
  CHECK_FALSE(context.version().empty());
  CHECK(context.platform().rfind("EGL ", 0) == 0);

  gl::Caps caps = gl::queryCaps();
  INFO(caps.summary());
  CHECK(caps.major * 10 + caps.minor >= 43);
  CHECK(caps.renderer == context.renderer());
  // GL 4.3's guaranteed minimums (GL 4.6 spec, tables 23.64, 23.67).
  CHECK(caps.maxShaderStorageBlockSize >= (GLint64(1) << 24));
  CHECK(caps.maxTextureBufferSize >= 65536);  // GL 4.3, table 23.53
  CHECK(caps.maxComputeWorkGroupInvocations >= 1024);
  CHECK(caps.maxComputeWorkGroupSize[0] >= 1024);
  CHECK(caps.maxComputeWorkGroupCount[0] >= 65535);
  CHECK(caps.maxComputeSharedMemorySize >= 32768);
  CHECK(caps.timerQuery);
  CHECK(caps.khrDebug);
}

TEST_CASE("GL: CSM_EGL_PLATFORM picks or rejects a path", "[gl][context][quick]") {
  test::glContext();
  SECTION("an unknown value is an error that says so") {
    ScopedEnv env("CSM_EGL_PLATFORM", "vulkan");
    std::string error;
    CHECK(gl::HeadlessContext::create(&error) == nullptr);
    CHECK(error.find("CSM_EGL_PLATFORM=vulkan") != std::string::npos);
  }
  SECTION("each path either makes a context or says what is missing and what to install") {
    for (const char* path : {"device", "surfaceless", "default"}) {
      ScopedEnv env("CSM_EGL_PLATFORM", path);
      std::string error;
      auto context = gl::HeadlessContext::create(&error);
      INFO(path << ": " << (context ? context->platform() : error));
      if (context) {
        CHECK(context->version().find("4.") != std::string::npos);
        if (std::string(path) == "surfaceless")
          CHECK(context->platform() == "EGL surfaceless platform");
        if (std::string(path) == "device") CHECK(context->platform().rfind("EGL device", 0) == 0);
      } else {
        CHECK(error.find("libegl-mesa0") != std::string::npos);
        CHECK(error.find("  - ") != std::string::npos);
      }
    }
  }
  // The shared context must survive other contexts coming and going on its display.
  test::glContext();
  CHECK(gl::checkErrors("after other contexts"));
  CHECK(glGetString(GL_RENDERER) != nullptr);
}

TEST_CASE("GL: error checks and KHR_debug output reach the log", "[gl][debug][quick]") {
  test::glContext();
  test::LogCapture log;
  REQUIRE(gl::errorChecksEnabled());
  // 0xdeadbeef was never generated: binding it is GL_INVALID_OPERATION in core profile.
  glBindBuffer(GL_ARRAY_BUFFER, 0xdeadbeef);
  CHECK_FALSE(gl::checkErrors("binding a bogus buffer"));
  CHECK(log.text().find("GL_INVALID_OPERATION in binding a bogus buffer") != std::string::npos);
  // The synchronous debug callback reported the same error as it happened.
  CHECK(log.text().find("GL debug (api, error") != std::string::npos);
  CHECK(gl::checkErrors("nothing left"));

  // The macro for raw calls names the call and where it was made.
  CSM_GL_CALL(glBindBuffer(GL_ARRAY_BUFFER, 0xdeadbeef));
  CHECK(log.text().find("GL_INVALID_OPERATION in glBindBuffer(GL_ARRAY_BUFFER, 0xdeadbeef) at ") !=
        std::string::npos);
  CHECK(log.text().find("gl_context_test.cpp:") != std::string::npos);
  CHECK(gl::checkErrors("nothing left"));
}
