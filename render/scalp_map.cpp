#include "render/scalp_map.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/mannequin.h"
#include "sim/head/head_model.h"

namespace csm {
namespace {

constexpr int kSize = 256;  // about 2 mm a texel on the mannequin's scalp
// Passes of a 5-texel box per axis: about a Gaussian of 2 sqrt(passes) texels (8 mm).
constexpr int kBlurPasses = 8;

// kBlurPasses of a 5x5 box over each layer: roots a few millimetres apart merge into one
// scalp.
template <class T>
void blur(std::vector<T>& v, int layers) {
  std::vector<T> tmp = v;
  auto at = [](int l, int y, int x) {
    return (std::size_t(l) * kSize + std::size_t(y)) * kSize + std::size_t(x);
  };
  for (int pass = 0; pass < kBlurPasses; ++pass)
    for (int axis = 0; axis < 2; ++axis) {
      for (int l = 0; l < layers; ++l)
        for (int y = 0; y < kSize; ++y)
          for (int x = 0; x < kSize; ++x) {
            T sum = v[0] * 0.0f;
            for (int o = -2; o <= 2; ++o) {
              const int xx = axis == 0 ? std::clamp(x + o, 0, kSize - 1) : x;
              const int yy = axis == 1 ? std::clamp(y + o, 0, kSize - 1) : y;
              sum += v[at(l, yy, xx)];
            }
            tmp[at(l, y, x)] = sum / 5.0f;
          }
      std::swap(v, tmp);
    }
}

std::uint8_t unorm8(float c) {
  return std::uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
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

ScalpTexels scalpTexels(const Groom& groom, const std::vector<Sphere>& spheres) {
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
  blur(count, layers);
  if (groomColours) blur(colour, layers);
  // Coverage against the typical density of roots where hair grows (the median over texels
  // holding a tenth of the densest one or more): full inside, none where the density falls
  // under 0.4 of it, so the first few millimetres inside a hairline or a parting show the
  // strands over skin, as the hair there thins, and the paint fades in behind them.
  std::vector<float> grown;
  const float densest = count.empty() ? 0.0f : *std::max_element(count.begin(), count.end());
  for (float c : count)
    if (c > 0.1f * densest) grown.push_back(c);
  float typical = 0.1f;
  if (!grown.empty()) {
    std::nth_element(grown.begin(), grown.begin() + std::ptrdiff_t(grown.size() / 2), grown.end());
    typical = std::max(grown[grown.size() / 2], 1e-3f);
  }
  ScalpTexels out;
  out.size = kSize;
  out.layers = layers;
  out.rgba.resize(count.size() * 4);
  for (std::size_t i = 0; i < count.size(); ++i) {
    const float t = std::clamp((count[i] / typical - 0.4f) / 0.6f, 0.0f, 1.0f);
    const float coverage = t * t * (3.0f - 2.0f * t);
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

gl::Texture makeScalpMap(const Groom& groom, const std::vector<Sphere>& spheres) {
  const ScalpTexels t = scalpTexels(groom, spheres);
  gl::Texture map = gl::Texture::create2DArray(gl::TextureFormat::Rgba8, t.size, t.size, t.layers);
  map.setFilter(gl::Filter::Linear, gl::Filter::Linear).setWrap(gl::Wrap::ClampToEdge);
  map.setSubImage(0, 0, 0, 0, t.size, t.size, t.layers, gl::PixelFormat::Rgba,
                  gl::PixelType::UnsignedByte, t.rgba.data());
  return map;
}

}  // namespace csm
