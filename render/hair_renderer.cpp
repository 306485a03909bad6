#include "render/hair_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/bindings.h"
#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/shader_source.h"
#include "render/gl_state.h"

namespace csm {
namespace {

constexpr std::uint32_t kRestart = 0xffffffffu;  // GL_PRIMITIVE_RESTART_FIXED_INDEX, uint

// Mirrors FrameUniforms in shaders/render/frame.glsl (std140: only mat4, vec4 and ivec4).
struct FrameUniforms {
  glm::mat4 viewProj;
  glm::mat4 lightViewProj;
  glm::mat4 headRotation;
  glm::vec4 eye;
  glm::vec4 lightDir;
  glm::vec4 lightColor;
  glm::vec4 rootColor;
  glm::vec4 tipColor;
  glm::vec4 specShift;
  glm::vec4 specStrength;
  glm::vec4 headColor;
  glm::vec4 background;
  glm::vec4 viewport;
  glm::vec4 lightRange;
  glm::vec4 follow;
  glm::ivec4 counts;
  glm::ivec4 counts2;
};
static_assert(sizeof(FrameUniforms) == 3 * 64 + 14 * 16);

// How far apart follow hairs get at the tip, relative to the root: clumps open up toward the
// ends (AMD TressFX's "tip separation" does the same).
constexpr float kFollowTipSpread = 1.0f;

std::vector<gl::Define> sharedDefines(int samples) {
  auto d = [](const char* name, int v) { return gl::Define{name, std::to_string(v)}; };
  return {d("FRAME_UNIFORMS_BINDING", bindings::kFrameUniforms),
          d("POSITIONS_BINDING", bindings::kPositions),
          d("REST_POSITIONS_BINDING", bindings::kRestPositions),
          d("STRAND_FIRST_BINDING", bindings::kStrandFirst),
          d("STRAND_ATTRIBUTES_BINDING", bindings::kStrandAttributes),
          d("HEAD_SPHERES_BINDING", bindings::kHeadSpheres),
          d("LIGHT_DEPTH_UNIT", bindings::kLightDepthUnit),
          d("OPACITY_LAYERS_UNIT", bindings::kOpacityLayersUnit),
          d("HEAD_SHADOW_UNIT", bindings::kHeadShadowUnit),
          d("RESOLVED_UNIT", bindings::kResolvedUnit),
          d("SCALP_UNIT", bindings::kScalpUnit),
          d("SAMPLES", samples)};
}

int bitsFor(std::uint32_t maxValue) {
  int bits = 1;
  while (bits < 32 && (std::uint64_t(1) << bits) <= maxValue) ++bits;
  return bits;
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

// Octahedral mapping of a unit vector to [0,1]^2 (Cigolle et al. 2014): no poles, so the
// crown and the back of the head get texels like everywhere else. head.frag mirrors it.
glm::vec2 octahedral(glm::vec3 d) {
  d /= std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  glm::vec2 p(d.x, d.y);
  if (d.z < 0.0f)
    p = glm::vec2((1.0f - std::abs(d.y)) * (d.x >= 0.0f ? 1.0f : -1.0f),
                  (1.0f - std::abs(d.x)) * (d.y >= 0.0f ? 1.0f : -1.0f));
  return p * 0.5f + 0.5f;
}

void bindStorage(GLuint index, GLuint buffer) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, buffer);
}

}  // namespace

struct HairRenderer::Programs {
  gl::Program hairDepth{gl::NoCreate}, hairOpacity{gl::NoCreate}, hair{gl::NoCreate};
  gl::Program headDepth{gl::NoCreate}, head{gl::NoCreate};
  gl::Program background{gl::NoCreate}, post{gl::NoCreate};
};

