// The simulated scene: the values behind the simulation's parameters. The parameter table
// (sim/param/sim_params.h) names each field once, with its key, range and description; JSON, --set,
// --list-params and the ImGui panels all walk it (with the view's, render/view_params.h).
#pragma once

#include <algorithm>
#include <cstddef>
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

// What the hair collides with. Strands: the head and segment contacts between strands, as
// constraints in every substep (sim/solver/contacts.h).
enum class CollisionMode : int { Off = 0, Head = 1, Strands = 2, Volume = 3, VolumeStrands = 4 };
inline bool collidesWithHead(CollisionMode m) {
  return m != CollisionMode::Off;
}
inline bool strandContacts(CollisionMode m) {
  return m == CollisionMode::Strands || m == CollisionMode::VolumeStrands;
}
inline bool volumeForces(CollisionMode m) {
  return m == CollisionMode::Volume || m == CollisionMode::VolumeStrands;
}
// The names presets and metrics use, in enum order (collision.mode's choices).
inline constexpr const char* kCollisionModeNames[] = {"off", "head", "strands", "volume",
                                                      "volume+strands"};
inline const char* collisionModeName(CollisionMode m) {
  return kCollisionModeNames[int(m)];
}
enum class HeadMotion : int { None = 0, Nod, Shake, Spin, Sway, Bounce };
// What the head is, for collision and drawing: the built-in mannequin's signed distance field
// (sim/head/head_model.h), or the spheres of head.spheres, as the paper does.
enum class HeadShape : int { Sdf = 0, Spheres = 1 };
// A motion clip's up axis and the way its character faces at its first frame, in the clip's own
// axes: inferred from the skeleton (Auto), or said.
enum class ClipUp : int { Auto = 0, Y, Z, X };
enum class ClipFacing : int { Auto = 0, PlusZ, MinusZ, PlusX, MinusX, PlusY, MinusY };
// How a strand-contact iteration moves a segment (sim/solver/contacts.h): sweep takes its pairs in
// order, each from where the ones before it left the segment; jacobi moves it by the mean of
// what its pairs ask from where the iteration began.
enum class ContactSolve : int { Sweep = 0, Jacobi = 1 };
// What a strand contact is (sim/solver/contacts.h): a position constraint each substep
// (constraints), or the paper's penalty force, k (d0 - d) along the normal with normal damping
// and friction, which the next substep's prediction feels (penalty).
enum class ContactModel : int { Constraints = 0, Penalty = 1 };
// Where the generator parts the hair: none (it falls from the crown all round), down the middle,
// or on the head's left (+x) or right (-x).
enum class Parting : int { None = 0, Centre = 1, Left = 2, Right = 3 };
// How stiffness is given (sim/solver/stiffness.h). Paper: a window in particles and alpha = the
// pull toward the goals per step, as the paper does; the hair gets stiffer with more substeps and
// softer with more particles. Calibrated: a window in metres and a bending stiffness per unit
// mass; each step pulls by alpha = min(1, k h^2), so the hair is the same at any step size,
// resolution and density.
enum class StiffnessModel : int { Paper = 0, Calibrated = 1 };
// Which way a groom file's face looks in the file's own axes: auto takes TressFX (DirectX's
// left-handed frame, the face toward -z) as -z and every other format as +z; -z mirrors the
// file's z into the head frame (face +z, right-handed), +z keeps it.
enum class ImportFacing : int { Auto = 0, PlusZ = 1, MinusZ = 2 };
// Where a groom file goes: fitted onto the scene's head (Fit); kept where the file put it on
// head.mesh, the head's own fit applied to both (Head: a data set's groom beside its head); or
// Head when head.mesh is set and the file's roots lie on its surface once in the head frame, else
// Fit (Auto).
enum class ImportPlace : int { Auto = 0, Fit = 1, Head = 2 };

