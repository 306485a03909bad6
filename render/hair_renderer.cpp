#include "render/hair_renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/gtc/quaternion.hpp>

#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/draw.h"
#include "gl/program.h"
#include "gl/shader_source.h"
#include "gl/state_backup.h"
#include "render/bindings.h"
#include "render/compute_dispatch.h"
#include "render/frame_uniforms.h"
#include "render/camera.h"
#include "render/hair_color.h"
#include "render/scalp_map.h"
#include "sim/head/head_model.h"
#include "sim/head/mannequin.h"

namespace csm {
namespace {

using render_block::FrameUniforms;  // render/frame_uniforms.h

// A share of the strands is drawn wider by 1/sqrt(share), up to this: most of the coverage
// without turning the hair into straws.
constexpr float kMaxWidthScale = 2.0f;
// The colour of the guides drawn alone (render.show_guides), sRGB.
constexpr glm::vec3 kGuideHighlight(1.0f, 0.55f, 0.1f);
// Children drawn into the deep opacity maps per guide, each standing for children / this many.
constexpr int kShadowChildren = 1;
// The width (m) a strand drawn render.strand_width pixels wide stands for in the shadow maps,
// where a width in pixels means nothing: a texel's side of the default preset's 1,024-texel
// map, so that preset's shadows are as dark as when every fragment counted in full. With
// render.strand_width_m the shadows take that width instead.
constexpr float kShadowWidthOfPixelStrands = 0.0009f;

// What every render program is built with beyond the files: the sample count. Binding points
// are no defines: the shaders include render/bindings.glsl, as the C++ does.
std::vector<gl::Define> sharedDefines(int samples) {
  return {gl::Define{"SAMPLES", std::to_string(samples)}};
}

// Preset colours are display colours, as a colour picker shows them; lighting needs them
// linear. (Groom files store linear colours already.)
float srgbToLinear(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
glm::vec3 srgbToLinear(const glm::vec3& c) {
  return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)};
}

// What a DrawAmount comes to for a groom: guides drawn, strands per guide (the guide and
// its first instances - 1 children), and how much wider and more opaque (in the shadow maps)
// each is drawn to stand for the ones left out.
struct Selection {
  std::size_t guides = 0;
  int instances = 1;
  float widthScale = 1.0f, opacityScale = 1.0f;
};

// `guides`: the strands of the geometry drawn, `children` each; `simulated` of the `all` strands
// the full picture draws are simulated. The amount's share of the simulated strands plus its
// `extra` share of the rest (children, followers) is drawn.
Selection select(std::size_t guides, int children, const DrawAmount& amount, double simulated,
                 double all) {
  Selection s;
  const int perGuide = 1 + std::max(children, 0);
  const double share = std::clamp(double(amount.strands), 0.0, 1.0);
  const double extra = std::clamp(double(amount.extra), 0.0, 1.0);
  const double wanted =
      std::max(1.0, std::round(share * (simulated + extra * std::max(all - simulated, 0.0))));
  if (wanted >= double(guides)) {
    // Children go first: whole guides with fewer of their children.
    s.guides = guides;
    s.instances =
        std::clamp(int(std::floor(wanted / double(std::max<std::size_t>(guides, 1)))), 1, perGuide);
  } else {
    s.guides = std::size_t(wanted);
    s.instances = 1;
  }
  const double drawn = double(s.guides) * s.instances;
  const double ratio = drawn > 0.0 ? std::max(all / drawn, 1.0) : 1.0;
  s.widthScale = std::min(kMaxWidthScale, float(std::sqrt(ratio)));
  s.opacityScale = float(ratio);
  return s;
}

}  // namespace

