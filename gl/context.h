#pragma once
#include <memory>
#include <string>

namespace csm::gl {

// A GL 4.3+ core context. The wrappers in gl use whichever context is current and
// never ask which kind it is, so the GLFW window only has to derive from this.
class Context {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Makes the context current on the calling thread.
  virtual bool makeCurrent() = 0;
  // Makes no context current on the calling thread, if this one is (before another thread
  // takes it, or before it is destroyed on another thread).
  virtual void releaseCurrent() = 0;

  // GL_RENDERER and GL_VERSION, read when the context was made.
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  // How the context was made, e.g. "EGL device 1 /dev/dri/renderD128 (NVIDIA) CUDA 0",
  // "EGL surfaceless platform", "GLFW window".
  const std::string& platform() const { return platform_; }

 protected:
  Context() = default;
  // Reads renderer and version from the current context.
  void setInfo(std::string platform);
  // Takes renderer and version from the context this one shares with.
  void copyInfo(const Context& from, std::string platform);

 private:
  std::string renderer_, version_, platform_;
};

// An offscreen context with no window and no surface, through EGL. Tried in this order:
//  1. EGL_EXT_platform_device: the GPUs EGL enumerates, NVIDIA's first, then other DRM
//     devices (polyscope's EGL backend also picks among eglQueryDevicesEXT's devices);
//  2. EGL_MESA_platform_surfaceless: Mesa's driver for the machine (llvmpipe without a GPU);
//  3. software devices of EGL_EXT_platform_device;
//  4. EGL_DEFAULT_DISPLAY.
// CSM_EGL_PLATFORM=device|surfaceless|default in the environment allows only that path
// (device then includes software devices). CSM_EGL_DEVICE=N|NAME takes that device of path 1
// or 3 and no other: N is the CUDA device index where the driver reports one (NVIDIA's, as
// nvidia-smi numbers them), else the place in EGL's order; NAME is matched against the labels
// ("/dev/dri/renderD129", "NVIDIA"); a device that does not exist is an error listing those
// that do. Draw into a Framebuffer: there is no default one.
class HeadlessContext final : public Context {
 public:
  struct Options {
    bool debug = false;  // a debug context, for richer KHR_debug messages
  };

  // nullptr when no GL 4.3 core context can be made; `error` then says what each path
  // lacked and what to install. The context is current on return.
  static std::unique_ptr<HeadlessContext> create(std::string* error = nullptr);
  static std::unique_ptr<HeadlessContext> create(const Options& options,
                                                 std::string* error = nullptr);
  ~HeadlessContext() override;

  bool makeCurrent() override;
  void releaseCurrent() override;

 private:
  HeadlessContext() = default;
  // EGLDisplay and EGLContext, kept as void* so this header needs no EGL.
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace csm::gl
