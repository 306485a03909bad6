// Guides and followers: a dense groom simulates a few of its own strands (the guides) and
// draws every other strand (a follower) from the guides near it, as the engines of the field do.
// The guides are chosen and the followers bound once, when the scene loads; each frame the
// followers are made from the guides' positions (sim/groom/followers.h on the CPU, the
// renderer's follower pass on the GPU). docs/METHOD.md, "Guides and followers", has the why.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/groom.h"

namespace csm {

// At most this many guides drive a follower.
inline constexpr int kFollowerGuides = 4;
// How many are simulated: guideCount (sim/core/config.h), from hairstyle.guides.

// `count` strands of `groom` spread over it: farthest-point sampling in a distance that adds to
// the roots' distance on the scalp half the distance between the strands' shapes (their middle
// and tip from the root), so the guides cover the scalp, the lengths and the curls. Strands of
// fewer than two points are never chosen. Deterministic; the first k of the sampling are the
// sampling of k. Returned in strand order.
std::vector<std::uint32_t> chooseGuides(const Groom& groom, std::size_t count);

// The drawn groom and how each of its strands follows the guides.
struct FollowerBinding {
  Groom drawn;  // every strand drawn: the scene's groom, rest shape in the head's frame
  std::vector<std::uint32_t> guideStrand;  // per guide: its strand in `drawn`, ascending
  // Per drawn strand: up to kFollowerGuides guides (indices into guideStrand) and their weights,
  // which sum to 1; unused slots have weight 0. A guide's own strand has itself, weight 1.
  std::vector<glm::uvec4> guides;
  std::vector<glm::vec4> weights;
  // Per drawn point: the share of its strand's rest length from the root, 0 at the root and
  // exactly 1 at the tip. A follower's point follows its guides at the same share.
  std::vector<float> share;
  // Followers bound to a guide beyond kBindRadius spacings, or to one whose shape parts from
  // theirs, because no other was there (a lone strand across a gap).
  std::size_t farFollowers = 0;

  std::size_t guideCount() const { return guideStrand.size(); }
  // The groom of the guides alone, in guide order: what is simulated.
  Groom guideGroom() const;
};

// Binds every strand of `drawn` to the guides `guideStrand` (ascending strand indices, as
// chooseGuides returns): the kFollowerGuides guides nearest its root whose shape does not part
// from its own (a guide whose early direction turns more than 60 degrees from the follower's is
// across a parting), weighted by inverse squared distance. Deterministic.
FollowerBinding bindFollowers(Groom drawn, std::vector<std::uint32_t> guideStrand);

// The strands within this many guide spacings of a follower's root are its candidates.
inline constexpr float kBindRadius = 3.0f;

}  // namespace csm