struct HairRenderer::Programs {
  gl::Program points{gl::NoCreate}, children{gl::NoCreate}, shade{gl::NoCreate},
      childShade{gl::NoCreate};
  gl::Program hairDepth{gl::NoCreate}, hairOpacity{gl::NoCreate}, childOpacity{gl::NoCreate},
      hair{gl::NoCreate}, thinHair{gl::NoCreate}, childHair{gl::NoCreate};
  gl::Program headDepth{gl::NoCreate}, head{gl::NoCreate};
  gl::Program background{gl::NoCreate}, post{gl::NoCreate};

  // All fourteen, or none (with the compiler's log).
  static std::unique_ptr<Programs> build(int samples, std::string* log) {
    const std::vector<gl::Define> defines = sharedDefines(samples);
    std::vector<gl::Define> shadowDefines = defines;
    shadowDefines.push_back({"SHADOW_PASS", ""});
    std::vector<gl::Define> childDefines = defines;
    childDefines.push_back({"CHILD_LINES", ""});
    std::vector<gl::Define> thinDefines = defines;
    thinDefines.push_back({"GUIDE_LINES", ""});
    std::vector<gl::Define> childShadowDefines = shadowDefines;
    childShadowDefines.push_back({"CHILD_LINES", ""});
    auto p = std::make_unique<Programs>();
    std::string all;
    bool ok = true;
    auto one = [&](gl::Program& out, const char* name, const char* vert, const char* frag,
                   const std::vector<gl::Define>& d) {
      std::string l;
      std::optional<gl::Program> made = gl::buildProgram(
          name, {{gl::ShaderStage::Vertex, vert}, {gl::ShaderStage::Fragment, frag}}, d, &l);
      if (!l.empty()) all += l + "\n";
      if (made)
        out = std::move(*made);
      else
        ok = false;
    };
    // Named by their file, as the solver's passes are: the pass profile's rows.
    auto compute = [&](gl::Program& out, const char* source) {
      std::string l;
      std::optional<gl::Program> made =
          gl::buildProgram(source, {{gl::ShaderStage::Compute, source}}, defines, &l);
      if (!l.empty()) all += l + "\n";
      if (made)
        out = std::move(*made);
      else
        ok = false;
    };
    compute(p->points, "render/hair_points.comp");
    compute(p->children, "render/hair_children.comp");
    compute(p->shade, "render/hair_shade.comp");
    compute(p->childShade, "render/hair_child_shade.comp");
    one(p->hairDepth, "hair depth", "render/hair.vert", "render/depth_only.frag", shadowDefines);
    one(p->hairOpacity, "hair opacity", "render/hair.vert", "render/hair_opacity.frag",
        shadowDefines);
    one(p->childOpacity, "child opacity", "render/hair.vert", "render/hair_opacity.frag",
        childShadowDefines);
    one(p->hair, "hair", "render/hair.vert", "render/hair.frag", defines);
    one(p->thinHair, "thin hair", "render/hair.vert", "render/hair.frag", thinDefines);
    one(p->childHair, "child hair", "render/hair.vert", "render/hair.frag", childDefines);
    one(p->headDepth, "head depth", "render/head.vert", "render/depth_only.frag", shadowDefines);
    one(p->head, "head", "render/head.vert", "render/head.frag", defines);
    one(p->background, "background", "render/fullscreen.vert", "render/background.frag", defines);
    one(p->post, "post", "render/fullscreen.vert", "render/post.frag", defines);
    if (log) *log = all;
    return ok ? std::move(p) : nullptr;
  }
};

std::unique_ptr<HairRenderer> HairRenderer::create(std::string* error) {
  std::unique_ptr<HairRenderer> r(new HairRenderer());
  std::string log;
  if (!r->followers_.build(&log)) {
    if (error) *error = "the renderer's shaders failed to build:\n" + log;
    return nullptr;
  }
  // Built for the default render.samples; others are built when first asked for.
  if (!r->programsFor(std::min(RenderConfig{}.samples, r->maxSamples_), &log)) {
    if (error) *error = "the renderer's shaders failed to build:\n" + log;
    return nullptr;
  }
  return r;
}

