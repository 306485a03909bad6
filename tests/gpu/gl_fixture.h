#pragma once
// One headless GL context shared by every GPU test in the binary, as Magnum's *GLTest
// cases share one windowless context. It is made on first use and lives until exit.
#include <memory>
#include <string>
#include <string_view>

#include <catch2/catch.hpp>

#include "gl/context.h"
#include "gl/debug.h"

namespace csm::test {

// The shared context, current on the calling thread. REQUIREs that it could be made, so a
// machine without GL 4.3 fails each GPU test with the reason instead of crashing in GL.
// GL error checks and KHR_debug output are on, so driver complaints show in the test log.
inline gl::HeadlessContext& glContext() {
  struct Shared {
    std::string error;
    std::unique_ptr<gl::HeadlessContext> context;
    Shared() {
      context = gl::HeadlessContext::create(&error);
      if (context) {
        gl::setErrorChecks(true);
        gl::enableDebugOutput(true);
      }
    }
  };
  static Shared shared;
  INFO(shared.error);
  REQUIRE(shared.context != nullptr);
  REQUIRE(shared.context->makeCurrent());
  return *shared.context;
}

// Collects gl's log messages while alive, for tests that check what was logged.
class LogCapture {
 public:
  LogCapture() {
    gl::setLogSink([this](gl::LogLevel level, std::string_view message) {
      if (level == gl::LogLevel::Error) ++errors_;
      text_.append(message);
      text_ += '\n';
    });
  }
  ~LogCapture() { gl::setLogSink({}); }
  LogCapture(const LogCapture&) = delete;
  LogCapture& operator=(const LogCapture&) = delete;

  const std::string& text() const { return text_; }
  int errors() const { return errors_; }

 private:
  std::string text_;
  int errors_ = 0;
};

}  // namespace csm::test
