// A shot's cache: a shot simulated once (--bake DIR) and drawn from there, any frames in any
// process (--from-cache DIR), as a render farm splits a shot into chunks. The folder holds
//   manifest.json       the whole preset (every parameter), where its files are, the solver, dt,
//                       the frames the bake runs, the groom's hash and its files' hashes, the
//                       format's version (cache::kCacheVersion)
//   frames/frame_00001.bin ...   a frame each (sim/run/cache_files.h): positions, pose, time
//   resume.state        the whole simulation at the last keyframe, for --resume
// Every file is written whole or not at all. A cache is refused, saying what is wrong, when it is
// of another version, when a frame is truncated or changed, and when what would draw it (the
// groom grown again, the groom and head files, the simulation's parameters) is not what baked it.
#pragma once

#include <cstdint>
#include <string>

#include "app/preset_value.h"
#include "sim/run/grown_scene.h"

namespace csm {

// A file a scene reads (hairstyle.file, head.mesh), and the hash of its bytes when baked.
struct CacheInput {
  std::string key;   // the parameter naming it
  std::string path;  // resolved
  uint64_t hash = 0;
};

struct CacheManifest {
  Preset preset;           // every parameter the bake ran with
  std::string source;      // what the scene came from (the preset's file), for messages
  std::string baseDir;     // where the preset's relative paths point
  std::string solver;      // "gpu" or "cpu"
  long frames = 0;         // the frames the bake runs: 1..frames
  int keyframeEvery = 10;  // a resume state every this many frames, and at the last
  size_t strands = 0, particles = 0, drawnStrands = 0;
  size_t drawnPoints = 0;  // the drawn strands' points (a guided groom's followers: not cached)
  uint64_t groomHash = 0;  // groomHash (sim/run/grown_scene.h) of the scene grown
  std::vector<CacheInput> inputs;
};

namespace shot_cache {

inline constexpr const char* kManifestName = "manifest.json";
inline constexpr const char* kStateName = "resume.state";

// True when `dir` is a folder holding a cache's manifest.
bool isCache(const std::string& dir);
// DIR/frames/frame_00031.bin
std::string framePath(const std::string& dir, long frame);
std::string statePath(const std::string& dir);

// The files `preset` reads, each with the hash of its bytes now; false, saying which, when one
// cannot be read.
bool inputsOf(const Preset& preset, const std::string& baseDir, std::vector<CacheInput>& out,
              std::string* error);
// FNV-1a 64 of a file's bytes; false when it cannot be read.
bool fileHash(const std::string& path, uint64_t& out, std::string* error);

// Makes DIR and DIR/frames and writes the manifest (atomically).
bool writeManifest(const std::string& dir, const CacheManifest& m, std::string* error);
// Reads DIR's manifest: its version checked, its preset read as a preset file is (every
// problem named by its JSON path in the manifest).
bool readManifest(const std::string& dir, CacheManifest& out, std::string* error);

// The frames 1..n whose files are there and of a whole frame's size (not read: readFrame checks
// the rest), n counted from 1 up to the first that is not.
long completeFrames(const std::string& dir, const CacheManifest& m);

// What would draw the cache is what baked it: the files' hashes, the groom grown again (its
// hash and counts). False, saying what differs.
bool matches(const CacheManifest& m, const GrownScene& grown, std::string* error);

}  // namespace shot_cache
}  // namespace csm
