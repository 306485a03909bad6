// Where the scalp ends on a head (METHOD.md section 6.5): the brow the forehead rises from and the
// ears the hairline passes over, found on the head's own shape. The generator's hairline
// (hairstyle.hairline_front, the ears' clearance) is laid out on the mannequin; on head.mesh it is
// moved by as much as that head's brow and ears lie from the mannequin's, so a scan's forehead and
// eyes stay clear whatever its proportions.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"

namespace csm {

inline constexpr double kMannequinBrowY = 0.012;

struct ScalpMarks {
  double browY = kMannequinBrowY;  // the brow's height (head frame, m): a fringe hangs to it
  // The outer point of the ear on the +x side (head frame, m): no root within 30 degrees of it,
  // seen from the scalp centre.
  glm::dvec3 ear{0.074, -0.025, -0.002};
  // Degrees added to hairstyle.hairline_front (lower: positive): the forehead as high, along it
  // from the brow, as the mannequin's.
  double hairlineShift = 0.0;
  bool measured = false;  // found on the head's shape (false: the mannequin's)
  std::string text;       // what was found, or why the mannequin's are used
};

// The mannequin's, as the generator has always used them.
ScalpMarks mannequinScalpMarks();
// Found on a head's field (the head frame, face +z): the brow from the face's profile down the
// middle (the nose's tip, the nasion where the bridge bends in above it, the brow 12 mm over that),
// the ears as the widest points beside the cranium from the nasion down 5 cm; each moved from the
// mannequin's by as much as the same measure differs between the two. A shape without a nose
// before a brow keeps the mannequin's, and says so.
ScalpMarks measureScalpMarks(const DistanceGrid& head);

}  // namespace csm
