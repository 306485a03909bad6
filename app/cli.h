// The command line. Every later feature adds its options here.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace csm {

struct Options {
  std::string preset;  // a preset .json or a groom file; empty = built-in default
  bool headless = false;
  long frames = -1;     // the last frame run or drawn; -1: 60 headless, unbounded in the window
  long firstFrame = 1;  // --frames A-B: the first frame drawn or written (frames count from 1)
  std::string solver = "gpu";
  std::vector<std::pair<std::string, std::string>> sets;  // --set KEY=VALUE
  std::string metrics;                                    // --metrics FILE.json
  bool listParams = false;
  std::vector<std::string> validate;
  bool validateMode = false;
  bool help = false;
  bool quiet = false;
  bool requireGpu = false;  // --require-gpu: a software OpenGL renderer is an error
  bool info = false;        // --info: the OpenGL device and its limits, then exit
  std::string savePreset;   // --save-preset FILE.json: write the resolved scene
  // Capture.
  std::string outDir;
  int every = 1;
  int width = 1280, height = 720;
  bool noRender = false;
  std::string video;
  std::string exportHair;
  std::string exportSequence;  // --export-hair-sequence DIR
  bool exportGuides = false;   // --export-guides: the simulated strands alone
  // A shot's cache (app/shot_cache.h).
  std::string bake;       // --bake DIR: write every frame simulated into a cache
  bool resume = false;    // --resume: go on with --bake DIR's cache from its last frame kept
  std::string fromCache;  // --from-cache DIR (or a cache's folder as the file): draw, not simulate
  // Window scripting.
  std::string screenshot;
  long exitAfter = -1;
};

// "N" (frames 1..N) or "A-B" (A..B, 1 <= A <= B) into first and last; false, saying why, for
// anything else.
bool parseFrameRange(const std::string& text, long& first, long& last, std::string* error);

// Parses argv. On a usage error returns nullopt and fills `error`.
std::optional<Options> parseCommandLine(int argc, char** argv, std::string* error);
std::string usageText();

}  // namespace csm
