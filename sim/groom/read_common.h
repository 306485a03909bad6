// Shared pieces of the groom readers and writers: the result type, byte access with
// offsets for error messages, whole-file reads with a size cap, atomic writes.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/base/file_io.h"
#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/repair.h"

namespace csm::io {

// What a reader returns. Exactly one of the two is set: `groom` on success, `error` (one
// line, "<name>: byte <offset>: <what was expected>") on failure. Readers never throw.
struct GroomReadResult {
  std::optional<Groom> groom;
  std::string error;
  // What the reader repaired (io/repair.h's first pass): strands dropped, points merged.
  GroomRepair repair;
  // False when the format does not say which end of a strand is its root (OBJ curves).
  bool rootsKnown = true;
  // True when the format's face looks toward -z in a left-handed frame (TressFX: DirectX): the
  // scene mirrors z into the head frame unless hairstyle.import_facing says otherwise.
  bool facesMinusZ = false;
  // What the file holds that csmhair has no use for, or uses in its own way (a TressFX project's
  // follow-hair counts, collision spheres, simulation values), one line each, for the report.
  std::vector<std::string> unused;
  // What the file sets that csmhair has a meaning for, said in csmhair's terms (a TressFX
  // project's damping as sim.damping), one line each.
  std::vector<std::string> mapped;
  // Collision spheres the file comes with, in its units and frame (a TressFX project's).
  std::vector<Sphere> spheres;

  explicit operator bool() const { return groom.has_value(); }
};

// Sanity limits, checked before anything is allocated. The paper's largest scene has 760k
// particles; real grooms ship 10k-150k strands of 50-200 points. Ten million points is
// ~120 MB of positions, beyond which a file is far more likely corrupt than real.
inline constexpr uint64_t kMaxPoints = 10'000'000;
// Every strand needs at least two points.
inline constexpr uint64_t kMaxStrands = kMaxPoints / 2;
// The largest legal cyHair file at kMaxPoints (all arrays present) is ~410 MB.
inline constexpr uint64_t kMaxFileBytes = uint64_t{512} << 20;

// Returns an empty string when `groom` is structurally sound (offsets start at 0, never
// decrease, end at points.size(); every strand has >= 2 points; optional arrays are empty
// or one entry per strand), otherwise what is wrong. Used by writers before touching disk.
std::string checkGroomStructure(const Groom& groom);

// True when `path` ends in `ext` (".obj"), in any case.
bool hasExtension(std::string_view path, std::string_view ext);

namespace detail {

// The end of every reader: the first repair (io/repair.h: strands with a coordinate that is not
// finite or with fewer than two distinct points dropped, repeated points merged), each note
// placed in the file by `where`; sets result.groom, or result.error when no strand is left.
// `fileStrand`, when given, is each strand's number in the file (a reader that dropped some
// before), for the notes.
void finishGroom(GroomReadResult& result, Groom groom, std::string_view name,
                 std::function<std::string(size_t point, int axis)> where,
                 std::vector<size_t> fileStrand = {});

// "byte N" of a coordinate of point i when point i's x lies at byte base + stride * i.
std::function<std::string(size_t point, int axis)> byteOfPoint(uint64_t base, uint64_t stride);

// Reads the file at `path` (refusing one over kMaxFileBytes before allocating) and hands its
// bytes to `read(bytes, path)`; a file that cannot be read is an error naming it.
template <class Reader>
GroomReadResult readGroomFile(const std::string& path, Reader read) {
  GroomReadResult result;
  const auto bytes = readFileBytes(path, kMaxFileBytes, &result.error);
  if (!bytes) return result;
  return read(std::span<const std::byte>(*bytes), std::string_view(path));
}

}  // namespace detail
}  // namespace csm::io
