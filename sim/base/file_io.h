// Files as bytes: little-endian loads, messages that name a byte offset, whole-file reads with
// a size cap checked before allocating, and writes that never leave a half-written file. The
// groom readers and writers (sim/groom) and the OBJ head reader (sim/head) share them.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace csm::io::detail {

// The file formats are little-endian; reading them with memcpy is only correct on a
// little-endian host, which is every platform this project builds on.
static_assert(std::endian::native == std::endian::little,
              "groom readers assume a little-endian host");

template <class T>
T loadLE(std::span<const std::byte> bytes, uint64_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

// "<name>: byte <offset>: <message>"
std::string errorAt(std::string_view name, uint64_t offset, std::string_view message);

// Formats a float for messages ("nan", "-inf", "0.25").
std::string floatText(float value);

// Reads a whole file, refusing files larger than maxBytes before allocating.
// On failure returns nullopt and sets *error to a message that starts with the path.
std::optional<std::vector<std::byte>> readFileBytes(const std::string& path, uint64_t maxBytes,
                                                    std::string* error);

// Writes `bytes` to path + ".tmp<pid>", then renames it over `path`, so a reader never sees a
// half-written file, a failed write leaves the old file intact, and processes writing one path
// at once each write their own.
bool writeFileAtomically(const std::string& path, std::span<const std::byte> bytes,
                         std::string* error);

}  // namespace csm::io::detail

namespace csm {

// `path` against the folder of the preset it came from ("" for the built-in preset): files
// named in a preset (a groom, a head mesh) are relative to it.
std::string resolveRelative(const std::string& baseDir, const std::string& path);

}  // namespace csm
