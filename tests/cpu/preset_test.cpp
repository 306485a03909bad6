#include <catch2/catch.hpp>

#include <filesystem>
#include <csignal>
#include <fstream>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "app/params.h"
#include "app/preset.h"
#include "render/hair_color.h"
#include "render/view_params.h"
#include "sim/param/sim_params.h"
#include "sim/run/scene_checks.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> presetFiles() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(CSM_SOURCE_DIR) / "presets"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string parseErrors(const std::string& text) {
  Preset c;
  PresetErrors e;
  CHECK_FALSE(parsePreset(text, "bad.json", c, e));
  return e.text();
}

}  // namespace

TEST_CASE("every parameter's default lies in its range and has a description", "[quick]") {
  const Preset c;
  for (const PresetParam& p : params()) {
    INFO(p.key);
    CHECK(!p.description.empty());
    CHECK(!p.label.empty());
    CHECK(findParam(p.key) == &p);
    if (p.type == ParamType::Enum) CHECK(!p.options.empty());
    Preset copy = c;
    CHECK(paramFromJson(p, copy, paramToJson(p, c)) == "");
  }
}

TEST_CASE("every preset in presets/ validates and round-trips through save and load", "[quick]") {
  const auto files = presetFiles();
  REQUIRE(files.size() >= 5);
  for (const std::string& f : files) {
    INFO(f);
    Preset c;
    PresetErrors e;
    REQUIRE(loadPreset(f, c, e));
    const std::string tmp = (fs::temp_directory_path() / "csm_roundtrip.json").string();
    std::string err;
    REQUIRE(savePreset(tmp, c, &err));
    Preset back;
    back.scene.hairstyle.strands = 1;  // load must overwrite it
    REQUIRE(loadPreset(tmp, back, e));
    for (const PresetParam& p : params()) {
      INFO(p.key);
      CHECK(sameValue(p, c, back));
    }
    fs::remove(tmp);
  }
}

TEST_CASE("the built-in default preset is valid", "[quick]") {
  Preset c;
  PresetErrors e;
  CHECK(parsePreset(defaultPresetText(), "default", c, e));
  CHECK(e.empty());
}

TEST_CASE("bad presets are refused with the file and the JSON path", "[quick]") {
  CHECK_THAT(parseErrors(R"({"sim": {"dt": "fast"}})"),
             Catch::Contains("bad.json: sim.dt: expected a number, got a string"));
  CHECK_THAT(parseErrors(R"({"sim": {"substeps": 1000}})"),
             Catch::Contains("bad.json: sim.substeps: value 1000 is out of range [1, 64]"));
  CHECK_THAT(
      parseErrors(R"({"sim": {"stifness_window": 3}})"),
      Catch::Contains("sim.stifness_window: unknown key (did you mean \"stiffness_window\"?)"));
  CHECK_THAT(parseErrors(R"({"sim": {"stifness_window": 3}})"), Catch::Contains("substeps"));
  // A renamed key says where it went.
  CHECK_THAT(parseErrors(R"({"hairstyle": {"follow_count": 4}})"),
             Catch::Contains("hairstyle.follow_count: no longer read: it is now render.children"));
  CHECK_THAT(parseErrors(R"({"collision": {"mode": "sometimes"}})"),
             Catch::Contains("collision.mode: \"sometimes\" is not one of off|head|strands"));
  CHECK_THAT(parseErrors("{\n  \"sim\": {\"dt\": 0.01,,}\n}"), Catch::Contains("bad.json:2:"));
  CHECK_THAT(parseErrors("{\n  \"sim\": {\"dt\": 0.01,,}\n}"), Catch::Contains("invalid JSON"));
  CHECK_THAT(parseErrors(R"({"head": {"spheres": [{"center": [0,0,0], "radius": -1}]}})"),
             Catch::Contains("head.spheres[0].radius: value -1 is out of range"));
  CHECK_THAT(parseErrors(R"({"hairstyle": {"length_min": 0.5, "length_max": 0.3}})"),
             Catch::Contains("hairstyle.length_min"));
  CHECK_THAT(parseErrors(R"([1, 2])"), Catch::Contains("top level must be a JSON object"));
}

