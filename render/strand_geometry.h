// What every hair pass draws from: the groom's topology on the GPU and the buffers the
// render's compute passes fill each frame (shaders/render/hair_common.glsl).
//
// A guide (simulated strand) is drawn through its spline points, render.subdivision per
// simulated segment; its children (render.children) each have as many points. Index
// buffers list spline points for the guides (ribbons, two triangles a segment; the shadow
// passes' lines, every shadowStride()-th point) and child points for the children (line
// segments, a child having a point every childStride()-th spline point of its guide). Rebuilt when
// the groom or the subdivision changes; the children's when their count does.
//
// Guides are laid out in the index buffers in a shuffled order, so that the first k of them
// are an even sample of the head: drawing a share of the strands draws a prefix.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "sim/core/config.h"
#include "sim/core/groom.h"

namespace csm {

// Where each strand's children go, from the roots at rest (head frame): the hair's density
// around each root (1 inside, about 0.5 on a hairline or parting, where children thin out),
// the way into the hair from there, and the nearest strand growing the same way (children
// between two guides follow both). Two vec4 per strand, as hair_common.glsl reads them.
struct GuideLinks {
  std::vector<glm::vec4> data;  // [2s]: inward (frame's normal, binormal), 0, density;
                                // [2s + 1]: neighbour (uint bits), its distance, spacing
  float spacing = 0.0f;         // the typical distance between neighbouring roots (m)
};
GuideLinks guideLinks(const Groom& groom);

class StrandGeometry {
 public:
  // Rebuilds when `generation`, the groom or the subdivision changed; true when it did.
  bool update(const Groom& groom, long generation, int subdivision,
              const std::vector<Sphere>& spheres);
  // Lays out `children` children per guide (buffers and index lists rebuilt when the count
  // changes). Returns the children that fit in kMaxChildBytes: fewer than asked only for
  // the largest grooms.
  int setChildren(int children);
  static constexpr std::size_t kMaxChildBytes = std::size_t(768) << 20;
  int children() const { return children_; }
  // On a software rasterizer long draws go in chunks, each waiting for the one before the last:
  // its binned triangles (llvmpipe keeps every flushed chunk's until its threads have drawn it)
  // stay a few chunks' worth.
  void setPaced(bool paced) { paced_ = paced; }
  // The most indices a paced draw issues at once (whole triangles and lines: a multiple of 6).
  static constexpr std::size_t kDrawChunk = std::size_t(6) << 16;

  // Binds every buffer the hair shaders and compute passes read or write.
  void bind() const;
  // The first `guides` guides: ribbons (two triangles per spline segment), or line segments
  // at the shadow passes' step.
  void drawRibbons(std::size_t guides) const;
  void drawGuideLines(std::size_t guides) const;
  // Guides thinner than a pixel: line segments at the shadow passes' step.
  void drawThinGuides(std::size_t guides) const;
  // The first `children` children of every guide: line segments (the same in the shadow
  // passes and the picture).
  void drawChildren(int children) const;

  std::size_t guides() const { return guides_; }  // strands with at least one segment
  std::size_t splinePoints() const { return splinePoints_; }
  std::size_t childPoints() const { return childRun_; }  // points of one child of each guide
  int childStride() const { return childStride_; }       // spline points per child point step
  int subdivision() const { return subdivision_; }
  int shadowStride() const { return shadowStride_; }  // spline points per shadow line step
  int strandFlags() const { return strandFlags_; }    // 1: groom colours, 2: groom thickness
  float rootSpacing() const { return links_.spacing; }
  // A sphere in the head's frame that holds hair and head wherever the hair swings.
  glm::vec3 boundCenter() const { return boundCenter_; }
  float boundRadius() const { return boundRadius_; }

  // The order guides are drawn in (for tests): a permutation of the drawable strands.
  const std::vector<std::uint32_t>& guideOrder() const { return order_; }
  // This frame's points, for tests: vec4 per guide spline point (position, s), and per child
  // point (position, shadow opacity share or -1) in hair_children.comp's layout.
  const gl::Buffer& guidePoints() const { return guidePoints_; }
  const gl::Buffer& childPointBuffer() const { return childPoints_; }
  const std::vector<std::uint32_t>& splineFirst() const { return splineFirstHost_; }
  const std::vector<std::uint32_t>& childFirst() const { return childFirstHost_; }
  const GuideLinks& links() const { return links_; }

 private:
  // The first `count` entries of `prefix` (guides or child ranks).
  void draw(const gl::VertexArray& vao, const std::vector<std::size_t>& prefix, gl::Primitive mode,
            std::size_t count) const;

  struct Key {
    long generation = -1;
    const Groom* groom = nullptr;
    std::size_t strands = 0, points = 0;
    int subdivision = 0;
    bool operator==(const Key&) const = default;
  } key_;
  gl::Buffer restPositions_{gl::NoCreate}, strandFirst_{gl::NoCreate},
      strandAttributes_{gl::NoCreate}, dummyAttributes_{gl::NoCreate};
  gl::Buffer splineFirst_{gl::NoCreate}, pointStrand_{gl::NoCreate}, guideLinks_{gl::NoCreate},
      childFirst_{gl::NoCreate}, childStrand_{gl::NoCreate};
  gl::Buffer guidePoints_{gl::NoCreate}, guideTangents_{gl::NoCreate}, guideFrames_{gl::NoCreate},
      guideShade_{gl::NoCreate}, childPoints_{gl::NoCreate}, childColors_{gl::NoCreate};
  gl::Buffer stripIndices_{gl::NoCreate}, shadowIndices_{gl::NoCreate}, childIndices_{gl::NoCreate};
  gl::VertexArray stripVao_{gl::NoCreate}, shadowVao_{gl::NoCreate}, childVao_{gl::NoCreate};
  // Index counts of the first k guides, k = 0..guides, and of the first k child ranks.
  std::vector<std::size_t> stripPrefix_, shadowPrefix_, childPrefix_;
  std::vector<std::uint32_t> order_, splineFirstHost_, childFirstHost_;
  GuideLinks links_;
  std::size_t splinePoints_ = 0, childRun_ = 0;
  int children_ = -1;  // children per guide laid out; -1: none yet
  int subdivision_ = 1, shadowStride_ = 1, childStride_ = 1, strandFlags_ = 0;
  bool paced_ = false;
  std::size_t guides_ = 0;
  glm::vec3 boundCenter_{0.0f};
  float boundRadius_ = 0.5f;
};

}  // namespace csm
