#include "sim/groom/scene_groom.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "sim/base/file_io.h"
#include "sim/base/format.h"
#include "sim/base/parallel.h"
#include "sim/base/units.h"
#include "sim/core/sphere_fit.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_fit.h"
#include "sim/head/head_model.h"
#include "sim/groom/fit.h"
#include "sim/groom/follow_hairs.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/growth_head.h"
#include "sim/groom/hairstyle.h"
#include "sim/groom/resample.h"

namespace csm {

namespace {

// Empty when every point of the fitted groom is finite (a strand that collapsed to a point is
// the repair's to drop).
std::string checkFitted(const Groom& g) {
  for (size_t s = 0; s < g.strandCount(); ++s) {
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i) {
      const glm::vec3& p = g.points[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return "point " + std::to_string(i - g.first[s]) + " of strand " + std::to_string(s) +
               " is not finite";
    }
    if (s < g.thickness.size() && !std::isfinite(g.thickness[s]))
      return "the thickness of strand " + std::to_string(s) + " is not finite";
  }
  return {};
}

void reverseStrand(Groom& g, size_t s) {
  std::reverse(g.points.begin() + g.first[s], g.points.begin() + g.first[s + 1]);
}

// The component-wise median of points: where most of them are, whatever a minority does.
glm::dvec3 medianPoint(std::vector<glm::dvec3> points) {
  glm::dvec3 m(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    auto mid = points.begin() + long(points.size() / 2);
    std::nth_element(
        points.begin(), mid, points.end(),
        [axis](const glm::dvec3& p, const glm::dvec3& q) { return p[axis] < q[axis]; });
    m[axis] = (*mid)[axis];
  }
  return m;
}

// The median distance of points from their median point: how tightly they gather.
double medianSpread(const std::vector<glm::dvec3>& points) {
  const glm::dvec3 m = medianPoint(points);
  std::vector<double> d;
  for (const glm::dvec3& p : points) d.push_back(glm::length(p - m));
  std::nth_element(d.begin(), d.begin() + long(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// The sphere through points by least squares (fitSphere). A flat set has no finite sphere: then
// the nearest of large ones is as good a surface, and a radius of 100 spreads stands for it.
Sphere sphereThrough(const std::vector<glm::dvec3>& points) {
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& p : points) mean += p;
  mean /= double(points.size());
  double spread = 0.0;
  for (const glm::dvec3& p : points) spread = std::max(spread, glm::length(p - mean));
  if (points.size() < 4 || !(spread > 0.0)) return {glm::vec3(mean), float(spread)};
  const std::optional<SphereFit> fit = fitSphere(points);
  if (fit && fit->radius <= 100.0 * spread) return {glm::vec3(fit->centre), float(fit->radius)};
  const glm::dvec3 away = fit ? fit->centre - mean : glm::dvec3(0.0);
  const double far = glm::length(away);
  const glm::dvec3 dir = far > 0.0 && std::isfinite(far) ? away / far : glm::dvec3(0.0, -1.0, 0.0);
  return {glm::vec3(mean + 100.0 * spread * dir), float(100.0 * spread)};
}

// For a groom whose format does not say which end is the root: turns the strands so that each
// starts at its end on the scalp. Roots gather on a scalp, tips spread by the hair's length:
// first the whole groom, by which ends gather the more tightly (the median distance from their
// median point, which a minority of strands the other way round does not move; a bounding
// sphere would be set by them). Then a strand whose other end lies nearer that median point is
// in doubt, and is turned only when its other end lies nearer the scalp by a tenth of the
// scalp's radius: the scalp being the sphere through the first ends of the strands not in doubt.
// Hair swept over the crown has its tip near the roots' middle, but no nearer the scalp than
// its root. Returns how many strands were turned from the file's order.
size_t turnRootsFirst(Groom& g) {
  std::vector<glm::dvec3> firsts, lasts;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    firsts.emplace_back(g.points[g.first[s]]);
    lasts.emplace_back(g.points[g.first[s + 1] - 1]);
  }
  if (firsts.empty()) return 0;
  const bool tipsFirst = medianSpread(lasts) < medianSpread(firsts);
  if (tipsFirst) std::swap(firsts, lasts);
  const glm::dvec3 crown = medianPoint(firsts);
  std::vector<bool> doubtful(g.strandCount(), false);
  std::vector<glm::dvec3> roots;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    doubtful[s] = glm::length(lasts[s] - crown) < glm::length(firsts[s] - crown);
    if (!doubtful[s]) roots.push_back(firsts[s]);
  }
  const Sphere scalp = roots.empty() ? Sphere{glm::vec3(crown), 0.0f} : sphereThrough(roots);
  auto gap = [&](const glm::dvec3& p) {
    return std::abs(glm::length(p - glm::dvec3(scalp.center)) - double(scalp.radius));
  };
  const double on = 0.1 * double(scalp.radius);
  size_t turned = 0;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const bool turn = doubtful[s] && gap(lasts[s]) < gap(firsts[s]) - on;
    if (turn != tipsFirst) {
      reverseStrand(g, s);
      ++turned;
    }
  }
  return turned;
}

// The facing checked once the groom is on the head: hair falls behind and down from its roots
// (a fringe forward, the rest back). When the free strands' tips lie on the whole before their
// roots by more than a fifth of their reach, the groom's front may have landed behind: said,
// with the setting that turns it.
std::string facingCheck(const Groom& g) {
  double forward = 0.0, reach = 0.0;
  size_t counted = 0;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    if (g.holdsTip(s)) continue;
    const glm::vec3 d = g.points[g.first[s + 1] - 1] - g.points[g.first[s]];
    forward += double(d.z);
    reach += double(glm::length(d));
    ++counted;
  }
  if (counted == 0 || !(forward > 0.2 * reach)) return {};
  char text[200];
  std::snprintf(text, sizeof text,
                "the hair falls toward the face (its tips %.0f mm before their roots on the "
                "whole): if the groom's front is behind, set hairstyle.import_facing",
                1000.0 * forward / double(counted));
  return text;
}