struct HairstyleConfig {
  std::string file;  // a groom file (.hair, .tfx); empty = the generator below
  int strands = 2000;
  // Strands simulated (guides); the others are drawn from them (sim/groom/guides.h). 0: every
  // strand; -1: every strand up to 20,000, 4,000 guides beyond.
  int guides = -1;
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
  Parting parting = Parting::None;
  bool fringe = false;    // hair from the front of the scalp falls forward, cut at the brow
  float volume = 0.006f;  // thickness of the hair's layer over the scalp (m)
  // Passes that push the grown strands apart where they lie closer than 2.2 r (r: the
  // collision radius), no particle further than separateLimit from where it grew and the
  // roots where they are (sim/groom/hairstyle.h); 0 keeps the groom as grown.
  int separatePasses = 0;
  float separateLimit = 0.005f;  // m
  int seed = 1;
  // Imported grooms.
  float importScale = 0.0f;  // 0 = fit to the head automatically
  glm::vec3 importRotation{0.0f};
  glm::vec3 importOffset{0.0f};
  ImportFacing importFacing = ImportFacing::Auto;
  ImportPlace importPlace = ImportPlace::Auto;
  float resampleTolerance = 0.002f;  // metres; 0 keeps the file's points
};

// hairstyle.guides = -1 (auto): a groom of more strands than this simulates kAutoGuides of them.
inline constexpr std::size_t kAutoGuideThreshold = 20000;
inline constexpr std::size_t kAutoGuides = 4000;

// The strands a groom of `strands` strands simulates for hairstyle.guides = `setting`: every
// strand at 0 (and when the setting is at least the groom's count), `setting` of them when
// positive, and at -1 every strand up to kAutoGuideThreshold, kAutoGuides beyond.
inline std::size_t guideCount(int setting, std::size_t strands) {
  if (setting > 0) return std::min(std::size_t(setting), strands);
  if (setting < 0 && strands > kAutoGuideThreshold) return kAutoGuides;
  return strands;
}

struct HeadConfig {
  std::string mesh;  // an OBJ or PLY head; empty = the built-in mannequin
  // How `mesh` comes into the head frame (sim/head/head_fit.h): metres per file unit (0 infers
  // it), its up and facing axes (auto infers them), and whether its cranium is moved onto the
  // mannequin's (false keeps the file's place).
  float meshScale = 0.0f;
  ClipUp meshUp = ClipUp::Auto;
  ClipFacing meshFacing = ClipFacing::Auto;
  bool meshPlace = true;
  // With `mesh`, an OBJ torso (the same frame, at rest) that moves with the chest's pose while
  // `mesh` moves with the head's; empty: `mesh` is the whole body, moving with the head.
  std::string torsoMesh;
  std::string meshDir;  // where a relative `mesh` is found: the preset's folder (not a parameter)
  std::vector<Sphere> spheres{
      {{0.0f, 0.0f, 0.0f}, 0.1f}, {{0.0f, -0.065f, 0.03f}, 0.07f}, {{0.0f, -0.16f, -0.01f}, 0.05f}};
  bool fitSpheres = false;  // as many spheres as `spheres`, fitted to the head's field
  HeadMotion motion = HeadMotion::None;
  float amplitude = 20.0f;              // degrees (nod, shake, sway) or centimetres (bounce)
  float frequency = 0.5f;               // Hz
  glm::vec3 pivot{0.0f, -0.15f, 0.0f};  // the neck: head rotations turn about it
};

// A motion-capture clip (BVH) that moves the character instead of head.motion (sim/motion).
struct MotionConfig {
  std::string clip;    // a BVH file, relative to the preset; empty = head.motion
  float scale = 0.0f;  // metres per clip unit; 0 infers it from the skeleton's height
  ClipUp up = ClipUp::Auto;
  ClipFacing facing = ClipFacing::Auto;
  std::string headJoint;   // empty: found by its usual names (Head, ...)
  std::string chestJoint;  // empty: Chest, Spine2, Spine1, ...
  bool loop = true;        // past its end the clip starts again; else it holds its last frame
  bool inPlace = false;    // the clip's horizontal travel removed
  // The least DFTL while the clip drives the character (dftlOf): a clip's starts, stops and
  // landings swing strands far harder than head.motion, and without it the strain limit's sweep
  // whips their tips (docs/BENCHMARKS.md, "Hair on a moving character").
  float dftl = 0.9f;
};

