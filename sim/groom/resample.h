// Resampling groom strands to the particle counts the solver wants. Groom files carry
// 50-200 points per strand for rendering; the paper simulates 8-25 particles per strand
// by length and curl (METHOD.md §5), and the picture's smoothness comes from spline
// subdivision at draw time, not from more particles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/groom.h"

namespace csm::io {

struct ResampleOptions {
  uint32_t minParticles = 8;  // paper: 8..25
  uint32_t maxParticles = 25;
  float tolerance = 1e-3f;  // metres: allowed deviation of the resampled polyline
};

struct ResampleStats {
  size_t pointsBefore = 0;
  size_t pointsAfter = 0;
  size_t strandsKept = 0;           // already within [min, max] points: left as they were
  size_t strandsOverTolerance = 0;  // even maxParticles deviate more than the tolerance
  float maxDeviation = 0.0f;        // largest deviation over the resampled strands, metres

  // "The tolerance saved N particles" compared with giving every strand maxParticles is
  // strandCount * maxParticles - pointsAfter; compared with the file, this:
  size_t pointsSaved() const { return pointsBefore > pointsAfter ? pointsBefore - pointsAfter : 0; }
};

// Resamples every strand with more than maxParticles or fewer than minParticles points to
// the smallest count n in [minParticles, maxParticles] whose uniformly arc-length-spaced
// particles (root and tip kept exactly) give a polyline no original point is farther than
// `tolerance` from; maxParticles when none is close enough. Strands already within the
// bounds keep their points. Per-strand colour and thickness are unchanged.
// Options are clamped to 2 <= minParticles <= maxParticles.
ResampleStats resampleGroom(Groom& groom, const ResampleOptions& options);

// `n` (>= 2) points evenly spaced in arc length along the polyline q, in double precision (the
// generator's dense curves): the first and the last at q's ends.
std::vector<glm::dvec3> resamplePolyline(std::span<const glm::dvec3> q, int n);

// `count` (>= 2) points spaced uniformly by arc length along the polyline `strand` (float, as a
// groom file's points are; resampleGroom's).
std::vector<glm::vec3> resampleStrand(std::span<const glm::vec3> strand, uint32_t count);

// The largest distance from a point of `original` to the polyline `resampled` (the exact
// one-sided Hausdorff distance, O(n m); resampleGroom uses a faster local bound).
float polylineDeviation(std::span<const glm::vec3> original, std::span<const glm::vec3> resampled);

}  // namespace csm::io
