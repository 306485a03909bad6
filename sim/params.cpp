#include "sim/params.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include <nlohmann/json.hpp>

namespace csm {
namespace {

#define FIELD(member) [](Config& c) -> void* { return &c.member; }

using P = ParamType;
using E = Effect;

bool paperModel(const Config& c) {
  return c.sim.stiffnessModel == StiffnessModel::Paper;
}
bool calibratedModel(const Config& c) {
  return c.sim.stiffnessModel == StiffnessModel::Calibrated;
}

std::vector<Param> buildParams() {
  return {
      // Preset
      {"name", "Name", "Preset", P::String, 0, 0, "Short name of the preset.", E::Info,
       FIELD(name)},
      {"description", "Description", "Preset", P::String, 0, 0, "What the scene shows.", E::Info,
       FIELD(description)},

      // Hairstyle
      {"hairstyle.file", "Groom file", "Hairstyle", P::String, 0, 0,
       "A cyHair .hair or TressFX .tfx groom to load instead of growing strands; empty = the "
       "generator. Relative paths are relative to the preset.",
       E::Rebuild, FIELD(hairstyle.file)},
      {"hairstyle.strands",
       "Strands",
       "Hairstyle",
       P::Int,
       1,
       1000000,
       "Number of simulated strands. A smaller count keeps the first strands of a larger one.",
       E::Rebuild,
       FIELD(hairstyle.strands),
       {},
       true},
      {"hairstyle.particles_per_strand", "Particles per strand", "Hairstyle", P::Int, 0, 64,
       "Fixed particle count per strand; 0 chooses it per strand from its length and curl.",
       E::Rebuild, FIELD(hairstyle.particlesPerStrand)},
      {"hairstyle.min_particles", "Min particles", "Hairstyle", P::Int, 3, 64,
       "Fewest particles a strand gets when chosen by length.", E::Rebuild,
       FIELD(hairstyle.minParticles)},
      {"hairstyle.max_particles", "Max particles", "Hairstyle", P::Int, 3, 64,
       "Most particles a strand gets when chosen by length.", E::Rebuild,
       FIELD(hairstyle.maxParticles)},
      {"hairstyle.segment_length", "Segment length", "Hairstyle", P::Float, 0.002, 0.2,
       "Target arc length between particles (m) when the count follows length and curl.",
       E::Rebuild, FIELD(hairstyle.segmentLength)},
      {"hairstyle.length_min", "Length min", "Hairstyle", P::Float, 0.005, 2.0,
       "Shortest strand (m).", E::Rebuild, FIELD(hairstyle.lengthMin)},
      {"hairstyle.length_max", "Length max", "Hairstyle", P::Float, 0.005, 2.0,
       "Longest strand (m).", E::Rebuild, FIELD(hairstyle.lengthMax)},
      {"hairstyle.curl_radius", "Curl radius", "Hairstyle|Curl", P::Float, 0.0, 0.1,
       "Helix radius at the tip (m); 0 = straight.", E::Rebuild, FIELD(hairstyle.curlRadius)},
      {"hairstyle.curl_pitch", "Curl pitch", "Hairstyle|Curl", P::Float, 0.005, 0.5,
       "Length along the strand of one turn of curl (m).", E::Rebuild, FIELD(hairstyle.curlPitch)},
      {"hairstyle.curl_start", "Curl start", "Hairstyle|Curl", P::Float, 0.0, 1.0,
       "Fraction of the length, from the root, where curl begins: straight at the scalp, curly "
       "toward the tips.",
       E::Rebuild, FIELD(hairstyle.curlStart)},
      {"hairstyle.scalp_angle", "Scalp angle", "Hairstyle|Scalp", P::Float, 5.0, 180.0,
       "How far from the crown the scalp reaches (degrees).", E::Rebuild,
       FIELD(hairstyle.scalpAngle)},
      {"hairstyle.hairline_front", "Front hairline", "Hairstyle|Scalp", P::Float, 5.0, 180.0,
       "How far from the crown the hairline reaches on the forehead (degrees).", E::Rebuild,
       FIELD(hairstyle.hairlineFront)},
      {"hairstyle.fall", "Fall", "Hairstyle", P::Float, 0.0, 1.0,
       "How quickly strands turn from the scalp normal to hang down: 0 stands up, 1 falls at "
       "once.",
       E::Rebuild, FIELD(hairstyle.fall)},
      {"hairstyle.sweep", "Sweep back", "Hairstyle", P::Float, 0.0, 2.0,
       "How far hair growing toward the face is swept back and to the sides (0 = it falls over "
       "the face).",
       E::Rebuild, FIELD(hairstyle.sweep)},
      {"hairstyle.seed", "Seed", "Hairstyle", P::Int, 0, 2147483647,
       "Random seed of the groom. The same seed gives the same hair.", E::Rebuild,
       FIELD(hairstyle.seed)},
      {"hairstyle.import_scale", "Import scale", "Hairstyle|Import", P::Float, 0.0, 1000.0,
       "Scale applied to a groom file; 0 fits it to the head.", E::Rebuild,
       FIELD(hairstyle.importScale)},
      {"hairstyle.import_rotation", "Import rotation", "Hairstyle|Import", P::Vec3, -360, 360,
       "Euler XYZ rotation (degrees) applied to a groom file.", E::Rebuild,
       FIELD(hairstyle.importRotation)},
      {"hairstyle.import_offset", "Import offset", "Hairstyle|Import", P::Vec3, -10, 10,
       "Offset (m) applied to a groom file after fitting.", E::Rebuild,
       FIELD(hairstyle.importOffset)},
      {"hairstyle.resample_tolerance", "Resample tolerance", "Hairstyle|Import", P::Float, 0.0,
       0.05,
       "Largest distance (m) the resampled strand may stray from the file's curve; 0 keeps the "
       "file's points.",
       E::Rebuild, FIELD(hairstyle.resampleTolerance)},
      {"hairstyle.follow_count", "Follow hairs", "Hairstyle|Follow", P::Int, 0, 64,
       "Render-only strands drawn around each simulated strand.", E::Render,
       FIELD(hairstyle.followCount)},
      {"hairstyle.follow_spread", "Follow spread", "Hairstyle|Follow", P::Float, 0.0, 0.05,
       "Distance (m) of follow hairs from their guide at the root.", E::Render,
       FIELD(hairstyle.followSpread)},

      // Head
      {"head.spheres", "Head spheres", "Head", P::Spheres, -10, 10,
       "Spheres (centre in the head frame, radius) that the hair collides with; the first is "
       "the scalp the hair grows from.",
       E::Rebuild, FIELD(head.spheres)},
      {"head.motion",
       "Motion",
       "Head",
       P::Enum,
       0,
       0,
       "How the head moves: none, nod, shake, spin, sway or bounce.",
       E::Live,
       FIELD(head.motion),
       {"none", "nod", "shake", "spin", "sway", "bounce"}},
      {"head.amplitude", "Amplitude", "Head", P::Float, 0.0, 180.0,
       "Amplitude of the motion: degrees, or centimetres for bounce.", E::Live,
       FIELD(head.amplitude)},
      {"head.frequency", "Frequency", "Head", P::Float, 0.0, 10.0, "Motion frequency (Hz).",
       E::Live, FIELD(head.frequency)},
      {"head.pivot", "Pivot", "Head", P::Vec3, -1, 1,
       "Point in the head frame that rotations turn about (the neck).", E::Live, FIELD(head.pivot)},

      // Simulation
      {"sim.dt",
       "Frame time step",
       "Simulation",
       P::Float,
       1e-4,
       0.1,
       "Simulated seconds per frame; each frame is split into substeps.",
       E::Live,
       FIELD(sim.dt),
       {},
       true},
      {"sim.stiffness_model",
       "Stiffness model",
       "Simulation",
       P::Enum,
       0,
       0,
       "calibrated: a window in metres and a bending stiffness; the hair looks the same at any "
       "substeps, particle count and density (DESIGN.md section 4). paper: a window in "
       "particles and alpha per step, as the paper does: more substeps stiffen the hair, more "
       "particles soften it.",
       E::Live,
       FIELD(sim.stiffnessModel),
       {"paper", "calibrated"}},
      {"sim.substeps", "Substeps", "Simulation", P::Int, 1, 64,
       "Steps per frame (paper); the fewest steps per frame (calibrated: more when the "
       "stiffness needs them, up to max substeps).",
       E::Live, FIELD(sim.substeps)},
      {"sim.max_substeps",
       "Max substeps",
       "Simulation",
       P::Int,
       1,
       256,
       "Calibrated: the most steps per frame the stiffness may ask for. When it binds, the "
       "stiffest strands are softer than asked, and the log and the panel say so.",
       E::Live,
       FIELD(sim.maxSubsteps),
       {},
       false,
       calibratedModel},
      {"sim.window_length",
       "Stiffness window",
       "Simulation",
       P::Float,
       0.002,
       1.0,
       "Calibrated: half-length of each shape-matching region along the strand (m; the panel "
       "shows cm). Regions never hold fewer than 3 particles. A longer window gives smoother "
       "bends and needs fewer steps for the same stiffness.",
       E::Live,
       FIELD(sim.windowLength),
       {},
       true,
       calibratedModel,
       100.0,
       "cm"},
      {"sim.bending_stiffness",
       "Bending stiffness",
       "Simulation",
       P::Float,
       1e-7,
       100.0,
       "Calibrated: bending stiffness per unit mass, EI over the linear density (m^4/s^2). A "
       "real hair is about 1e-3; a clump of hair acts stiffer. Doubling it halves the sag.",
       E::Live,
       FIELD(sim.bendingStiffness),
       {},
       true,
       calibratedModel,
       1.0,
       "m^4/s^2"},
      {"sim.root_length",
       "Root length",
       "Simulation",
       P::Float,
       0.0,
       0.2,
       "Calibrated: length of strand from the root that the scalp holds rigidly (m; the panel "
       "shows cm); at least `pinned` particles. A length, so the held piece stays the same with "
       "more particles.",
       E::Live,
       FIELD(sim.rootLength),
       {},
       false,
       calibratedModel,
       100.0,
       "cm"},
      {"sim.stiffness_window",
       "Stiffness window w",
       "Simulation",
       P::Int,
       1,
       32,
       "Paper: half-width of each shape-matching region, in particles: larger = stiffer hair.",
       E::Live,
       FIELD(sim.stiffnessWindow),
       {},
       false,
       paperModel,
       1.0,
       "particles"},
      {"sim.stiffness",
       "Stiffness alpha",
       "Simulation",
       P::Float,
       0.0,
       1.0,
       "Paper: how far particles move toward their goals each step (1 = the paper).",
       E::Live,
       FIELD(sim.stiffness),
       {},
       false,
       paperModel},
      {"sim.damping", "Damping", "Simulation", P::Float, 0.0, 100.0,
       "Linear velocity damping (1/s): velocities fall by exp(-damping t).", E::Live,
       FIELD(sim.damping)},
      {"sim.strain_limiting", "Strain limiting", "Simulation", P::Bool, 0, 1,
       "Limit segment stretch root to tip after shape matching.", E::Live,
       FIELD(sim.strainLimiting)},
      {"sim.strain_limit", "Strain limit", "Simulation", P::Float, 0.0, 1.0,
       "Largest relative stretch of a segment, epsilon.", E::Live, FIELD(sim.strainLimit)},
      {"sim.pinned", "Pinned particles", "Simulation", P::Int, 1, 4,
       "Particles from the root that follow the head rigidly (calibrated: at least this many; "
       "see root length).",
       E::Live, FIELD(sim.pinned)},
      {"sim.gravity", "Gravity", "Simulation", P::Vec3, -100, 100, "Gravity (m/s^2).", E::Live,
       FIELD(sim.gravity)},
      {"sim.density",
       "Linear density",
       "Simulation",
       P::Float,
       1e-7,
       1.0,
       "Mass per metre of strand (kg/m); particle masses follow segment lengths. Shape matching "
       "and every acceleration are independent of it; it sets EI = bending stiffness x "
       "density.",
       E::Live,
       FIELD(sim.density),
       {},
       true},
      {"sim.dftl", "DFTL correction", "Simulation", P::Float, 0.0, 1.0,
       "Dynamic follow-the-leader velocity correction after strain limiting (Mueller et al. "
       "2012); 0 = off, 1 = full.",
       E::Live, FIELD(sim.dftl)},
      {"sim.rotation_iterations", "Rotation iterations", "Simulation", P::Int, 1, 32,
       "Quaternion iterations per region and step when extracting rotations (warm-started).",
       E::Live, FIELD(sim.rotationIterations)},

      // Collision
      {"collision.mode",
       "Collisions",
       "Simulation|Collision",
       P::Enum,
       0,
       0,
       "off: none; head: hair against the head spheres; full: head and hair against hair.",
       E::Live,
       FIELD(collision.mode),
       {"off", "head", "full"}},
      {"collision.radius",
       "Hair radius",
       "Simulation|Collision",
       P::Float,
       1e-5,
       0.02,
       "Collision radius of a strand (m).",
       E::Live,
       FIELD(collision.radius),
       {},
       true},
      {"collision.stiffness",
       "Penalty stiffness",
       "Simulation|Collision",
       P::Float,
       0.0,
       1e6,
       "Hair-hair penalty: acceleration per metre of overlap (1/s^2).",
       E::Live,
       FIELD(collision.stiffness),
       {},
       true},
      {"collision.damping", "Normal damping", "Simulation|Collision", P::Float, 0.0, 1000.0,
       "Hair-hair damping of the approaching speed (1/s).", E::Live, FIELD(collision.damping)},
      {"collision.friction", "Hair friction", "Simulation|Collision", P::Float, 0.0, 1.0,
       "Hair-hair friction: share of sliding speed removed per contact.", E::Live,
       FIELD(collision.friction)},
      {"collision.head_friction", "Head friction", "Simulation|Collision", P::Float, 0.0, 2.0,
       "Coulomb friction coefficient between hair and head: sliding slows by at most this "
       "times the push the head gives.",
       E::Live, FIELD(collision.headFriction)},

      // Wind
      {"wind.strength", "Strength", "Wind", P::Float, 0.0, 50.0, "Mean wind speed (m/s).", E::Live,
       FIELD(wind.strength)},
      {"wind.direction", "Direction", "Wind", P::Vec3, -1, 1,
       "Direction the wind blows toward (normalised when used).", E::Live, FIELD(wind.direction)},
      {"wind.gusts", "Gusts", "Wind", P::Float, 0.0, 2.0, "Relative amplitude of gusts over time.",
       E::Live, FIELD(wind.gusts)},
      {"wind.gust_frequency", "Gust frequency", "Wind", P::Float, 0.0, 10.0,
       "How often gusts come (Hz).", E::Live, FIELD(wind.gustFrequency)},
      {"wind.turbulence", "Turbulence", "Wind", P::Float, 0.0, 2.0,
       "Relative amplitude of the spatial turbulence.", E::Live, FIELD(wind.turbulence)},
      {"wind.turbulence_scale", "Turbulence scale", "Wind", P::Float, 0.005, 2.0,
       "Size of turbulent eddies (m).", E::Live, FIELD(wind.turbulenceScale)},
      {"wind.drag", "Drag", "Wind", P::Float, 0.0, 100.0,
       "Acceleration per m/s of wind across the strand (1/s), applied implicitly (stable at "
       "any step).",
       E::Live, FIELD(wind.drag)},

      // Rendering
      {"render.shadows", "Shadows", "Rendering", P::Bool, 0, 1, "Deep opacity map self-shadowing.",
       E::Render, FIELD(render.shadows)},
      {"render.strand_width", "Strand width", "Rendering", P::Float, 0.1, 8.0,
       "Width of a drawn strand (pixels).", E::Render, FIELD(render.strandWidth)},
      {"render.subdivision", "Subdivision", "Rendering", P::Int, 1, 16,
       "Spline segments drawn per simulated segment.", E::Render, FIELD(render.subdivision)},
      {"render.root_color", "Root colour", "Rendering|Colour", P::Color, 0, 1,
       "Hair colour at the root.", E::Render, FIELD(render.rootColor)},
      {"render.tip_color", "Tip colour", "Rendering|Colour", P::Color, 0, 1,
       "Hair colour at the tip.", E::Render, FIELD(render.tipColor)},
      {"render.color_variation", "Colour variation", "Rendering|Colour", P::Float, 0.0, 1.0,
       "Per-strand random variation of brightness.", E::Render, FIELD(render.colorVariation)},
      {"render.specular_shift1", "Primary shift", "Rendering|Specular", P::Float, -1.0, 1.0,
       "Shift of the primary (white) highlight along the strand normal.", E::Render,
       FIELD(render.specularShift1)},
      {"render.specular_shift2", "Secondary shift", "Rendering|Specular", P::Float, -1.0, 1.0,
       "Shift of the secondary (tinted) highlight.", E::Render, FIELD(render.specularShift2)},
      {"render.specular_exponent1",
       "Primary exponent",
       "Rendering|Specular",
       P::Float,
       1.0,
       1000.0,
       "Sharpness of the primary highlight.",
       E::Render,
       FIELD(render.specularExponent1),
       {},
       true},
      {"render.specular_exponent2",
       "Secondary exponent",
       "Rendering|Specular",
       P::Float,
       1.0,
       1000.0,
       "Sharpness of the secondary highlight.",
       E::Render,
       FIELD(render.specularExponent2),
       {},
       true},
      {"render.specular_strength1", "Primary strength", "Rendering|Specular", P::Float, 0.0, 4.0,
       "Brightness of the primary highlight.", E::Render, FIELD(render.specularStrength1)},
      {"render.specular_strength2", "Secondary strength", "Rendering|Specular", P::Float, 0.0, 4.0,
       "Brightness of the secondary highlight.", E::Render, FIELD(render.specularStrength2)},
      {"render.opacity", "Opacity", "Rendering|Shadows", P::Float, 0.01, 1.0,
       "Opacity of one strand, for coverage and shadows.", E::Render, FIELD(render.opacity)},
      {"render.layer_spacing", "Layer spacing", "Rendering|Shadows", P::Float, 0.0005, 0.2,
       "Depth between deep opacity map layers (m).", E::Render, FIELD(render.layerSpacing)},
      {"render.shadow_map_size", "Shadow map size", "Rendering|Shadows", P::Int, 128, 4096,
       "Resolution of the deep opacity maps.", E::Render, FIELD(render.shadowMapSize)},
      {"render.head_color", "Head colour", "Rendering|Colour", P::Color, 0, 1,
       "Colour of the head.", E::Render, FIELD(render.headColor)},
      {"render.background", "Background", "Rendering|Colour", P::Color, 0, 1, "Background colour.",
       E::Render, FIELD(render.background)},
      {"render.samples", "MSAA samples", "Rendering", P::Int, 1, 16,
       "Multisampling for hair thinner than a pixel.", E::Render, FIELD(render.samples)},

      // Camera and light
      {"camera.target", "Target", "Camera", P::Vec3, -10, 10, "Point the camera looks at (m).",
       E::Render, FIELD(camera.target)},
      {"camera.distance", "Distance", "Camera", P::Float, 0.05, 20.0,
       "Distance from the target (m).", E::Render, FIELD(camera.distance)},
      {"camera.yaw", "Yaw", "Camera", P::Float, -360.0, 360.0, "Angle about y (degrees).",
       E::Render, FIELD(camera.yaw)},
      {"camera.pitch", "Pitch", "Camera", P::Float, -89.0, 89.0,
       "Angle above the horizon (degrees).", E::Render, FIELD(camera.pitch)},
      {"camera.fov", "Field of view", "Camera", P::Float, 5.0, 120.0,
       "Vertical field of view (degrees).", E::Render, FIELD(camera.fov)},
      {"light.direction", "Direction", "Light", P::Vec3, -1, 1,
       "Direction the light travels (normalised when used).", E::Render, FIELD(light.direction)},
      {"light.color", "Colour", "Light", P::Color, 0, 1, "Light colour.", E::Render,
       FIELD(light.color)},
      {"light.intensity", "Intensity", "Light", P::Float, 0.0, 10.0, "Light intensity.", E::Render,
       FIELD(light.intensity)},
      {"light.ambient", "Ambient", "Light", P::Float, 0.0, 2.0, "Ambient light.", E::Render,
       FIELD(light.ambient)},
  };
}

#undef FIELD

std::string fmtNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string jsonKind(const nlohmann::json& v) {
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

std::string outOfRange(const Param& p, double v) {
  return "value " + fmtNumber(v) + " is out of range [" + fmtNumber(p.min) + ", " +
         fmtNumber(p.max) + "]";
}

std::string readVec3(const Param& p, const nlohmann::json& v, glm::vec3& out) {
  if (!v.is_array() || v.size() != 3) return "expected an array of 3 numbers, got " + jsonKind(v);
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) return "element " + std::to_string(i) + ": expected a number";
    double x = v[i].get<double>();
    if (!std::isfinite(x) || x < p.min || x > p.max)
      return "element " + std::to_string(i) + ": " + outOfRange(p, x);
    out[i] = static_cast<float>(x);
  }
  return {};
}

// The shortest decimal that reads back as the same float, as a double: JSON then says 0.04,
// not 0.03999999910593033, and reading it gives the float back.
double shortest(float v) {
  if (!std::isfinite(v)) return v;
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf - 1, v);
  *r.ptr = '\0';
  return std::strtod(buf, nullptr);
}

}  // namespace