TEST_CASE("a strand count the machine cannot hold is refused before allocation", "[quick]") {
  Config c;
  c.hairstyle.strands = 1000000;
  c.hairstyle.particlesPerStrand = 64;
  // 64M particles at a few hundred bytes each: more than half of any test machine's memory
  // or beyond the particle limit.
  CHECK_FALSE(checkCapacity(c).empty());
  c.hairstyle.strands = 10000;
  c.hairstyle.particlesPerStrand = 16;
  CHECK(checkCapacity(c).empty());
}

TEST_CASE("saving never leaves a truncated preset", "[quick]") {
  const fs::path dir = fs::temp_directory_path() / "csm_atomic";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "p.json").string();
  Preset c;
  c.name = "original";
  std::string err;
  REQUIRE(savePreset(path, c, &err));
  const auto sizeBefore = fs::file_size(path);

  // A disk that fills up mid-write: cap the file size far below the preset's, so writes fail
  // (SIGXFSZ ignored, the writes get EFBIG instead).
  struct rlimit old;
  getrlimit(RLIMIT_FSIZE, &old);
  struct rlimit tiny = old;
  tiny.rlim_cur = 200;
  auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  setrlimit(RLIMIT_FSIZE, &tiny);
  c.name = "changed";
  const bool saved = savePreset(path, c, &err);
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);

  CHECK_FALSE(saved);
  CHECK_THAT(err, Catch::Contains("p.json"));
  CHECK(fs::file_size(path) == sizeBefore);
  Preset back;
  PresetErrors e;
  REQUIRE(loadPreset(path, back, e));
  CHECK(back.name == "original");
  for (const auto& entry : fs::directory_iterator(dir))
    CHECK(entry.path().filename() == "p.json");  // no temporary left behind

  // A target that cannot be replaced (a directory): refused, nothing left behind.
  fs::create_directories(dir / "q.json" / "inside");
  CHECK_FALSE(savePreset((dir / "q.json").string(), c, &err));
  CHECK(fs::is_directory(dir / "q.json" / "inside"));
  fs::remove_all(dir);
}

TEST_CASE("command-line values are parsed per type", "[quick]") {
  Preset c;
  CHECK(paramFromText(*findParam("wind.strength"), c, "3.5") == "");
  CHECK(c.scene.wind.strength == 3.5f);
  CHECK(paramFromText(*findParam("collision.mode"), c, "head") == "");
  CHECK(c.scene.collision.mode == CollisionMode::Head);
  CHECK(paramFromText(*findParam("collision.mode"), c, "full") == "");  // older presets
  CHECK(c.scene.collision.mode == CollisionMode::Strands);
  CHECK(paramFromText(*findParam("wind.direction"), c, "0,0,1") == "");
  CHECK(c.scene.wind.direction == glm::vec3(0, 0, 1));
  CHECK(paramFromText(*findParam("render.shadows"), c, "false") == "");
  CHECK_FALSE(c.view.render.shadows);
  CHECK(paramFromText(*findParam("sim.substeps"), c, "2.5") != "");
  CHECK(paramFromText(*findParam("name"), c, "42") == "");
  CHECK(c.name == "42");
}

TEST_CASE("a parameter's type is its field's, and the modules' lists make the preset's",
          "[quick]") {
  // Declared by pointer to member: the row's type comes from the field's C++ type.
  CHECK(findParam("sim.dt")->type == ParamType::Float);
  CHECK(findParam("sim.substeps")->type == ParamType::Int);
  CHECK(findParam("sim.strain_limiting")->type == ParamType::Bool);
  CHECK(findParam("sim.stiffness_model")->type == ParamType::Enum);
  CHECK(findParam("wind.direction")->type == ParamType::Vec3);
  CHECK(findParam("render.root_color")->type == ParamType::Color);
  CHECK(findParam("head.spheres")->type == ParamType::Spheres);
  CHECK(findParam("hairstyle.file")->type == ParamType::String);
  // A row reads and writes the field it names, through the preset.
  Preset p;
  findParam("sim.substeps")->ref<int>(p) = 7;
  CHECK(p.scene.sim.substeps == 7);
  findParam("camera.distance")->ref<float>(p) = 2.5f;
  CHECK(p.view.camera.distance == 2.5f);
  CHECK_THROWS(findParam("camera.distance")->ref<int>(p));
  // The simulation's rows and the view's, and nothing else but the preset's own two.
  CHECK(params().size() == simParams().size() + viewParams().size() + 2);
  for (const Param<Config>& s : simParams()) CHECK(findParam(s.key) != nullptr);
  for (const Param<ViewConfig>& v : viewParams()) CHECK(findParam(v.key) != nullptr);
  // Defaults are the config structs' own.
  CHECK(valueText(*findParam("sim.dt"), Preset{}) ==
        paramToJson(*findSimParam("sim.dt"), Config{}).dump());
}

