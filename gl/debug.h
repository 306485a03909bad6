#pragma once
// Logging, glGetError checks behind a switch, and the KHR_debug message callback.
#include <functional>
#include <string_view>

namespace csm::gl {

enum class LogLevel { Info, Warning, Error };

// Where gl's messages go (shader logs, GL errors, debug output). The default
// writes to stderr; the viewer can route them to its log panel. Not thread-safe to
// change while another thread logs.
using LogSink = std::function<void(LogLevel, std::string_view)>;
void setLogSink(LogSink sink);  // an empty sink restores the default
void logMessage(LogLevel level, std::string_view message);

// glGetError after every wrapper operation costs a round trip into the driver, so it
// is off unless switched on here, by CSM_GL_ERROR_CHECKS in the environment ("1"/"0"),
// or by the CMake option CSM_GL_ERROR_CHECKS (Dear ImGui's GL_CALL, polyscope's
// enableRenderErrorChecks).
void setErrorChecks(bool enabled);
bool errorChecksEnabled();

// Drains glGetError and logs each error with `where`; returns true if there was none.
// Runs even when checks are switched off: call it where an error must be seen.
bool checkErrors(const char* where);

// The wrappers call this after each operation: free when checks are off.
inline void maybeCheckErrors(const char* where) {
  if (errorChecksEnabled()) checkErrors(where);
}

// Installs a KHR_debug (core in 4.3) callback that logs driver messages. Synchronous
// output makes a message arrive inside the call that caused it, so a breakpoint in the
// sink shows the culprit; it is slower. Notifications are dropped. Returns false where
// the context has no KHR_debug. Messages are richest in a debug context
// (HeadlessContext::Options::debug).
bool enableDebugOutput(bool synchronous = true);
void disableDebugOutput();

}  // namespace csm::gl

// Wraps a raw GL call with a check, for code outside the wrappers.
#define CSM_GL_CALL(call)                                                         \
  do {                                                                            \
    call;                                                                         \
    ::csm::gl::maybeCheckErrors(#call " at " __FILE__ ":" CSM_GL_STR_(__LINE__)); \
  } while (0)
#define CSM_GL_STR_(x) CSM_GL_STR2_(x)
#define CSM_GL_STR2_(x) #x