HairRenderer::HairRenderer() : clock_(gl::queryCaps().timerQuery) {
  const gl::Caps caps = gl::queryCaps();
  maxSamples_ = std::max(
      1, std::min({caps.maxSamples, caps.maxColorTextureSamples, caps.maxDepthTextureSamples}));
  clock_.setSynchronous(caps.software);
  pacedDraws_ = caps.software;
  emptyVao_ = gl::VertexArray();
  frameUniforms_ =
      gl::Buffer(GLsizeiptr(sizeof(FrameUniforms)), nullptr, gl::BufferUsage::DynamicDraw);
  shadowFor(RenderConfig{}.shadowMapSize);
}

HairRenderer::~HairRenderer() = default;

void HairRenderer::setPacedDraws(bool on) {
  pacedDraws_ = on;
  for (auto& [key, g] : geometries_) g->setPaced(on);
}

HairRenderer::Programs* HairRenderer::programsFor(int samples, std::string* log) {
  auto it = programs_.find(samples);
  if (it != programs_.end()) return it->second.get();
  std::unique_ptr<Programs> p = Programs::build(samples, log);
  if (!p) return nullptr;
  return programs_.emplace(samples, std::move(p)).first->second.get();
}

bool HairRenderer::reloadShaders(std::string* log) {
  // Every variant in use, or none: a failed reload keeps all the old programs.
  FollowerPass followers;
  if (!followers.build(log)) return false;
  std::map<int, std::unique_ptr<Programs>> rebuilt;
  for (const auto& [samples, old] : programs_) {
    std::unique_ptr<Programs> p = Programs::build(samples, log);
    if (!p) return false;
    rebuilt.emplace(samples, std::move(p));
  }
  programs_ = std::move(rebuilt);
  followers_.build(log);
  return true;
}

FrameTarget& HairRenderer::targetFor(int width, int height, int samples) {
  std::unique_ptr<FrameTarget>& t = targets_[samples];
  if (!t) t = std::make_unique<FrameTarget>();
  t->resize(width, height, samples);
  // Two qualities at most are in use: drop targets of sample counts no longer asked for.
  if (targets_.size() > 2)
    for (auto it = targets_.begin(); it != targets_.end();)
      it = it->second.get() != t.get() && it->second.get() != target_ ? targets_.erase(it)
                                                                      : std::next(it);
  return *t;
}

StrandGeometry& HairRenderer::geometryFor(int subdivision, bool followers) {
  std::unique_ptr<StrandGeometry>& g = geometries_[{subdivision, followers}];
  if (!g) {
    g = std::make_unique<StrandGeometry>();
    g->setPaced(pacedDraws_);
  }
  // Full and interactive quality, and the guides standing in for their followers.
  if (geometries_.size() > 3)
    for (auto it = geometries_.begin(); it != geometries_.end();)
      it = it->second.get() != g.get() && it->second.get() != geometry_ ? geometries_.erase(it)
                                                                        : std::next(it);
  geometry_ = g.get();
  return *g;
}

ShadowMaps& HairRenderer::shadowFor(int size) {
  std::unique_ptr<ShadowMaps>& m = shadowMaps_[size];
  if (!m) {
    m = std::make_unique<ShadowMaps>();
    m->resize(size);
  }
  if (shadowMaps_.size() > 2)
    for (auto it = shadowMaps_.begin(); it != shadowMaps_.end();)
      it = it->second.get() != m.get() && it->second.get() != shadow_ ? shadowMaps_.erase(it)
                                                                      : std::next(it);
  shadow_ = m.get();
  return *m;
}

