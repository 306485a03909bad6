#include "gl/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

namespace csm::gl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default:
      return "EGL error " + std::to_string(e);
  }
}

// EGL returns the same EGLDisplay for the same platform and device, and eglTerminate
// would pull it from under any other context on it, so terminate only with the last one.
std::mutex& displayMutex() {
  static std::mutex m;
  return m;
}
std::map<EGLDisplay, int>& displayUsers() {
  static std::map<EGLDisplay, int> users;
  return users;
}
void retainDisplay(EGLDisplay d) {
  std::lock_guard lock(displayMutex());
  ++displayUsers()[d];
}
void releaseDisplay(EGLDisplay d) {
  std::lock_guard lock(displayMutex());
  auto it = displayUsers().find(d);
  if (it == displayUsers().end() || --it->second == 0) {
    if (it != displayUsers().end()) displayUsers().erase(it);
    eglTerminate(d);
  }
}

struct Device {
  EGLDeviceEXT handle;
  std::string label;
  int score;      // higher first: NVIDIA 3, other DRM GPU 2, other non-software 1, software 0
  int index;      // place in eglQueryDevicesEXT's order
  int cuda = -1;  // the CUDA device index, where the driver says it (EGL_NV_device_cuda)
};

std::vector<Device> enumerateDevices(std::string* note) {
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) {
    *note = "eglQueryDevicesEXT found no devices";
    return {};
  }
  std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(count));
  eglQueryDevicesEXT(count, handles.data(), &count);
  handles.resize(std::size_t(count));
  std::vector<Device> devices;
  for (EGLDeviceEXT h : handles) {
    int index = int(devices.size());
    const char* ext = eglQueryDeviceStringEXT(h, EGL_EXTENSIONS);
    std::string drm, vendor;
    if (hasExtension(ext, "EGL_EXT_device_drm"))
      if (const char* f = eglQueryDeviceStringEXT(h, EGL_DRM_DEVICE_FILE_EXT)) drm = f;
    if (hasExtension(ext, "EGL_EXT_device_query_name"))
      if (const char* v = eglQueryDeviceStringEXT(h, EGL_VENDOR)) vendor = v;
    bool software = hasExtension(ext, "EGL_MESA_device_software");
    bool nvidia =
        hasExtension(ext, "EGL_NV_device_cuda") || vendor.find("NVIDIA") != std::string::npos;
    if (nvidia && vendor.empty()) vendor = "NVIDIA";
    int cuda = -1;
    EGLAttrib value = 0;
    if (hasExtension(ext, "EGL_NV_device_cuda") &&
        eglQueryDeviceAttribEXT(h, EGL_CUDA_DEVICE_NV, &value))
      cuda = int(value);
    int score = software ? 0 : nvidia ? 3 : !drm.empty() ? 2 : 1;
    // "EGL device 1 /dev/dri/renderD129 (NVIDIA) CUDA 0"; a device with no DRM file (a GPU
    // passed into a virtual machine) has none to show.
    std::string label = "EGL device " + std::to_string(index) +
                        (software      ? std::string(" software")
                         : drm.empty() ? ""
                                       : " " + drm);
    if (!vendor.empty()) label += " (" + vendor + ")";
    if (cuda >= 0) label += " CUDA " + std::to_string(cuda);
    devices.push_back({h, label, score, index, cuda});
  }
  std::stable_sort(devices.begin(), devices.end(),
                   [](const Device& a, const Device& b) { return a.score > b.score; });
  return devices;
}

std::string listDevices(const std::vector<Device>& devices) {
  std::string s;
  for (const Device& d : devices) s += "\n    " + d.label;
  return s.empty() ? std::string(" none") : s;
}

// The device CSM_EGL_DEVICE names: a number is the CUDA device index where the driver reports
// one for every device that is not software (nvidia-smi and CUDA_VISIBLE_DEVICES count so),
// else the place in EGL's order; anything else is matched against the devices' labels (the
// DRM file, the vendor). Empty with `error` set when nothing matches.
std::vector<Device> chooseDevice(const std::vector<Device>& devices, const std::string& want,
                                 std::string* error) {
  char* end = nullptr;
  long number = std::strtol(want.c_str(), &end, 10);
  const bool isNumber = !want.empty() && end && *end == '\0';
  std::vector<Device> chosen;
  if (isNumber) {
    bool cudaOrder = false;
    for (const Device& d : devices) cudaOrder = cudaOrder || d.cuda >= 0;
    for (const Device& d : devices)
      if ((cudaOrder ? d.cuda : d.index) == number) chosen.push_back(d);
    if (chosen.empty())
      *error = "CSM_EGL_DEVICE=" + want + ": no EGL device has " +
               (cudaOrder ? "that CUDA index" : "that index") +
               "; the devices are:" + listDevices(devices);
  } else {
    for (const Device& d : devices)
      if (d.label.find(want) != std::string::npos) chosen.push_back(d);
    if (chosen.empty())
      *error = "CSM_EGL_DEVICE=" + want +
               ": no EGL device's name contains it; the devices are:" + listDevices(devices);
  }
  return chosen;
}

