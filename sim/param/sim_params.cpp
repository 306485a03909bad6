#include "sim/param/sim_params.h"

#include <algorithm>
#include <iterator>

namespace csm {
namespace {

bool paperModel(const Config& c) {
  return c.sim.stiffnessModel == StiffnessModel::Paper;
}
bool separates(const Config& c) {
  return c.hairstyle.separatePasses > 0;
}
bool calibratedModel(const Config& c) {
  return c.sim.stiffnessModel == StiffnessModel::Calibrated;
}

bool hasClip(const Config& c) {
  return !c.motion.clip.empty();
}

bool volumeMode(const Config& c) {
  return volumeForces(c.collision.mode);
}

bool strandMode(const Config& c) {
  return strandContacts(c.collision.mode);
}

// Strand contacts between guides: a generated groom simulated through fewer strands than it has
// (a file's strand count is known once read; hairstyle.strands is its cap).
bool guidedStrandMode(const Config& c) {
  const std::size_t strands = std::size_t(std::max(c.hairstyle.strands, 0));
  return strandMode(c) && guideCount(c.hairstyle.guides, strands) < strands;
}

bool penaltyModel(const Config& c) {
  return strandMode(c) && c.collision.model == ContactModel::Penalty;
}

std::vector<Param<Config>> build() {
  return {
      param("hairstyle.file", "Groom file", "Hairstyle", &Config::hairstyle, &HairstyleConfig::file,
            0, 0,
            "A groom to load instead of growing strands: cyHair .hair, TressFX .tfx (any version) "
            "or OBJ curves .obj (Blender's hair export); empty = the generator. Relative paths "
            "are relative to the preset.",
            Effect::Rebuild),
      param("hairstyle.strands", "Strands", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::strands, 1, 1000000,
            "Number of strands drawn (a groom file's: how many of its strands are kept). A smaller "
            "count keeps the first strands of a larger one.",
            Effect::Rebuild)
          .logScale(),
      param("hairstyle.guides", "Simulated strands", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::guides, -1, 1000000,
            "Strands simulated (guides), spread over the scalp, its lengths and curls; every other "
            "strand is drawn from the guides near it. 0: every strand is simulated; -1: every "
            "strand up to 20,000, 4,000 guides beyond.",
            Effect::Rebuild),
      param("hairstyle.particles_per_strand", "Particles per strand", "Hairstyle",
            &Config::hairstyle, &HairstyleConfig::particlesPerStrand, 0, 64,
            "Fixed particle count per strand; 0 chooses it per strand from its length and curl.",
            Effect::Rebuild),
      param("hairstyle.min_particles", "Min particles", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::minParticles, 3, 64,
            "Fewest particles a strand gets when chosen by length.", Effect::Rebuild),
      param("hairstyle.max_particles", "Max particles", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::maxParticles, 3, 64,
            "Most particles a strand gets when chosen by length.", Effect::Rebuild),
      param("hairstyle.segment_length", "Segment length", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::segmentLength, 0.002, 0.2,
            "Target arc length between particles (m) when the count follows length and curl.",
            Effect::Rebuild),
      param("hairstyle.length_min", "Length min", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::lengthMin, 0.005, 2.0, "Shortest strand (m).", Effect::Rebuild),
      param("hairstyle.length_max", "Length max", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::lengthMax, 0.005, 2.0, "Longest strand (m).", Effect::Rebuild),
      param("hairstyle.curl_radius", "Curl radius", "Hairstyle|Curl", &Config::hairstyle,
            &HairstyleConfig::curlRadius, 0.0, 0.1, "Helix radius at the tip (m); 0 = straight.",
            Effect::Rebuild),
      param("hairstyle.curl_pitch", "Curl pitch", "Hairstyle|Curl", &Config::hairstyle,
            &HairstyleConfig::curlPitch, 0.005, 0.5,
            "Length along the strand of one turn of curl (m).", Effect::Rebuild),
      param(
          "hairstyle.curl_start", "Curl start", "Hairstyle|Curl", &Config::hairstyle,
          &HairstyleConfig::curlStart, 0.0, 1.0,
          "Fraction of the length, from the root, where curl begins: straight at the scalp, curly "
          "toward the tips.",
          Effect::Rebuild),
      param("hairstyle.scalp_angle", "Scalp angle", "Hairstyle|Scalp", &Config::hairstyle,
            &HairstyleConfig::scalpAngle, 5.0, 180.0,
            "How far from the crown the scalp reaches (degrees).", Effect::Rebuild),
      param("hairstyle.hairline_front", "Front hairline", "Hairstyle|Scalp", &Config::hairstyle,
            &HairstyleConfig::hairlineFront, 5.0, 180.0,
            "How far from the crown the hairline reaches on the forehead (degrees).",
            Effect::Rebuild),
      param("hairstyle.fall", "Fall", "Hairstyle", &Config::hairstyle, &HairstyleConfig::fall, 0.0,
            1.0,
            "How quickly strands turn from the scalp normal to hang down: 0 stands up, 1 falls at "
            "once.",
            Effect::Rebuild),
      param(
          "hairstyle.sweep", "Sweep back", "Hairstyle", &Config::hairstyle, &HairstyleConfig::sweep,
          0.0, 2.0,
          "How far hair growing toward the face is swept back and to the sides (0 = it falls over "
          "the face).",
          Effect::Rebuild),
      param("hairstyle.parting", "Parting", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::parting, 0, 0,
            "Where the hair parts on top: none (it falls from the crown all round), centre, or "
            "on the head's left or right. Hair lies on the scalp away from the parting.",
            Effect::Rebuild)
          .choices({"none", "centre", "left", "right"}),
      param("hairstyle.fringe", "Fringe", "Hairstyle", &Config::hairstyle, &HairstyleConfig::fringe,
            0, 1,
            "Hair from the front of the scalp falls forward over the forehead, cut at the brow "
            "(the eyes stay open).",
            Effect::Rebuild),
      param("hairstyle.volume", "Volume", "Hairstyle", &Config::hairstyle, &HairstyleConfig::volume,
            0.0, 0.05,
            "Thickness of the hair's layer over the scalp (m): hair from higher roots lies this "
            "much further out, over the hair from lower roots.",
            Effect::Rebuild)
          .display(1000.0, "mm"),
      param("hairstyle.separate_passes", "Separation passes", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::separatePasses, 0, 100,
            "Passes that push the grown strands apart to 2.2 hair radii where they lie closer, "
            "so that the groom starts without strands through each other; 0 keeps it as grown. "
            "Each pass costs a search of the groom's segment pairs.",
            Effect::Rebuild),
      param("hairstyle.separate_limit", "Separation limit", "Hairstyle", &Config::hairstyle,
            &HairstyleConfig::separateLimit, 0.0, 0.05,
            "Farthest (m) the separation passes move a particle from where it grew.",
            Effect::Rebuild)
          .display(1000.0, "mm")
          .onlyWhen(separates),
      param("hairstyle.seed", "Seed", "Hairstyle", &Config::hairstyle, &HairstyleConfig::seed, 0,
            2147483647, "Random seed of the groom. The same seed gives the same hair.",
            Effect::Rebuild),
      param("hairstyle.import_scale", "Import scale", "Hairstyle|Import", &Config::hairstyle,
            &HairstyleConfig::importScale, 0.0, 1000.0,
            "Scale applied to a groom file; 0 fits it to the head.", Effect::Rebuild),
      param("hairstyle.import_rotation", "Import rotation", "Hairstyle|Import", &Config::hairstyle,
            &HairstyleConfig::importRotation, -360, 360,
            "Euler XYZ rotation (degrees) applied to a groom file.", Effect::Rebuild),
      param("hairstyle.import_offset", "Import offset", "Hairstyle|Import", &Config::hairstyle,
            &HairstyleConfig::importOffset, -10, 10,
            "Offset (m) applied to a groom file after fitting.", Effect::Rebuild),
      param("hairstyle.import_facing", "Import facing", "Hairstyle|Import", &Config::hairstyle,
            &HairstyleConfig::importFacing, 0, 0,
            "Which way the groom file's face looks in its own axes: auto takes TressFX "
            "(left-handed, DirectX) as -z and mirrors its z into the head frame (face +z), every "
            "other format as +z; -z mirrors any file, +z none.",
            Effect::Rebuild)
          .choices({"auto", "+z", "-z"}),
      param("hairstyle.import_place", "Import place", "Hairstyle|Import", &Config::hairstyle,
            &HairstyleConfig::importPlace, 0, 0,
            "Where a groom file goes: fit scales and places it onto the scene's head; head keeps "
            "it where the file put it on head.mesh (a data set's groom beside its own head), "
            "brought into the head frame with the head; auto keeps it when head.mesh is set and "
            "the file's roots lie on that head's surface, else fits it.",
            Effect::Rebuild)
          .choices({"auto", "fit", "head"}),
      param(
          "hairstyle.resample_tolerance", "Resample tolerance", "Hairstyle|Import",
          &Config::hairstyle, &HairstyleConfig::resampleTolerance, 0.0, 0.05,
          "Largest distance (m) the resampled strand may stray from the file's curve; 0 keeps the "
          "file's points.",
          Effect::Rebuild),
      param("head.mesh", "Head mesh", "Head", &Config::head, &HeadConfig::mesh, 0, 0,
            "A Wavefront OBJ or PLY head to collide with and draw when collision.head_shape is "
            "sdf (a scan open at the neck is capped), brought into the head frame (y up, face "
            "+z) by head.mesh_scale, mesh_up, mesh_facing and mesh_place; empty = the built-in "
            "mannequin. Relative paths are relative to the preset.",
            Effect::Rebuild),
      param("head.mesh_scale", "Mesh scale", "Head", &Config::head, &HeadConfig::meshScale, 0.0,
            1000.0,
            "Metres per head.mesh unit (0.01 for centimetres); 0 infers the unit from the "
            "cranium's size (m, dm, cm, mm or inches).",
            Effect::Rebuild)
          .onlyWhen([](const Config& c) { return !c.head.mesh.empty(); }),
      param("head.mesh_up", "Mesh up axis", "Head", &Config::head, &HeadConfig::meshUp, 0, 0,
            "head.mesh's up axis; auto takes the way away from the opening at the neck, or y.",
            Effect::Rebuild)
          .choices({"auto", "y", "z", "x"})
          .onlyWhen([](const Config& c) { return !c.head.mesh.empty(); }),
      param("head.mesh_facing", "Mesh facing", "Head", &Config::head, &HeadConfig::meshFacing, 0, 0,
            "Where head.mesh's face looks in its own axes; auto takes the side with the face's "
            "detail (nose, eyes, lips), or +z (-y for z up).",
            Effect::Rebuild)
          .choices({"auto", "+z", "-z", "+x", "-x", "+y", "-y"})
          .onlyWhen([](const Config& c) { return !c.head.mesh.empty(); }),
      param("head.mesh_place", "Mesh placed", "Head", &Config::head, &HeadConfig::meshPlace, 0, 1,
            "Move head.mesh's cranium onto the mannequin's, so that the scalp, the neck and "
            "head.pivot meet it as they meet the mannequin; off keeps the file's place.",
            Effect::Rebuild)
          .onlyWhen([](const Config& c) { return !c.head.mesh.empty(); }),
      param("head.torso_mesh", "Torso mesh", "Head", &Config::head, &HeadConfig::torsoMesh, 0, 0,
            "With head.mesh, an OBJ or PLY torso (the same file frame, at rest; closed) that moves "
            "with the chest while head.mesh moves with the head; empty: head.mesh is the whole "
            "body. Relative paths are relative to the preset.",
            Effect::Rebuild)
          .onlyWhen([](const Config& c) { return !c.head.mesh.empty(); }),
      param("head.spheres", "Head spheres", "Head", &Config::head, &HeadConfig::spheres, -10, 10,
            "Spheres (centre in the head frame, radius) that the hair collides with; the first is "
            "the scalp the hair grows from.",
            Effect::Rebuild),
      param("head.fit_spheres", "Fit spheres", "Head", &Config::head, &HeadConfig::fitSpheres, 0, 1,
            "Replace head.spheres by as many spheres fitted inside head.mesh (or the mannequin): "
            "the largest ball inside it, then each the ball that covers most of the rest of the "
            "head above y = -0.2 m (not the shoulders).",
            Effect::Rebuild),
      param("head.motion", "Motion", "Head", &Config::head, &HeadConfig::motion, 0, 0,
            "How the head moves: none, nod, shake, spin, sway or bounce.", Effect::Live)
          .choices({"none", "nod", "shake", "spin", "sway", "bounce"}),
      param("head.amplitude", "Amplitude", "Head", &Config::head, &HeadConfig::amplitude, 0.0,
            180.0, "Amplitude of the motion: degrees, or centimetres for bounce.", Effect::Live),
      param("head.frequency", "Frequency", "Head", &Config::head, &HeadConfig::frequency, 0.0, 10.0,
            "Motion frequency (Hz).", Effect::Live),
      param("head.pivot", "Pivot", "Head", &Config::head, &HeadConfig::pivot, -1, 1,
            "Point in the head frame that rotations turn about (the neck).", Effect::Live),
      param("motion.clip", "Clip", "Motion", &Config::motion, &MotionConfig::clip, 0, 0,
            "A motion-capture clip (BVH) that moves the character: its head and chest joints "
            "drive the head and the torso, its travel carries them through the world. Relative "
            "paths are relative to the preset; empty = head.motion.",
            Effect::Rebuild),
      param("motion.scale", "Clip scale", "Motion", &Config::motion, &MotionConfig::scale, 0.0,
            100.0,
            "Metres per clip unit (0.01 for centimetres, 0.0254 for inches); 0 infers it from the "
            "skeleton's height (a standing adult).",
            Effect::Rebuild)
          .logScale(),
      param("motion.up", "Clip up axis", "Motion", &Config::motion, &MotionConfig::up, 0, 0,
            "The clip's up axis; auto infers it from the skeleton (the head above the hips).",
            Effect::Rebuild)
          .choices({"auto", "y", "z", "x"}),
      param("motion.facing", "Clip facing", "Motion", &Config::motion, &MotionConfig::facing, 0, 0,
            "Where the clip's character faces at its first frame, in the clip's axes; auto infers "
            "it from the left and right joints. It is turned to face +z, as the head does.",
            Effect::Rebuild)
          .choices({"auto", "+z", "-z", "+x", "-x", "+y", "-y"}),
      param("motion.head_joint", "Head joint", "Motion", &Config::motion, &MotionConfig::headJoint,
            0, 0, "The clip's joint that moves the head; empty finds Head (or Neck) by name.",
            Effect::Rebuild),
      param(
          "motion.chest_joint", "Chest joint", "Motion", &Config::motion, &MotionConfig::chestJoint,
          0, 0,
          "The clip's joint that moves the torso; empty finds Chest, Spine2, Spine1, ... by name.",
          Effect::Rebuild),
      param("motion.loop", "Loop", "Motion", &Config::motion, &MotionConfig::loop, 0, 1,
            "Past its end the clip starts again (its travel carried on); off holds its last frame.",
            Effect::Live)
          .onlyWhen(hasClip),
      param("motion.in_place", "In place", "Motion", &Config::motion, &MotionConfig::inPlace, 0, 1,
            "Removes the clip's horizontal travel: the character moves on the spot.", Effect::Live)
          .onlyWhen(hasClip),
      param("motion.dftl", "Least DFTL", "Motion", &Config::motion, &MotionConfig::dftl, 0.0, 1.0,
            "The least DFTL correction (sim.dftl) while the clip drives the character: its "
            "starts, stops, landings and jerks swing strands far harder than head.motion, and "
            "without it the strain-limiting sweep whips their tips several times faster than the "
            "head moved (0.9 keeps them within what the motion and gravity explain); 0 leaves "
            "sim.dftl alone.",
            Effect::Live)
          .onlyWhen(hasClip),
      param("sim.dt", "Frame time step", "Simulation", &Config::sim, &SimConfig::dt, 1e-4, 0.1,
            "Simulated seconds per frame; each frame is split into substeps.", Effect::Live)
          .logScale(),
      param(
          "sim.stiffness_model", "Stiffness model", "Simulation", &Config::sim,
          &SimConfig::stiffnessModel, 0, 0,
          "calibrated: a window in metres and a bending stiffness; the hair looks the same at any "
          "substeps, particle count and density (METHOD.md section 4). paper: a window in "
          "particles and alpha per step, as the paper does: more substeps stiffen the hair, more "
          "particles soften it.",
          Effect::Live)
          .choices({"paper", "calibrated"}),
      param("sim.substeps", "Substeps", "Simulation", &Config::sim, &SimConfig::substeps, 1, 64,
            "Steps per frame (paper); the fewest steps per frame (calibrated: more when the "
            "stiffness needs them, up to max substeps).",
            Effect::Live),
      param("sim.max_substeps", "Step budget", "Simulation", &Config::sim, &SimConfig::maxSubsteps,
            1, 256,
            "Calibrated: the most steps per frame (the step budget). Strands stiffer than it "
            "resolves, a groom's shortest, run at alpha = 1 (as stiff as the steps allow): "
            "counted in the log and the panel. Raise it when the stiffness asks for more.",
            Effect::Live)
          .onlyWhen(calibratedModel),
      param("sim.window_length", "Stiffness window", "Simulation", &Config::sim,
            &SimConfig::windowLength, 0.002, 0.1,
            "Calibrated: half-length of each shape-matching region along the strand (m; the panel "
            "shows cm). Regions never hold fewer than 3 particles. A longer window gives smoother "
            "bends and needs fewer steps for the same stiffness. At most 10 cm: a window that "
            "holds most of a strand barely pulls it to its goals (alpha under 0.002 a step), and "
            "the strain limit's sweep then whips the hair (docs/RELIABILITY.md, torture map).",
            Effect::Live)
          .logScale()
          .onlyWhen(calibratedModel)
          .display(100.0, "cm"),
      param("sim.bending_stiffness", "Bending stiffness", "Simulation", &Config::sim,
            &SimConfig::bendingStiffness, 1e-7, 100.0,
            "Calibrated: bending stiffness per unit mass, EI over the linear density (m^4/s^2). A "
            "real hair is about 1e-3; a clump of hair acts stiffer. Doubling it halves the sag.",
            Effect::Live)
          .logScale()
          .onlyWhen(calibratedModel)
          .display(1.0, "m^4/s^2"),
      param("sim.root_length", "Root length", "Simulation", &Config::sim, &SimConfig::rootLength,
            0.0, 0.2,
            "Calibrated: where the scalp clamps the strand, its length from the root (m; the panel "
            "shows cm); at least `pinned` particles' reach. The clamp holds position and direction "
            "(a built-in end) and may fall between particles: the held piece is this length "
            "whatever the particles.",
            Effect::Live)
          .onlyWhen(calibratedModel)
          .display(100.0, "cm"),
      param("sim.stiffness_window", "Stiffness window w", "Simulation", &Config::sim,
            &SimConfig::stiffnessWindow, 1, 32,
            "Paper: half-width of each shape-matching region, in particles: larger = stiffer hair.",
            Effect::Live)
          .onlyWhen(paperModel)
          .display(1.0, "particles"),
      param("sim.stiffness", "Stiffness alpha", "Simulation", &Config::sim, &SimConfig::stiffness,
            0.0, 1.0, "Paper: how far particles move toward their goals each step (1 = the paper).",
            Effect::Live)
          .onlyWhen(paperModel),
      param("sim.damping", "Damping", "Simulation", &Config::sim, &SimConfig::damping, 0.0, 100.0,
            "Linear velocity damping (1/s): velocities fall by exp(-damping t).", Effect::Live),
      param("sim.strain_limiting", "Strain limiting", "Simulation", &Config::sim,
            &SimConfig::strainLimiting, 0, 1,
            "Limit segment stretch root to tip after shape matching.", Effect::Live),
      param("sim.strain_limit", "Strain limit", "Simulation", &Config::sim, &SimConfig::strainLimit,
            0.0, 1.0, "Largest relative stretch of a segment, epsilon.", Effect::Live),
      param("sim.pinned", "Pinned particles", "Simulation", &Config::sim, &SimConfig::pinned, 1, 4,
            "Particles from the root that follow the head rigidly (calibrated: at least this many; "
            "see root length).",
            Effect::Live),
      param("sim.gravity", "Gravity", "Simulation", &Config::sim, &SimConfig::gravity, -100, 100,
            "Gravity (m/s^2).", Effect::Live),
      param("sim.density", "Linear density", "Simulation", &Config::sim, &SimConfig::density, 1e-7,
            1.0,
            "Mass per metre of strand (kg/m); particle masses follow segment lengths. It describes "
            "the hair and changes nothing in its motion: shape matching, gravity, wind drag and "
            "the contact accelerations are all per unit mass, so a uniform mass scale cancels "
            "(METHOD.md section 4); the panel shows EI = bending stiffness x density from it.",
            Effect::Info)
          .logScale(),
      param("sim.dftl", "DFTL correction", "Simulation", &Config::sim, &SimConfig::dftl, 0.0, 1.0,
            "Dynamic follow-the-leader velocity correction after strain limiting (Mueller et al. "
            "2012); 0 = off, 1 = full. Soft hair needs it: where the bending number B / (g L^3) "
            "of the longest strand is under about 2e-2 the strain-limiting sweep whips the tips "
            "and gains energy whatever the steps, and the stiffness line below says how much "
            "correction holds it (0.9 always does).",
            Effect::Live),
      param("sim.rotation_iterations", "Rotation iterations", "Simulation", &Config::sim,
            &SimConfig::rotationIterations, 1, 32,
            "Quaternion iterations per region and step when extracting rotations (warm-started).",
            Effect::Live),
      param("collision.mode", "Collisions", "Simulation|Collision", &Config::collision,
            &CollisionConfig::mode, 0, 0,
            "off: none; head: hair against the head spheres; strands: and contacts between strands "
            "that hold them apart; volume: and hair as a continuum on a grid (friction between "
            "neighbours, a push out of over-dense places; cost linear in particles); "
            "volume+strands: both. \"full\" (older presets) reads as strands.",
            Effect::Live)
          .choices({std::begin(kCollisionModeNames), std::end(kCollisionModeNames)})
          .alias("full", int(CollisionMode::Strands)),
      param("collision.head_shape", "Head shape", "Simulation|Collision", &Config::collision,
            &CollisionConfig::headShape, 0, 0,
            "sdf: the built-in mannequin (head, neck, shoulders), or head.mesh, as a signed "
            "distance field sampled at 4 mm, collided with and drawn; spheres: head.spheres, as "
            "the paper does.",
            Effect::Rebuild)
          .choices({"sdf", "spheres"}),
      param("collision.radius", "Hair radius", "Simulation|Collision", &Config::collision,
            &CollisionConfig::radius, 1e-5, 0.02,
            "Collision radius of a strand (m): two strands touch at twice this.", Effect::Live)
          .logScale(),
      param("collision.margin", "Contact margin", "Simulation|Collision", &Config::collision,
            &CollisionConfig::margin, 0.0, 0.01,
            "Strand contacts: pairs within 2 radii + this at the start of a frame are the ones its "
            "substeps hold apart (m). Larger catches faster motion and costs more.",
            Effect::Live)
          .display(1000.0, "mm"),
      param("collision.compliance", "Contact compliance", "Simulation|Collision",
            &Config::collision, &CollisionConfig::compliance, 0.0, 100.0,
            "Strand contacts: give of a contact, metres per newton (XPBD); 0 = hard.",
            Effect::Live),
      param("collision.iterations", "Contact iterations", "Simulation|Collision",
            &Config::collision, &CollisionConfig::iterations, 1, 16,
            "Strand contacts: iterations per substep. More hold dense hair apart better "
            "(fewer crossings) and cost one more contact solve each.",
            Effect::Live)
          .onlyWhen(strandMode),
      param("collision.solve", "Contact solve", "Simulation|Collision", &Config::collision,
            &CollisionConfig::solve, 0, 0,
            "Strand contacts: how an iteration moves a segment. sweep: its pairs in order, each "
            "from where the ones before it left the segment (a deep pair among shallow ones is "
            "resolved at once); jacobi: by the mean of what its pairs ask. The same cost.",
            Effect::Live)
          .choices({"sweep", "jacobi"})
          .onlyWhen(strandMode),
      param("collision.contact_model", "Contact model", "Simulation|Collision", &Config::collision,
            &CollisionConfig::model, 0, 0,
            "Strand contacts: constraints hold each pair at its contact distance every substep "
            "(XPBD); penalty is the paper's model: a force k (d0 - d) along the normal, damped, "
            "with friction, felt from the next substep on (cheaper, and it lets dense hair "
            "through: docs/BENCHMARKS.md).",
            Effect::Live)
          .choices({"constraints", "penalty"})
          .onlyWhen(strandMode),
      param("collision.penalty_stiffness", "Penalty stiffness", "Simulation|Collision",
            &Config::collision, &CollisionConfig::penaltyStiffness, 1.0, 1e7,
            "Penalty contacts: acceleration per metre of overlap (1/s^2). Explicit: past about "
            "(2 / h)^2 over the contacts an end has, the hair shakes.",
            Effect::Live)
          .logScale()
          .onlyWhen(penaltyModel),
      param("collision.penalty_damping", "Penalty damping", "Simulation|Collision",
            &Config::collision, &CollisionConfig::penaltyDamping, 0.0, 1000.0,
            "Penalty contacts: acceleration per m/s of approach along the normal (1/s).",
            Effect::Live)
          .onlyWhen(penaltyModel),
      param("collision.lists", "Contact lists a frame", "Simulation|Collision", &Config::collision,
            &CollisionConfig::lists, 1, 16,
            "Strand contacts: candidate searches a frame (at most its substeps), the first as "
            "it starts and the others spread over its substeps. More catch strands that close "
            "in on each other within a frame faster than the margin covers; each costs a "
            "search.",
            Effect::Live)
          .onlyWhen(strandMode),
      param("collision.contact_memory_mb", "Contact memory (MiB)", "Simulation|Collision",
            &Config::collision, &CollisionConfig::contactMemoryMb, 16, 65536,
            "Strand contacts on the GPU: the most memory the buffers that grow with the hair's "
            "density (grid entries, candidate pairs, their lists) may take together, a quarter "
            "for the entries and the rest for the pairs. A frame whose candidates need more "
            "keeps the list before it and is counted and said (the Stats panel, the end of a "
            "headless run). A memory limit, not a look: changing it starts the hair again, "
            "its buffers sized anew.",
            Effect::Rebuild)
          .onlyWhen(strandMode),
      param("collision.friction", "Hair friction", "Simulation|Collision", &Config::collision,
            &CollisionConfig::friction, 0.0, 2.0,
            "Coulomb friction coefficient between strands: sliding is held back by at most this "
            "times the push that keeps them apart.",
            Effect::Live),
      param("collision.wisps", "Guides as wisps", "Simulation|Collision", &Config::collision,
            &CollisionConfig::wisps, 0, 1,
            "Strand contacts of a groom simulated through guides: each guide touches others as the "
            "wisp of the strands it stands for (radius times the square root of their mean "
            "count), not as one strand.",
            Effect::Live)
          .onlyWhen(guidedStrandMode),
      param("collision.head_friction", "Head friction", "Simulation|Collision", &Config::collision,
            &CollisionConfig::headFriction, 0.0, 2.0,
            "Coulomb friction coefficient between hair and head: sliding slows by at most this "
            "times the push the head gives.",
            Effect::Live),
      param("collision.volume_cell", "Volume cell", "Simulation|Collision|Volume",
            &Config::collision, &CollisionConfig::volumeCell, 0.002, 0.05,
            "Volume mode: node spacing of the grid hair is splatted to (m). Finer resolves "
            "thinner gaps and costs more memory.",
            Effect::Live)
          .onlyWhen(volumeMode)
          .display(1000.0, "mm"),
      param("collision.volume_friction", "Volume friction", "Simulation|Collision|Volume",
            &Config::collision, &CollisionConfig::volumeFriction, 0.0, 100.0,
            "Volume mode: rate (1/s) at which each particle's velocity joins the mean velocity "
            "of the hair around it.",
            Effect::Live)
          .onlyWhen(volumeMode),
      param("collision.volume_stiffness", "Volume stiffness", "Simulation|Collision|Volume",
            &Config::collision, &CollisionConfig::volumeStiffness, 0.0, 100.0,
            "Volume mode: push out of over-dense places, m/s^2 per unit gradient (1/m) of the "
            "volume fraction over what is allowed.",
            Effect::Live)
          .onlyWhen(volumeMode),
      param("collision.volume_fraction", "Volume fraction", "Simulation|Collision|Volume",
            &Config::collision, &CollisionConfig::volumeFraction, 0.01, 1.0,
            "Volume mode: the fraction of space hair may fill before it is pushed (or what the "
            "groom packed at rest, where that is more).",
            Effect::Live)
          .onlyWhen(volumeMode),
      param("wind.strength", "Strength", "Wind", &Config::wind, &WindConfig::strength, 0.0, 50.0,
            "Mean wind speed (m/s).", Effect::Live),
      param("wind.direction", "Direction", "Wind", &Config::wind, &WindConfig::direction, -1, 1,
            "Direction the wind blows toward (normalised when used).", Effect::Live),
      param("wind.gusts", "Gusts", "Wind", &Config::wind, &WindConfig::gusts, 0.0, 2.0,
            "Relative amplitude of gusts over time.", Effect::Live),
      param("wind.gust_frequency", "Gust frequency", "Wind", &Config::wind,
            &WindConfig::gustFrequency, 0.0, 10.0, "How often gusts come (Hz).", Effect::Live),
      param("wind.turbulence", "Turbulence", "Wind", &Config::wind, &WindConfig::turbulence, 0.0,
            2.0, "Relative amplitude of the spatial turbulence.", Effect::Live),
      param("wind.turbulence_scale", "Turbulence scale", "Wind", &Config::wind,
            &WindConfig::turbulenceScale, 0.005, 2.0, "Size of turbulent eddies (m).",
            Effect::Live),
      param("wind.drag", "Drag", "Wind", &Config::wind, &WindConfig::drag, 0.0, 100.0,
            "Acceleration per m/s of wind across the strand (1/s), applied implicitly (stable at "
            "any step).",
            Effect::Live),
  };
}

}  // namespace

const std::vector<Param<Config>>& simParams() {
  static const std::vector<Param<Config>> list = build();
  return list;
}

const Param<Config>* findSimParam(std::string_view key) {
  return findParam(simParams(), key);
}

bool sameScene(const Config& a, const Config& b) {
  for (const Param<Config>& p : simParams())
    if (!sameValue(p, a, b)) return false;
  return true;
}

bool needsRegrow(const Config& a, const Config& b) {
  for (const Param<Config>& p : simParams())
    if (p.effect == Effect::Rebuild && !sameValue(p, a, b)) return true;
  return false;
}

}  // namespace csm