void HairRenderer::updateUniforms(const FrameView& frame, int children, int drawnChildren,
                                  float widthScale, float childWidth, float shadowOpacityScale,
                                  int drawnWidth, int drawnHeight) {
  const ViewConfig& look = *frame.look;
  const RenderConfig& r = look.render;
  const float aspect = float(frame.width) / float(std::max(frame.height, 1));
  const glm::mat4 view = frame.useCameraMatrices ? frame.view : cameraView(look.camera);
  const glm::mat4 proj =
      frame.useCameraMatrices ? frame.projection : cameraProjection(look.camera, aspect);
  const glm::vec3 eye = glm::vec3(glm::inverse(view)[3]);

  // The light: orthographic, around the sphere that holds the hair this frame.
  glm::vec3 dir = look.light.direction;
  dir = glm::length(dir) > 1e-6f ? glm::normalize(dir) : glm::vec3(0.0f, -1.0f, 0.0f);
  const glm::vec3 center = glm::vec3(frame.headPose.apply(glm::dvec3(geometry_->boundCenter())));
  const float R = geometry_->boundRadius();
  lightViewProj_ = ShadowMaps::lightViewProjection(dir, center, R);

  FrameUniforms u{};
  u.viewProj = proj * view;
  u.lightViewProj = lightViewProj_;
  u.headRotation = glm::mat4(glm::mat3_cast(glm::quat(frame.headPose.rotation)));
  u.eye = glm::vec4(eye, 1.0f);
  u.lightDir = glm::vec4(dir, look.light.intensity);
  u.lightColor = glm::vec4(srgbToLinear(look.light.color), look.light.ambient);
  const HairColors colors = hairColors(r);
  u.rootColor = glm::vec4(srgbToLinear(colors.root), r.colorVariation);
  u.tipColor = glm::vec4(srgbToLinear(colors.tip), std::clamp(r.opacity, 0.0f, 1.0f));
  const bool highlightGuides = r.showGuides && frame.followers;
  if (highlightGuides) {
    // The guides alone: one bright colour, whatever the groom's own.
    u.rootColor = glm::vec4(srgbToLinear(kGuideHighlight), 0.0f);
    u.tipColor = glm::vec4(srgbToLinear(kGuideHighlight), 1.0f);
  }
  u.specShift =
      glm::vec4(r.specularShift1, r.specularShift2, r.specularExponent1, r.specularExponent2);
  // A width in the frame's pixels is that many of them, however small the image drawn.
  const float pixelScale = float(drawnHeight) / float(std::max(frame.height, 1));
  u.specStrength =
      glm::vec4(r.specularStrength1, r.specularStrength2, r.strandWidth * widthScale * pixelScale,
                std::max(r.layerSpacing, 1e-5f));
  u.headColor = glm::vec4(srgbToLinear(r.headColor), r.shadows ? 1.0f : 0.0f);
  u.background = glm::vec4(srgbToLinear(r.background), 1.0f);
  u.viewport = glm::vec4(float(drawnWidth), float(drawnHeight), 1.0f / float(drawnWidth),
                         1.0f / float(drawnHeight));
  // Orthographic depth is linear: one unit of depth is the whole 2R of the light's box.
  const float size = float(shadow_->size());
  u.lightRange = glm::vec4(2.0f * R, size, 1.0f / size, 2.0f * R / size);
  u.children = glm::vec4(r.childRadius > 0.0f ? r.childRadius : geometry_->rootSpacing(),
                         std::clamp(r.childClump, 0.0f, 1.0f), shadowOpacityScale,
                         std::max(r.childNoise, 0.0f));
  const int shadowChildren = std::max(std::min(drawnChildren, kShadowChildren), 1);
  u.children2 =
      glm::vec4(std::clamp(r.childLength, 0.0f, 0.9f), std::clamp(r.childInterpolation, 0.0f, 1.0f),
                float(drawnChildren) / float(shadowChildren), 0.0f);
  // Highlighted guides take no groom colours (flag 1).
  u.counts = glm::ivec4(geometry_->subdivision(), children, geometry_->childStride(),
                        geometry_->strandFlags() & (highlightGuides ? ~1 : ~0));
  u.counts2 = glm::ivec4(int(geometry_->splinePoints()), head_.sphereCount(), 0, 0);
  // The mannequin's eyes and lips, from the scalp centre its mesh is drawn about.
  const MannequinFace& face = kMannequinFace;
  u.faceEye = glm::vec4(glm::vec3(face.eye - kMannequinScalpCentre), head_.paintsFace() ? 1 : 0);
  u.faceEyeSizes = glm::vec4(face.ball, face.corneaOffset, face.cornea, face.iris);
  u.faceMouth = glm::vec4(glm::vec3(face.mouth - kMannequinScalpCentre), face.pupil);
  u.faceLips = glm::vec4(face.lipsHalfWidth, face.lipsHalfHeight, 0.0f, 0.0f);
  u.irisColor = glm::vec4(srgbToLinear(r.irisColor), 1.0f);
  // A width in metres: pixels per metre at view depth 1 from the projection's vertical scale
  // (1 / tan(fov / 2) for the orbit camera), so a strand narrows with distance as it would.
  const float widthM = std::max(r.strandWidthM, 0.0f);
  // The shadows take each strand's width narrowed as the picture's (children: 1 / sqrt(1 + n)),
  // not the share's widening, which the opacity scale makes up for.
  u.width = glm::vec4(widthM * widthScale, 0.5f * proj[1][1] * float(drawnHeight),
                      (widthM > 0.0f ? widthM : kShadowWidthOfPixelStrands) * childWidth, 0.0f);
  frameUniforms_.setSubData(0, sizeof(u), &u);
}