struct Made {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLConfig config = EGL_NO_CONFIG_KHR;
};

// A GL 4.3+ core context on an initialized display, sharing objects with `share` (or none);
// EGL_NO_CONTEXT with the last EGL error in `lastError` when no version from 4.6 down works.
EGLContext createCoreContext(EGLDisplay display, EGLConfig config, EGLContext share, bool debug,
                             std::string* lastError) {
  EGLContext context = EGL_NO_CONTEXT;
  for (int v = 6; v >= 3 && context == EGL_NO_CONTEXT; --v) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION_KHR,
                              4,
                              EGL_CONTEXT_MINOR_VERSION_KHR,
                              v,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR,
                              EGL_CONTEXT_FLAGS_KHR,
                              debug ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0,
                              EGL_NONE};
    context = eglCreateContext(display, config, share, attribs);
    if (context == EGL_NO_CONTEXT) *lastError = eglErrorName(eglGetError());
  }
  return context;
}

// Initializes `display` and makes a current GL 4.3+ core context on it; on failure returns
// an empty Made and says why in `note`.
Made makeContext(EGLDisplay display, bool debug, std::string* note) {
  if (display == EGL_NO_DISPLAY) {
    *note = "no EGL display (" + eglErrorName(eglGetError()) + ")";
    return {};
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    *note = "eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
    return {};
  }
  retainDisplay(display);
  auto fail = [&](std::string why) {
    *note = std::move(why);
    releaseDisplay(display);
    return Made{};
  };
  const char* ext = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(ext, "EGL_KHR_surfaceless_context"))
    return fail("the display has no EGL_KHR_surfaceless_context");
  bool egl15 = major > 1 || (major == 1 && minor >= 5);
  if (!egl15 && !hasExtension(ext, "EGL_KHR_create_context"))
    return fail("the display has neither EGL 1.5 nor EGL_KHR_create_context (no core profile)");
  if (!eglBindAPI(EGL_OPENGL_API))
    return fail("eglBindAPI(EGL_OPENGL_API) failed: the display offers no desktop OpenGL");

  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(ext, "EGL_KHR_no_config_context")) {
    // No surface will ever be made, so any surface type will do.
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(display, attribs, &config, 1, &n) || n < 1)
      return fail("no EGLConfig renders desktop OpenGL");
  }

  std::string lastError;
  EGLContext context = createCoreContext(display, config, EGL_NO_CONTEXT, debug, &lastError);
  if (context == EGL_NO_CONTEXT)
    return fail("no OpenGL 4.3 core context (tried 4.6 down to 4.3: " + lastError + ")");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    std::string why =
        "eglMakeCurrent without a surface failed (" + eglErrorName(eglGetError()) + ")";
    eglDestroyContext(display, context);
    return fail(why);
  }
  if (epoxy_gl_version() < 43) {
    std::string why = "the context reports OpenGL " + std::to_string(epoxy_gl_version() / 10) +
                      "." + std::to_string(epoxy_gl_version() % 10) + ", compute shaders need 4.3";
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    return fail(why);
  }
  return {display, context, config};
}

}  // namespace

void Context::setInfo(std::string platform) {
  auto str = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return std::string(s ? reinterpret_cast<const char*>(s) : "");
  };
  renderer_ = str(GL_RENDERER);
  version_ = str(GL_VERSION);
  platform_ = std::move(platform);
}

