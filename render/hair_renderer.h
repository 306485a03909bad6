// The renderer: deep opacity maps (Yuksel & Keyser 2008), Kajiya-Kay hair (1989) with
// shifted highlights (Scheuermann 2004), the head, the backdrop, drawing what a FrameView
// (render/renderer.h) holds; tests read its maps and geometry through RendererProbe
// (render/renderer_probe.h).
//
// Passes, each timed as a stage, over parts that each do one job:
//   shadow  (ShadowMaps) light-space depth of the nearest hair (z0); the head's depth (back
//           faces); hair opacity accumulated additively into the four layers of one RGBA16F
//           target, starting at z0, render.layer_spacing apart. Hair drawn as line strips
//           one texel wide, each fragment weighted by the share of its texel the strand's
//           width covers, so the shadows are as dark at every map size.
//   head    (HeadMesh) the backdrop and the head spheres into the HDR frame (FrameTarget).
//   hair    camera-facing ribbons, Catmull-Rom subdivided, Kajiya-Kay shaded, shadows read
//           per vertex from the maps, transparency as per-strand sample coverage.
//   post    tone mapping per sample, resolve, gamma, into the target framebuffer.
// Every hair pass draws StrandGeometry. Three compute passes a frame write the drawn curves
// once (hair_common.glsl): every guide's spline points and frames, its render.children
// children, and, once the deep opacity maps are drawn, the light at every guide point. The
// three draws then only read them: the shadow passes' lines (guides and children), the
// guides' ribbons and the children's lines. Children take their guide's light, so shading
// costs one evaluation per guide point however many children there are.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

#include "gl/buffer.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/follower_pass.h"
#include "render/frame_target.h"
#include "render/head_mesh.h"
#include "render/pass_clock.h"
#include "render/renderer.h"
#include "render/shadow_maps.h"
#include "render/strand_geometry.h"

namespace csm {

class HairRenderer final {
 public:
  // Needs a current GL 4.3 core context. Null with the compiler's log when shaders fail.
  static std::unique_ptr<HairRenderer> create(std::string* error);
  ~HairRenderer();

  void render(const FrameView& frame);
  // GPU time per pass of recent frames: "shadow", "hair", "head" (timer queries).
  std::vector<StageTime> stageTimes();
  // Recompiles the shaders from disk; on failure keeps the old programs, `log` says why.
  bool reloadShaders(std::string* log);

  // Strands drawn by the last render(): guides drawn times (1 + children drawn).
  std::size_t drawnStrands() const { return drawnStrands_; }
  // Per-pass times from glFinish and the CPU clock instead of timer queries. On by default
  // on software rasterizers: llvmpipe's elapsed-time queries see only its rasterizer threads,
  // not the vertex shading done inside the draw calls, and were measured to put most of the
  // hair pass on the pass after it. On a GPU it would stall the pipeline: queries there.
  // The viewer turns it off (it would stall every frame of the window).
  void setSynchronousTiming(bool on) { clock_.setSynchronous(on); }
  // Multisampling the last frame used (render.samples clamped to what the driver offers).
  int samples() const { return target_ ? target_->samples() : 1; }

 private:
  // Tests read the maps, the geometry and the follower pass, and choose the paced draws,
  // through it (render/renderer_probe.h).
  friend class RendererProbe;
  // Long draws in chunks, each waiting for the one before the last (StrandGeometry::setPaced):
  // on by default on a software rasterizer.
  void setPacedDraws(bool on);
  struct Programs;
  HairRenderer();
  Programs* programsFor(int samples, std::string* log);
  FrameTarget& targetFor(int width, int height, int samples);
  // The geometry for a subdivision, of the drawn groom or (`followers`) a guided groom's drawn
  // strands.
  StrandGeometry& geometryFor(int subdivision, bool followers);
  ShadowMaps& shadowFor(int size);
  // `drawnWidth` x `drawnHeight`: the image the passes draw (the frame's size times
  // DrawAmount::resolution), whose pixels set the strands' widths.
  // `children`: children laid out per guide; `drawnChildren` of them drawn.
  void updateUniforms(const FrameView& frame, int children, int drawnChildren, float widthScale,
                      float childWidth, float shadowOpacityScale, int drawnWidth, int drawnHeight);
  // The compute passes: every guide's spline points, then `children` children per guide.
  void makePoints(Programs& p, int children);

  std::map<int, std::unique_ptr<Programs>> programs_;  // by sample count
  int maxSamples_ = 1;
  PassClock clock_;
  bool pacedDraws_ = false;  // long draws paced (StrandGeometry::setPaced): a CPU rasterizer

  // The groom's topology per subdivision (full and interactive quality's).
  std::map<std::pair<int, bool>, std::unique_ptr<StrandGeometry>> geometries_;
  StrandGeometry* geometry_ = nullptr;
  HeadMesh head_;
  FollowerPass followers_;
  gl::Texture scalp_{gl::NoCreate};  // RGBA8 octahedral map per sphere: root colour, coverage
  // The groom, generation and strands a root it was made for.
  std::tuple<const Groom*, long, float> scalpKey_{nullptr, -1, 0.0f};
  gl::Buffer frameUniforms_{gl::NoCreate};
  gl::VertexArray emptyVao_{gl::NoCreate};

  // Full and interactive quality each keep their targets: switching costs no reallocation.
  std::map<int, std::unique_ptr<ShadowMaps>> shadowMaps_;  // by size
  std::map<int, std::unique_ptr<FrameTarget>> targets_;    // by sample count
  ShadowMaps* shadow_ = nullptr;
  FrameTarget* target_ = nullptr;
  glm::mat4 lightViewProj_{1.0f};
  std::size_t drawnStrands_ = 0;
};

}  // namespace csm