void HairRenderer::render(const FrameView& frame) {
  if (!frame.scene || !frame.look || !frame.groom || !frame.head || frame.width <= 0 ||
      frame.height <= 0)
    return;
  const RenderConfig& look = frame.look->render;
  const DrawAmount& amount = frame.amount;
  gl::StateBackup backup;
  clock_.beginFrame();

  const int samples =
      std::clamp(amount.samples > 0 ? amount.samples : look.samples, 1, maxSamples_);
  const int shadowSize =
      std::clamp(amount.shadowMapSize > 0 ? amount.shadowMapSize : look.shadowMapSize, 16, 8192);
  const int subdivision =
      std::clamp(amount.subdivision > 0 ? amount.subdivision : look.subdivision, 1, 64);
  // A groom simulated through guides draws its followers: the follower pass makes them first.
  // render.show_guides draws the guides alone, highlighted, as simulated; an amount with no
  // extra strands draws them too, not highlighted, each standing for its followers.
  const FollowerBinding* bound = look.showGuides ? nullptr : frame.followers;
  const FollowerBinding* followers = amount.extra > 0.0f ? bound : nullptr;
  const Groom* groom = followers ? &followers->drawn : frame.groom;
  geometryFor(subdivision, groom != frame.groom)
      .update(*groom, frame.generation, subdivision, frame.head->spheres());
  // The scalp is painted where the whole picture's hair grows.
  const Groom* grown = bound ? &bound->drawn : frame.groom;
  // Each strand drawn with its children (the full picture's, whatever interactive quality
  // draws), the guides alone without.
  const float perRoot = look.showGuides ? 1.0f : float(1 + std::max(0, look.children));
  if (scalpKey_ != std::make_tuple(grown, frame.generation, perRoot)) {
    scalp_ = makeScalpMap(*grown, scalpSpheres(*frame.head), perRoot);
    scalpKey_ = {grown, frame.generation, perRoot};
  }
  // Interactive quality may draw a smaller image; the post pass scales it up to the frame.
  const float scale = std::clamp(amount.resolution, 0.05f, 1.0f);
  const int drawnWidth = std::max(16, int(std::lround(float(frame.width) * scale)));
  const int drawnHeight = std::max(16, int(std::lround(float(frame.height) * scale)));
  FrameTarget& target = targetFor(drawnWidth, drawnHeight, samples);
  target_ = &target;
  // The programs for the samples the driver made, which may be more than asked for.
  std::string log;
  Programs* programs = programsFor(target.samples(), &log);
  if (!programs) {
    gl::logMessage(gl::LogLevel::Error, "HairRenderer: " + log);
    return;
  }
  ShadowMaps& shadow = shadowFor(shadowSize);
  head_.update(*frame.head, frame.headPose, frame.torsoPose);

  // Children as asked for, as many as fit; each strand narrower by sqrt(1 + children), so
  // 1 + n strands cover sqrt(1 + n) times the guides' area (docs/METHOD.md, section 8).
  const int children = geometry_->setChildren(look.children);
  // The simulated strands, and all the full picture draws: the drawn strands and their children.
  const double simulated = double(frame.groom->strandCount());
  const double all = double(grown->strandCount()) * (1.0 + children);
  const Selection drawn = select(geometry_->guides(), children, amount, simulated, all);
  unsigned positions = frame.positionBuffer;
  drawnStrands_ = positions != 0 ? drawn.guides * std::size_t(drawn.instances) : 0;
  const float childWidth = 1.0f / std::sqrt(float(1 + children));
  const int drawnChildren = drawnStrands_ > 0 ? drawn.instances - 1 : 0;
  updateUniforms(frame, children, drawnChildren, drawn.widthScale * childWidth, childWidth,
                 drawn.opacityScale, drawnWidth, drawnHeight);

  // The solver may have written the positions from a compute shader.
  gl::memoryBarrier(gl::Barrier::Storage);
  if (followers && positions != 0) {
    clock_.begin("followers");
    followers_.update(*followers, frame.generation, *frame.head);
    positions = followers_.run(positions, BodyPose{frame.headPose, frame.torsoPose});
  }
  frameUniforms_.bindBase(gl::BufferTarget::Uniform, bindings::kFrameUniforms);
  gl::bindStorageBuffer(bindings::kPositions, positions);
  geometry_->bind();
  head_.bind();
  Programs& p = *programs;
  if (drawnStrands_ > 0) {
    clock_.begin("strands");
    makePoints(p, drawnChildren > 0 ? children : 0);
  }
  // The guides' lines, and in the opacity pass a few ranks of children standing for all
  // (uChildren2.z): the maps are smooth, and children lie within a layer of their guide.
  // The nearest hair's depth (z0) comes from the guides alone.
  auto drawLines = [&](gl::Program& guides, gl::Program* childLines) {
    if (drawnStrands_ == 0) return;
    guides.use();
    geometry_->drawGuideLines(drawn.guides);
    if (childLines && drawnChildren > 0) {
      childLines->use();
      geometry_->drawChildren(std::min(drawnChildren, kShadowChildren));
    }
  };

  // Shadow: deep opacity maps and the head's depth, from the light. Each stage's timer
  // starts after its first framebuffer is bound: llvmpipe times a query from the first
  // rasterizer command after the begin, and one begun before a bind never starts.
  if (look.shadows) {
    shadow.clear();
    clock_.begin("shadow");
    gl::setViewport(0, 0, shadow.size(), shadow.size());
    gl::applyDrawState({.depthTest = true});
    shadow.lightDepthTarget().bind();
    drawLines(p.hairDepth, nullptr);

    // The head's back faces: a lit surface never shadows itself.
    shadow.headShadowTarget().bind();
    gl::applyDrawState({.depthTest = true, .cull = gl::Cull::Front});
    p.headDepth.use();
    head_.draw(p.headDepth, amount.fullHead);

    // Opacity layers: every hair fragment counts, so no depth test; additive blending.
    shadow.opacityTarget().bind();
    gl::applyDrawState({.blend = gl::Blend::Additive});
    shadow.lightDepth().bind(bindings::kLightDepthUnit);
    drawLines(p.hairOpacity, &p.childOpacity);
  }

  // Head: the backdrop, then the spheres, into the frame.
  gl::setViewport(0, 0, drawnWidth, drawnHeight);
  target.framebuffer().bind();
  clock_.begin("head");
  target.framebuffer().clearDepth(1.0f);
  shadow.lightDepth().bind(bindings::kLightDepthUnit);
  shadow.opacityLayers().bind(bindings::kOpacityLayersUnit);
  shadow.headShadow().bind(bindings::kHeadShadowUnit);
  scalp_.bind(bindings::kScalpUnit);
  gl::applyDrawState({});
  p.background.use();
  emptyVao_.bind();
  gl::drawArrays(gl::Primitive::Triangles, 0, 3);
  gl::applyDrawState({.depthTest = true, .cull = gl::Cull::Back});
  p.head.use();
  head_.draw(p.head, amount.fullHead);

  // Hair: the light at every guide point (and each child's from it), then the guides:
  // ribbons, both faces (consecutive triangles alternate their winding), or lines where
  // thinner than a pixel (in pixels: with children, or a width under one; a ribbon is drawn
  // at least 1.5 pixels wide, a line one).
  clock_.begin("hair");
  if (drawnStrands_ > 0) {
    dispatchOver(p.shade, geometry_->splinePoints());
    if (drawnChildren > 0)
      dispatchOver(p.childShade, geometry_->childPoints() * std::size_t(children));
    gl::applyDrawState({.depthTest = true});
    if (look.strandWidthM <= 0.0f && look.strandWidth * drawn.widthScale * childWidth < 1.0f) {
      p.thinHair.use();
      geometry_->drawThinGuides(drawn.guides);
    } else {
      p.hair.use();
      geometry_->drawRibbons(drawn.guides);
    }
  }
  // Children: depth-tested before shading against the head and the guides, no depth writes.
  if (drawnChildren > 0) {
    clock_.begin("children");
    gl::applyDrawState({.depthTest = true, .depthWrite = false});
    p.childHair.use();
    geometry_->drawChildren(drawnChildren);
  }

  // Post: tone map each sample, resolve, gamma, into the caller's framebuffer.
  gl::applyDrawState({});
  gl::Framebuffer::bindRaw(gl::FramebufferTarget::Draw, frame.targetFramebuffer);
  clock_.begin("post");
  gl::setViewport(0, 0, frame.width, frame.height);
  target.color().bind(bindings::kResolvedUnit);
  p.post.use();
  p.post.setUniform("uDrawn", glm::ivec2(drawnWidth, drawnHeight));
  p.post.setUniform("uScale", glm::vec2(float(drawnWidth) / float(frame.width),
                                        float(drawnHeight) / float(frame.height)));
  emptyVao_.bind();
  gl::drawArrays(gl::Primitive::Triangles, 0, 3);
  clock_.endFrame();
  gl::maybeCheckErrors("HairRenderer::render");
}

void HairRenderer::makePoints(Programs& p, int children) {
  dispatchOver(p.points, geometry_->splinePoints());
  if (children > 0) dispatchOver(p.children, geometry_->childPoints() * std::size_t(children));
}

std::vector<StageTime> HairRenderer::stageTimes() {
  return clock_.times();
}

std::size_t drawnStrandCount(std::size_t strands, const RenderConfig& render) {
  return strands * std::size_t(1 + std::max(render.children, 0));
}

DrawAmount interactiveAmount(const RenderConfig& render) {
  DrawAmount a;
  if (!render.interactive) return a;
  a.strands = render.interactiveAmount;
  a.subdivision = render.interactiveSubdivision;
  a.samples = render.interactiveSamples;
  a.shadowMapSize = render.interactiveShadowMapSize;
  a.fullHead = false;
  a.resolution = render.interactiveResolution;
  return a;
}

}  // namespace csm
