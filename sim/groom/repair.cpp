#include "sim/groom/repair.h"

#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

namespace csm::io {
namespace {

bool finite(const glm::vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string lengthText(double metresOrUnits) {
  std::ostringstream out;
  out.precision(3);
  out << metresOrUnits;
  return out.str();
}

}  // namespace

void GroomRepair::add(const GroomRepair& other) {
  droppedStrands += other.droppedStrands;
  mergedPoints += other.mergedPoints;
  for (const std::string& n : other.notes)
    if (notes.size() < kMaxNotes) notes.push_back(n);
}

std::string GroomRepair::summary() const {
  std::string s;
  if (droppedStrands)
    s = "dropped " + std::to_string(droppedStrands) +
        (droppedStrands == 1 ? " strand" : " strands");
  if (mergedPoints) {
    if (!s.empty()) s += ", ";
    s += "merged " + std::to_string(mergedPoints) + (mergedPoints == 1 ? " point" : " points");
  }
  return s;
}

GroomRepair repairGroom(Groom& groom, const RepairOptions& options) {
  GroomRepair report;
  auto note = [&](size_t strand, size_t point, int axis, const std::string& what) {
    if (report.notes.size() >= GroomRepair::kMaxNotes) return;
    std::string line = options.name.empty() ? std::string() : options.name + ": ";
    if (options.where) line += options.where(point, axis) + ": ";
    const size_t number = strand < options.fileStrand.size() ? options.fileStrand[strand] : strand;
    report.notes.push_back(line + "strand " + std::to_string(number) + " " + what);
  };

  Groom out;
  out.points.reserve(groom.points.size());
  out.first.reserve(groom.first.size());
  std::vector<glm::vec3> kept;
  const double merge2 = options.mergeDistance * options.mergeDistance;
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const uint32_t begin = groom.first[s], end = groom.first[s + 1];
    size_t bad = end;
    for (uint32_t i = begin; i < end && bad == end; ++i)
      if (!finite(groom.points[i])) bad = i;
    auto drop = [&](size_t point, const std::string& why, int axis = 0) {
      ++report.droppedStrands;
      note(s, point, axis, "dropped: " + why);
    };
    if (bad != end) {
      const glm::vec3& p = groom.points[bad];
      const int axis = std::isfinite(p.x) ? (std::isfinite(p.y) ? 2 : 1) : 0;
      std::ostringstream v;
      v << p[axis];
      drop(bad,
           std::string("coordinate ") + "xyz"[axis] + " of point " + std::to_string(bad - begin) +
               " is " + v.str(),
           axis);
      continue;
    }
    double length = 0.0;
    for (uint32_t i = begin + 1; i < end; ++i)
      length += glm::length(glm::dvec3(groom.points[i]) - glm::dvec3(groom.points[i - 1]));
    if (!(length > 0.0)) {
      drop(begin, "all " + std::to_string(end - begin) + " points are equal");
      continue;
    }
    if (length < options.minLength) {
      drop(begin,
           "it is " + lengthText(length) + " long, shorter than " + lengthText(options.minLength));
      continue;
    }
    kept.assign(1, groom.points[begin]);
    size_t merged = 0;
    for (uint32_t i = begin + 1; i < end; ++i) {
      const glm::vec3& p = groom.points[i];
      const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(kept.back());
      if (glm::dot(d, d) > merge2) {
        kept.push_back(p);
        continue;
      }
      ++merged;
      // The tip stays where the file has it: the point before it is the one that goes.
      if (i + 1 == end && kept.size() > 1) kept.back() = p;
    }
    if (kept.size() < 2) {
      // Only a strand shorter than mergeDistance gets here, and that takes minLength >= it.
      drop(begin, "its points lie within " + lengthText(options.mergeDistance) + " of its root");
      continue;
    }
    if (merged) {
      report.mergedPoints += merged;
      note(s, begin, 0,
           "had " + std::to_string(merged) + " repeated point" + (merged == 1 ? "" : "s") +
               " merged");
    }
    out.addStrand(kept);
    out.addStrandData(groom, s);
  }
  if (!report.empty()) groom = std::move(out);
  return report;
}

}  // namespace csm::io