std::unique_ptr<HairRenderer> HairRenderer::create(std::string* error) {
  std::unique_ptr<HairRenderer> r(new HairRenderer());
  std::string log;
  // Built for the default render.samples; render() rebuilds if a preset asks otherwise.
  if (!r->buildPrograms(std::min(RenderConfig{}.samples, r->maxSamples_), &log)) {
    if (error) *error = "the renderer's shaders failed to build:\n" + log;
    return nullptr;
  }
  return r;
}

std::unique_ptr<Renderer> Renderer::create(std::string* error) {
  return HairRenderer::create(error);
}

HairRenderer::HairRenderer() {
  const gl::Caps caps = gl::queryCaps();
  GLint colorSamples = 1, depthSamples = 1;
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
  maxSamples_ = std::max(1, std::min({caps.maxSamples, colorSamples, depthSamples}));
  timers_ = caps.timerQuery;
  synchronousTiming_ = caps.software;

  // A unit UV sphere, counter-clockwise seen from outside; positions double as normals.
  constexpr int kStacks = 32, kSlices = 64;
  std::vector<glm::vec3> vertices;
  for (int i = 0; i <= kStacks; ++i) {
    const float theta = float(M_PI) * float(i) / kStacks;
    for (int j = 0; j <= kSlices; ++j) {
      const float phi = 2.0f * float(M_PI) * float(j) / kSlices;
      vertices.emplace_back(std::sin(theta) * std::sin(phi), std::cos(theta),
                            std::sin(theta) * std::cos(phi));
    }
  }
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < kStacks; ++i)
    for (int j = 0; j < kSlices; ++j) {
      const std::uint32_t a = std::uint32_t(i * (kSlices + 1) + j), b = a + kSlices + 1;
      indices.insert(indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  sphereVertices_ = gl::Buffer(vertices, GL_STATIC_DRAW);
  sphereIndices_ = gl::Buffer(indices, GL_STATIC_DRAW);
  sphereIndexCount_ = GLsizei(indices.size());
  headVao_ = gl::VertexArray();
  headVao_.setAttribute(0, sphereVertices_, 3, GL_FLOAT, sizeof(glm::vec3), 0);
  headVao_.setIndexBuffer(sphereIndices_);
  emptyVao_ = gl::VertexArray();
  stripVao_ = gl::VertexArray();
  lineVao_ = gl::VertexArray();

  frameUniforms_ = gl::Buffer(GLsizeiptr(sizeof(FrameUniforms)), nullptr, GL_DYNAMIC_DRAW);
  headSpheres_ = gl::Buffer(GLsizeiptr(sizeof(glm::vec4)), nullptr, GL_DYNAMIC_DRAW);
  // Bound in place of the per-strand attributes when the groom has none: every SSBO a shader
  // declares must be backed by a buffer.
  const glm::vec4 one(1.0f);
  dummyAttributes_ = gl::Buffer(GLsizeiptr(sizeof(one)), &one, GL_STATIC_DRAW);
  updateShadowMaps(1024);
}

HairRenderer::~HairRenderer() = default;

bool HairRenderer::buildPrograms(int samples, std::string* log) {
  const std::vector<gl::Define> defines = sharedDefines(samples);
  std::vector<gl::Define> shadowDefines = defines;
  shadowDefines.push_back({"SHADOW_PASS", ""});
  auto programs = std::make_unique<Programs>();
  std::string all;
  bool ok = true;
  auto build = [&](gl::Program& out, const char* name, const char* vert, const char* frag,
                   const std::vector<gl::Define>& d) {
    std::string l;
    std::optional<gl::Program> p =
        gl::buildProgram(name, {{GL_VERTEX_SHADER, vert}, {GL_FRAGMENT_SHADER, frag}}, d, &l);
    if (!l.empty()) all += l + "\n";
    if (p)
      out = std::move(*p);
    else
      ok = false;
  };
  build(programs->hairDepth, "hair depth", "render/hair.vert", "render/depth_only.frag",
        shadowDefines);
  build(programs->hairOpacity, "hair opacity", "render/hair.vert", "render/hair_opacity.frag",
        shadowDefines);
  build(programs->hair, "hair", "render/hair.vert", "render/hair.frag", defines);
  build(programs->headDepth, "head depth", "render/head.vert", "render/depth_only.frag",
        shadowDefines);
  build(programs->head, "head", "render/head.vert", "render/head.frag", defines);
  build(programs->background, "background", "render/fullscreen.vert", "render/background.frag",
        defines);
  build(programs->post, "post", "render/fullscreen.vert", "render/post.frag", defines);
  if (log) *log = all;
  if (!ok) return false;
  programs_ = std::move(programs);
  programSamples_ = samples;
  return true;
}

bool HairRenderer::reloadShaders(std::string* log) {
  return buildPrograms(programSamples_ > 0 ? programSamples_ : 1, log);
}

void HairRenderer::updateTopology(const FrameView& frame) {
  const Groom& groom = *frame.groom;
  const Config& config = *frame.scene;
  TopologyKey key{frame.generation, frame.groom, groom.strandCount(), groom.pointCount(),
                  std::clamp(frame.look->render.subdivision, 1, 64)};
  if (key == topologyKey_) return;
  topologyKey_ = key;

  const std::size_t strands = groom.strandCount();
  std::uint32_t maxSegments = 1;
  for (std::size_t s = 0; s < strands; ++s)
    maxSegments = std::max(maxSegments, groom.strandSize(s) > 1 ? groom.strandSize(s) - 1 : 1);
  // The vertex id packs guide, point and side into 32 bits (hair_common.glsl), with all ones
  // reserved for primitive restart; a groom too big for the subdivision gets less of it.
  int subdivision = key.subdivision;
  for (;;) {
    pointBits_ = bitsFor(maxSegments * std::uint32_t(subdivision));
    const int guideBits = 31 - pointBits_;
    if (strands == 0 || guideBits >= 31 || (std::uint64_t(strands) >> guideBits) == 0) break;
    if (subdivision == 1) break;
    subdivision = std::max(1, subdivision / 2);
  }
  if (subdivision != key.subdivision)
    gl::logMessage(gl::LogLevel::Warning, "HairRenderer: render.subdivision lowered to " +
                                              std::to_string(subdivision) +
                                              " so every vertex of this groom has an id");
  subdivision_ = subdivision;
  // The deep opacity maps are smooth by construction: half the subdivision is plenty there.
  shadowSubdivision_ = std::max(1, (subdivision + 1) / 2);

  std::vector<glm::vec4> rest(groom.pointCount());
  for (std::size_t i = 0; i < rest.size(); ++i) rest[i] = glm::vec4(groom.points[i], 1.0f);
  restPositions_ = gl::Buffer(rest, GL_STATIC_DRAW);
  strandFirst_ = gl::Buffer(groom.first, GL_STATIC_DRAW);

  strandFlags_ = 0;
  std::vector<glm::vec4> attributes(std::max<std::size_t>(strands, 1), glm::vec4(1.0f));
  if (groom.color.size() == strands && strands > 0) {
    strandFlags_ |= 1;
    for (std::size_t s = 0; s < strands; ++s)
      attributes[s] = glm::vec4(glm::clamp(groom.color[s], 0.0f, 1.0f), 1.0f);
  }
  if (groom.thickness.size() == strands && strands > 0) {
    double sum = 0.0;
    for (float t : groom.thickness) sum += std::max(t, 0.0f);
    const double mean = sum / double(strands);
    if (mean > 0.0) {
      strandFlags_ |= 2;
      // Relative to the groom's mean, so render.strand_width stays the typical width.
      for (std::size_t s = 0; s < strands; ++s)
        attributes[s].a = float(std::clamp(groom.thickness[s] / mean, 0.1, 4.0));
    }
  }
  strandAttributes_ = gl::Buffer(attributes, GL_STATIC_DRAW);

  std::vector<std::uint32_t> strip, lines;
  guides_ = 0;
  for (std::size_t s = 0; s < strands; ++s) {
    const std::uint32_t n = groom.strandSize(s);
    if (n < 2) continue;  // a single point draws nothing
    ++guides_;
    const std::uint32_t base = std::uint32_t(s) << (pointBits_ + 1);
    const std::uint32_t points = (n - 1) * std::uint32_t(subdivision_) + 1;
    for (std::uint32_t p = 0; p < points; ++p) {
      strip.push_back(base | p << 1);
      strip.push_back(base | p << 1 | 1u);
    }
    strip.push_back(kRestart);
    const std::uint32_t shadowPoints = (n - 1) * std::uint32_t(shadowSubdivision_) + 1;
    for (std::uint32_t p = 0; p < shadowPoints; ++p) lines.push_back(base | p << 1);
    lines.push_back(kRestart);
  }
  stripCount_ = GLsizei(strip.size());
  lineCount_ = GLsizei(lines.size());
  if (strip.empty()) strip.push_back(kRestart);
  if (lines.empty()) lines.push_back(kRestart);
  stripIndices_ = gl::Buffer(strip, GL_STATIC_DRAW);
  lineIndices_ = gl::Buffer(lines, GL_STATIC_DRAW);
  stripVao_.setIndexBuffer(stripIndices_);
  lineVao_.setIndexBuffer(lineIndices_);

  // A sphere in the head's frame that holds the hair wherever it swings: no particle gets
  // further from its root than the strand's length (plus the strain limit's slack).
  glm::vec3 lo(0.0f), hi(0.0f);
  if (!groom.points.empty()) lo = hi = groom.points[0];
  for (const glm::vec3& p : groom.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  for (const Sphere& sp : config.head.spheres) {
    lo = glm::min(lo, sp.center - sp.radius);
    hi = glm::max(hi, sp.center + sp.radius);
  }
  boundCenter_ = 0.5f * (lo + hi);
  float radius = 0.05f;
  for (const Sphere& sp : config.head.spheres)
    radius = std::max(radius, glm::length(sp.center - boundCenter_) + sp.radius);
  for (std::size_t s = 0; s < strands; ++s) {
    const std::uint32_t f = groom.first[s], n = groom.strandSize(s);
    float length = 0.0f;
    for (std::uint32_t i = 1; i < n; ++i)
      length += glm::length(groom.points[f + i] - groom.points[f + i - 1]);
    if (n > 0)
      radius = std::max(radius, glm::length(groom.points[f] - boundCenter_) + 1.1f * length);
  }
  boundRadius_ = radius + 0.01f;
  updateScalp(groom, config.head.spheres);
}

void HairRenderer::updateScalp(const Groom& groom, const std::vector<Sphere>& spheres) {
  // Where the roots are, per head sphere, blurred into a density. The head shader paints the
  // scalp in the hair's root colour there, so the gaps between strands show hair-coloured
  // scalp rather than bare skin, as on a real head.
  constexpr int kSize = 128;
  const int layers = std::max<int>(1, int(std::min<std::size_t>(spheres.size(), 64)));
  std::vector<float> count(std::size_t(layers) * kSize * kSize, 0.0f);
  std::vector<glm::vec3> colour(count.size(), glm::vec3(0.0f));
  const bool groomColours = groom.color.size() == groom.strandCount();
  for (std::size_t s = 0; s < groom.strandCount(); ++s) {
    if (groom.strandSize(s) == 0) continue;
    const glm::vec3 root = groom.points[groom.first[s]];
    int best = -1;
    float bestGap = 0.0f;
    for (int k = 0; k < layers && k < int(spheres.size()); ++k) {
      const float gap = std::abs(glm::length(root - spheres[k].center) - spheres[k].radius);
      if (best < 0 || gap < bestGap) best = k, bestGap = gap;
    }
    if (best < 0 || bestGap > 0.02f) continue;  // not on any sphere
    const glm::vec3 d = root - spheres[best].center;
    if (glm::length(d) < 1e-9f) continue;
    const glm::vec2 uv = octahedral(glm::normalize(d));
    const int x = std::clamp(int(uv.x * kSize), 0, kSize - 1);
    const int y = std::clamp(int(uv.y * kSize), 0, kSize - 1);
    const std::size_t i = (std::size_t(best) * kSize + std::size_t(y)) * kSize + std::size_t(x);
    count[i] += 1.0f;
    if (groomColours) colour[i] += groom.color[s];
  }
  // Two passes of a 5x5 box: roots a few millimetres apart merge into one scalp.
  auto blur = [&](auto& v) {
    auto tmp = v;
    for (int pass = 0; pass < 2; ++pass)
      for (int axis = 0; axis < 2; ++axis) {
        for (int l = 0; l < layers; ++l)
          for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
              auto sum = v[0] * 0.0f;
              for (int o = -2; o <= 2; ++o) {
                const int xx = axis == 0 ? std::clamp(x + o, 0, kSize - 1) : x;
                const int yy = axis == 1 ? std::clamp(y + o, 0, kSize - 1) : y;
                sum += v[(std::size_t(l) * kSize + std::size_t(yy)) * kSize + std::size_t(xx)];
              }
              tmp[(std::size_t(l) * kSize + std::size_t(y)) * kSize + std::size_t(x)] = sum / 5.0f;
            }
        std::swap(v, tmp);
      }
  };
  blur(count);
  if (groomColours) blur(colour);
  std::vector<std::uint8_t> texels(count.size() * 4);
  for (std::size_t i = 0; i < count.size(); ++i) {
    // One root per ten texels already reads as a covered scalp.
    const float coverage = std::clamp(count[i] / 0.1f, 0.0f, 1.0f);
    const glm::vec3 c = groomColours && count[i] > 0.0f ? colour[i] / count[i] : glm::vec3(0.0f);
    texels[i * 4 + 0] = std::uint8_t(std::lround(std::clamp(c.r, 0.0f, 1.0f) * 255.0f));
    texels[i * 4 + 1] = std::uint8_t(std::lround(std::clamp(c.g, 0.0f, 1.0f) * 255.0f));
    texels[i * 4 + 2] = std::uint8_t(std::lround(std::clamp(c.b, 0.0f, 1.0f) * 255.0f));
    texels[i * 4 + 3] = std::uint8_t(std::lround(coverage * 255.0f));
  }
  scalp_ = gl::Texture::create2DArray(GL_RGBA8, kSize, kSize, layers);
  scalp_.setFilter(GL_LINEAR, GL_LINEAR).setWrap(GL_CLAMP_TO_EDGE);
  scalp_.setSubImage(0, 0, 0, 0, kSize, kSize, layers, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
}

void HairRenderer::updateShadowMaps(int size) {
  if (size == shadowSize_) return;
  shadowSize_ = size;
  lightDepth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, size, size);
  lightDepth_.setFilter(GL_NEAREST, GL_NEAREST).setWrap(GL_CLAMP_TO_EDGE);
  headShadow_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, size, size);
  headShadow_.setFilter(GL_LINEAR, GL_LINEAR)
      .setWrap(GL_CLAMP_TO_EDGE)
      .setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE)
      .setParameter(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // Half floats: layers sum a few hundred strand opacities at most, and blending them is
  // cheaper than in 32-bit floats.
  opacityLayers_ = gl::Texture::create2D(GL_RGBA16F, size, size);
  opacityLayers_.setFilter(GL_NEAREST, GL_NEAREST).setWrap(GL_CLAMP_TO_EDGE);

  lightDepthFbo_ = gl::Framebuffer();
  lightDepthFbo_.attach(GL_DEPTH_ATTACHMENT, lightDepth_).setDrawBuffers({GL_NONE});
  headShadowFbo_ = gl::Framebuffer();
  headShadowFbo_.attach(GL_DEPTH_ATTACHMENT, headShadow_).setDrawBuffers({GL_NONE});
  opacityFbo_ = gl::Framebuffer();
  opacityFbo_.attach(GL_COLOR_ATTACHMENT0, opacityLayers_).setDrawBuffers({GL_COLOR_ATTACHMENT0});
  for (const gl::Framebuffer* f : {&lightDepthFbo_, &headShadowFbo_, &opacityFbo_}) {
    std::string message;
    if (!f->checkComplete(&message))
      gl::logMessage(gl::LogLevel::Error, "HairRenderer: shadow maps: " + message);
  }
}

