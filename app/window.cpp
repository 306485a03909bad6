#include "app/window.h"

#include <cstdlib>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace csm {
namespace {

// GLFW reports errors through a callback; keep the last one so create() can say why.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int code, const char* description) {
  lastGlfwError() = description ? description : ("GLFW error " + std::to_string(code));
}

const char* kNoDisplayAdvice =
    "Run with --headless to simulate and render without a window (add --out DIR for "
    "images), or start a display, e.g. xvfb-run -a csmhair ...";

void coreContextHints(bool debug) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
}

// The context of a hidden window, for a thread other than the main one.
class SharedWindowContext final : public gl::Context {
 public:
  SharedWindowContext(GLFWwindow* window, const gl::Context& parent) : window_(window) {
    copyInfo(parent, parent.platform() + ", shared");
  }
  ~SharedWindowContext() override { glfwDestroyWindow(window_); }
  bool makeCurrent() override {
    glfwMakeContextCurrent(window_);
    return glfwGetCurrentContext() == window_;
  }
  void releaseCurrent() override {
    if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
  }

 private:
  GLFWwindow* window_;
};

// Input callbacks that only note the time. Installed before Dear ImGui's, which chain to
// them (imgui_impl_glfw.cpp keeps the previous callbacks and calls them).
void noteInput(GLFWwindow* w) {
  if (auto* window = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w))) window->noteInput();
}
void onCursor(GLFWwindow* w, double, double) {
  noteInput(w);
}
void onButton(GLFWwindow* w, int, int, int) {
  noteInput(w);
}
void onScroll(GLFWwindow* w, double, double) {
  noteInput(w);
}
void onKey(GLFWwindow* w, int, int, int, int) {
  noteInput(w);
}
void onChar(GLFWwindow* w, unsigned) {
  noteInput(w);
}

}  // namespace

std::unique_ptr<GlfwWindow> GlfwWindow::create(const Options& options, std::string* error) {
  glfwSetErrorCallback(onGlfwError);
  lastGlfwError().clear();
  if (!glfwInit()) {
    if (error) {
      const char* display = std::getenv("DISPLAY");
      const char* wayland = std::getenv("WAYLAND_DISPLAY");
      const bool none = (!display || !*display) && (!wayland || !*wayland);
      *error = std::string(none ? "no display to open a window on" : "cannot open a window") +
               " (" + (lastGlfwError().empty() ? "glfwInit failed" : lastGlfwError()) + "). " +
               kNoDisplayAdvice;
    }
    return nullptr;
  }
  glfwDefaultWindowHints();
  coreContextHints(options.debug);
  // The renderer multisamples into its own framebuffer; the window's stays plain so that a
  // screenshot reads exactly what is shown.
  glfwWindowHint(GLFW_SAMPLES, 0);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!window) {
    if (error)
      *error =
          "cannot create a window with an OpenGL 4.3 core context (" +
          (lastGlfwError().empty() ? std::string("glfwCreateWindow failed") : lastGlfwError()) +
          "). The simulation needs compute shaders (GL 4.3); Mesa's llvmpipe provides them "
          "where there is no GPU. " +
          kNoDisplayAdvice;
    glfwTerminate();
    return nullptr;
  }
  std::unique_ptr<GlfwWindow> w(new GlfwWindow());
  w->window_ = window;
  w->debug_ = options.debug;
  glfwSetWindowUserPointer(window, w.get());
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetMouseButtonCallback(window, onButton);
  glfwSetScrollCallback(window, onScroll);
  glfwSetKeyCallback(window, onKey);
  glfwSetCharCallback(window, onChar);
  glfwMakeContextCurrent(window);
  w->setVsync(options.vsync);
  w->setInfo("GLFW window");
  return w;
}

GlfwWindow::~GlfwWindow() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::makeCurrent() {
  glfwMakeContextCurrent(window_);
  return glfwGetCurrentContext() == window_;
}

void GlfwWindow::releaseCurrent() {
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
}

std::unique_ptr<gl::Context> GlfwWindow::createShared(std::string* error) {
  glfwDefaultWindowHints();
  coreContextHints(debug_);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  lastGlfwError().clear();
  GLFWwindow* hidden = glfwCreateWindow(1, 1, "csmhair simulation", nullptr, window_);
  if (!hidden) {
    if (error)
      *error =
          "cannot create a shared context (" +
          (lastGlfwError().empty() ? std::string("glfwCreateWindow failed") : lastGlfwError()) +
          ")";
    return nullptr;
  }
  return std::make_unique<SharedWindowContext>(hidden, *this);
}

bool GlfwWindow::shouldClose() const {
  return glfwWindowShouldClose(window_);
}

void GlfwWindow::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::swapBuffers() {
  glfwSwapBuffers(window_);
}

void GlfwWindow::setVsync(bool on) {
  vsync_ = on;
  glfwSwapInterval(on ? 1 : 0);
}

void GlfwWindow::setTitle(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

WindowSize GlfwWindow::framebufferSize() const {
  WindowSize s;
  glfwGetFramebufferSize(window_, &s.width, &s.height);
  return s;
}

}  // namespace csm
