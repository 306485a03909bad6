#include "sim/groom/hair_sequence.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "sim/groom/cyhair.h"

namespace csm::io {

namespace {

template <class Vec>
Groom posed(const Groom& groom, const std::vector<Vec>& positions) {
  Groom out;
  out.first = groom.first;
  out.points.reserve(positions.size());
  for (const Vec& p : positions) out.points.emplace_back(p);
  out.color = groom.color;
  out.thickness = groom.thickness;
  out.tipHeld = groom.tipHeld;
  return out;
}

template <class Vec>
bool writeFrame(const std::string& dir, long n, const Groom& groom,
                const std::vector<Vec>& positions, std::string* error) {
  if (positions.size() != groom.pointCount()) {
    if (error)
      *error = "frame " + std::to_string(n) + " has " + std::to_string(positions.size()) +
               " points, the groom " + std::to_string(groom.pointCount());
    return false;
  }
  const std::string path = (std::filesystem::path(dir) / sequenceFrameName(n)).string();
  return writeCyHair(path, posed(groom, positions), error);
}

}  // namespace

Groom posedGroom(const Groom& groom, const std::vector<glm::vec4>& positions) {
  return posed(groom, positions);
}

Groom posedGroom(const Groom& groom, const std::vector<glm::vec3>& positions) {
  return posed(groom, positions);
}

std::string sequenceFrameName(long n) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05ld.hair", n);
  return name;
}

bool prepareSequenceDir(const std::string& dir, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    if (error)
      *error = "cannot make the folder " + dir + " for the hair sequence" +
               (ec ? ": " + ec.message() : std::string());
    return false;
  }
  return true;
}

bool writeSequenceFrame(const std::string& dir, long n, const Groom& groom,
                        const std::vector<glm::vec4>& positions, std::string* error) {
  return writeFrame(dir, n, groom, positions, error);
}

bool writeSequenceFrame(const std::string& dir, long n, const Groom& groom,
                        const std::vector<glm::vec3>& positions, std::string* error) {
  return writeFrame(dir, n, groom, positions, error);
}

}  // namespace csm::io