void HairRenderer::updateTargets(int width, int height, int samples) {
  if (width == targetWidth_ && height == targetHeight_ && samples == samples_) return;
  targetWidth_ = width;
  targetHeight_ = height;
  samples_ = samples;
  if (samples > 1) {
    color_ = gl::Texture::create2DMultisample(GL_RGBA16F, width, height, samples);
    // The driver may round the count up; the shaders must loop over what it made.
    GLint made = samples;
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, color_.id());
    glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &made);
    samples_ = std::max(1, int(made));
    depth_ = gl::Renderbuffer(GL_DEPTH_COMPONENT24, width, height, samples_);
  } else {
    color_ = gl::Texture::create2D(GL_RGBA16F, width, height);
    color_.setFilter(GL_NEAREST, GL_NEAREST);
    depth_ = gl::Renderbuffer(GL_DEPTH_COMPONENT24, width, height, 0);
  }
  sceneFbo_ = gl::Framebuffer();
  sceneFbo_.attach(GL_COLOR_ATTACHMENT0, color_)
      .attach(GL_DEPTH_ATTACHMENT, depth_)
      .setDrawBuffers({GL_COLOR_ATTACHMENT0});
  std::string message;
  if (!sceneFbo_.checkComplete(&message))
    gl::logMessage(gl::LogLevel::Error, "HairRenderer: frame target: " + message);
}

