#include "gl/caps.h"

#include "gl/debug.h"

namespace csm::gl {
namespace {

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

GLint integer(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

}  // namespace

bool isSoftwareRenderer(const std::string& renderer) {
  for (const char* s : {"llvmpipe", "softpipe", "swrast", "SwiftShader"})
    if (renderer.find(s) != std::string::npos) return true;
  return false;
}

std::string softwareRendererWarning(const std::string& renderer) {
  return "OpenGL runs on a software renderer (" + renderer +
         "): the GPU solver and the drawing run on the CPU, far slower than on a GPU. "
         "--require-gpu makes this an error; CSM_EGL_DEVICE chooses the headless device";
}

Caps queryCaps() {
  Caps c;
  c.vendor = glString(GL_VENDOR);
  c.renderer = glString(GL_RENDERER);
  c.version = glString(GL_VERSION);
  c.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
  c.major = integer(GL_MAJOR_VERSION);
  c.minor = integer(GL_MINOR_VERSION);
  c.software = isSoftwareRenderer(c.renderer);

  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &c.maxShaderStorageBlockSize);
  c.maxShaderStorageBufferBindings = integer(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS);
  c.maxComputeShaderStorageBlocks = integer(GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS);
  for (GLuint i = 0; i < 3; ++i) {
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &c.maxComputeWorkGroupCount[i]);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, i, &c.maxComputeWorkGroupSize[i]);
  }
  c.maxComputeWorkGroupInvocations = integer(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
  c.maxComputeSharedMemorySize = integer(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
  c.maxUniformBlockSize = integer(GL_MAX_UNIFORM_BLOCK_SIZE);
  c.maxTextureSize = integer(GL_MAX_TEXTURE_SIZE);
  c.maxTextureBufferSize = integer(GL_MAX_TEXTURE_BUFFER_SIZE);
  c.textureBufferOffsetAlignment = integer(GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT);
  c.maxArrayTextureLayers = integer(GL_MAX_ARRAY_TEXTURE_LAYERS);
  c.maxColorAttachments = integer(GL_MAX_COLOR_ATTACHMENTS);
  c.maxSamples = integer(GL_MAX_SAMPLES);
  c.maxColorTextureSamples = integer(GL_MAX_COLOR_TEXTURE_SAMPLES);
  c.maxDepthTextureSamples = integer(GL_MAX_DEPTH_TEXTURE_SAMPLES);
  int version = c.major * 10 + c.minor;
  c.timerQuery = version >= 33 || epoxy_has_gl_extension("GL_ARB_timer_query");
  c.khrDebug = version >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
  maybeCheckErrors("queryCaps");
  return c;
}

std::string Caps::summary() const {
  auto n = [](auto v) { return std::to_string(v); };
  auto xyz = [&](const std::array<GLint, 3>& a) {
    return n(a[0]) + " x " + n(a[1]) + " x " + n(a[2]);
  };
  std::string s;
  s += "GL vendor:                  " + vendor + "\n";
  s += "GL renderer:                " + renderer + (software ? " (software)" : "") + "\n";
  s += "GL version:                 " + version + "\n";
  s += "GLSL version:               " + glslVersion + "\n";
  s += "max SSBO block size:        " + n(maxShaderStorageBlockSize) + " bytes\n";
  s += "max SSBO bindings:          " + n(maxShaderStorageBufferBindings) + "\n";
  s += "max compute SSBO blocks:    " + n(maxComputeShaderStorageBlocks) + "\n";
  s += "max work group count:       " + xyz(maxComputeWorkGroupCount) + "\n";
  s += "max work group size:        " + xyz(maxComputeWorkGroupSize) + "\n";
  s += "max work group invocations: " + n(maxComputeWorkGroupInvocations) + "\n";
  s += "max compute shared memory:  " + n(maxComputeSharedMemorySize) + " bytes\n";
  s += "max uniform block size:     " + n(maxUniformBlockSize) + " bytes\n";
  s += "max texture size:           " + n(maxTextureSize) + "\n";
  s += "max texture buffer size:    " + n(maxTextureBufferSize) + " texels\n";
  s += "texture buffer offset align: " + n(textureBufferOffsetAlignment) + " bytes\n";
  s += "max array texture layers:   " + n(maxArrayTextureLayers) + "\n";
  s += "max color attachments:      " + n(maxColorAttachments) + "\n";
  s += "max samples:                " + n(maxSamples) + "\n";
  s += std::string("timer query:                ") + (timerQuery ? "yes" : "no") + "\n";
  s += std::string("KHR_debug:                  ") + (khrDebug ? "yes" : "no");
  return s;
}

}  // namespace csm::gl
