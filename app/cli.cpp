#include "app/cli.h"

#include <charconv>
#include <cstring>

#include "sim/groom/groom_file.h"

namespace csm {
namespace {

bool parseLong(const std::string& s, long& out) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

bool parseFrameRange(const std::string& text, long& first, long& last, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = "--frames " + text + ": " + why;
    return false;
  };
  const size_t dash = text.find('-', 1);
  if (dash == std::string::npos) {
    if (!parseLong(text, last) || last < 0) return fail("needs N (a whole number >= 0) or A-B");
    first = 1;
    return true;
  }
  long a = 0, b = 0;
  if (!parseLong(text.substr(0, dash), a) || !parseLong(text.substr(dash + 1), b))
    return fail("needs A-B, two whole numbers (e.g. 31-45)");
  if (a < 1) return fail("frames count from 1");
  if (b < a) return fail("the first frame is after the last");
  first = a;
  last = b;
  return true;
}

std::string usageText() {
  return R"(csmhair: every strand of a head of hair, simulated with Chain Shape Matching.

usage: csmhair [PRESET.json | GROOM.hair|.tfx|.tfxproj|.obj|.data|.bin|.ply] [options]

  --headless             no window: simulate (and render, when a renderer is built) off-screen
  --frames N | A-B       frames to run (headless default 60; from 1), or the frames A..B alone
                         drawn and written (a run simulates up to B; a cache draws A..B)
  --solver cpu|gpu       the CPU reference or the GPU solver (default gpu)
  --set KEY=VALUE        override a parameter (repeatable); see --list-params
  --metrics FILE.json    write timings and accuracy measures
  --list-params          print every parameter: key, type and range, default, description
  --validate PRESET...   check presets and exit (status 2 when one is invalid)
  --save-preset FILE     write the resolved scene (preset + --set) as a preset and exit
  --out DIR              headless: write frame_00001.png ... into DIR
  --every K              keep every K-th frame (default 1)
  --size WxH             image size (default 1280x720)
  --no-render            headless: simulate only
  --video FILE.mp4       headless: pipe frames to ffmpeg
  --export-hair FILE     write the final strands (metres, y up) by FILE's extension: cyHair
                         .hair, OBJ curves .obj (one \"l i j\" an edge, as Blender reads
                         them), USC-HairSalon .data, CT2Hair .bin, strand PLY .ply (binary;
                         ASCII when FILE ends in _ascii.ply)
  --export-hair-sequence DIR
                         headless: write every kept frame (--every) as DIR/frame_00001.hair,
                         ... (cyHair, the same strands in each)
  --export-guides        export the simulated strands alone (hairstyle.guides), not every
                         strand as drawn
  --bake DIR             headless: simulate into a shot's cache in DIR (a manifest and a file
                         a frame, each written whole), to draw later with --from-cache
  --resume               with --bake: go on from the cache's last frame kept (a bake that was
                         stopped), the same frames as one that was not
  --from-cache DIR       headless: draw the cache's frames (--frames A-B) without simulating;
                         render parameters may be --set, simulation parameters may not. Opening
                         DIR as the file does the same (the window scrubs it)
  --screenshot FILE.png  window: save what the window shows after --exit-after frames
                         (at full quality)
  --exit-after N         window: simulate N frames as fast as they come (not paced to
                         real time), then exit
  --quiet                no progress on stderr
  --require-gpu          exit with status 1 when OpenGL runs on a software renderer
                         (llvmpipe, softpipe, swrast) instead of a GPU; without it that is a
                         warning (stderr, the window's Messages)
  --info                 print the headless OpenGL device (how it was chosen, renderer,
                         driver version) and its limits, then exit
  --help                 this text

Environment:
  CSM_EGL_DEVICE=N|NAME  headless: the EGL device to run on, and no other. N is the CUDA
                         device index where the driver reports one (NVIDIA: as nvidia-smi
                         counts), else the place in EGL's device list; NAME is matched
                         against the devices' names (e.g. /dev/dri/renderD129, NVIDIA). A
                         device that does not exist is an error listing those that do.
  CSM_EGL_PLATFORM=device|surfaceless|default
                         headless: only that EGL path (default: GPUs first, then Mesa's
                         surfaceless driver, then software devices, then the default display)

Exit status: 0 success, 1 runtime failure (no GL context, NaN in the simulation, I/O),
2 bad input (command line, preset, groom file).
)";
}

