// BVH, the motion-capture interchange (Biovision Hierarchy): a skeleton of joints, each with an
// offset from its parent and the channels its frames animate, then a frame of values a line.
// The reader takes what real files hold: any number of joints, 3 or 6 channels (or any subset)
// on any joint in any order, rotation orders mixed in one file, end sites, tabs or spaces, CRLF;
// everything else is an error that names the line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace csm {

enum class BvhChannel : int { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

struct BvhJoint {
  std::string name;
  int parent = -1;  // index into BvhClip::joints; -1 for a root
  glm::dvec3 offset{0.0};
  std::vector<BvhChannel> channels;
  int firstChannel = 0;     // its first value's index in a frame
  glm::dvec3 endSite{0.0};  // the end site's offset, when it has one
  bool hasEndSite = false;
};

struct BvhClip {
  std::vector<BvhJoint> joints;  // parents before their children
  int channelCount = 0;
  double frameTime = 0.0;      // seconds
  std::vector<double> values;  // frames x channelCount
  int frameCount() const { return channelCount > 0 ? int(values.size() / channelCount) : 0; }
};

// A joint's transform in the clip's world at a frame: x_world = rotation * x_joint + position.
struct JointPose {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 position{0.0};
};

// Parses BVH text; `name` heads the messages ("walk.bvh:12: ..."). False with *error set.
bool parseBvh(std::string_view text, std::string_view name, BvhClip& out, std::string* error);
// Reads and parses a file.
bool readBvh(const std::string& path, BvhClip& out, std::string* error);

// Every joint's pose at `frame`, in the clip's units and axes. A joint's position channels set
// its place in its parent (instead of its offset); its rotation channels turn it in their order
// (the first outermost: "Zrotation Xrotation Yrotation" is Rz Rx Ry).
void jointPoses(const BvhClip& clip, int frame, std::vector<JointPose>& out);

}  // namespace csm