// Keeps `count` strands spread evenly over the file's order (all when count covers them).
void keepStrands(Groom& g, size_t count) {
  const size_t total = g.strandCount();
  if (count >= total) return;
  Groom out;
  std::vector<glm::vec3> pts;
  for (size_t k = 0; k < count; ++k) {
    const size_t s = k * total / count;
    pts.assign(g.points.begin() + g.first[s], g.points.begin() + g.first[s + 1]);
    out.addStrand(pts);
    out.addStrandData(g, s);
  }
  g = std::move(out);
}

// How far the groom's roots lie from head.mesh's surface once the head's fit has brought both into
// the head frame: the median and the 90th percentile of the roots' distances (with unknown roots,
// the nearer end's), in metres, over at most 4,000 strands spread over the file.
struct RootGap {
  double median = 1e30, high = 1e30;
};

RootGap rootGap(const Groom& g, const HeadFit& fit, const DistanceGrid& field, bool eitherEnd) {
  std::vector<double> gaps;
  const size_t n = g.strandCount(), step = std::max<size_t>(1, n / 4000);
  for (size_t s = 0; s < n; s += step) {
    auto gap = [&](uint32_t i) {
      return std::abs(field.sample(glm::dvec3(fit.apply(g.points[i]))));
    };
    double d = gap(g.first[s]);
    if (eitherEnd) d = std::min(d, gap(g.first[s + 1] - 1));
    gaps.push_back(d);
  }
  if (gaps.empty()) return {};
  std::sort(gaps.begin(), gaps.end());
  return {gaps[gaps.size() / 2], gaps[std::min(gaps.size() - 1, gaps.size() * 9 / 10)]};
}

// A groom is on its own head when most of its roots lie within this of the head's surface (a
// data set's roots sit on or a little inside its scalp), and nine in ten within kOwnHeadHigh.
inline constexpr double kOwnHeadMedian = 0.005, kOwnHeadHigh = 0.02;

