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

std::string checkPoints(const Groom& groom, std::string_view name, uint64_t base, uint64_t stride) {
  for (size_t i = 0; i < groom.points.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = groom.points[i][c];
      if (!std::isfinite(v)) {
        return errorAt(name, base + stride * i + 4 * c,
                       std::string("coordinate ") + "xyz"[c] + " of point " + std::to_string(i) +
                           " is " + floatText(v) + "; expected a finite number");
      }
    }
  }
  // A strand whose points all coincide has no direction and no rest length: the solver
  // cannot shape-match it and resampling cannot place particles along it.
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const uint32_t begin = groom.first[s], end = groom.first[s + 1];
    bool moves = false;
    for (uint32_t i = begin + 1; i < end && !moves; ++i) {
      moves = groom.points[i] != groom.points[begin];
    }
    if (!moves) {
      return errorAt(name, base + stride * begin,
                     "strand " + std::to_string(s) + " has zero length (all " +
                         std::to_string(end - begin) +
                         " points are equal); expected a strand that goes somewhere");
    }
  }
  return {};
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
