#include "sim/motion/clip.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "sim/base/file_io.h"
#include "sim/base/units.h"

namespace csm {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A joint's name without an exporter's namespace ("mixamorig:Head", "Armature|Head").
std::string bareName(const std::string& name) {
  const size_t cut = name.find_last_of(":|");
  return lower(cut == std::string::npos ? name : name.substr(cut + 1));
}

int jointNamed(const BvhClip& clip, const std::string& name) {
  for (size_t i = 0; i < clip.joints.size(); ++i)
    if (lower(clip.joints[i].name) == lower(name) || bareName(clip.joints[i].name) == lower(name))
      return int(i);
  return -1;
}

int firstJointNamed(const BvhClip& clip, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (int j = jointNamed(clip, n); j >= 0) return j;
  return -1;
}

std::string jointList(const BvhClip& clip) {
  std::string out;
  for (size_t i = 0; i < clip.joints.size() && i < 40; ++i)
    out += (i ? ", " : "") + clip.joints[i].name;
  if (clip.joints.size() > 40) out += ", ...";
  return out;
}

// A joint's side and the name it has without it ("LeftUpLeg" -> 'l', "upleg"; "Foot_R" -> 'r').
char sideOf(const std::string& name, std::string& rest) {
  const std::string n = bareName(name);
  for (const auto& [prefix, side] : {std::pair{"left", 'l'}, std::pair{"right", 'r'}})
    if (n.rfind(prefix, 0) == 0) {
      rest = n.substr(std::string_view(prefix).size());
      return side;
    }
  for (const auto& [suffix, side] :
       {std::pair{"_l", 'l'}, std::pair{"_r", 'r'}, std::pair{".l", 'l'}, std::pair{".r", 'r'},
        std::pair{"left", 'l'}, std::pair{"right", 'r'}}) {
    const std::string_view s(suffix);
    if (n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0) {
      rest = n.substr(0, n.size() - s.size());
      return side;
    }
  }
  // CMU's "LHipJoint", "RThumb": a capital L or R before another capital.
  const std::string raw =
      name.substr(name.find_last_of(":|") == std::string::npos ? 0 : name.find_last_of(":|") + 1);
  if (raw.size() > 1 && (raw[0] == 'L' || raw[0] == 'R') &&
      std::isupper(static_cast<unsigned char>(raw[1]))) {
    rest = lower(raw.substr(1));
    return raw[0] == 'L' ? 'l' : 'r';
  }
  return 0;
}

// The joints where a limb meets the trunk, whose left-right pairs say the body's facing.
bool isTrunkJoint(const std::string& bare) {
  for (const char* part : {"hip", "upleg", "upperleg", "thigh", "shoulder", "collar", "clavicle"})
    if (bare.find(part) != std::string::npos) return true;
  return false;
}

glm::dvec3 axisVector(int axis, double sign) {
  glm::dvec3 v(0.0);
  v[axis] = sign;
  return v;
}

double turnDegrees(const glm::dquat& q) {
  const double w = std::min(1.0, std::abs(q.w));
  return glm::degrees(2.0 * std::acos(w));
}

// Whether the body goes from frame a to frame b, ft seconds apart, faster than a person moves
// (the head or the chest faster than kCutSpeed, or turning faster than kCutTurnSpeed).
template <class Frame>
bool jumps(const Frame& a, const Frame& b, double ft) {
  const double speed =
      std::max(glm::length(b.headAt - a.headAt), glm::length(b.chestAt - a.chestAt)) / ft;
  const double turnSpeed = std::max(turnDegrees(b.head * glm::inverse(a.head)),
                                    turnDegrees(b.chest * glm::inverse(a.chest))) /
                           ft;
  return speed > kCutSpeed || turnSpeed > kCutTurnSpeed;
}

// The units clips come in; the one that makes the skeleton a standing adult's height is taken.
constexpr LengthUnit kClipUnits[] = {
    {"m", "metres", 1.0},         {"cm", "centimetres", 0.01},
    {"mm", "millimetres", 0.001}, {"inch", "inches", 0.0254},
    {"ft", "feet", 0.3048},       {"CMU unit", "CMU units", 0.056444}};  // (1 / 0.45) inches
constexpr double kAdultHeight = 1.65;                                    // m, toes to the crown

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

std::shared_ptr<const MotionClip> MotionClip::load(const MotionConfig& motion,
                                                   const std::string& baseDir,
                                                   const glm::dvec3& pivot, std::string* error) {
  const std::string path = resolveRelative(baseDir, motion.clip);
  BvhClip bvh;
  std::string why;
  if (!readBvh(path, bvh, &why)) {
    if (error) *error = "motion.clip: " + why;
    return nullptr;
  }
  auto clip = make(bvh, motion, pivot, path, &why);
  if (!clip && error) *error = "motion.clip: " + why;
  return clip;
}

std::shared_ptr<const MotionClip> MotionClip::make(const BvhClip& bvh, const MotionConfig& motion,
                                                   const glm::dvec3& pivot, const std::string& name,
                                                   std::string* error) {
  auto fail = [&](const std::string& message) -> std::shared_ptr<const MotionClip> {
    if (error) *error = name + ": " + message;
    return nullptr;
  };
  if (bvh.frameCount() < 1) return fail("no frames");
  auto out = std::shared_ptr<MotionClip>(new MotionClip());
  MotionClip& c = *out;
  ClipFacts& f = c.facts_;
  c.name_ = name;
  c.pivot_ = pivot;
  c.frameTime_ = bvh.frameTime;
  f.joints = int(bvh.joints.size());
  f.frames = bvh.frameCount();
  f.frameTime = bvh.frameTime;
  for (const BvhJoint& j : bvh.joints) {
    f.jointNames.push_back(j.name);
    f.jointParents.push_back(j.parent);
  }

  // The joints that drive the two parts.
  int head = -1, chest = -1;
  if (!motion.headJoint.empty()) {
    head = jointNamed(bvh, motion.headJoint);
    if (head < 0)
      return fail("motion.head_joint '" + motion.headJoint + "' is no joint of the clip (" +
                  jointList(bvh) + ")");
  } else {
    head = firstJointNamed(bvh, {"Head", "head1", "Neck1", "Neck", "upperneck"});
    if (head < 0)
      return fail("no head joint (Head, Neck): name it with motion.head_joint (" + jointList(bvh) +
                  ")");
  }
  if (!motion.chestJoint.empty()) {
    chest = jointNamed(bvh, motion.chestJoint);
    if (chest < 0)
      return fail("motion.chest_joint '" + motion.chestJoint + "' is no joint of the clip (" +
                  jointList(bvh) + ")");
  } else {
    chest = firstJointNamed(
        bvh, {"UpperChest", "Chest2", "Chest", "Spine2", "Spine3", "Spine1", "Thorax", "Spine"});
    if (chest < 0 || chest == head) {
      // The head's grandparent, or the root.
      chest = bvh.joints[size_t(head)].parent;
      if (chest >= 0 && bvh.joints[size_t(chest)].parent >= 0)
        chest = bvh.joints[size_t(chest)].parent;
      if (chest < 0) chest = 0;
    }
  }
  f.headJoint = bvh.joints[size_t(head)].name;
  f.chestJoint = bvh.joints[size_t(chest)].name;

  // The first frame's skeleton: the up axis, the height, the facing.
  std::vector<JointPose> poses;
  jointPoses(bvh, 0, poses);
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < bvh.joints.size(); ++i) {
    points.push_back(poses[i].position);
    if (bvh.joints[i].hasEndSite)
      points.push_back(poses[i].rotation * bvh.joints[i].endSite + poses[i].position);
  }
  glm::dvec3 mean(0.0), lo = points[0], hi = points[0];
  for (const glm::dvec3& p : points) {
    mean += p / double(points.size());
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  glm::dvec3 up;
  if (motion.up != ClipUp::Auto) {
    const int axis = motion.up == ClipUp::X ? 0 : motion.up == ClipUp::Y ? 1 : 2;
    up = axisVector(axis, 1.0);
    f.upSaid = true;
  } else {
    // The head stands above the body's middle along the up axis, most of all.
    const glm::dvec3 d = poses[size_t(head)].position - mean;
    int axis = 1;
    for (int a = 0; a < 3; ++a)
      if (std::abs(d[a]) > std::abs(d[axis])) axis = a;
    up = axisVector(axis, d[axis] < 0.0 ? -1.0 : 1.0);
  }
  f.up = "xyz"[up.x != 0.0 ? 0 : up.y != 0.0 ? 1 : 2];
  const double heightUnits = glm::dot(hi - lo, glm::abs(up));
  if (motion.scale > 0.0f) {
    f.scale = motion.scale;
    f.unit = "set";
  } else {
    if (!(heightUnits > 0.0)) return fail("the skeleton has no height at the first frame");
    const LengthUnit& u = nearestUnit(kAdultHeight / heightUnits, kClipUnits);
    f.scale = u.metres;
    f.unit = u.symbol;
  }
  f.height = heightUnits * f.scale;

  glm::dvec3 forward;
  if (motion.facing != ClipFacing::Auto) {
    const int i = int(motion.facing) - 1;  // +z -z +x -x +y -y
    static const int kAxis[6] = {2, 2, 0, 0, 1, 1};
    forward = axisVector(kAxis[i], i % 2 == 0 ? 1.0 : -1.0);
    f.facingSaid = true;
  } else {
    // The character's left from its paired joints (LeftHand and RightHand, Foot_L and Foot_R,
    // LHipJoint and RHipJoint), then forward = left x up.
    // The hips' and the shoulders' pairs first: hands and feet swing with the step.
    auto leftOf = [&](bool trunkOnly) {
      glm::dvec3 left(0.0);
      for (size_t i = 0; i < bvh.joints.size(); ++i) {
        std::string restI;
        if (sideOf(bvh.joints[i].name, restI) != 'l' || (trunkOnly && !isTrunkJoint(restI)))
          continue;
        for (size_t k = 0; k < bvh.joints.size(); ++k) {
          std::string restK;
          if (sideOf(bvh.joints[k].name, restK) == 'r' && restK == restI)
            left += poses[i].position - poses[k].position;
        }
      }
      return left - glm::dot(left, up) * up;
    };
    glm::dvec3 left = leftOf(true);
    if (glm::length(left) < 1e-9) left = leftOf(false);
    if (glm::length(left) < 1e-9)
      return fail("no left and right joints to find the facing from: set motion.facing");
    forward = glm::normalize(glm::cross(left, up));
    // A clip that travels goes the way its character faces, within the hips' sway: its travel
    // up to its first cut (a later take may go elsewhere).
    std::vector<JointPose> at;
    glm::dvec3 last = poses[size_t(head)].position;
    for (int k = 1; k < bvh.frameCount(); ++k) {
      jointPoses(bvh, k, at);
      const glm::dvec3 p = at[size_t(head)].position;
      if (glm::length(p - last) * f.scale / bvh.frameTime > kCutSpeed) break;
      last = p;
    }
    glm::dvec3 travel = last - poses[size_t(head)].position;
    travel -= glm::dot(travel, up) * up;
    if (glm::length(travel) > 0.2 * heightUnits &&
        glm::dot(glm::normalize(travel), forward) > std::cos(glm::radians(30.0)))
      forward = glm::normalize(travel);
  }
  forward -= glm::dot(forward, up) * up;
  if (glm::length(forward) < 1e-9) return fail("motion.facing is along motion.up");
  forward = glm::normalize(forward);
  {
    // The facing as the nearest axis and how far from it.
    int axis = 0;
    for (int a = 0; a < 3; ++a)
      if (std::abs(forward[a]) > std::abs(forward[axis])) axis = a;
    f.facing = std::string(forward[axis] < 0 ? "-" : "+") + "xyz"[axis];
    const double off = glm::degrees(std::acos(std::min(1.0, std::abs(forward[axis]))));
    if (off > 1.0) f.facing += " turned " + fixed(off, 0) + " degrees";
  }
  // Clip axes to the world's: left -> +x, up -> +y, forward -> +z.
  const glm::dvec3 leftAxis = glm::cross(up, forward);
  const glm::dmat3 toWorld = glm::transpose(glm::dmat3(leftAxis, up, forward));
  const glm::dquat turn = glm::normalize(glm::quat_cast(toWorld));

  // Every frame: the head's and the chest's rotation relative to the first frame, their places
  // relative to where the head joint was.
  const int n = bvh.frameCount();
  c.frames_.resize(size_t(n));
  c.cutBefore_.assign(size_t(n), 0);
  glm::dquat head0, chest0;
  glm::dvec3 headAt0(0.0);
  for (int k = 0; k < n; ++k) {
    if (k > 0) jointPoses(bvh, k, poses);
    const glm::dquat h = glm::normalize(turn * poses[size_t(head)].rotation);
    const glm::dquat ch = glm::normalize(turn * poses[size_t(chest)].rotation);
    const glm::dvec3 hp = f.scale * (turn * poses[size_t(head)].position);
    const glm::dvec3 cp = f.scale * (turn * poses[size_t(chest)].position);
    if (k == 0) {
      head0 = h;
      chest0 = ch;
      headAt0 = hp;
    }
    Frame& fr = c.frames_[size_t(k)];
    fr.head = glm::normalize(h * glm::inverse(head0));
    fr.chest = glm::normalize(ch * glm::inverse(chest0));
    fr.headAt = hp - headAt0;
    fr.chestAt = cp - headAt0;
  }
  c.chestPivot_ = pivot + c.frames_[0].chestAt;
  const double ft = bvh.frameTime;
  for (int k = 1; k < n; ++k) {
    const Frame& a = c.frames_[size_t(k - 1)];
    const Frame& b = c.frames_[size_t(k)];
    if (jumps(a, b, ft)) {
      c.cutBefore_[size_t(k)] = 1;
      f.cuts.push_back(k);
    } else {
      f.peakHeadSpeed = std::max(f.peakHeadSpeed, glm::length(b.headAt - a.headAt) / ft);
    }
  }
  const Frame& last = c.frames_.back();
  const Frame& first = c.frames_.front();
  glm::dvec3 travel = last.headAt - first.headAt;
  travel.y = 0.0;
  f.travel = glm::length(travel);
  // A loop goes on from where the last frame left the body, a frame's step further.
  glm::dvec3 shift = last.chestAt - first.chestAt;
  if (n > 1) shift += last.chestAt - c.frames_[size_t(n - 2)].chestAt;
  shift.y = 0.0;
  c.loopShift_ = shift;
  return out;
}

MotionClip::Frame MotionClip::blend(const Frame& a, const Frame& b, double s) const {
  Frame out;
  out.head = glm::slerp(a.head, b.head, s);
  out.chest = glm::slerp(a.chest, b.chest, s);
  out.headAt = glm::mix(a.headAt, b.headAt, s);
  out.chestAt = glm::mix(a.chestAt, b.chestAt, s);
  return out;
}

BodyPose MotionClip::at(const Frame& fr, const glm::dvec3& shift, bool inPlace) const {
  glm::dvec3 move = shift;
  if (inPlace) {
    // The body's horizontal travel (its chest's) taken from both parts.
    move = -(fr.chestAt - frames_[0].chestAt);
    move.y = 0.0;
  }
  BodyPose p;
  p.head.rotation = fr.head;
  p.head.translation = pivot_ + fr.headAt + move - fr.head * pivot_;
  const glm::dvec3 chestTravel = fr.chestAt - frames_[0].chestAt;
  p.torso.rotation = fr.chest;
  p.torso.translation = chestPivot_ + chestTravel + move - fr.chest * chestPivot_;
  return p;
}

bool MotionClip::seamIsCut() const {
  if (frames_.size() < 2) return false;
  const Frame& a = frames_.back();
  Frame b = frames_.front();
  b.headAt += loopShift_;
  b.chestAt += loopShift_;
  return jumps(a, b, frameTime_);
}

BodyPose MotionClip::sample(double t, bool loop, bool inPlace) const {
  const int n = int(frames_.size());
  const double u = std::max(0.0, t / frameTime_);
  if (n == 1) return at(frames_[0], glm::dvec3(0.0), inPlace);
  if (!loop) {
    if (u >= n - 1) return at(frames_.back(), glm::dvec3(0.0), inPlace);
    const int k = int(std::floor(u));
    if (cutBefore_[size_t(k + 1)]) return at(frames_[size_t(k)], glm::dvec3(0.0), inPlace);
    return at(blend(frames_[size_t(k)], frames_[size_t(k + 1)], u - k), glm::dvec3(0.0), inPlace);
  }
  const double loops = std::floor(u / n);
  const double r = u - loops * n;
  const int k = std::min(n - 1, int(std::floor(r)));
  const double s = r - k;
  const glm::dvec3 shift = loops * loopShift_;
  if (k < n - 1) {
    if (cutBefore_[size_t(k + 1)]) return at(frames_[size_t(k)], shift, inPlace);
    return at(blend(frames_[size_t(k)], frames_[size_t(k + 1)], s), shift, inPlace);
  }
  // The seam: the last frame to the first of the next loop.
  if (seamIsCut()) return at(frames_.back(), shift, inPlace);
  Frame next = frames_.front();
  next.headAt += loopShift_;
  next.chestAt += loopShift_;
  Frame b = blend(frames_.back(), next, s);
  if (inPlace) {
    // In place the seam's travel is not the clip's: blend what in place keeps of each.
    const BodyPose pa = at(frames_.back(), shift, true), pb = at(frames_.front(), shift, true);
    BodyPose out;
    out.head = interpolate(pa.head, pb.head, s);
    out.torso = interpolate(pa.torso, pb.torso, s);
    return out;
  }
  return at(b, shift, false);
}

std::vector<double> MotionClip::cutsBetween(double t0, double t1, bool loop) const {
  std::vector<double> out;
  const int n = int(frames_.size());
  if (n < 2 || !(t1 > t0)) return out;
  auto consider = [&](double t) {
    if (t > t0 && t <= t1) out.push_back(t);
  };
  if (!loop) {
    for (int k : facts_.cuts) consider(k * frameTime_);
    return out;
  }
  const double period = n * frameTime_;
  const long first = long(std::floor(std::max(0.0, t0) / period));
  const long last = long(std::floor(t1 / period));
  for (long l = first; l <= last; ++l) {
    for (int k : facts_.cuts) consider(l * period + k * frameTime_);
    if (seamIsCut()) consider((l + 1) * period);
  }
  std::sort(out.begin(), out.end());
  return out;
}

int MotionClip::frameAt(double t, bool loop) const {
  const long n = long(frames_.size());
  const long k = long(std::floor(std::max(0.0, t) / frameTime_ + 1e-9));
  return int(loop ? k % n : std::min(k, n - 1));
}

std::string MotionClip::summary() const {
  const ClipFacts& f = facts_;
  std::string s = name_ + ": " + std::to_string(f.joints) + " joints, " + std::to_string(f.frames) +
                  " frames at " + fixed(1.0 / f.frameTime, 1) + " fps (" + fixed(duration(), 2) +
                  " s); ";
  if (f.unit == "set")
    s += fixed(f.scale, 6) + " m a unit (motion.scale)";
  else
    s += f.unit + " (inferred: a skeleton " + fixed(f.height, 2) + " m tall)";
  s += ", " + std::string(1, f.up) + " up" + (f.upSaid ? "" : " (inferred)");
  s += ", facing " + f.facing + (f.facingSaid ? "" : " (inferred)");
  s += "; head joint " + f.headJoint + ", chest joint " + f.chestJoint;
  s += "; travel " + fixed(f.travel, 2) + " m, head up to " + fixed(f.peakHeadSpeed, 2) + " m/s";
  s += "; " + std::to_string(f.cuts.size()) + (f.cuts.size() == 1 ? " cut" : " cuts");
  return s;
}

Pose torsoPoseAt(const Config& c, const MotionClip* clip, double t, const Pose& head) {
  if (!clip) return torsoUnder(head, torsoPose(c.head, t), glm::dvec3(c.head.pivot));
  return clip->sample(t, c.motion.loop, c.motion.inPlace).torso;
}

}  // namespace csm
