// Grows strands from the scalp (the first head sphere), deterministically from a seed.
// Strand s depends only on the seed and s: a smaller strand count is a prefix of a larger one
// (as grown: hairstyle.separate_passes then moves the strands against each other).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/repair.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"

namespace csm {

struct DistanceGrid;

// Particles of one strand chosen by its arc length (curl included), within the preset's bounds:
// the paper's 8-25.
int particlesForLength(const HairstyleConfig& h, double arcLength);

// Grows on the spheres (the first is the scalp), or, given a field, on its surface with roots
// seen from kMannequinScalpCentre (sim/head/mannequin.h).
Groom growHairstyle(const HairstyleConfig& h, const std::vector<Sphere>& head,
                    float collisionRadius, const DistanceGrid* field = nullptr);

// The scene's hairstyle on the scene's head (its field when collision.head_shape is sdf).
Groom growHairstyle(const Config& c, const HeadModel& head);

// Whether hair grows in direction dir (a unit vector from the scalp's centre, head frame): the
// cap of hairstyle.scalp_angle about the crown, lower at the back than at the forehead, and on
// the mannequin not over its ears.
bool onScalp(const HairstyleConfig& h, const glm::dvec3& dir, bool mannequin);

struct GroomReport {
  size_t fileStrands = 0;      // strands in the groom file (0 for the generator)
  size_t filePoints = 0;       // points of the kept strands before resampling
  size_t simulatedPoints = 0;  // particles simulated
  // The file's flaws, repaired (io/repair.h): strands dropped, points merged, the first notes.
  io::GroomRepair repair;
  size_t turnedStrands = 0;    // strands read tip first (OBJ curves), turned root first
  size_t pushedParticles = 0;  // particles moved out of the head when the groom was fitted
  size_t savedPoints() const {
    return filePoints > simulatedPoints ? filePoints - simulatedPoints : 0;
  }
};

// Where a long import stands: the stage ("reading", "repairing", "fitting", "resampling",
// "placing"), and the fraction of the whole import done (0..1). Called on the thread that builds
// the groom, a few hundred times at most; what it shows and how often is the caller's choice.
using ImportProgress = std::function<void(std::string_view stage, double done)>;

// What the import did that a user should hear of (never silent): "the groom file: dropped 3
// strands, merged 12 points; 2 strands turned root first; 40 particles moved out of the head",
// then the first notes, one a line; "" when there is nothing to say (the generator, a clean
// file).
std::string groomReportText(const GroomReport& r);

// The groom a preset asks for: the generator, or a file (resolved against baseDir) of which
// hairstyle.strands strands are kept (spread over the file), fitted to the head, roots
// snapped to the scalp, repaired at the scene's resolution, resampled to the particles the
// tolerance needs, and pushed out of the head. Returns false with a message naming the file
// (and byte offset or line) on failure.
bool buildGroom(const Config& c, const HeadModel& head, const std::string& baseDir, Groom& out,
                std::string* error, GroomReport* report = nullptr,
                const ImportProgress& progress = {});

// What buildGroom does with a groom file once read (`g`, from `path`): the strands kept, the
// fit to the head, the roots snapped, the second repair (strands shorter than half of
// hairstyle.segment_length dropped, points closer than kMergeShare of it merged), the
// resampling, the particles pushed out of the head, the checks. With `findRoots` (a format that
// does not say which end is the root: OBJ curves) each strand first starts at the end that lies
// on the scalp the groom's first ends share (turned round where its other end does).
bool fitFileGroom(const Config& c, const HeadModel& head, Groom g, const std::string& path,
                  Groom& out, std::string* error, GroomReport* report = nullptr,
                  bool findRoots = false, const ImportProgress& progress = {});

// Points of an imported strand closer than this share of hairstyle.segment_length are merged
// (0.1 mm at the default 2 cm): far below any groom's sampling (a dense one has a point a
// millimetre), far above float's resolution of a position on a head (~3e-8 m), so that no
// simulated segment is so short that float positions blur its length.
inline constexpr double kMergeShare = 0.005;

}  // namespace csm
