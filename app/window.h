// The desktop window: a GLFW window with a GL 4.3+ core context. It derives from
// gl::Context, so everything in render/ and sim/gpu works in it as in the headless context.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "gl/context.h"

struct GLFWwindow;

namespace csm {

struct WindowSize {
  int width = 0, height = 0;
};

class GlfwWindow final : public gl::Context {
 public:
  struct Options {
    int width = 1280, height = 720;  // screen coordinates
    std::string title = "csmhair";
    bool vsync = true;
    bool debug = false;  // a debug context, for richer KHR_debug messages
  };

  // Null when there is no display or no GL 4.3 core context; `error` then says which, and
  // what to do instead. The context is current on return. One window per process.
  static std::unique_ptr<GlfwWindow> create(const Options& options, std::string* error);
  ~GlfwWindow() override;

  bool makeCurrent() override;
  void releaseCurrent() override;
  // A hidden 1x1 window whose context shares this one's objects (buffers, textures, programs,
  // sync objects; not vertex arrays, framebuffers or queries): the simulation thread's,
  // current nowhere on return. Call on the main thread (GLFW makes windows there only), and
  // destroy it there too, after the thread using it has released it.
  std::unique_ptr<gl::Context> createShared(std::string* error);

  GLFWwindow* handle() const { return window_; }
  bool shouldClose() const;
  void requestClose();
  void swapBuffers();
  void setVsync(bool on);
  bool vsync() const { return vsync_; }
  void setTitle(const std::string& title);
  // The default framebuffer's size in pixels (differs from the window's on HiDPI screens).
  WindowSize framebufferSize() const;
  // When the user last moved the mouse, clicked, scrolled or typed in the window (input
  // seen by glfwPollEvents or glfwWaitEvents*): the main loop runs at full rate after it.
  std::chrono::steady_clock::time_point lastInput() const { return lastInput_; }
  void noteInput() { lastInput_ = std::chrono::steady_clock::now(); }

 private:
  GlfwWindow() = default;
  GLFWwindow* window_ = nullptr;
  bool vsync_ = true;
  bool debug_ = false;
  std::chrono::steady_clock::time_point lastInput_{};
};

}  // namespace csm
