#include "sim/head/head_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "sim/base/units.h"
#include "sim/core/sphere_fit.h"

namespace csm {
namespace {

constexpr double kCapDepth = 0.07;        // m: the top of the head, above the brow and the ears
constexpr double kPlaceTolerance = 0.04;  // m: a cranium this near the mannequin's stays put
constexpr double kFacingContrast = 1.3;   // the face's detail over the back's, to be sure of it

const std::array<glm::dvec3, 6> kAxes{glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                      glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                      glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
const std::array<const char*, 6> kAxisNames{"+x", "-x", "+y", "-y", "+z", "-z"};

// The signed axis nearest a direction.
int nearestAxis(const glm::dvec3& d) {
  int best = 0;
  for (int i = 1; i < 6; ++i)
    if (glm::dot(d, kAxes[size_t(i)]) > glm::dot(d, kAxes[size_t(best)])) best = i;
  return best;
}

std::vector<double> vertexAreas(const SurfaceMesh& m) {
  std::vector<double> area(m.positions.size(), 0.0);
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
        c(m.positions[m.indices[t + 2]]);
    const double third = glm::length(glm::cross(b - a, c - a)) / 6.0;
    for (int k = 0; k < 3; ++k) area[m.indices[t + size_t(k)]] += third;
  }
  return area;
}

// The integrated absolute mean curvature (each edge's dihedral angle times its length) of the
// face band, in the four horizontal directions from the cranium's axis (indices into kAxes).
std::array<double, 6> detailBySide(const SurfaceMesh& m, const glm::dvec3& up, const Cap& cap,
                                   double unitsPerMetre) {
  std::array<double, 6> sum{};
  std::unordered_map<uint64_t, size_t> firstFace;
  const uint64_t n = m.positions.size();
  auto normalOf = [&](size_t t) {
    const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
        c(m.positions[m.indices[t + 2]]);
    const glm::dvec3 nrm = glm::cross(b - a, c - a);
    const double len = glm::length(nrm);
    return len > 0.0 ? nrm / len : glm::dvec3(0.0);
  };
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const uint64_t a = m.indices[t + size_t(e)], b = m.indices[t + size_t(e + 1) % 3];
      const uint64_t key = std::min(a, b) * n + std::max(a, b);
      auto [it, added] = firstFace.try_emplace(key, t);
      if (added) continue;
      const glm::dvec3 pa(m.positions[a]), pb(m.positions[b]);
      const glm::dvec3 mid = 0.5 * (pa + pb) - cap.centre;
      const double height = glm::dot(mid, up) / unitsPerMetre;
      if (height < -0.12 || height > 0.03) continue;
      const glm::dvec3 across = mid - glm::dot(mid, up) * up;
      if (glm::length(across) < 0.02 * unitsPerMetre) continue;
      const double cosine = std::clamp(glm::dot(normalOf(it->second), normalOf(t)), -1.0, 1.0);
      const double weight = std::acos(cosine) * glm::length(pb - pa);
      sum[size_t(nearestAxis(across))] += weight;
    }
  return sum;
}

std::string metres(const glm::dvec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f) m", v.x, v.y, v.z);
  return text;
}

}  // namespace

Cap craniumCap(const SurfaceMesh& m, const glm::dvec3& up, double depth) {
  Cap cap;
  if (m.positions.empty()) return cap;
  double top = -1e300;
  for (const glm::vec3& p : m.positions) top = std::max(top, glm::dot(glm::dvec3(p), up));
  const std::vector<double> area = vertexAreas(m);
  std::vector<glm::dvec3> points;
  std::vector<double> weights;
  for (size_t v = 0; v < m.positions.size(); ++v)
    if (glm::dot(glm::dvec3(m.positions[v]), up) >= top - depth) {
      points.emplace_back(m.positions[v]);
      weights.push_back(area[v]);
    }
  if (const std::optional<SphereFit> fit = fitSphere(points, weights)) {
    cap.centre = fit->centre;
    cap.radius = fit->radius;
  }
  return cap;
}

bool HeadFit::changed() const {
  return scale != 1.0 || rotation != glm::dmat3(1.0) || translation != glm::dvec3(0.0);
}

glm::vec3 HeadFit::apply(const glm::vec3& p) const {
  return glm::vec3(rotation * (scale * glm::dvec3(p)) + translation);
}

void HeadFit::applyTo(SurfaceMesh& mesh) const {
  for (glm::vec3& p : mesh.positions) p = apply(p);
  for (glm::vec3& n : mesh.normals) n = glm::vec3(rotation * glm::dvec3(n));
}

std::string HeadFit::text() const {
  char size[64];
  std::snprintf(size, sizeof size, "%.1f cm", craniumRadius * 100.0);
  std::string s = unit.empty() ? "scale " + std::to_string(scale) + " (head.mesh_scale)"
                               : "units " + unit + " (inferred: the cranium is " + size +
                                     " in radius; head.mesh_scale overrides)";
  s += "; up " + up + " (" + upWhy + ")";
  s += "; facing " + facing + " (" + facingWhy + ")";
  s += "; " + placeWhy;
  return s;
}