void HairRenderer::updateUniforms(const FrameView& frame) {
  const Config& c = *frame.scene;
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
  const glm::vec3 center = glm::vec3(frame.head.apply(glm::dvec3(boundCenter_)));
  const float R = boundRadius_;
  const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::mat4 lightView = glm::lookAt(center - dir * R, center, up);
  lightViewProj_ = glm::ortho(-R, R, -R, R, 0.0f, 2.0f * R) * lightView;

  FrameUniforms u{};
  u.viewProj = proj * view;
  u.lightViewProj = lightViewProj_;
  u.headRotation = glm::mat4(glm::mat3_cast(glm::quat(frame.head.rotation)));
  u.eye = glm::vec4(eye, 1.0f);
  u.lightDir = glm::vec4(dir, look.light.intensity);
  u.lightColor = glm::vec4(srgbToLinear(look.light.color), look.light.ambient);
  u.rootColor = glm::vec4(srgbToLinear(r.rootColor), r.colorVariation);
  u.tipColor = glm::vec4(srgbToLinear(r.tipColor), std::clamp(r.opacity, 0.0f, 1.0f));
  u.specShift =
      glm::vec4(r.specularShift1, r.specularShift2, r.specularExponent1, r.specularExponent2);
  u.specStrength = glm::vec4(r.specularStrength1, r.specularStrength2, r.strandWidth,
                             std::max(r.layerSpacing, 1e-5f));
  u.headColor = glm::vec4(srgbToLinear(r.headColor), r.shadows ? 1.0f : 0.0f);
  u.background = glm::vec4(srgbToLinear(r.background), 1.0f);
  u.viewport = glm::vec4(float(frame.width), float(frame.height), 1.0f / float(frame.width),
                         1.0f / float(frame.height));
  // Orthographic depth is linear: one unit of depth is the whole 2R of the light's box.
  u.lightRange = glm::vec4(2.0f * R, float(shadowSize_), 1.0f / float(shadowSize_), 0.0f);
  u.follow = glm::vec4(c.hairstyle.followSpread, kFollowTipSpread, 0.0f, 0.0f);
  u.counts =
      glm::ivec4(subdivision_, std::max(c.hairstyle.followCount, 0), pointBits_, strandFlags_);
  u.counts2 = glm::ivec4(shadowSubdivision_, headSphereCount_, 0, 0);
  frameUniforms_.setSubData(0, sizeof(u), &u);
}