// The file's groom kept where it lies on head.mesh: the head's fit applied to its points (and its
// strands' thickness and follow hairs' radius, in the same units). Says so in `note`; false, with
// the reason in `note`, when hairstyle.import_place is auto and the roots are not on that head.
bool keepOnOwnHead(const Config& c, const HeadModel& head, Groom& g, bool eitherEnd,
                   std::string& note) {
  const HeadFit* fit = head.meshFit();
  const ImportPlace place = c.hairstyle.importPlace;
  if (place == ImportPlace::Fit || !fit) return false;
  // Auto keeps only what the preset has not placed by hand.
  const HairstyleConfig& h = c.hairstyle;
  const bool placedByHand = h.importScale > 0.0f || h.importFacing == ImportFacing::MinusZ;
  if (place == ImportPlace::Auto && placedByHand) return false;
  const RootGap gap = rootGap(g, *fit, head.shapeField(), eitherEnd);
  const double mm = 1000.0 * std::min(gap.median, 9.99e5);
  if (place == ImportPlace::Auto && !(gap.median < kOwnHeadMedian && gap.high < kOwnHeadHigh)) {
    note = format(
        "fitted to the head: its roots lie %.1f mm from head.mesh's surface (the median, in the "
        "head's frame), not on it (hairstyle.import_place)",
        mm);
    return false;
  }
  for (glm::vec3& p : g.points) p = fit->apply(p);
  for (float& t : g.thickness) t = float(double(t) * fit->scale);
  for (Groom::FollowHairs& f : g.follow) f.radius = float(double(f.radius) * fit->scale);
  note = format(
      "kept where the file put it on head.mesh (its roots %.1f mm from the surface, the median), "
      "brought into the head frame with the head (hairstyle.import_place)",
      mm);
  return true;
}

// The scale the fit inferred from the roots' size, with the unit it is nearest (the file's unit
// as far as a head's size tells it); "" when it is within 10 % of metres (nothing to say).
std::string inferredScaleText(double scale) {
  if (!(scale > 0.0) || std::abs(std::log(scale)) < std::log(1.1)) return {};
  const LengthUnit& nearest = nearestUnit(scale);
  const double off = scale / nearest.metres;
  if (off > 1.0 / 1.5 && off < 1.5)
    return format(
        "scaled by %.4g to the head's size, inferred from the roots' (the file in about %s; "
        "hairstyle.import_scale overrides)",
        scale, nearest.name);
  return format(
      "scaled by %.4g to the head's size, inferred from the roots' (hairstyle.import_scale "
      "overrides)",
      scale);
}

}  // namespace

bool buildGroom(const Config& c, const HeadModel& head, const std::string& baseDir, Groom& out,
                std::string* error, GroomReport* report, const ImportProgress& progress) {
  GroomReport local;
  GroomReport& r = report ? *report : local;
  r = {};
  if (head.spheres().empty()) {
    if (error) *error = "head.spheres: at least one sphere is needed to grow hair from";
    return false;
  }
  const HairstyleConfig& h = c.hairstyle;
  if (h.file.empty()) {
    out = growHairstyle(c, head);
    r.filePoints = r.simulatedPoints = out.pointCount();
    return true;
  }
  if (h.importPlace == ImportPlace::Head && !head.meshFit()) {
    if (error)
      *error =
          "hairstyle.import_place: \"head\" keeps a groom where its file put it on head.mesh, "
          "but head.mesh is empty";
    return false;
  }
  const std::string path = resolveRelative(baseDir, h.file);
  if (progress) progress("reading", 0.0);
  io::GroomReadResult read = io::readGroom(path);
  if (!read.groom) {
    if (error) *error = read.error;
    return false;
  }
  // On its own head (a data set's groom beside its head mesh): where the file put it, in the
  // head's frame. The head's fit turned the head, so the groom shares its axes and is not
  // mirrored; the fit below keeps its scale and place.
  std::string placeNote;
  const bool kept = keepOnOwnHead(c, head, *read.groom, !read.rootsKnown, placeNote);
  Config placed = c;
  if (kept) {
    placed.hairstyle.importScale = 1.0f;
    if (h.importScale > 0.0f) placeNote += "; hairstyle.import_scale is not used: the head's is";
  }
  // Into the head frame's handedness: TressFX's face looks toward -z in DirectX's left-handed
  // axes; mirroring z turns it to +z and keeps its left at the character's left.
  const bool mirror = !kept && (h.importFacing == ImportFacing::MinusZ ||
                                (h.importFacing == ImportFacing::Auto && read.facesMinusZ));
  if (mirror)
    for (glm::vec3& p : read.groom->points) p.z = -p.z;
  if (!fitFileGroom(placed, head, std::move(*read.groom), path, out, error, &r, !read.rootsKnown,
                    progress))
    return false;
  r.keptOnHead = kept;
  r.placeNote = placeNote;
  r.mirrored = mirror;
  // The project's collision spheres where the fit put the groom (mirrored with it first).
  for (Sphere sphere : read.spheres) {
    if (mirror) sphere.center.z = -sphere.center.z;
    r.fileSpheres.push_back({r.fit.apply(sphere.center), sphere.radius * r.fit.scale});
  }
  // The follow hairs the file asks for, beside their guides on the head as it is now.
  if (!out.follow.empty()) {
    const size_t before = out.strandCount();
    const GrowthHead growth{head.spheres(), head.field()};
    r.fileGuides = addFollowHairs(out, growth, double(c.collision.radius), uint64_t(h.seed));
    r.followHairs = out.strandCount() - before;
  }
  r.unused = read.unused;
  r.mapped = read.mapped;
  // The file's strands and repairs: those the reader dropped, then those the scene did.
  r.fileStrands += read.repair.droppedStrands;
  io::GroomRepair both = read.repair;
  both.add(r.repair);
  r.repair = both;
  return true;
}

