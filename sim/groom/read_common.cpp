#include "sim/groom/read_common.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace csm::io {

std::string checkGroomStructure(const Groom& groom) {
  if (groom.first.empty() || groom.first.front() != 0) {
    return "strand offsets must start with 0";
  }
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    if (groom.first[s + 1] < groom.first[s] + 2) {
      return "strand " + std::to_string(s) + " has fewer than 2 points";
    }
  }
  if (groom.first.back() != groom.points.size()) {
    return "strand offsets end at " + std::to_string(groom.first.back()) + " but there are " +
           std::to_string(groom.points.size()) + " points";
  }
  if (!groom.color.empty() && groom.color.size() != groom.strandCount()) {
    return "color has " + std::to_string(groom.color.size()) + " entries for " +
           std::to_string(groom.strandCount()) + " strands";
  }
  if (!groom.thickness.empty() && groom.thickness.size() != groom.strandCount()) {
    return "thickness has " + std::to_string(groom.thickness.size()) + " entries for " +
           std::to_string(groom.strandCount()) + " strands";
  }
  if (!groom.tipHeld.empty() && groom.tipHeld.size() != groom.strandCount()) {
    return "tipHeld has " + std::to_string(groom.tipHeld.size()) + " entries for " +
           std::to_string(groom.strandCount()) + " strands";
  }
  if (!groom.follow.empty() && groom.follow.size() != groom.strandCount()) {
    return "follow has " + std::to_string(groom.follow.size()) + " entries for " +
           std::to_string(groom.strandCount()) + " strands";
  }
  return {};
}

bool hasExtension(std::string_view path, std::string_view ext) {
  if (path.size() < ext.size()) return false;
  return std::equal(ext.begin(), ext.end(), path.end() - ext.size(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

namespace detail {

void finishGroom(GroomReadResult& result, Groom groom, std::string_view name,
                 std::function<std::string(size_t point, int axis)> where,
                 std::vector<size_t> fileStrand) {
  const size_t strands = groom.strandCount() + result.repair.droppedStrands;
  RepairOptions options;
  options.name = std::string(name);
  options.where = std::move(where);
  options.fileStrand = std::move(fileStrand);
  result.repair.add(repairGroom(groom, options));
  if (groom.strandCount() == 0) {
    result.error = std::string(name) + ": no strand can be used: all " + std::to_string(strands) +
                   " were dropped" +
                   (result.repair.notes.empty() ? std::string()
                                                : " (the first: " + result.repair.notes[0] + ")");
    return;
  }
  result.groom = std::move(groom);
}

std::function<std::string(size_t point, int axis)> byteOfPoint(uint64_t base, uint64_t stride) {
  return [base, stride](size_t point, int axis) {
    return "byte " + std::to_string(base + stride * point + 4 * uint64_t(axis));
  };
}

}  // namespace detail
}  // namespace csm::io
