// Motion clips (sim/motion): the BVH reader against hand-made files whose poses are worked out
// by hand (channel orders, 6-channel joints, end sites, CRLF, a truncated file and a bad channel
// name refused with the line), and the clips of scripts/make_clips.py: the same walk in
// centimetres, metres and Z-up inches gives one motion, the head turns while the chest stays, a
// cut is found, the travel is the clip's, a loop goes on, a simulation carries the hair over a cut.
#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "sim/motion/bvh.h"
#include "sim/motion/clip.h"
#include "sim/run/simulation.h"
#include "sim/solver/cpu_solver.h"

namespace csm {
namespace {

const std::string kClips = CSM_CLIP_DIR;

// A root and one child a unit above it; the root's channels as given, one frame of values.
std::string twoJoints(const std::string& channels, const std::string& values,
                      const std::string& childChannels = "CHANNELS 3 Zrotation Xrotation Yrotation",
                      const std::string& childValues = "0 0 0") {
  return "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS " + channels +
         "\n\tJOINT Head\n\t{\n\t\tOFFSET 0 1 0\n\t\t" + childChannels +
         "\n\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 2 0\n\t\t}\n\t}\n}\nMOTION\nFrames: 1\nFrame Time: "
         ".03333\n" +
         values + " " + childValues + "\n";
}

glm::dvec3 headAt(const std::string& text) {
  BvhClip clip;
  std::string error;
  REQUIRE(parseBvh(text, "t.bvh", clip, &error));
  std::vector<JointPose> poses;
  jointPoses(clip, 0, poses);
  return poses[1].position;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-9) {
  return glm::length(a - b) <= tol;
}

std::shared_ptr<const MotionClip> load(const std::string& file, MotionConfig motion = {}) {
  motion.clip = file;
  std::string error;
  auto clip = MotionClip::load(motion, kClips, glm::dvec3(0.0, -0.15, 0.0), &error);
  INFO(error);
  REQUIRE(clip);
  return clip;
}

double degreesOf(const glm::dquat& q) {
  return glm::degrees(2.0 * std::acos(std::min(1.0, std::abs(q.w))));
}

TEST_CASE("a BVH joint turns in its channels' order, the first outermost", "[quick]") {
  // Zrotation 90 alone: the child's offset (0,1,0) turns to (-1,0,0).
  CHECK(near(headAt(twoJoints("6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",
                              "0 0 0 90 0 0")),
             {-1, 0, 0}));
  // Yrotation Xrotation = Ry Rx: (0,1,0) -> Rx: (0,0,1) -> Ry: (1,0,0).
  CHECK(near(headAt(twoJoints("3 Yrotation Xrotation Zrotation", "90 90 0")), {1, 0, 0}));
  // Xrotation Yrotation = Rx Ry: Ry leaves (0,1,0), Rx takes it to (0,0,1).
  CHECK(near(headAt(twoJoints("3 Xrotation Yrotation Zrotation", "90 90 0")), {0, 0, 1}));
  // The root's position channels move it; the channels may be in any order and case.
  CHECK(near(headAt(twoJoints("6 Zrotation Xrotation Yrotation xposition Yposition Zposition",
                              "0 0 0 5 6 7")),
             {5, 7, 7}));
}

TEST_CASE("a BVH joint with position channels is placed by them, not its offset", "[quick]") {
  // Bandai's files: 6 channels on every joint, the positions the offsets (or not).
  const std::string text = twoJoints(
      "6 Xposition Yposition Zposition Zrotation Xrotation Yrotation", "1 0 0 0 0 0",
      "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation", "0 3 0 0 0 0");
  CHECK(near(headAt(text), {1, 3, 0}));
  BvhClip clip;
  std::string error;
  REQUIRE(parseBvh(text, "t.bvh", clip, &error));
  CHECK(clip.channelCount == 12);
  CHECK(clip.joints[1].firstChannel == 6);
  CHECK(clip.joints[1].hasEndSite);
  CHECK(clip.joints[1].endSite == glm::dvec3(0, 2, 0));
  CHECK(clip.frameTime == Approx(0.03333));
}

TEST_CASE("a BVH file with CRLF, tabs and a name with spaces reads", "[quick]") {
  std::string text = twoJoints("3 Zrotation Xrotation Yrotation", "0 0 0");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  crlf.replace(crlf.find("ROOT Hips"), 9, "ROOT My Hips");
  BvhClip clip;
  std::string error;
  REQUIRE(parseBvh(crlf, "t.bvh", clip, &error));
  CHECK(clip.joints[0].name == "My Hips");
}

TEST_CASE("a bad BVH file is refused with its line", "[quick]") {
  BvhClip clip;
  std::string error;
  // A channel that does not exist, on line 5.
  CHECK_FALSE(parseBvh(twoJoints("3 Zrotation Xrot Yrotation", "0 0 0"), "bad.bvh", clip, &error));
  CHECK(error.find("bad.bvh:5:") == 0);
  CHECK(error.find("'Xrot' is not a channel") != std::string::npos);
  // Truncated: the frame ends early (the last line, 19).
  std::string text = twoJoints("3 Zrotation Xrotation Yrotation", "0 0 0");
  text = text.substr(0, text.rfind(" 0 0"));
  CHECK_FALSE(parseBvh(text, "cut.bvh", clip, &error));
  CHECK(error.find("cut.bvh:19:") == 0);
  CHECK(error.find("the file ends in frame 1 of 1") != std::string::npos);
  // More frames declared than the file holds.
  std::string more = twoJoints("3 Zrotation Xrotation Yrotation", "0 0 0");
  more.replace(more.find("Frames: 1"), 9, "Frames: 3");
  CHECK_FALSE(parseBvh(more, "few.bvh", clip, &error));
  CHECK(error.find("frame 2 of 3") != std::string::npos);
  // A value that is not a number, named by frame and value.
  std::string nan = twoJoints("3 Zrotation Xrotation Yrotation", "0 x 0");
  CHECK_FALSE(parseBvh(nan, "nan.bvh", clip, &error));
  CHECK(error.find("frame 1, value 2: 'x'") != std::string::npos);
  // Not a BVH at all.
  CHECK_FALSE(parseBvh("{\"a\": 1}", "preset.json", clip, &error));
  CHECK(error.find("preset.json:1: expected HIERARCHY") == 0);
  // A brace missing: the file ends inside the joint.
  std::string open = twoJoints("3 Zrotation Xrotation Yrotation", "0 0 0");
  open.erase(open.find("}\nMOTION"), 2);
  CHECK_FALSE(parseBvh(open, "open.bvh", clip, &error));
  CHECK(error.find("expected JOINT, End Site or '}'") != std::string::npos);
}

TEST_CASE("one walk in cm, metres and Z-up inches is one motion") {
  auto cm = load("walk_cm.bvh"), m = load("walk_m.bvh"), zup = load("walk_zup_inch.bvh");
  CHECK(cm->facts().unit == "cm");
  CHECK(m->facts().unit == "m");
  CHECK(zup->facts().unit == "inch");
  CHECK(zup->facts().up == 'z');
  CHECK(cm->facts().up == 'y');
  CHECK(zup->facts().facing == "-y");
  CHECK(cm->facts().facing == "+z");
  for (double t : {0.0, 0.5, 1.37, 4.0, 8.9}) {
    const BodyPose a = cm->sample(t, false, false), b = m->sample(t, false, false),
                   c = zup->sample(t, false, false);
    INFO("t = " << t);
    // The files keep six digits of their own unit.
    CHECK(near(a.head.translation, b.head.translation, 1e-5));
    CHECK(near(a.head.translation, c.head.translation, 1e-5));
    CHECK(degreesOf(a.head.rotation * glm::inverse(c.head.rotation)) < 1e-3);
    CHECK(degreesOf(a.torso.rotation * glm::inverse(b.torso.rotation)) < 1e-3);
  }
  // 1.4 m/s for 9 s, forward (+z in the world).
  const glm::dvec3 end = cm->sample(9.0, false, false).head.apply(glm::dvec3(0.0, -0.15, 0.0));
  CHECK(end.z == Approx(12.6).margin(0.05));
  CHECK(std::abs(end.x) < 0.05);
  CHECK(cm->facts().travel == Approx(12.6).margin(0.05));
}

TEST_CASE("the units, axes and facing a clip is said to have override the inferred ones") {
  MotionConfig said;
  said.scale = 0.02f;  // twice the centimetre
  said.facing = ClipFacing::MinusZ;
  said.up = ClipUp::Y;
  auto clip = load("walk_cm.bvh", said);
  CHECK(clip->facts().unit == "set");
  CHECK(clip->facts().upSaid);
  CHECK(clip->facts().facingSaid);
  // Twice as far, and backwards: the character said to face -z is turned to face +z.
  const glm::dvec3 end = clip->sample(9.0, false, false).head.apply(glm::dvec3(0.0, -0.15, 0.0));
  CHECK(end.z == Approx(-25.2).margin(0.1));
  MotionConfig named;
  named.headJoint = "NoSuchJoint";
  named.clip = "walk_cm.bvh";
  std::string error;
  CHECK_FALSE(MotionClip::load(named, kClips, glm::dvec3(0.0), &error));
  CHECK(error.find("motion.head_joint 'NoSuchJoint' is no joint") != std::string::npos);
}

TEST_CASE("a clip's joints are found by the names other tools give them") {
  CHECK(load("run_6ch.bvh")->facts().headJoint == "mixamorig:Head");
  CHECK(load("run_6ch.bvh")->facts().chestJoint == "mixamorig:Spine2");
  CHECK(load("run_6ch.bvh")->facts().facing == "+x");
  CHECK(load("dance_zup.bvh")->facts().chestJoint == "Chest2");
  CHECK(load("dance_zup.bvh")->facts().unit == "CMU unit");
  CHECK(load("dance_zup.bvh")->facts().frameTime == Approx(1.0 / 60.0).epsilon(1e-6));
  CHECK(load("turn_mixed.bvh")->facts().facing == "-z");
  // 4.5 m/s forward.
  auto run = load("run_6ch.bvh");
  const glm::dvec3 at2 = run->sample(2.0, false, false).head.translation;
  const glm::dvec3 at1 = run->sample(1.0, false, false).head.translation;
  CHECK((at2 - at1).z == Approx(4.5).margin(0.3));
}

TEST_CASE("a clip's head turns 80 degrees while its chest stays") {
  auto clip = load("turn_mixed.bvh");
  const BodyPose turned = clip->sample(2.0, false, false);
  CHECK(degreesOf(turned.head.rotation) == Approx(80.0).margin(0.5));
  CHECK(degreesOf(turned.torso.rotation) < 2.0);
  // About the up axis, to the character's left (+y turns +z towards +x).
  const glm::dvec3 nose = turned.head.rotation * glm::dvec3(0, 0, 1);
  CHECK(nose.x > 0.95);
  // The neck stays where it was.
  CHECK(near(turned.head.apply(glm::dvec3(0.0, -0.15, 0.0)), glm::dvec3(0.0, -0.15, 0.0), 0.02));
}

TEST_CASE("a cut in a clip is found, held across and carried by the simulation") {
  auto clip = load("cut.bvh");
  REQUIRE(clip->facts().cuts == std::vector<int>{60});
  CHECK(clip->cutsBetween(1.99, 2.01, false) == std::vector<double>{60 * clip->frameTime()});
  CHECK(clip->cutsBetween(0.0, 1.9, false).empty());
  // Between the frames either side of the cut the clip holds the one before.
  const Pose before = clip->sample(59 * clip->frameTime(), false, false).head;
  const Pose mid = clip->sample(59.5 * clip->frameTime(), false, false).head;
  CHECK(near(before.translation, mid.translation));
  CHECK(clip->facts().peakHeadSpeed < 2.0);

  Config config;
  config.hairstyle.strands = 60;
  config.motion.clip = "cut.bvh";
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim.load(config, kClips, &error));
  CHECK(sim.clipFrames() == 240);
  for (int f = 0; f < 130; ++f) sim.stepFrame();
  CHECK(sim.clipCuts() == 1);
  // The hair went with the head: every particle within a strand's length of the roots' place.
  std::vector<glm::vec4> x;
  sim.readPositions(x);
  const glm::dvec3 neck = sim.headPose().apply(glm::dvec3(0.0, -0.15, 0.0));
  double farthest = 0.0;
  for (const glm::vec4& p : x) farthest = std::max(farthest, glm::length(glm::dvec3(p) - neck));
  CHECK(farthest < 0.6);
}

TEST_CASE("a clip's in place turned on mid-walk takes the hair along, not apart") {
  Config config;
  config.hairstyle.strands = 60;
  config.motion.clip = "walk_cm.bvh";
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim.load(config, kClips, &error));
  for (int f = 0; f < 120; ++f) sim.stepFrame();  // 2.8 m down the road
  config.motion.inPlace = true;
  REQUIRE(sim.setConfig(config, &error));
  for (int f = 0; f < 3; ++f) sim.stepFrame();
  CHECK(sim.carriedFrames() == 1);
  std::vector<glm::vec4> x, v;
  sim.readPositions(x);
  sim.readVelocities(v);
  const glm::dvec3 neck = sim.headPose().apply(glm::dvec3(0.0, -0.15, 0.0));
  CHECK(std::hypot(neck.x, neck.z) < 0.15);  // back on the spot
  double farthest = 0.0, fastest = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    farthest = std::max(farthest, glm::length(glm::dvec3(x[i]) - neck));
    fastest = std::max(fastest, double(glm::length(glm::vec3(v[i]))));
  }
  CHECK(farthest < 0.6);
  CHECK(fastest < 5.0);
}

TEST_CASE("a clip loops with its travel carried on, holds its end, or stays in place") {
  auto clip = load("walk_cm.bvh");
  const double d = clip->duration();
  const double endZ = clip->sample(d, false, false).head.translation.z;
  CHECK(clip->sample(d + 2.0, false, false).head.translation.z == Approx(endZ));
  CHECK(clip->sample(d + 2.0, true, false).head.translation.z > endZ + 2.0);
  for (double t : {1.0, 5.0, d + 3.0}) {
    glm::dvec3 p = clip->sample(t, true, true).head.translation;
    CHECK(std::hypot(p.x, p.z) < 0.15);
  }
  // The walk's seam is no cut; the loop is seamless to within a step.
  CHECK(clip->cutsBetween(0.0, 3 * d, true).empty());
}

}  // namespace
}  // namespace csm