std::optional<Options> parseCommandLine(int argc, char** argv, std::string* error) {
  Options o;
  auto fail = [&](const std::string& msg) -> std::optional<Options> {
    if (error) *error = msg;
    return std::nullopt;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](std::string& out) -> bool {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    auto number = [&](long& out, long min) -> bool {
      std::string s;
      return value(s) && parseLong(s, out) && out >= min;
    };
    if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--headless") {
      o.headless = true;
    } else if (arg == "--frames") {
      std::string range;
      if (!value(range)) return fail("--frames needs N or A-B");
      std::string why;
      if (!parseFrameRange(range, o.firstFrame, o.frames, &why)) return fail(why);
    } else if (arg == "--bake") {
      if (!value(o.bake)) return fail("--bake needs a directory");
    } else if (arg == "--resume") {
      o.resume = true;
    } else if (arg == "--from-cache") {
      if (!value(o.fromCache)) return fail("--from-cache needs a cache's directory");
    } else if (arg == "--solver") {
      if (!value(o.solver) || (o.solver != "cpu" && o.solver != "gpu"))
        return fail("--solver needs cpu or gpu");
    } else if (arg == "--set") {
      std::string kv;
      if (!value(kv)) return fail("--set needs KEY=VALUE");
      const size_t eq = kv.find('=');
      if (eq == std::string::npos || eq == 0)
        return fail("--set " + kv + ": expected KEY=VALUE, e.g. --set wind.strength=3");
      o.sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else if (arg == "--metrics") {
      if (!value(o.metrics)) return fail("--metrics needs a file name");
    } else if (arg == "--list-params") {
      o.listParams = true;
    } else if (arg == "--validate") {
      o.validateMode = true;
      while (i + 1 < argc && std::strncmp(argv[i + 1], "--", 2) != 0)
        o.validate.push_back(argv[++i]);
      if (o.validate.empty()) return fail("--validate needs at least one preset file");
    } else if (arg == "--save-preset") {
      if (!value(o.savePreset)) return fail("--save-preset needs a file name");
    } else if (arg == "--out") {
      if (!value(o.outDir)) return fail("--out needs a directory");
    } else if (arg == "--every") {
      long k;
      if (!number(k, 1)) return fail("--every needs a whole number >= 1");
      o.every = int(k);
    } else if (arg == "--size") {
      std::string s;
      long w = 0, h = 0;
      const size_t x = value(s) ? s.find('x') : std::string::npos;
      if (x == std::string::npos || !parseLong(s.substr(0, x), w) ||
          !parseLong(s.substr(x + 1), h) || w < 16 || h < 16 || w > 16384 || h > 16384)
        return fail("--size needs WxH with each side in 16..16384, e.g. 1280x720");
      o.width = int(w);
      o.height = int(h);
    } else if (arg == "--no-render") {
      o.noRender = true;
    } else if (arg == "--video") {
      if (!value(o.video)) return fail("--video needs a file name");
    } else if (arg == "--export-hair-sequence") {
      if (!value(o.exportSequence)) return fail("--export-hair-sequence needs a directory");
    } else if (arg == "--export-hair") {
      if (!value(o.exportHair)) return fail("--export-hair needs a file name");
      // Said before anything is simulated, not after the run.
      if (!io::isWritableGroomName(o.exportHair))
        return fail("--export-hair " + o.exportHair +
                    ": the name must end in .hair (cyHair), .obj (OBJ curves), .data "
                    "(USC-HairSalon), .bin (CT2Hair) or .ply (strand PLY)");
    } else if (arg == "--export-guides") {
      o.exportGuides = true;
    } else if (arg == "--screenshot") {
      if (!value(o.screenshot)) return fail("--screenshot needs a file name");
    } else if (arg == "--exit-after") {
      if (!number(o.exitAfter, 0)) return fail("--exit-after needs a whole number >= 0");
    } else if (arg == "--require-gpu") {
      o.requireGpu = true;
    } else if (arg == "--info") {
      o.info = true;
    } else if (arg == "--quiet") {
      o.quiet = true;
    } else if (arg.rfind("--", 0) == 0) {
      return fail("unknown option " + arg + " (see --help)");
    } else if (o.preset.empty()) {
      o.preset = arg;
    } else {
      return fail("only one preset can be given; got " + o.preset + " and " + arg);
    }
  }
  if (o.resume && o.bake.empty()) return fail("--resume goes on with a bake: give --bake DIR");
  if (!o.fromCache.empty() && !o.bake.empty())
    return fail("--bake and --from-cache: a run either simulates into a cache or draws from one");
  return o;
}

}  // namespace csm
