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

// The groom a preset asks for: the generator, or a file (resolved against baseDir), fitted to
// the head and resampled. Returns false with a message naming the file on failure.
bool buildGroom(const Config& c, const std::string& baseDir, Groom& out, std::string* error);

}  // namespace csm