void HairRenderer::drawHair(GLenum mode, bool shadowPass) const {
  const GLsizei count = shadowPass ? lineCount_ : stripCount_;
  if (count == 0 || drawnStrands_ == 0) return;
  (shadowPass ? lineVao_ : stripVao_).bind();
  const GLsizei instances = GLsizei(drawnStrands_ / std::max<std::size_t>(guides_, 1));
  glDrawElementsInstanced(mode, count, GL_UNSIGNED_INT, nullptr, instances);
  gl::maybeCheckErrors("HairRenderer::drawHair");
}

void HairRenderer::drawHead() const {
  if (headSphereCount_ == 0) return;
  headVao_.bind();
  glDrawElementsInstanced(GL_TRIANGLES, sphereIndexCount_, GL_UNSIGNED_INT, nullptr,
                          headSphereCount_);
  gl::maybeCheckErrors("HairRenderer::drawHead");
}

void HairRenderer::render(const FrameView& frame) {
  if (!frame.scene || !frame.look || !frame.groom || frame.width <= 0 || frame.height <= 0) return;
  const Config& c = *frame.scene;
  const RenderConfig& look = frame.look->render;
  GlStateBackup backup;
  if (timers_ && !synchronousTiming_) timer_.beginFrame();

  const int samples = std::clamp(look.samples, 1, maxSamples_);
  updateTopology(frame);
  updateTargets(frame.width, frame.height, samples);
  if (programSamples_ != samples_) {
    std::string log;
    if (!buildPrograms(samples_, &log)) gl::logMessage(gl::LogLevel::Error, "HairRenderer: " + log);
  }
  updateShadowMaps(std::clamp(look.shadowMapSize, 16, 8192));

  const std::vector<Sphere> spheres = worldSpheres(c.head.spheres, frame.head);
  std::vector<glm::vec4> sphereData;
  for (const Sphere& s : spheres) sphereData.emplace_back(s.center, s.radius);
  headSphereCount_ = GLsizei(sphereData.size());
  if (!sphereData.empty()) headSpheres_.upload(sphereData);

  drawnStrands_ = frame.positionBuffer != 0
                      ? guides_ * std::size_t(1 + std::max(c.hairstyle.followCount, 0))
                      : 0;
  updateUniforms(frame);

  // The solver may have written the positions from a compute shader.
  gl::memoryBarrier(gl::Barrier::Storage);
  frameUniforms_.bindBase(GL_UNIFORM_BUFFER, bindings::kFrameUniforms);
  bindStorage(bindings::kPositions, frame.positionBuffer);
  restPositions_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kRestPositions);
  strandFirst_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kStrandFirst);
  (strandFlags_ ? strandAttributes_ : dummyAttributes_)
      .bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kStrandAttributes);
  headSpheres_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::kHeadSpheres);

  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_PRIMITIVE_RESTART);
  glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const Programs& p = *programs_;

  // Shadow: deep opacity maps and the head's depth, from the light. Each stage's timer
  // starts after its first framebuffer is bound: llvmpipe times a query from the first
  // rasterizer command after the begin, and one begun before a bind never starts.
  headShadowFbo_.clearDepth(1.0f);
  opacityFbo_.clearColor(0, std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f});
  lightDepthFbo_.clearDepth(1.0f);
  if (look.shadows) {
    beginStage("shadow");
    glViewport(0, 0, shadowSize_, shadowSize_);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    lightDepthFbo_.bind();
    p.hairDepth.use();
    drawHair(GL_LINE_STRIP, true);

    headShadowFbo_.bind();
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);  // back faces: a lit surface never shadows itself
    p.headDepth.use();
    drawHead();
    glDisable(GL_CULL_FACE);

    // Opacity layers: every hair fragment counts, so no depth test; additive blending.
    opacityFbo_.bind();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    lightDepth_.bind(bindings::kLightDepthUnit);
    p.hairOpacity.use();
    drawHair(GL_LINE_STRIP, true);
    glDisable(GL_BLEND);
  }

  // Head: the backdrop, then the spheres, into the multisampled frame.
  glViewport(0, 0, frame.width, frame.height);
  sceneFbo_.bind();
  beginStage("head");
  sceneFbo_.clearDepth(1.0f);
  lightDepth_.bind(bindings::kLightDepthUnit);
  opacityLayers_.bind(bindings::kOpacityLayersUnit);
  headShadow_.bind(bindings::kHeadShadowUnit);
  scalp_.bind(bindings::kScalpUnit);
  glDisable(GL_DEPTH_TEST);
  p.background.use();
  emptyVao_.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  p.head.use();
  drawHead();
  glDisable(GL_CULL_FACE);

  // Hair: ribbons, both faces (a strip alternates its winding).
  beginStage("hair");
  glEnable(GL_MULTISAMPLE);
  p.hair.use();
  drawHair(GL_TRIANGLE_STRIP, false);

  // Post: tone map each sample, resolve, gamma, into the caller's framebuffer.
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.targetFramebuffer);
  beginStage("post");
  glViewport(0, 0, frame.width, frame.height);
  color_.bind(bindings::kResolvedUnit);
  p.post.use();
  emptyVao_.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  endStages();
  gl::maybeCheckErrors("HairRenderer::render");
}

