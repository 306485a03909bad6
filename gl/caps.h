#pragma once
#include <array>
#include <string>

#include "gl/gl.h"

namespace csm::gl {

// What the current context is and what it allows. The simulation sizes its SSBOs and work
// groups from these: GL 4.3 only guarantees 16 MiB per storage block and 1024 invocations
// per work group (GL 4.6 spec, table 23.64 and 23.67).
struct Caps {
  std::string vendor, renderer, version, glslVersion;
  int major = 0, minor = 0;               // GL version, e.g. 4 and 5
  bool software = false;                  // llvmpipe, softpipe, swrast: CPU rasterizer
  GLint64 maxShaderStorageBlockSize = 0;  // bytes
  GLint maxShaderStorageBufferBindings = 0;
  GLint maxComputeShaderStorageBlocks = 0;
  std::array<GLint, 3> maxComputeWorkGroupCount{};
  std::array<GLint, 3> maxComputeWorkGroupSize{};
  GLint maxComputeWorkGroupInvocations = 0;
  GLint maxComputeSharedMemorySize = 0;  // bytes
  GLint maxUniformBlockSize = 0;         // bytes
  GLint maxTextureSize = 0;
  GLint maxTextureBufferSize = 0;          // texels of one buffer texture
  GLint textureBufferOffsetAlignment = 0;  // bytes: where a view of a buffer's range may start
  GLint maxArrayTextureLayers = 0;
  GLint maxColorAttachments = 0;
  GLint maxSamples = 0;
  GLint maxColorTextureSamples = 0;  // multisample textures
  GLint maxDepthTextureSamples = 0;
  bool timerQuery = false;  // GL_TIME_ELAPSED (core since 3.3)
  bool khrDebug = false;

  // One line per field, for logs and --info.
  std::string summary() const;
};

// Whether GL_RENDERER names a software rasterizer (llvmpipe, softpipe, swrast, SwiftShader).
bool isSoftwareRenderer(const std::string& renderer);

// One line for logs and warnings: that the context runs on the CPU, naming it, and what follows.
std::string softwareRendererWarning(const std::string& renderer);

// Queries the current context. Not cached: the window and headless contexts differ.
Caps queryCaps();

}  // namespace csm::gl