bool fitFileGroom(const Config& c, const HeadModel& model, Groom g, const std::string& path,
                  Groom& out, std::string* error, GroomReport* report, bool findRoots,
                  const ImportProgress& progress) {
  // The stages' shares of a large import's time (5 M points: csmhair-bench --only import).
  auto at = [&](const char* stage, double done) {
    if (progress) progress(stage, done);
  };
  GroomReport local;
  GroomReport& r = report ? *report : local;
  r = {};
  const HairstyleConfig& h = c.hairstyle;
  r.fileStrands = g.strandCount();
  keepStrands(g, size_t(h.strands));
  at("fitting", 0.2);
  io::FitOptions fit;
  fit.scale = h.importScale;
  fit.autoFit = h.importScale <= 0.0f;
  fit.rotationDeg = h.importRotation;
  fit.offset = h.importOffset;
  fit.headSpheres = model.spheres();
  fit.headField = model.field();
  fit.snapRoots = true;
  const GrowthHead head{fit.headSpheres, fit.headField};
  if (findRoots) r.turnedStrands = turnRootsFirst(g);
  const io::FitReport fitted = io::fitToHead(g, fit);
  r.fit = fitted;
  r.scaleInferred = fit.autoFit;
  // The reader checked that the file's points are finite and its strands go somewhere, but the
  // fit can undo both: points near float's limit rotated or scaled past it, a tiny spread of
  // roots scaled up to the head's size, or a tiny import scale that collapses a strand.
  if (const std::string problem = checkFitted(g); !problem.empty()) {
    if (error)
      *error = path + ": " + problem + " after fitting to the head (scale " +
               std::to_string(fitted.scale) +
               "); check hairstyle.import_scale, import_rotation and import_offset";
    return false;
  }
  // Flaws that only the scene's resolution names: strands too short to simulate, points too
  // close to tell apart.
  at("repairing", 0.35);
  io::RepairOptions repair;
  repair.minLength = kMinLengthShare * double(h.segmentLength);
  repair.mergeDistance = kMergeShare * double(h.segmentLength);
  repair.name = path;
  const size_t fitStrands = g.strandCount();
  r.repair = io::repairGroom(g, repair);
  if (g.strandCount() == 0) {
    if (error)
      *error = path + ": no strand is left: all " + std::to_string(fitStrands) +
               " are shorter than a fifth of hairstyle.segment_length (" +
               std::to_string(repair.minLength) + " m) once fitted to the head (scale " +
               std::to_string(fitted.scale) +
               "); check hairstyle.import_scale, import_rotation and import_offset";
    return false;
  }
  r.filePoints = g.pointCount();
  at("resampling", 0.45);
  if (h.resampleTolerance > 0.0f) {
    io::ResampleOptions opt;
    opt.minParticles = uint32_t(h.minParticles);
    opt.maxParticles = uint32_t(h.maxParticles);
    opt.tolerance = h.resampleTolerance;
    io::resampleGroom(g, opt);
  }
  const std::string problem = io::checkGroomStructure(g);
  if (!problem.empty()) {
    if (error) *error = path + ": " + problem;
    return false;
  }
  for (size_t s = 0; s < g.strandCount(); ++s)
    if (g.strandSize(s) > kMaxStrandParticles) {
      if (error)
        *error = path + ": strand " + std::to_string(s) + " has " +
                 std::to_string(g.strandSize(s)) + " points, more than the " +
                 std::to_string(kMaxStrandParticles) +
                 " a strand the solvers take: set hairstyle.resample_tolerance above 0 to thin "
                 "it to at most hairstyle.max_particles";
      return false;
    }
  // No particle starts inside the head: the roots are on its surface, the rest inside go out
  // to the collision radius.
  // Each particle on its own: in chunks of strands on the cores, the counts summed after.
  const double margin = double(c.collision.radius);
  at("placing", 0.7);
  std::vector<size_t> pushedIn(coreCount(), 0), tiedMoved(coreCount(), 0);
  parallelChunks(g.strandCount(), 256, [&](size_t begin, size_t end, size_t chunk) {
    for (size_t s = begin; s < end; ++s) {
      const size_t before = pushedIn[chunk];
      for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i) {
        glm::dvec3 p(g.points[i]), normal;
        // Only a particle inside: one the hair radius from the surface is where a simulation
        // holds it, and a groom exported from one comes back as it went out. A particle deep
        // in the head takes more than one push along the field's gradient.
        if (!(head.distance(p, normal) < 0.0)) continue;
        bool pushed = false;
        for (int k = 0; k < 8 && head.pushOut(p, margin); ++k) pushed = true;
        if (pushed) {
          g.points[i] = glm::vec3(p);
          ++pushedIn[chunk];
        }
      }
      // A tied strand's rest shape is where the simulation starts it: the fitted one, its ends
      // as far apart as the moved strand's length allows.
      if (g.holdsTip(s) && pushedIn[chunk] > before) ++tiedMoved[chunk];
    }
  });
  for (const size_t n : pushedIn) r.pushedParticles += n;
  for (const size_t n : tiedMoved) r.refitTied += n;
  at("placing", 1.0);
  if (r.pushedParticles > 0) {
    // Particles pushed from inside land on the surface nearest each: a run of them (a strand
    // the file drew through the head) lands on one point. Merged again, counted again.
    r.repair.add(io::repairGroom(g, repair));
    if (g.strandCount() == 0) {
      if (error)
        *error = path +
                 ": no strand is left: every strand lies inside the head, once fitted to "
                 "it (scale " +
                 std::to_string(fitted.scale) +
                 "); check hairstyle.import_scale, import_rotation and import_offset";
      return false;
    }
  }
  r.simulatedPoints = g.pointCount();
  r.heldTips = size_t(std::count(g.tipHeld.begin(), g.tipHeld.end(), uint8_t(1)));
  r.facingNote = facingCheck(g);
  out = std::move(g);
  return true;
}

