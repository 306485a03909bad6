// What the ContactSearch (sim/gpu/contact_search.h) holds, read back at once (a GPU stall): for
// tests and tools, never the frame loop, which samples behind fences (sim/gpu/sample_ring.h).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sim/gpu/contact_search.h"

namespace csm::gpu {

// The counters (CSM_COUNTER_*).
std::vector<uint32_t> readCounters(const ContactSearch& grid);
// The candidate pairs closer than 2r (segment, segment); *overflow when the list did not hold
// all the search found.
std::vector<std::pair<uint32_t, uint32_t>> readPairs(const ContactSearch& grid, bool* overflow);
// This frame's candidates of each segment (other segment, contact distance), as
// findCandidates lists them.
std::vector<std::vector<std::pair<uint32_t, float>>> readCandidates(const ContactSearch& grid);
// Which segment each invocation of the list pass and the contact solve takes: the segments of
// each run of CSM_PARTICLE_GROUP by candidate count, most first, ties by index.
std::vector<uint32_t> readSegmentOrder(const ContactSearch& grid);

}  // namespace csm::gpu