HeadFit fitHead(SurfaceMesh& m, const std::vector<glm::vec3>& holes, const HeadFitOptions& o) {
  HeadFit fit;
  glm::dvec3 centroid(0.0);
  for (const glm::vec3& p : m.positions) centroid += glm::dvec3(p);
  if (!m.positions.empty()) centroid /= double(m.positions.size());

  // Up: away from the neck's opening (the capped hole farthest below the rest), else the given
  // axis or the file's convention (y).
  int upAxis = 2;
  switch (o.up) {
    case ClipUp::Y:
      upAxis = 2, fit.upWhy = "head.mesh_up";
      break;
    case ClipUp::Z:
      upAxis = 4, fit.upWhy = "head.mesh_up";
      break;
    case ClipUp::X:
      upAxis = 0, fit.upWhy = "head.mesh_up";
      break;
    case ClipUp::Auto:
      if (!holes.empty()) {
        glm::dvec3 away(0.0);
        double farthest = -1.0;
        for (const glm::vec3& h : holes) {
          const glm::dvec3 d = centroid - glm::dvec3(h);
          if (glm::length(d) > farthest) farthest = glm::length(d), away = d;
        }
        upAxis = nearestAxis(away);
        fit.upWhy =
            std::string("away from the opening at the neck, capped; head.mesh_up overrides");
      } else {
        fit.upWhy =
            "the file's convention: no opening at the neck to tell it by; head.mesh_up "
            "overrides";
      }
      break;
  }
  const glm::dvec3 up = kAxes[size_t(upAxis)];
  fit.up = kAxisNames[size_t(upAxis)];

  // The unit: the one that makes the cranium's sphere nearest the mannequin's (8.1 cm by this
  // measure), from metres to millimetres and inches.
  double scale = o.scale > 0.0f ? double(o.scale) : 1.0;
  Cap cap;
  if (o.scale > 0.0f) {
    cap = craniumCap(m, up, kCapDepth / scale);
  } else {
    double bestScore = 1e300;
    for (const LengthUnit& u : kLengthUnits) {
      const Cap c = craniumCap(m, up, kCapDepth / u.metres);
      const double r = c.radius * u.metres;
      if (!(r > 0.0)) continue;
      const double score = std::abs(std::log(r / kMannequinCraniumRadius));
      if (score < bestScore) bestScore = score, scale = u.metres, fit.unit = u.symbol, cap = c;
    }
    if (fit.unit.empty()) {
      fit.unit = "m";
      cap = craniumCap(m, up, kCapDepth);
    }
  }
  fit.craniumRadius = cap.radius * scale;
  fit.scale = scale;

  // Facing: of the two horizontal axes, the one whose two sides differ most in detail (the ears
  // are alike on either side), toward its more detailed side, when that is clearly so.
  int faceAxis = upAxis == 4 ? 3 : 4;  // the convention: +z, or -y for z up (Blender's front)
  fit.facingWhy = "the convention for " + fit.up + " up";
  if (o.facing != ClipFacing::Auto) {
    const int byChoice[] = {4, 4, 5, 0, 1, 2, 3};  // auto, +z, -z, +x, -x, +y, -y
    faceAxis = byChoice[int(o.facing)];
    fit.facingWhy = "head.mesh_facing";
  } else {
    const std::array<double, 6> detail = detailBySide(m, up, cap, 1.0 / scale);
    double bestContrast = 0.0;
    int best = -1;
    for (int a = 0; a < 6; a += 2) {
      if (a == (upAxis & ~1)) continue;
      const double plus = detail[size_t(a)], minus = detail[size_t(a + 1)];
      const double contrast = std::max(plus, minus) / std::max(1e-12, std::min(plus, minus));
      if (contrast > bestContrast) bestContrast = contrast, best = plus >= minus ? a : a + 1;
    }
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.1fx", bestContrast);
    if (best >= 0 && bestContrast >= kFacingContrast) {
      faceAxis = best;
      fit.facingWhy =
          std::string("the face's detail, ") + ratio + " the back's; head.mesh_facing overrides";
    } else {
      fit.facingWhy += std::string(": no side has clearly more detail (") + ratio +
                       "); head.mesh_facing overrides";
    }
  }
  if ((faceAxis & ~1) == (upAxis & ~1)) faceAxis = upAxis == 4 ? 3 : 4;  // never along up
  const glm::dvec3 face = kAxes[size_t(faceAxis)];
  fit.facing = kAxisNames[size_t(faceAxis)];
  const glm::dvec3 left = glm::cross(up, face);
  // Rows: the file's left, up and face become x, y and z.
  fit.rotation = glm::transpose(glm::dmat3(left, up, face));

  // The place: the cranium onto the mannequin's.
  const glm::dvec3 at = fit.rotation * (scale * cap.centre);
  const glm::dvec3 target(0.0, kMannequinCraniumY, kMannequinCraniumZ);
  if (!o.place) {
    fit.placeWhy = "kept where the file put it (head.mesh_place)";
  } else if (cap.radius > 0.0 && glm::length(target - at) > kPlaceTolerance) {
    fit.translation = target - at;
    fit.placeWhy = "moved by " + metres(fit.translation) +
                   " to put the cranium where the mannequin's is (head.mesh_place as_is keeps it)";
  } else {
    fit.placeWhy = "in place: the cranium within 4 cm of the mannequin's";
  }
  fit.applyTo(m);
  return fit;
}

}  // namespace csm