void Context::copyInfo(const Context& from, std::string platform) {
  renderer_ = from.renderer_;
  version_ = from.version_;
  platform_ = std::move(platform);
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error) {
  return create(Options{}, error);
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(const Options& options,
                                                         std::string* error) {
  std::string only;
  if (const char* env = std::getenv("CSM_EGL_PLATFORM"); env && *env) only = env;
  if (!only.empty() && only != "device" && only != "surfaceless" && only != "default") {
    if (error) *error = "CSM_EGL_PLATFORM=" + only + " is not one of device, surfaceless, default";
    return nullptr;
  }
  auto allowed = [&](const char* path) { return only.empty() || only == path; };

  // Client extensions come from EGL_NO_DISPLAY; a null string means EGL 1.4 without
  // EGL_EXT_client_extensions, where only the default display exists.
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client) eglGetError();
  bool platformBase = hasExtension(client, "EGL_EXT_platform_base");

  std::vector<std::string> notes;
  std::unique_ptr<HeadlessContext> result;
  auto attempt = [&](const std::string& label, EGLDisplay display) {
    std::string note;
    Made made = makeContext(display, options.debug, &note);
    if (made.context == EGL_NO_CONTEXT) {
      notes.push_back(label + ": " + note);
      return false;
    }
    result.reset(new HeadlessContext);
    result->display_ = made.display;
    result->context_ = made.context;
    result->setInfo(label);
    return true;
  };

  std::string wantDevice;
  if (const char* env = std::getenv("CSM_EGL_DEVICE"); env && *env) wantDevice = env;
  if (!wantDevice.empty()) {
    if (only.empty()) {
      only = "device";
    } else if (only != "device") {
      if (error) *error = "CSM_EGL_DEVICE is set but CSM_EGL_PLATFORM=" + only + " is not device";
      return nullptr;
    }
  }

  std::vector<Device> devices;
  // NVIDIA's driver names enumeration and query together as EGL_EXT_device_base.
  bool deviceSupported = platformBase && hasExtension(client, "EGL_EXT_platform_device") &&
                         (hasExtension(client, "EGL_EXT_device_enumeration") ||
                          hasExtension(client, "EGL_EXT_device_base"));
  if (allowed("device")) {
    if (deviceSupported) {
      std::string note;
      devices = enumerateDevices(&note);
      if (devices.empty()) notes.push_back("EGL device: " + note);
    } else {
      notes.push_back(
          "EGL device: no EGL_EXT_platform_device / EGL_EXT_device_enumeration (client "
          "extensions: " +
          std::string(client ? client : "none") + ")");
    }
  }
  if (!wantDevice.empty()) {
    // The named device or nothing: never another one quietly.
    std::string why;
    devices = chooseDevice(devices, wantDevice, &why);
    if (devices.empty()) {
      if (error) *error = why;
      return nullptr;
    }
    for (const Device& d : devices)
      if (attempt(d.label, eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr)))
        return result;
    if (error) {
      *error = "CSM_EGL_DEVICE=" + wantDevice + ": no OpenGL 4.3 core context on it:\n";
      for (const std::string& n : notes) *error += "  - " + n + "\n";
    }
    return nullptr;
  }
  auto tryDevices = [&](bool software) {
    for (const Device& d : devices)
      if ((d.score == 0) == software &&
          attempt(d.label, eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr)))
        return true;
    return false;
  };

  if (allowed("device") && tryDevices(false)) return result;
  if (allowed("surfaceless")) {
    if (platformBase && hasExtension(client, "EGL_MESA_platform_surfaceless")) {
      if (attempt("EGL surfaceless platform",
                  eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                           nullptr)))
        return result;
    } else {
      notes.push_back("EGL surfaceless: no EGL_MESA_platform_surfaceless");
    }
  }
  if (allowed("device") && tryDevices(true)) return result;
  if (allowed("default") && attempt("EGL default display", eglGetDisplay(EGL_DEFAULT_DISPLAY)))
    return result;

  if (error) {
    *error = "cannot create a headless OpenGL 4.3 core context";
    if (!only.empty()) *error += " (CSM_EGL_PLATFORM=" + only + ")";
    *error += ":\n";
    for (const std::string& n : notes) *error += "  - " + n + "\n";
    *error +=
        "Install an EGL driver with desktop OpenGL 4.3: Mesa's (Debian/Ubuntu: libegl1 "
        "libegl-mesa0 libgl1-mesa-dri; llvmpipe gives 4.5 without a GPU) or the NVIDIA "
        "driver's EGL library (libnvidia-egl / libEGL_nvidia.so.0).";
  }
  return nullptr;
}

HeadlessContext::~HeadlessContext() {
  auto display = static_cast<EGLDisplay>(display_);
  auto context = static_cast<EGLContext>(context_);
  if (eglGetCurrentContext() == context)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, context);
  releaseDisplay(display);
}

void HeadlessContext::releaseCurrent() {
  auto display = static_cast<EGLDisplay>(display_);
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

bool HeadlessContext::makeCurrent() {
  return eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(context_)) == EGL_TRUE;
}

}  // namespace csm::gl