TEST_CASE("render.hair_color: natural colours by name from JSON and --set, each its own",
          "[quick]") {
  Preset c;
  CHECK(c.view.render.hairColor == HairColor::Custom);  // presets look as they did
  PresetErrors e;
  REQUIRE(parsePreset(R"({"render": {"hair_color": "blond"}})", "p.json", c, e));
  CHECK(c.view.render.hairColor == HairColor::Blond);
  CHECK(paramFromText(*findParam("render.hair_color"), c, "red") == "");
  CHECK(c.view.render.hairColor == HairColor::Red);
  CHECK(paramFromText(*findParam("render.hair_color"), c, "purple") != "");
  CHECK(c.view.render.hairColor == HairColor::Red);
  CHECK(parseErrors(R"({"render": {"hair_color": "ginger"}})").find("hair_color") !=
        std::string::npos);

  // Each natural colour differs from every other at the root and the tip, is darker at the
  // root, and ignores the custom colours; custom gives them back.
  RenderConfig r;
  r.rootColor = {0.9f, 0.0f, 0.9f};
  r.tipColor = {0.0f, 0.9f, 0.0f};
  const std::vector<HairColor> natural = {HairColor::Black, HairColor::Brown, HairColor::Blond,
                                          HairColor::Red, HairColor::Grey};
  auto luma = [](glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  for (std::size_t i = 0; i < natural.size(); ++i) {
    INFO("colour " << int(natural[i]));
    const HairColors a = hairColors(natural[i], r);
    CHECK(luma(a.root) < luma(a.tip));
    CHECK(a.root != r.rootColor);
    for (std::size_t j = 0; j < i; ++j) {
      const HairColors b = hairColors(natural[j], r);
      CHECK(a.root != b.root);
      CHECK(a.tip != b.tip);
    }
  }
  CHECK(luma(hairColors(HairColor::Black, r).tip) < luma(hairColors(HairColor::Brown, r).tip));
  CHECK(luma(hairColors(HairColor::Brown, r).tip) < luma(hairColors(HairColor::Blond, r).tip));
  // Red hair is red: its tip's red well above its blue; grey is nearly neutral.
  const HairColors red = hairColors(HairColor::Red, r), grey = hairColors(HairColor::Grey, r);
  CHECK(red.tip.r > 4.0f * red.tip.b);
  CHECK(grey.tip.r - grey.tip.b < 0.1f);
  r.hairColor = HairColor::Custom;
  CHECK(hairColors(r).root == r.rootColor);
  CHECK(hairColors(r).tip == r.tipColor);
  // The panel greys the custom colours out while a natural colour is chosen.
  Preset p;
  CHECK(findParam("render.root_color")->applies(p));
  p.view.render.hairColor = HairColor::Grey;
  CHECK_FALSE(findParam("render.root_color")->applies(p));
  CHECK_FALSE(findParam("render.tip_color")->applies(p));
}

// Found by fuzz_preset (tests/fuzz/regressions/preset/number_overflow.json): nlohmann throws
// out_of_range, not parse_error, for a number beyond double's range; it escaped parsePreset.
TEST_CASE("a number beyond double's range is refused with a message, not thrown", "[quick]") {
  CHECK_THAT(parseErrors(R"({"sim": {"dt": 1e999}})"),
             Catch::Contains("bad.json: invalid JSON: number overflow parsing '1e999'"));
  CHECK_THAT(parseErrors(R"({"hairstyle": {"strands": -4e400}})"),
             Catch::Contains("bad.json: invalid JSON: number overflow"));
}
