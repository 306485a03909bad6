// The scalp's darkening (render/scalp_map.h) from the roots' real density: a dense groom covers
// its scalp; a sparse one (100 strands, one strand) darkens it a little and evenly, never a
// blotch a root.
#include <algorithm>
#include <vector>

#include <catch2/catch.hpp>

#include "app/preset.h"
#include "render/scalp_map.h"
#include "sim/groom/hairstyle.h"
#include "sim/head/head_model.h"

using namespace csm;

namespace {

struct Spread {
  float max = 0.0f;     // the most covered texel
  float median = 0.0f;  // over the texels covered a quarter of that or more
};

Spread spread(const ScalpTexels& t) {
  Spread s;
  s.max = *std::max_element(t.coverage.begin(), t.coverage.end());
  std::vector<float> grown;
  for (const float c : t.coverage)
    if (c >= 0.25f * s.max && c > 0.0f) grown.push_back(c);
  if (grown.empty()) return s;
  std::nth_element(grown.begin(), grown.begin() + long(grown.size() / 2), grown.end());
  s.median = grown[grown.size() / 2];
  return s;
}

ScalpTexels texelsOf(int strands, float perRoot) {
  Config c = defaultPreset().scene;
  c.hairstyle.strands = strands;
  const auto head = HeadModel::require(c);
  return scalpTexels(growHairstyle(c, *head), scalpSpheres(*head), perRoot);
}

}  // namespace

TEST_CASE(
    "the scalp's darkening follows the roots' density: full under a dense groom, faint and "
    "even under a sparse one",
    "[render][scalp][quick]") {
  // The default hairstyle as drawn: 3,000 strands, 6 children each.
  const Spread dense = spread(texelsOf(3000, 7.0f));
  INFO("dense: max " << dense.max << ", median " << dense.median);
  CHECK(dense.median > 0.9f);
  // 100 strands and no children: a trace of colour, not a spot at each root (a normalisation
  // to the groom's own typical density paints every root's blur full: max 1).
  const Spread sparse = spread(texelsOf(100, 1.0f));
  INFO("100 strands: max " << sparse.max << ", median " << sparse.median);
  CHECK(sparse.max < 0.1f);
  CHECK(sparse.max < 2.5f * sparse.median);  // even: no peak over each root
  // The same with their children: thin hair, still even.
  const Spread drawn = spread(texelsOf(100, 7.0f));
  INFO("100 strands drawn with 6 children: max " << drawn.max << ", median " << drawn.median);
  CHECK(drawn.max < 0.5f);
  CHECK(drawn.max < 2.5f * drawn.median);
  // One strand: next to nothing.
  CHECK(spread(texelsOf(1, 1.0f)).max < 0.01f);
}
