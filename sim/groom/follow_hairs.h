// Follow hairs as a file asks for them (a TressFX project's pieces: so many follow hairs a guide,
// their roots within a radius of the guide's, their tips further apart by the tip separation):
// made once, when the scene loads, as strands of the groom beside their guides, so that the
// scene simulates the file's strands and draws the follow hairs from them (sim/groom/guides.h).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/groom.h"
#include "sim/groom/growth_head.h"

namespace csm {

// Appends to `g` the follow hairs its strands ask for (Groom::follow, in metres once the groom is
// fitted), then clears the request. A follow hair is its guide displaced across it: the root by
// an offset within the radius, at random about the root's tangent, carried along the strand by
// the turn of its tangent from point to point (parallel transport) and grown towards the tip by
// the tip separation (1 + separation x the share of the length). Its root is put on the head's
// surface and any other point inside the head moved out to `margin`; its colour, thickness and
// held tip are its guide's. Deterministic for `seed`. Returns the guides: the strands `g` had,
// in order (empty when none asked for follow hairs).
std::vector<uint32_t> addFollowHairs(Groom& g, const GrowthHead& head, double margin,
                                     uint64_t seed);

}  // namespace csm
