// A groom: the rest shape of every strand in the head's local frame, before simulation.
// Built by the hairstyle generator (sim/groom/hairstyle.h) or read from a file (sim/groom/).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace csm {

// The most particles a strand may have: the GPU solver keeps a strand's prefix sums in a
// shader's private arrays of this size at most. Grooms with longer strands are refused.
inline constexpr uint32_t kMaxStrandParticles = 256;

struct Groom {
  // Strand s owns points [first[s], first[s + 1]); first.size() == strandCount() + 1.
  std::vector<uint32_t> first{0};
  // Rest positions in the head's local frame, metres, y up. Point first[s] is the root.
  std::vector<glm::vec3> points;
  // Optional per-strand data from a groom file; empty when the file has none.
  std::vector<glm::vec3> color;  // linear RGB, 0..1
  std::vector<float> thickness;  // metres
  // 1 where the head holds the strand's last point as it holds the root (a ponytail tied at the
  // nape, a braid, a bun: TressFX's bothEndsImmovable); empty when no strand's is held.
  std::vector<uint8_t> tipHeld;
  // Per strand: how many strands of the groom it is drawn for stands for (a guide: itself and
  // its followers' binding weights, FollowerBinding::guideGroom); empty when each strand stands
  // for itself. The volume mode splats each strand this many times over (sim/solver/volume.h).
  std::vector<float> weight;
  // Per strand: the follow hairs a file asks to be drawn about it (a TressFX project's pieces);
  // empty when it asks for none. The scene makes them (sim/groom/follow_hairs.h) and simulates the
  // file's strands as their guides.
  struct FollowHairs {
    uint32_t count = 0;          // follow hairs about this strand
    float radius = 0.0f;         // their roots lie within this of the strand's root (groom units)
    float tipSeparation = 0.0f;  // how much further from the strand they are at the tip: 1 = twice
  };
  std::vector<FollowHairs> follow;

  size_t strandCount() const { return first.size() - 1; }
  size_t pointCount() const { return points.size(); }
  uint32_t strandSize(size_t s) const { return first[s + 1] - first[s]; }
  bool holdsTip(size_t s) const { return s < tipHeld.size() && tipHeld[s] != 0; }
  float weightOf(size_t s) const { return s < weight.size() ? weight[s] : 1.0f; }

  void addStrand(const std::vector<glm::vec3>& strandPoints) {
    points.insert(points.end(), strandPoints.begin(), strandPoints.end());
    first.push_back(static_cast<uint32_t>(points.size()));
  }
  // Appends strand s's own data from `from` (colour, thickness, held tip: each where `from` has
  // it), for a groom built strand by strand from another.
  void addStrandData(const Groom& from, size_t s) {
    if (s < from.color.size()) color.push_back(from.color[s]);
    if (s < from.thickness.size()) thickness.push_back(from.thickness[s]);
    if (s < from.tipHeld.size()) tipHeld.push_back(from.tipHeld[s]);
    if (s < from.weight.size()) weight.push_back(from.weight[s]);
    if (s < from.follow.size()) follow.push_back(from.follow[s]);
  }
};

}  // namespace csm