void HairRenderer::beginStage(const char* name) {
  if (synchronousTiming_) {
    glFinish();
    const auto now = std::chrono::steady_clock::now();
    if (!openStage_.empty())
      frameTimes_.push_back(
          {openStage_, std::chrono::duration<double, std::milli>(now - openStart_).count()});
    openStage_ = name;
    openStart_ = now;
  } else if (timers_) {
    timer_.begin(name);
  }
}

void HairRenderer::endStages() {
  if (synchronousTiming_) {
    beginStage("");
    openStage_.clear();
    lastFrameTimes_ = std::move(frameTimes_);
    frameTimes_.clear();
  } else if (timers_) {
    timer_.end();
  }
}

std::vector<StageTime> HairRenderer::stageTimes() {
  if (synchronousTiming_) return lastFrameTimes_;
  std::vector<StageTime> out;
  if (!timers_) return out;
  timer_.collect();
  for (const gl::StageTimer::Stats& s : timer_.stats()) out.push_back({s.name, s.lastMs});
  return out;
}

glm::mat4 cameraView(const CameraConfig& camera) {
  const float yaw = glm::radians(camera.yaw), pitch = glm::radians(camera.pitch);
  const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                         std::cos(pitch) * std::cos(yaw));
  return glm::lookAt(camera.target + camera.distance * offset, camera.target,
                     glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 cameraProjection(const CameraConfig& camera, float aspect) {
  // The near plane follows the distance so depth precision does too; hair reaches about
  // 0.4 m in front of the target at most.
  const float nearPlane = std::max(0.002f, 0.02f * camera.distance);
  return glm::perspective(glm::radians(camera.fov), aspect, nearPlane, camera.distance + 10.0f);
}

std::size_t drawnStrandCount(std::size_t simulatedStrands, const Config& config) {
  return simulatedStrands * std::size_t(1 + std::max(config.hairstyle.followCount, 0));
}

}  // namespace csm
