#include "render/scalp_map.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/base/point_grid.h"
#include "sim/head/mannequin.h"
#include "sim/head/head_model.h"

namespace csm {
namespace {

constexpr int kSize = 256;  // about 1.3 mm a texel on the mannequin's scalp (0.09 m)
// The blur's reach: at least this, and at least the roots' typical spacing, so that each root
// spreads to its neighbours and a sparse groom paints a thin, even density, never a spot a root.
constexpr float kMinBlur = 0.008f;  // m
constexpr float kMaxBlur = 0.03f;   // m: a groom of a few strands is a faint wash, not a map
// Drawn strands a square metre at which the scalp is 63 % covered (1 - 1/e): 15 a square
// centimetre. The default hairstyle draws about 50 (3,000 strands and 6 children each over some
// 400 cm^2): covered; its 3,000 strands alone about 7 (a half); 100 strands alone, a trace.
constexpr float kCoveringDensity = 1.5e5f;

std::size_t texel(int l, int y, int x) {
  return (std::size_t(l) * kSize + std::size_t(y)) * kSize + std::size_t(x);
}

// `passes` of a 5-texel box per axis over each layer: about a Gaussian of sqrt(2 passes) texels.
template <class T>
void blur(std::vector<T>& v, int layers, int passes) {
  std::vector<T> tmp = v;
  for (int pass = 0; pass < passes; ++pass)
    for (int axis = 0; axis < 2; ++axis) {
      for (int l = 0; l < layers; ++l)
        for (int y = 0; y < kSize; ++y)
          for (int x = 0; x < kSize; ++x) {
            T sum = v[0] * 0.0f;
            for (int o = -2; o <= 2; ++o) {
              const int xx = axis == 0 ? std::clamp(x + o, 0, kSize - 1) : x;
              const int yy = axis == 1 ? std::clamp(y + o, 0, kSize - 1) : y;
              sum += v[texel(l, yy, xx)];
            }
            tmp[texel(l, y, x)] = sum / 5.0f;
          }
      std::swap(v, tmp);
    }
}

std::uint8_t unorm8(float c) {
  return std::uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// The unit direction of a point of the octahedral map (octahedral()'s inverse).
glm::vec3 fromOctahedral(glm::vec2 uv) {
  const glm::vec2 p = uv * 2.0f - 1.0f;
  glm::vec3 d(p.x, p.y, 1.0f - std::abs(p.x) - std::abs(p.y));
  if (d.z < 0.0f)
    d = glm::vec3((1.0f - std::abs(p.y)) * (p.x >= 0.0f ? 1.0f : -1.0f),
                  (1.0f - std::abs(p.x)) * (p.y >= 0.0f ? 1.0f : -1.0f), d.z);
  return glm::normalize(d);
}

// The solid angle of each texel of a layer (the map is not equal-area), from its corners.
std::vector<float> texelSolidAngles() {
  std::vector<float> a(std::size_t(kSize) * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float u0 = float(x) / kSize, u1 = float(x + 1) / kSize;
      const float v0 = float(y) / kSize, v1 = float(y + 1) / kSize;
      const glm::vec3 d00 = fromOctahedral({u0, v0}), d10 = fromOctahedral({u1, v0});
      const glm::vec3 d01 = fromOctahedral({u0, v1}), d11 = fromOctahedral({u1, v1});
      a[std::size_t(y) * kSize + std::size_t(x)] =
          0.5f * (glm::length(glm::cross(d10 - d00, d01 - d00)) +
                  glm::length(glm::cross(d10 - d11, d01 - d11)));
    }
  return a;
}

// The median distance from a root to its nearest neighbour (over at most 2,000 of them, spread
// over the groom), at most kMaxBlur; kMaxBlur for fewer than two roots.
float rootSpacing(const std::vector<glm::vec3>& roots) {
  if (roots.size() < 2) return kMaxBlur;
  const PointGrid grid(roots, kMaxBlur);
  const std::size_t step = std::max<std::size_t>(1, roots.size() / 2000);
  std::vector<float> nearest;
  for (std::size_t i = 0; i < roots.size(); i += step) {
    float best = kMaxBlur;
    grid.within(roots[i], kMaxBlur, [&](std::size_t j) {
      if (j != i) best = std::min(best, glm::length(roots[j] - roots[i]));
    });
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2),
                   nearest.end());
  return nearest[nearest.size() / 2];
}

}  // namespace

glm::vec2 octahedral(glm::vec3 d) {
  d /= std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  glm::vec2 p(d.x, d.y);
  if (d.z < 0.0f)
    p = glm::vec2((1.0f - std::abs(d.y)) * (d.x >= 0.0f ? 1.0f : -1.0f),
                  (1.0f - std::abs(d.x)) * (d.y >= 0.0f ? 1.0f : -1.0f));
  return p * 0.5f + 0.5f;
}

ScalpTexels scalpTexels(const Groom& groom, const std::vector<Sphere>& spheres,
                        float strandsPerRoot) {
  const int layers = std::max<int>(1, int(std::min<std::size_t>(spheres.size(), 64)));
  std::vector<float> count(std::size_t(layers) * kSize * kSize, 0.0f);
  std::vector<glm::vec3> colour(count.size(), glm::vec3(0.0f));
  const bool groomColours = groom.color.size() == groom.strandCount();
  std::vector<glm::vec3> roots;
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
    const std::size_t i = texel(best, y, x);
    count[i] += 1.0f;
    if (groomColours) colour[i] += groom.color[s];
    roots.push_back(root);
  }
  // The same blur of the roots and of the texels' areas: their ratio is the roots' density in
  // roots a square metre, whatever the map's distortion.
  const std::vector<float> solid = texelSolidAngles();
  std::vector<float> area(count.size());
  float meanRadius = 0.0f;
  for (int l = 0; l < layers; ++l) {
    const float r =
        l < int(spheres.size()) ? std::max(spheres[std::size_t(l)].radius, 1e-4f) : 0.1f;
    meanRadius += r / float(layers);
    for (std::size_t t = 0; t < solid.size(); ++t)
      area[std::size_t(l) * solid.size() + t] = solid[t] * r * r;
  }
  const float reach = std::clamp(rootSpacing(roots), kMinBlur, kMaxBlur);
  const float texelEdge = meanRadius * std::sqrt(4.0f * 3.14159265f) / float(kSize);
  const float sigma = reach / texelEdge;  // texels
  const int passes = std::clamp(int(std::ceil(sigma * sigma / 2.0f)), 1, 512);
  blur(count, layers, passes);
  blur(area, layers, passes);
  if (groomColours) blur(colour, layers, passes);
  ScalpTexels out;
  out.size = kSize;
  out.layers = layers;
  out.rgba.resize(count.size() * 4);
  out.coverage.resize(count.size());
  for (std::size_t i = 0; i < count.size(); ++i) {
    const float density = area[i] > 0.0f ? strandsPerRoot * count[i] / area[i] : 0.0f;
    const float coverage = 1.0f - std::exp(-density / kCoveringDensity);
    out.coverage[i] = coverage;
    const glm::vec3 c = groomColours && count[i] > 0.0f ? colour[i] / count[i] : glm::vec3(0.0f);
    out.rgba[i * 4 + 0] = unorm8(c.r);
    out.rgba[i * 4 + 1] = unorm8(c.g);
    out.rgba[i * 4 + 2] = unorm8(c.b);
    out.rgba[i * 4 + 3] = unorm8(coverage);
  }
  return out;
}

std::vector<Sphere> scalpSpheres(const HeadModel& head) {
  if (!head.field()) return head.spheres();
  return {Sphere{glm::vec3(kMannequinScalpCentre), 0.09f}};
}

gl::Texture makeScalpMap(const Groom& groom, const std::vector<Sphere>& spheres,
                         float strandsPerRoot) {
  const ScalpTexels t = scalpTexels(groom, spheres, strandsPerRoot);
  gl::Texture map = gl::Texture::create2DArray(gl::TextureFormat::Rgba8, t.size, t.size, t.layers);
  map.setFilter(gl::Filter::Linear, gl::Filter::Linear).setWrap(gl::Wrap::ClampToEdge);
  map.setSubImage(0, 0, 0, 0, t.size, t.size, t.layers, gl::PixelFormat::Rgba,
                  gl::PixelType::UnsignedByte, t.rgba.data());
  return map;
}

}  // namespace csm
