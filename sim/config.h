// Everything a scene is: the values behind every parameter of a preset.
// The parameter table (sim/params.h) declares each field once, with its key, range and
// description; JSON, --set, --list-params and the ImGui panels all walk that table.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace csm {

struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 0.1f;
  bool operator==(const Sphere&) const = default;
};

enum class CollisionMode : int { Off = 0, Head = 1, Full = 2 };
enum class HeadMotion : int { None = 0, Nod, Shake, Spin, Sway, Bounce };
// How stiffness is given (sim/stiffness.h). Paper: a window in particles and alpha = the pull
// toward the goals per step, as the paper does; the hair gets stiffer with more substeps and
// softer with more particles. Calibrated: a window in metres and a bending stiffness per unit
// mass; each step pulls by alpha = min(1, k h^2), so the hair is the same at any step size,
// resolution and density.
enum class StiffnessModel : int { Paper = 0, Calibrated = 1 };

struct HairstyleConfig {
  std::string file;  // a groom file (.hair, .tfx); empty = the generator below
  int strands = 2000;
  int particlesPerStrand = 0;  // 0 = chosen per strand from its length and curl
  int minParticles = 8;
  int maxParticles = 25;
  float segmentLength = 0.02f;  // target arc length between particles when chosen by length
  float lengthMin = 0.20f;
  float lengthMax = 0.30f;
  float curlRadius = 0.0f;      // helix radius at the tip, metres
  float curlPitch = 0.05f;      // helix pitch, metres per turn
  float curlStart = 0.5f;       // fraction of the length where curl begins
  float scalpAngle = 105.0f;    // degrees from the crown that the scalp covers
  float hairlineFront = 50.0f;  // degrees from the crown where the forehead begins
  float fall = 0.6f;            // 0 = strands stick out along the normal, 1 = fall straight down
  float sweep = 0.7f;           // how far hair from the front is swept back from the face
  int seed = 1;
  // Imported grooms.
  float importScale = 0.0f;  // 0 = fit to the head automatically
  glm::vec3 importRotation{0.0f};
  glm::vec3 importOffset{0.0f};
  float resampleTolerance = 0.002f;  // metres; 0 keeps the file's points
  // Render-only strands that follow each simulated one.
  int followCount = 0;
  float followSpread = 0.004f;
};

struct HeadConfig {
  std::vector<Sphere> spheres{
      {{0.0f, 0.0f, 0.0f}, 0.1f}, {{0.0f, -0.065f, 0.03f}, 0.07f}, {{0.0f, -0.16f, -0.01f}, 0.05f}};
  HeadMotion motion = HeadMotion::None;
  float amplitude = 20.0f;              // degrees (nod, shake, sway) or centimetres (bounce)
  float frequency = 0.5f;               // Hz
  glm::vec3 pivot{0.0f, -0.15f, 0.0f};  // the neck: head rotations turn about it
};

struct SimConfig {
  float dt = 1.0f / 60.0f;  // simulated seconds per frame
  int substeps = 4;         // paper: steps per frame; calibrated: the fewest steps per frame
  int maxSubsteps = 64;     // calibrated: the most steps per frame the stiffness may ask for
  StiffnessModel stiffnessModel = StiffnessModel::Calibrated;
  // Calibrated: the region of particle k holds the particles within windowLength of rest arc
  // length of it (at least its neighbours), and bendingStiffness is EI over the linear density
  // (m^4/s^2). The default needs 4 steps of 1/240 s on 2 cm segments, and gives the default
  // hairstyle the look that the paper model's w = 2, alpha = 1 gave it there
  // (docs/BENCHMARKS.md, "Stiffness").
  float windowLength = 0.04f;        // m
  float bendingStiffness = 3.8e-3f;  // m^4/s^2
  // Calibrated: the scalp holds the particles within rootLength of rest arc length of the root
  // (at least `pinned` of them), so the held piece does not shrink with more particles.
  float rootLength = 0.02f;  // m
  // Paper: region of particle k is [k-w, k+w]; alpha the pull towards the goals per step.
  int stiffnessWindow = 2;
  float stiffness = 1.0f;
  float damping = 1.0f;       // 1/s, linear velocity damping: v *= exp(-damping h) per step
  float strainLimit = 0.05f;  // epsilon: longest allowed stretch of a segment
  bool strainLimiting = true;
  int pinned = 2;  // particles from the root that follow the head (calibrated: at least)
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  float density = 1.0e-4f;     // kg per metre of strand
  float dftl = 0.0f;           // dynamic follow-the-leader velocity correction, 0..1
  int rotationIterations = 3;  // quaternion iterations per region per step, warm-started
};

struct CollisionConfig {
  CollisionMode mode = CollisionMode::Full;
  float radius = 0.001f;  // hair radius, metres
  // Penalty forces act one frame late and sum over a segment's contacts: strong normal
  // damping then overshoots and flings strands out of dense hair (20/s reached 16 m/s on the
  // Fig. 1 scene, 5/s stays under 3 m/s).
  float stiffness = 4000.0f;  // penalty, acceleration per metre of overlap (1/s^2)
  float damping = 5.0f;       // normal damping, 1/s
  float friction = 0.3f;      // hair-hair tangential damping, 0..1
  float headFriction = 0.3f;  // Coulomb friction coefficient against the head
};

struct WindConfig {
  float strength = 0.0f;  // m/s
  glm::vec3 direction{1.0f, 0.0f, 0.0f};
  float gusts = 0.3f;            // relative amplitude of gusts
  float gustFrequency = 0.4f;    // Hz
  float turbulence = 0.3f;       // relative amplitude of spatial turbulence
  float turbulenceScale = 0.1f;  // metres
  float drag = 2.0f;  // 1/s: acceleration per m/s of perpendicular relative wind (implicit)
};

struct RenderConfig {
  bool shadows = true;
  float strandWidth = 1.5f;  // pixels
  int subdivision = 4;       // spline segments drawn per simulated segment
  glm::vec3 rootColor{0.10f, 0.06f, 0.035f};
  glm::vec3 tipColor{0.35f, 0.22f, 0.12f};
  float colorVariation = 0.15f;
  float specularShift1 = -0.08f;  // along the normal, in tangent units (primary, white)
  float specularShift2 = 0.12f;   // secondary, tinted
  float specularExponent1 = 80.0f;
  float specularExponent2 = 20.0f;
  float specularStrength1 = 0.35f;
  float specularStrength2 = 0.25f;
  float opacity = 0.6f;        // per strand
  float layerSpacing = 0.01f;  // deep opacity map layer spacing, metres
  int shadowMapSize = 1024;
  glm::vec3 headColor{0.80f, 0.62f, 0.52f};
  glm::vec3 background{0.55f, 0.60f, 0.66f};
  int samples = 4;  // multisampling
};

struct CameraConfig {
  glm::vec3 target{0.0f, -0.05f, 0.0f};
  float distance = 0.75f;
  float yaw = 30.0f;    // degrees about y
  float pitch = 10.0f;  // degrees above the horizon
  float fov = 40.0f;    // vertical, degrees
};

struct LightConfig {
  glm::vec3 direction{-0.5f, -0.7f, -0.5f};  // the direction light travels
  glm::vec3 color{1.0f, 0.97f, 0.92f};
  float intensity = 2.2f;
  float ambient = 0.25f;
};

struct Config {
  std::string name = "default";
  std::string description;
  HairstyleConfig hairstyle;
  HeadConfig head;
  SimConfig sim;
  CollisionConfig collision;
  WindConfig wind;
  RenderConfig render;
  CameraConfig camera;
  LightConfig light;
};

}  // namespace csm