struct SimConfig {
  float dt = 1.0f / 60.0f;  // simulated seconds per frame
  int substeps = 4;         // paper: steps per frame; calibrated: the fewest steps per frame
  // Calibrated: the step budget, the most steps a frame. The strands stiffer than it resolves
  // (a real groom's shortest, which ask for tens of steps) run at alpha = 1, counted and said; 8
  // holds every shipped preset (3-6 steps) and a groom's own few short strands.
  int maxSubsteps = 8;
  StiffnessModel stiffnessModel = StiffnessModel::Calibrated;
  // Calibrated: the region of particle k holds the particles within windowLength of rest arc
  // length of it (at least its neighbours), and bendingStiffness is EI over the linear density
  // (m^4/s^2). The default needs 4 steps of 1/240 s on 2 cm segments, and gives the default
  // hairstyle the look that the paper model's w = 2, alpha = 1 gave it there
  // (docs/BENCHMARKS_HISTORY.md, "Stiffness that means the same at every step").
  float windowLength = 0.04f;        // m
  float bendingStiffness = 3.8e-3f;  // m^4/s^2
  // Calibrated: the scalp clamps the strand at rootLength of rest arc length from the root (at
  // least `pinned` particles' reach), between particles where it falls there: a built-in end
  // that holds position and direction (sim/solver/stiffness.h, ClampField), the same length
  // whatever the particles.
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
  CollisionMode mode = CollisionMode::Strands;
  HeadShape headShape = HeadShape::Spheres;  // shipped presets choose sdf
  float radius = 0.001f;                     // hair radius, metres: two strands touch at 2r
  // Strand contacts (sim/solver/contacts.h): the pairs within 2r + margin at the start of a frame
  // (and at each list within it) are the candidates its substeps resolve, so the margin must
  // cover how far two strands close in on each other until the next list.
  float margin = 0.0005f;   // m
  float compliance = 0.0f;  // m/N: 0 = hard contacts
  int iterations = 1;       // iterations of the strand contacts per substep
  ContactSolve solve = ContactSolve::Sweep;
  ContactModel model = ContactModel::Constraints;
  // The penalty model: acceleration per metre of overlap (1/s^2: a stiffness per unit mass) and
  // per m/s of approach (1/s). Explicit: stable while h sqrt(k n) < 2 for n contacts an end.
  float penaltyStiffness = 20000.0f;
  float penaltyDamping = 20.0f;
  // Candidate lists a frame (at most its substeps): the first where the frame starts, the
  // others spread over its substeps (listsBefore in sim/solver/contacts.h), each a search's cost.
  int lists = 1;
  // The most memory (MiB) the GPU's strand-contact buffers that grow with the hair's density
  // (the grid's entries, the pair list, its sides and both frames' lists) may take together;
  // a frame whose candidates need more keeps the list before it, and the run says so.
  int contactMemoryMb = 4096;
  float friction = 0.3f;  // Coulomb coefficient between strands
  // A guided groom's strand contacts: a guide as the wisp of the strands it stands for, its
  // contact radius r sqrt(mean weight), not a strand's (contactRadius, sim/solver/contacts.h).
  bool wisps = true;
  float headFriction = 0.3f;  // Coulomb friction coefficient against the head
  // The volume mode (sim/solver/volume.h).
  float volumeCell = 0.01f;      // m
  float volumeFriction = 5.0f;   // 1/s
  float volumeStiffness = 2.0f;  // m^2/s^2
  float volumeFraction = 0.2f;   // volume fraction hair may fill before it is pushed
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

// The scene the simulation runs: everything of a preset but how it is viewed
// (render/view_config.h) and what it is called (app/preset.h).
struct Config {
  HairstyleConfig hairstyle;
  HeadConfig head;
  MotionConfig motion;
  SimConfig sim;
  CollisionConfig collision;
  WindConfig wind;
};

// The DFTL correction the solvers apply: sim.dftl, and at least motion.dftl while a clip drives
// the character.
inline float dftlOf(const Config& c) {
  return c.motion.clip.empty() ? c.sim.dftl : std::max(c.sim.dftl, c.motion.dftl);
}

}  // namespace csm
