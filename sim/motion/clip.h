// A motion clip as the character's motion: a BVH clip (sim/motion/bvh.h) brought into the
// simulation's world (metres, y up, the character facing +z at the first frame), its head and
// chest joints found, and sampled at any time as the two rigid poses of the body: the head's and
// the torso's, each the identity at the clip's first frame (the mannequin stands as it was made
// there) and then moving as its joint moves, travel included. docs/METHOD.md, "Motion clips".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "sim/motion/bvh.h"

namespace csm {

// What was inferred of a clip (or said by motion.*), for the log and the Motion panel.
struct ClipFacts {
  int joints = 0;
  int frames = 0;
  double frameTime = 0.0;  // s
  double scale = 1.0;      // metres per clip unit
  std::string unit;        // "cm", "m", "inch", "CMU unit", "mm" or "set" (motion.scale)
  char up = 'y';           // the clip's up axis
  std::string facing;      // "+z", "-x", ...: where its character faces at the first frame
  bool upSaid = false, facingSaid = false;
  double height = 0.0;  // the standing skeleton's height, m
  std::string headJoint, chestJoint;
  double travel = 0.0;         // the head joint's horizontal distance, first frame to last, m
  double peakHeadSpeed = 0.0;  // m/s, between frames (cuts left out)
  std::vector<int> cuts;       // frames that jump from the one before faster than a person moves
  std::vector<std::string> jointNames;
  std::vector<int> jointParents;  // -1 for a root
};

// The fastest a person's head moves between two of a clip's frames; a frame further from the one
// before is a cut (a new take, a lost marker), which the simulation carries the hair over.
inline constexpr double kCutSpeed = 10.0;        // m/s
inline constexpr double kCutTurnSpeed = 1500.0;  // degrees a second

class MotionClip {
 public:
  // Reads motion.clip (relative to `baseDir`) and brings it in as `motion` says; `pivot` is the
  // head's neck point in the head frame (head.pivot), where the clip's head joint is put.
  static std::shared_ptr<const MotionClip> load(const MotionConfig& motion,
                                                const std::string& baseDir, const glm::dvec3& pivot,
                                                std::string* error);
  // The same from a parsed clip; `name` heads the messages.
  static std::shared_ptr<const MotionClip> make(const BvhClip& clip, const MotionConfig& motion,
                                                const glm::dvec3& pivot, const std::string& name,
                                                std::string* error);

  const ClipFacts& facts() const { return facts_; }
  // Seconds from the first frame to the last.
  double duration() const { return (frames_.size() - 1) * frameTime_; }
  int frameCount() const { return int(frames_.size()); }
  double frameTime() const { return frameTime_; }

  // The body at time t (s): frames slerped, looping (its travel carried on past each end) or
  // holding the last frame, with its horizontal travel or in place. Between a cut's frames it
  // holds the frame before the cut.
  BodyPose sample(double t, bool loop, bool inPlace) const;
  // The instants in (t0, t1] where the clip cuts (a frame after a cut begins, or a loop's seam
  // that jumps as far), in order.
  std::vector<double> cutsBetween(double t0, double t1, bool loop) const;
  // The clip's frame shown at time t (s): the one at or before it, looped or held.
  int frameAt(double t, bool loop) const;
  // One line of what was inferred ("walk.bvh: 22 joints, 273 frames at 30 fps, cm ...").
  std::string summary() const;

 private:
  struct Frame {
    glm::dquat head, chest;      // the joints' rotations in the world, relative to the first frame
    glm::dvec3 headAt, chestAt;  // the joints' places, relative to the head's at the first frame
  };
  BodyPose at(const Frame& f, const glm::dvec3& shift, bool inPlace) const;
  Frame blend(const Frame& a, const Frame& b, double s) const;
  bool seamIsCut() const;

  std::vector<Frame> frames_;
  std::vector<char> cutBefore_;  // frame k follows a cut
  double frameTime_ = 0.0;
  glm::dvec3 pivot_{0.0};
  glm::dvec3 chestPivot_{0.0};  // the chest joint at the first frame, in the head frame
  glm::dvec3 loopShift_{0.0};   // horizontal travel a loop adds
  std::string name_;
  ClipFacts facts_;
};

// The torso's pose at time t: the clip's (motion.loop, motion.in_place) or, without one, under
// the head at `head` (csm::torsoUnder: the body's part of head.motion, and the turn beyond the
// neck's reach).
Pose torsoPoseAt(const Config& c, const MotionClip* clip, double t, const Pose& head);

}  // namespace csm