const std::vector<Param>& params() {
  static const std::vector<Param> list = buildParams();
  return list;
}

const Param* findParam(std::string_view key) {
  for (const Param& p : params())
    if (p.key == key) return &p;
  return nullptr;
}

nlohmann::json paramToJson(const Param& p, const Config& c) {
  using nlohmann::json;
  switch (p.type) {
    case P::Bool:
      return p.ref<bool>(c);
    case P::Int:
      return p.ref<int>(c);
    case P::Float:
      return shortest(p.ref<float>(c));
    case P::Vec3:
    case P::Color: {
      const glm::vec3& v = p.ref<glm::vec3>(c);
      return json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
    }
    case P::Enum: {
      int i = p.ref<int>(c);
      return i >= 0 && i < static_cast<int>(p.options.size()) ? json(std::string(p.options[i]))
                                                              : json(i);
    }
    case P::String:
      return p.ref<std::string>(c);
    case P::Spheres: {
      json a = json::array();
      for (const Sphere& s : p.ref<std::vector<Sphere>>(c))
        a.push_back({{"center", {shortest(s.center.x), shortest(s.center.y), shortest(s.center.z)}},
                     {"radius", shortest(s.radius)}});
      return a;
    }
  }
  return nullptr;
}

std::string paramFromJson(const Param& p, Config& c, const nlohmann::json& v) {
  switch (p.type) {
    case P::Bool:
      if (!v.is_boolean()) return "expected true or false, got " + jsonKind(v);
      p.ref<bool>(c) = v.get<bool>();
      return {};
    case P::Int: {
      if (!v.is_number()) return "expected an integer, got " + jsonKind(v);
      double d = v.get<double>();
      if (!v.is_number_integer() && d != std::floor(d))
        return "expected an integer, got " + fmtNumber(d);
      if (d < p.min || d > p.max) return outOfRange(p, d);
      p.ref<int>(c) = static_cast<int>(d);
      return {};
    }
    case P::Float: {
      if (!v.is_number()) return "expected a number, got " + jsonKind(v);
      double d = v.get<double>();
      if (!std::isfinite(d) || d < p.min || d > p.max) return outOfRange(p, d);
      p.ref<float>(c) = static_cast<float>(d);
      return {};
    }
    case P::Vec3:
    case P::Color: {
      glm::vec3 out;
      std::string err = readVec3(p, v, out);
      if (err.empty()) p.ref<glm::vec3>(c) = out;
      return err;
    }
    case P::Enum: {
      if (!v.is_string()) return "expected one of " + describeType(p) + ", got " + jsonKind(v);
      std::string s = v.get<std::string>();
      for (size_t i = 0; i < p.options.size(); ++i)
        if (p.options[i] == s) {
          p.ref<int>(c) = static_cast<int>(i);
          return {};
        }
      return "\"" + s + "\" is not " + describeType(p);
    }
    case P::String:
      if (!v.is_string()) return "expected a string, got " + jsonKind(v);
      p.ref<std::string>(c) = v.get<std::string>();
      return {};
    case P::Spheres: {
      if (!v.is_array() || v.empty()) return "expected a non-empty array of spheres";
      if (v.size() > 64) return "at most 64 spheres";
      std::vector<Sphere> out;
      for (size_t i = 0; i < v.size(); ++i) {
        const auto& s = v[i];
        std::string where = "[" + std::to_string(i) + "]";
        if (!s.is_object()) return where + ": expected {\"center\": [x,y,z], \"radius\": r}";
        for (auto it = s.begin(); it != s.end(); ++it)
          if (it.key() != "center" && it.key() != "radius")
            return where + "." + it.key() + ": unknown key (keys: center, radius)";
        if (!s.contains("center") || !s.contains("radius"))
          return where + ": needs both center and radius";
        Sphere sp;
        std::string err = readVec3(p, s["center"], sp.center);
        if (!err.empty()) return where + ".center: " + err;
        if (!s["radius"].is_number()) return where + ".radius: expected a number";
        double r = s["radius"].get<double>();
        if (!(r > 0.0 && r <= 10.0))
          return where + ".radius: value " + fmtNumber(r) + " is out of range (0, 10]";
        sp.radius = static_cast<float>(r);
        out.push_back(sp);
      }
      p.ref<std::vector<Sphere>>(c) = out;
      return {};
    }
  }
  return "unsupported parameter type";
}

