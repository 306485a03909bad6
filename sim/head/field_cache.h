// A sampled field kept on disk between runs of the same program: the built-in mannequin's grid
// takes 1.9 s of a core to sample (a million nodes, seven evaluations of its distance each),
// which every start-up, every test process and every fuzz input paid.
//
// An entry is valid only for the executable that wrote it (its device, inode, size and
// modification time), so its nodes are bitwise what that program computes; a rebuilt program
// samples again. Entries live in $CSM_CACHE_DIR, else $XDG_CACHE_HOME/csmhair, else
// ~/.cache/csmhair (CSM_CACHE_DIR set and empty: no cache). Written under a name of the
// writer's own and renamed, so processes that start together never read a half-written one;
// a file that fails its checks (size, header, checksum) is sampled again and replaced. The
// newest few entries of a name are kept.
#pragma once

#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"

namespace csm {

// The folder entries go to ("" when caching is off or no folder can be named).
std::string fieldCacheDir();

// What became of a lookup: no cache folder, read, sampled and written, sampled but not written.
enum class FieldCacheResult { Off, Read, Written, Unwritable };

// sampleDistance(f, lo, hi, cell), read from the cache when this program wrote it there before
// under `name` and the same box and cell, else sampled and written there.
DistanceGrid cachedSampleDistance(std::string_view name, const DistanceFunction& f,
                                  const glm::dvec3& lo, const glm::dvec3& hi, double cell,
                                  FieldCacheResult* result = nullptr);

}  // namespace csm
