// The renderer: deep opacity maps (Yuksel & Keyser 2008), Kajiya-Kay hair (1989) with
// shifted highlights (Scheuermann 2004), the head, the backdrop. See renderer.h for the
// interface; this header adds what tests and debug views read back.
//
// Passes, each a StageTimer stage:
//   shadow  light-space depth of the nearest hair (z0); the head's depth (back faces); hair
//           opacity accumulated additively into the four layers of one RGBA16F target,
//           starting at z0, render.layer_spacing apart. Hair drawn as line strips.
//   head    the backdrop and the head spheres into the multisampled HDR target.
//   hair    camera-facing ribbons, Catmull-Rom subdivided, Kajiya-Kay shaded, shadows read
//           per vertex from the maps, transparency as per-strand sample coverage.
//   post    tone mapping per sample, resolve, gamma, into the target framebuffer.
// Every vertex is pulled from the positions SSBO by gl_VertexID (hair_common.glsl); follow
// hairs are instances of their guide. No compute pass and no intermediate vertex buffer:
// three draws read the same ~160k particles, and recomputing a spline point (four loads and
// a few FMAs) is cheaper than writing and re-reading millions of subdivided vertices, which
// would also cost (followCount + 1) x subdivision x 16 bytes per particle of memory.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/query.h"
#include "gl/renderbuffer.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/renderer.h"

namespace csm {

class HairRenderer final : public Renderer {
 public:
  // Needs a current GL 4.3 core context. Null with the compiler's log when shaders fail.
  static std::unique_ptr<HairRenderer> create(std::string* error);
  ~HairRenderer() override;

  void render(const FrameView& frame) override;
  std::vector<StageTime> stageTimes() override;
  bool reloadShaders(std::string* log) override;

  // Strands drawn by the last render(): simulated strands times (1 + follow hairs).
  std::size_t drawnStrands() const { return drawnStrands_; }
  // Per-pass times from glFinish and the CPU clock instead of timer queries. On by default
  // on software rasterizers: llvmpipe's GL_TIME_ELAPSED sees only its rasterizer threads,
  // not the vertex shading done inside the draw calls, and was measured to put most of the
  // hair pass on the pass after it. On a GPU it would stall the pipeline: queries there.
  void setSynchronousTiming(bool on) { synchronousTiming_ = on; }
  bool synchronousTiming() const { return synchronousTiming_; }
  // Multisampling actually used (render.samples clamped to what the driver offers).
  int samples() const { return samples_; }

  // The deep opacity maps of the last frame, for tests and debug views. lightDepth():
  // DEPTH_COMPONENT32F, the nearest hair's light-space depth (1 where there is none).
  // opacityLayers(): RGBA16F, channel k the cumulative opacity of layer k.
  const gl::Texture& lightDepth() const { return lightDepth_; }
  const gl::Texture& opacityLayers() const { return opacityLayers_; }
  const gl::Texture& headShadow() const { return headShadow_; }
  // World -> light clip space of the last frame (orthographic, depth maps linearly).
  const glm::mat4& lightViewProjection() const { return lightViewProj_; }

 private:
  struct Programs;
  HairRenderer();
  bool buildPrograms(int samples, std::string* log);
  void updateTopology(const FrameView& frame);
  void updateScalp(const Groom& groom, const std::vector<Sphere>& spheres);
  void updateTargets(int width, int height, int samples);
  void updateShadowMaps(int size);
  void updateUniforms(const FrameView& frame);
  void drawHair(GLenum mode, bool shadowPass) const;
  void drawHead() const;
  void beginStage(const char* name);  // ends the open stage, if any
  void endStages();

  std::unique_ptr<Programs> programs_;
  int programSamples_ = -1;
  int maxSamples_ = 1;
  bool timers_ = false;
  bool synchronousTiming_ = false;
  gl::StageTimer timer_;
  std::string openStage_;
  std::chrono::steady_clock::time_point openStart_;
  std::vector<StageTime> frameTimes_, lastFrameTimes_;

  // Topology, rebuilt when the groom or the subdivision changes.
  struct TopologyKey {
    long generation = -1;
    const Groom* groom = nullptr;
    std::size_t strands = 0, points = 0;
    int subdivision = 0;
    bool operator==(const TopologyKey&) const = default;
  } topologyKey_;
  gl::Buffer restPositions_{gl::NoCreate}, strandFirst_{gl::NoCreate},
      strandAttributes_{gl::NoCreate};
  gl::Buffer stripIndices_{gl::NoCreate}, lineIndices_{gl::NoCreate};
  gl::VertexArray stripVao_{gl::NoCreate}, lineVao_{gl::NoCreate};
  GLsizei stripCount_ = 0, lineCount_ = 0;
  int subdivision_ = 1, shadowSubdivision_ = 1, pointBits_ = 1, strandFlags_ = 0;
  std::size_t guides_ = 0, drawnStrands_ = 0;
  glm::vec3 boundCenter_{0.0f};  // head's local frame: a sphere holding hair and head
  float boundRadius_ = 0.5f;

  // The head: a unit UV sphere, instanced.
  gl::Buffer sphereVertices_{gl::NoCreate}, sphereIndices_{gl::NoCreate};
  gl::Buffer headSpheres_{gl::NoCreate};
  gl::VertexArray headVao_{gl::NoCreate}, emptyVao_{gl::NoCreate};
  gl::Texture scalp_{gl::NoCreate};  // RGBA8 octahedral map per sphere: root colour, coverage
  GLsizei sphereIndexCount_ = 0, headSphereCount_ = 0;

  gl::Buffer frameUniforms_{gl::NoCreate};
  gl::Buffer dummyAttributes_{gl::NoCreate};

  // Deep opacity maps.
  int shadowSize_ = 0;
  gl::Texture lightDepth_{gl::NoCreate}, headShadow_{gl::NoCreate}, opacityLayers_{gl::NoCreate};
  gl::Framebuffer lightDepthFbo_{gl::NoCreate}, headShadowFbo_{gl::NoCreate},
      opacityFbo_{gl::NoCreate};
  glm::mat4 lightViewProj_{1.0f};

  // The multisampled HDR frame.
  int targetWidth_ = 0, targetHeight_ = 0, samples_ = 0;
  gl::Texture color_{gl::NoCreate};
  gl::Renderbuffer depth_{gl::NoCreate};
  gl::Framebuffer sceneFbo_{gl::NoCreate};
};

}  // namespace csm
