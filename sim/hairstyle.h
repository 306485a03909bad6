// Grows strands from the scalp (the first head sphere), deterministically from a seed.
// Strand s depends only on the seed and s: a smaller strand count is a prefix of a larger one.
#pragma once

#include <string>
#include <vector>

#include "sim/config.h"
#include "sim/groom.h"

namespace csm {

// Particles of one strand chosen by its arc length (curl included), within the preset's bounds:
// the paper's 8-25.
int particlesForLength(const HairstyleConfig& h, double arcLength);

Groom growHairstyle(const HairstyleConfig& h, const std::vector<Sphere>& head,
                    float collisionRadius);

struct GroomReport {
  size_t fileStrands = 0;      // strands in the groom file (0 for the generator)
  size_t filePoints = 0;       // points of the kept strands before resampling
  size_t simulatedPoints = 0;  // particles simulated
  size_t savedPoints() const {
    return filePoints > simulatedPoints ? filePoints - simulatedPoints : 0;
  }
};

// The groom a preset asks for: the generator, or a file (resolved against baseDir) of which
// hairstyle.strands strands are kept (spread over the file), fitted to the head, roots
// snapped to the scalp, and resampled to the particles the tolerance needs. Returns false
// with a message naming the file (and byte offset) on failure.
bool buildGroom(const Config& c, const std::string& baseDir, Groom& out, std::string* error,
                GroomReport* report = nullptr);

// `path` against the folder of the preset it came from ("" for the built-in preset): groom
// files named in a preset are relative to it.
std::string resolveRelative(const std::string& baseDir, const std::string& path);

}  // namespace csm
