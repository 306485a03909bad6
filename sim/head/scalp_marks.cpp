#include "sim/head/scalp_marks.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "sim/head/mannequin.h"

namespace csm {
namespace {

constexpr double kStep = 0.002;  // m: the profile's spacing

// Where the line from (x, y, from) toward -z (or x toward 0) first enters the shape: 1 mm steps,
// then bisection.
std::optional<double> entering(const DistanceGrid& g, glm::dvec3 start, const glm::dvec3& dir,
                               double length) {
  double before = 0.0;
  if (g.sample(start) < 0.0) return std::nullopt;
  for (double t = 0.001; t <= length; t += 0.001) {
    if (g.sample(start + t * dir) < 0.0) {
      double lo = before, hi = t;
      for (int k = 0; k < 12; ++k) {
        const double mid = 0.5 * (lo + hi);
        (g.sample(start + mid * dir) < 0.0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    before = t;
  }
  return std::nullopt;
}

struct Raw {
  bool found = false;
  double tipY = 0, nasionY = 0, browY = 0;
  std::vector<glm::dvec2> forehead;  // (y, z) down the middle from the brow up
  glm::dvec3 ear{0.0};
  std::string why;
};

Raw measure(const DistanceGrid& g) {
  Raw r;
  // The front of the face down the middle: z where the surface is, every 2 mm of height.
  const double y0 = -0.12, y1 = 0.12;
  std::vector<double> front;
  for (double y = y0; y <= y1 + 1e-9; y += kStep) {
    const auto t = entering(g, {0.0, y, 0.3}, {0.0, 0.0, -1.0}, 0.6);
    front.push_back(t ? 0.3 - *t : -1.0);
  }
  const int n = int(front.size());
  auto yAt = [&](int i) { return y0 + i * kStep; };
  std::vector<double> smooth(front);
  for (int i = 1; i + 1 < n; ++i)
    smooth[size_t(i)] = (front[size_t(i - 1)] + front[size_t(i)] + front[size_t(i + 1)]) / 3.0;
  // The nose's tip: the most forward point between 9 cm below the cranium's centre and its level.
  int tip = -1;
  for (int i = 0; i < n; ++i)
    if (yAt(i) >= -0.09 && yAt(i) <= 0.0 && (tip < 0 || smooth[size_t(i)] > smooth[size_t(tip)]))
      tip = i;
  // A nose stands out of the face: the tip 5 mm before the profile 15 mm below it.
  const int below = tip - int(std::lround(0.015 / kStep));
  if (tip < 0 || below < 0 || smooth[size_t(tip)] - smooth[size_t(below)] < 0.005) {
    r.why = "no nose down the face's middle";
    return r;
  }
  // The nasion: the deepest point under the chord from the nose's tip to the forehead 8 cm above
  // it (however shallow the bridge, the profile bends in there); the brow 12 mm above it.
  const int forehead = std::min(n - 1, tip + int(std::lround(0.08 / kStep)));
  int nasion = -1;
  double deepest = -0.001;  // at least 1 mm under the chord
  for (int i = tip + 1; i < forehead; ++i) {
    const double along = double(i - tip) / double(forehead - tip);
    const double chord = glm::mix(smooth[size_t(tip)], smooth[size_t(forehead)], along);
    if (smooth[size_t(i)] - chord < deepest) deepest = smooth[size_t(i)] - chord, nasion = i;
  }
  if (nasion < 0) {
    r.why = "no bridge of the nose below a brow down the face's middle";
    return r;
  }
  r.tipY = yAt(tip);
  r.nasionY = yAt(nasion);
  r.browY = r.nasionY + 0.012;
  for (int i = nasion + int(std::lround(0.012 / kStep)); i < n && front[size_t(i)] > -1.0; ++i)
    r.forehead.emplace_back(yAt(i), smooth[size_t(i)]);
  if (r.forehead.size() < 2) {
    r.why = "no forehead above the brow";
    return r;
  }
  // The ear: the widest point on the +x side, from the nasion's height to 5 cm below it, from
  // 5 cm behind the cranium's centre to 1 cm before it (behind the cheekbones).
  double widest = -1.0;
  for (double y = r.nasionY - 0.05; y <= r.nasionY + 0.01; y += kStep)
    for (double z = -0.05; z <= 0.01; z += kStep) {
      const auto t = entering(g, {0.3, y, z}, {-1.0, 0.0, 0.0}, 0.3);
      if (t && 0.3 - *t > widest) widest = 0.3 - *t, r.ear = {widest, y, z};
    }
  if (widest < 0.0) {
    r.why = "no ear beside the cranium";
    return r;
  }
  r.found = true;
  return r;
}

const Raw& mannequinRaw() {
  static const Raw raw = measure(mannequinHeadGrid());
  return raw;
}

// A point of the middle profile seen from the scalp centre: degrees from straight up.
double angleOf(const glm::dvec2& yz) {
  return std::atan2(yz.y - kMannequinScalpCentre.z, yz.x - kMannequinScalpCentre.y) * 180.0 /
         3.14159265358979323846;
}

// The mannequin's front hairline (hairstyle.hairline_front's default) lies this far up its
// forehead from its brow.
constexpr double kReferenceHairline = 50.0;  // degrees

double foreheadToAngle(const Raw& r, double degrees) {
  double arc = 0.0;
  for (size_t i = 1; i < r.forehead.size(); ++i) {
    if (angleOf(r.forehead[i]) <= degrees) return arc;
    arc += glm::length(r.forehead[i] - r.forehead[i - 1]);
  }
  return arc;
}

// The angle of the point `arc` up the forehead from the brow.
double angleUpForehead(const Raw& r, double arc) {
  for (size_t i = 1; i < r.forehead.size(); ++i) {
    const double step = glm::length(r.forehead[i] - r.forehead[i - 1]);
    if (arc <= step) return angleOf(glm::mix(r.forehead[i - 1], r.forehead[i], arc / step));
    arc -= step;
  }
  return angleOf(r.forehead.back());
}

}  // namespace

ScalpMarks mannequinScalpMarks() {
  ScalpMarks m;
  m.text = "the mannequin's hairline";
  return m;
}

ScalpMarks measureScalpMarks(const DistanceGrid& head) {
  ScalpMarks m = mannequinScalpMarks();
  const Raw r = measure(head);
  const Raw& ref = mannequinRaw();
  if (!r.found || !ref.found) {
    m.text = "the mannequin's hairline: " +
             (r.found ? ref.why + " on the mannequin" : r.why + " on head.mesh");
    return m;
  }
  m.measured = true;
  m.browY += r.browY - ref.browY;
  m.ear += r.ear - ref.ear;
  // The forehead as high as the mannequin's, measured along it from the brow.
  const double forehead = foreheadToAngle(ref, kReferenceHairline);
  m.hairlineShift = angleUpForehead(r, forehead) - angleUpForehead(ref, forehead);
  char text[256];
  std::snprintf(
      text, sizeof text,
      "hairline from the head's shape: the brow at y = %.3f m (the mannequin's %+.1f cm), "
      "the ears at (%.3f, %.3f, %.3f) m, the front hairline %.1f cm up the forehead from it (%+.1f "
      "degrees)",
      r.browY, (r.browY - ref.browY) * 100.0, r.ear.x, r.ear.y, r.ear.z, forehead * 100.0,
      m.hairlineShift);
  m.text = text;
  return m;
}

}  // namespace csm