std::string groomReportText(const GroomReport& r) {
  std::string parts = r.repair.summary();
  auto add = [&](size_t n, const char* one, const char* many) {
    if (n == 0) return;
    if (!parts.empty()) parts += "; ";
    parts += std::to_string(n) + (n == 1 ? one : many);
  };
  add(r.turnedStrands, " strand turned root first", " strands turned root first");
  add(r.pushedParticles, " particle moved out of the head", " particles moved out of the head");
  add(r.heldTips, " strand held by the head at both ends",
      " strands held by the head at both ends");
  add(r.refitTied, " tied strand moved by the fit: it rests in its fitted shape",
      " tied strands moved by the fit: they rest in their fitted shape");
  if (r.followHairs > 0) {
    if (!parts.empty()) parts += "; ";
    parts += std::to_string(r.followHairs) + " follow hairs drawn from " +
             std::to_string(r.fileGuides.size()) +
             " guides, as the file asks (hairstyle.guides -1 simulates the guides)";
  }
  if (!r.fileSpheres.empty()) {
    if (!parts.empty()) parts += "; ";
    parts += std::to_string(r.fileSpheres.size()) +
             (r.fileSpheres.size() == 1 ? " collision sphere" : " collision spheres") +
             ", the head's when collision.head_shape is spheres";
  }
  if (r.scaleInferred) {
    if (const std::string scale = inferredScaleText(r.fit.scale); !scale.empty()) {
      if (!parts.empty()) parts += "; ";
      parts += scale;
    }
  }
  if (r.mirrored) {
    if (!parts.empty()) parts += "; ";
    parts +=
        "z mirrored into the head frame (a left-handed file, face -z: "
        "hairstyle.import_facing)";
  }
  for (const std::string* note : {&r.placeNote, &r.facingNote})
    if (!note->empty()) {
      if (!parts.empty()) parts += "; ";
      parts += *note;
    }
  if (parts.empty() && r.unused.empty() && r.mapped.empty()) return {};
  std::string text = "the groom file: " + (parts.empty() ? std::string("read") : parts);
  for (const std::string& n : r.repair.notes) text += "\n  " + n;
  for (const std::string& n : r.mapped) text += "\n  " + n;
  for (const std::string& n : r.unused) text += "\n  not used: " + n;
  return text;
}

}  // namespace csm