std::string paramFromText(const Param& p, Config& c, std::string_view text) {
  nlohmann::json v = nlohmann::json::parse(text, nullptr, false);
  if (v.is_discarded() || (p.type == P::String && !v.is_string())) {
    v = std::string(text);
    // "x,y,z" for vectors.
    if (p.type == P::Vec3 || p.type == P::Color) {
      nlohmann::json arr = nlohmann::json::parse("[" + std::string(text) + "]", nullptr, false);
      if (!arr.is_discarded()) v = arr;
    }
  }
  return paramFromJson(p, c, v);
}

std::string describeType(const Param& p) {
  switch (p.type) {
    case P::Bool:
      return "true|false";
    case P::Int:
      return "int in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Float:
      return "number in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Vec3:
      return "[x,y,z] each in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Color:
      return "[r,g,b] each in [0, 1]";
    case P::Enum: {
      std::string s = "one of ";
      for (size_t i = 0; i < p.options.size(); ++i) s += (i ? "|" : "") + std::string(p.options[i]);
      return s;
    }
    case P::String:
      return "string";
    case P::Spheres:
      return "[{\"center\": [x,y,z], \"radius\": r}, ...]";
  }
  return "?";
}

std::string valueText(const Param& p, const Config& c) {
  return paramToJson(p, c).dump();
}

bool sameValue(const Param& p, const Config& a, const Config& b) {
  return paramToJson(p, a) == paramToJson(p, b);
}

}  // namespace csm
