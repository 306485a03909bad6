// The files of a shot's cache below its manifest (app/shot_cache.h): a frame's file, what drawing
// it needs and nothing more (the simulated strands' positions, the head's pose, the time), and
// the resume state, the whole simulation at a keyframe. Each is written whole or not at all
// (io::detail::writeFileAtomically) and read back checked: its magic, the format's version, its
// size against its particles and a hash of its bytes, each failure naming the file and the byte.
//
// A frame file, little-endian:
//   0   char[8]  "csmframe"
//   8   uint32   format version (kCacheVersion)
//   12  uint32   0
//   16  int64    frame (1 after the first step)
//   24  float64  time (s)
//   32  float64  the head's rotation w, x, y, z
//   64  float64  the head's translation x, y, z (m)
//   88  uint64   particles n
//   96  uint64   FNV-1a 64 of every other byte of the file (this field read as 0)
//   104 float32  n x (x, y, z), world positions (m), in the groom's particle order
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "sim/run/frame_recording.h"
#include "sim/run/simulation.h"

namespace csm::cache {

// The cache format's version: a cache of another version is refused, not guessed at.
inline constexpr uint32_t kCacheVersion = 1;
inline constexpr size_t kFrameHeaderBytes = 104;

// The bytes of a frame of `particles` particles.
inline uint64_t frameBytes(size_t particles) {
  return kFrameHeaderBytes + 12ull * particles;
}

// A frame's file name in the cache's frames/ folder: frame_00031.bin.
std::string frameName(long frame);

bool writeFrame(const std::string& path, const FrameRecording::Shown& frame, std::string* error);
// Reads frame `number`, written by writeFrame, of `particles` particles; false, naming the file
// and the byte, for anything else (missing, truncated, another version, another groom, another
// frame, changed bytes).
bool readFrame(const std::string& path, long number, size_t particles, FrameRecording::Shown& frame,
               std::string* error);

// The whole simulation at a frame, to resume from: the clock, the head's poses and the solver's
// own state (SavedState, read back only by the build that wrote it; its layout is checked).
// The config is the manifest's and is not written.
bool writeState(const std::string& path, const SimulationState& state, std::string* error);
bool readState(const std::string& path, SimulationState& state, std::string* error);

}  // namespace csm::cache
