#include "sim/io/common.h"

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
  return {};
}

namespace detail {

std::string errorAt(std::string_view name, uint64_t offset, std::string_view message) {
  std::string text(name);
  text += ": byte ";
  text += std::to_string(offset);
  text += ": ";
  text += message;
  return text;
}

std::string floatText(float value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  std::ostringstream out;
  out << value;
  return out.str();
}

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

std::optional<std::vector<std::byte>> readFileBytes(const std::string& path, uint64_t maxBytes,
                                                    std::string* error) {
  auto fail = [&](const std::string& message) -> std::optional<std::vector<std::byte>> {
    if (error) *error = path + ": " + message;
    return std::nullopt;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("not a readable file");
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return fail("cannot get the file size: " + ec.message());
  if (size > maxBytes) {
    return fail("file of " + std::to_string(size) + " bytes exceeds the limit of " +
                std::to_string(maxBytes) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open for reading");
  std::vector<std::byte> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (static_cast<uint64_t>(in.gcount()) != size) {
    return fail("read " + std::to_string(in.gcount()) + " of " + std::to_string(size) + " bytes");
  }
  return bytes;
}

bool writeFileAtomically(const std::string& path, std::span<const std::byte> bytes,
                         std::string* error) {
  const std::string tmp = path + ".tmp";
  auto fail = [&](const std::string& message) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    if (error) *error = path + ": " + message;
    return false;
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return fail("cannot open " + tmp + " for writing");
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) return fail("writing " + tmp + " failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) return fail("cannot rename " + tmp + ": " + ec.message());
  return true;
}

}  // namespace detail
}  // namespace csm::io
