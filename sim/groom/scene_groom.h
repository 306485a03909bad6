// The groom a scene asks for (buildGroom): the generator's (sim/groom/hairstyle.h), or a file's,
// read, fitted to the head, repaired at the scene's resolution, resampled and pushed out of the
// head (fitFileGroom), with a report of what the import did.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/fit.h"
#include "sim/groom/repair.h"
#include "sim/head/head_model.h"

namespace csm {

struct GroomReport {
  size_t fileStrands = 0;      // strands in the groom file (0 for the generator)
  size_t filePoints = 0;       // points of the kept strands before resampling
  size_t simulatedPoints = 0;  // particles simulated
  // The file's flaws, repaired (io/repair.h): strands dropped, points merged, the first notes.
  io::GroomRepair repair;
  size_t turnedStrands = 0;    // strands read tip first (OBJ curves), turned root first
  size_t pushedParticles = 0;  // particles moved out of the head when the groom was fitted
  size_t heldTips = 0;         // strands the head holds at both ends (Groom::tipHeld)
  size_t refitTied = 0;        // of those, strands the fit moved: they rest in their fitted shape
  bool mirrored = false;       // z mirrored into the head frame (hairstyle.import_facing)
  bool keptOnHead = false;     // kept where the file put it on head.mesh (import_place)
  std::string placeNote;       // why it was kept there, or fitted though head.mesh is set
  std::string facingNote;      // the groom's hair falls toward the face: its front may be behind
  std::vector<std::string> unused;  // what the file holds that csmhair does not use (a project's)
  std::vector<std::string> mapped;  // what it sets, in csmhair's terms (a project's damping)
  io::FitReport fit;                // how the file's points came onto the head
  bool scaleInferred = false;       // fit.scale from the roots' size (hairstyle.import_scale 0)
  // The file's own guides and follow hairs (a TressFX project's, sim/groom/follow_hairs.h): the
  // strands that are the guides, and how many follow hairs were made beside them.
  std::vector<uint32_t> fileGuides;
  size_t followHairs = 0;
  // The file's collision spheres (a TressFX project's), in the head frame where the fit put the
  // groom: the head's spheres when collision.head_shape is spheres (sim/run/grown_scene.h).
  std::vector<Sphere> fileSpheres;
  size_t savedPoints() const {
    return filePoints > simulatedPoints ? filePoints - simulatedPoints : 0;
  }
};

// Where a long import stands: the stage ("reading", "repairing", "fitting", "resampling",
// "placing"), and the fraction of the whole import done (0..1). Called on the thread that builds
// the groom, a few hundred times at most; what it shows and how often is the caller's choice.
using ImportProgress = std::function<void(std::string_view stage, double done)>;

// What the import did that a user should hear of (never silent): "the groom file: dropped 3
// strands, merged 12 points; 2 strands turned root first; 40 particles moved out of the head;
// 8 strands held by the head at both ends",
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
// fit to the head, the roots snapped, the second repair (strands shorter than kMinLengthShare of
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

// Imported strands shorter than this share of hairstyle.segment_length are dropped (4 mm at the
// default 2 cm): stubs a groom tool left. A real groom's short strands (a mohawk's or a fade's,
// 5-10 mm) are kept: held by the head over their root length and stiffer than the step budget
// resolves, they run at alpha = 1 (sim/solver/stiffness.h, planFrame) and set no steps.
inline constexpr double kMinLengthShare = 0.2;

}  // namespace csm
