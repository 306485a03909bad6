// Grows strands from the scalp (the first head sphere), deterministically from a seed.
// Strand s depends only on the seed and s: a smaller strand count is a prefix of a larger one
// (as grown: hairstyle.separate_passes then moves the strands against each other).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/config.h"
#include "sim/groom.h"

namespace csm {

struct DistanceGrid;

// Particles of one strand chosen by its arc length (curl included), within the preset's bounds:
// the paper's 8-25.
int particlesForLength(const HairstyleConfig& h, double arcLength);

// Grows on the spheres (the first is the scalp), or, given a field, on its surface with roots
// seen from kMannequinScalpCentre (sim/head_shape.h).
Groom growHairstyle(const HairstyleConfig& h, const std::vector<Sphere>& head,
                    float collisionRadius, const DistanceGrid* field = nullptr);

// The scene's hairstyle on the scene's head (its field when collision.head_shape is sdf).
Groom growHairstyle(const Config& c);

// Whether hair grows in direction dir (a unit vector from the scalp's centre, head frame): the
// cap of hairstyle.scalp_angle about the crown, lower at the back than at the forehead, and on
// the mannequin not over its ears.
bool onScalp(const HairstyleConfig& h, const glm::dvec3& dir, bool mannequin);

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

// What buildGroom does with a groom file once read (`g`, from `path`): the strands kept, the
// fit to the head, the roots snapped, the resampling, the checks.
bool fitFileGroom(const Config& c, Groom g, const std::string& path, Groom& out, std::string* error,
                  GroomReport* report = nullptr);

// `path` against the folder of the preset it came from ("" for the built-in preset): groom
// files named in a preset are relative to it.
std::string resolveRelative(const std::string& baseDir, const std::string& path);

}  // namespace csm
