// What every hair pass draws from: the groom's topology on the GPU. Each drawn vertex is an
// index that packs guide, spline point and ribbon side into 32 bits (hair_common.glsl
// unpacks it and pulls the particle positions from the SSBO); follow hairs are instances of
// their guide. Rebuilt only when the groom or the subdivision changes.
//
// Guides are laid out in the index buffers in a shuffled order, so that the first k of them
// are an even sample of the head: drawing a share of the strands draws a prefix.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "sim/core/groom.h"
#include "sim/core/config.h"

namespace csm {

class StrandGeometry {
 public:
  // Rebuilds when `generation`, the groom or the subdivision changed; true when it did.
  bool update(const Groom& groom, long generation, int subdivision,
              const std::vector<Sphere>& spheres);

  // Binds the rest positions, the strand offsets and the per-strand attributes.
  void bind() const;
  // Ribbons (triangle strips, two vertices per spline point) of the first `guides` guides,
  // `instances` strands each (the guide and its first follow hairs).
  void drawRibbons(std::size_t guides, int instances) const;
  // Line strips at the shadow passes' subdivision.
  void drawLines(std::size_t guides, int instances) const;

  std::size_t guides() const { return guides_; }  // strands with at least one segment
  int subdivision() const { return subdivision_; }
  int shadowSubdivision() const { return shadowSubdivision_; }
  int pointBits() const { return pointBits_; }
  int strandFlags() const { return strandFlags_; }  // 1: groom colours, 2: groom thickness
  // A sphere in the head's frame that holds hair and head wherever the hair swings.
  glm::vec3 boundCenter() const { return boundCenter_; }
  float boundRadius() const { return boundRadius_; }

  // The order guides are drawn in (for tests): a permutation of the drawable strands.
  const std::vector<std::uint32_t>& guideOrder() const { return order_; }

 private:
  void draw(const gl::VertexArray& vao, const std::vector<std::size_t>& prefix, unsigned mode,
            std::size_t guides, int instances) const;

  struct Key {
    long generation = -1;
    const Groom* groom = nullptr;
    std::size_t strands = 0, points = 0;
    int subdivision = 0;
    bool operator==(const Key&) const = default;
  } key_;
  gl::Buffer restPositions_{gl::NoCreate}, strandFirst_{gl::NoCreate},
      strandAttributes_{gl::NoCreate}, dummyAttributes_{gl::NoCreate};
  gl::Buffer stripIndices_{gl::NoCreate}, lineIndices_{gl::NoCreate};
  gl::VertexArray stripVao_{gl::NoCreate}, lineVao_{gl::NoCreate};
  // Index counts of the first k guides, k = 0..guides.
  std::vector<std::size_t> stripPrefix_, linePrefix_;
  std::vector<std::uint32_t> order_;
  int subdivision_ = 1, shadowSubdivision_ = 1, pointBits_ = 1, strandFlags_ = 0;
  std::size_t guides_ = 0;
  glm::vec3 boundCenter_{0.0f};
  float boundRadius_ = 0.5f;
};

}  // namespace csm
