#include "sim/head/mannequin.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/field_cache.h"
#include "sim/head/surface_mesh.h"

namespace csm {

namespace {

double sphere(const glm::dvec3& p, const glm::dvec3& c, double r) {
  return glm::length(p - c) - r;
}

// Inigo Quilez's ellipsoid bound: exact on the surface, close to the distance near it.
double ellipsoid(const glm::dvec3& p, const glm::dvec3& c, const glm::dvec3& r) {
  const glm::dvec3 q = p - c;
  const double k0 = glm::length(q / r);
  const double k1 = glm::length(q / (r * r));
  return k1 > 1e-12 ? k0 * (k0 - 1.0) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

double capsule(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double r) {
  const glm::dvec3 pa = p - a, ba = b - a;
  const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
  return glm::length(pa - ba * h) - r;
}

// A capsule whose radius runs from ra at a to rb at b (the hull of the two spheres).
double roundCone(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double ra,
                 double rb) {
  const glm::dvec3 ba = b - a, pa = p - a;
  const double l2 = glm::dot(ba, ba), rr = ra - rb, a2 = l2 - rr * rr, il2 = 1.0 / l2;
  const double y = glm::dot(pa, ba), z = y - l2;
  const glm::dvec3 xv = pa * l2 - ba * y;
  const double x2 = glm::dot(xv, xv), y2 = y * y * l2, z2 = z * z * l2;
  const double k = (rr > 0.0 ? 1.0 : -1.0) * rr * rr * x2;
  if ((z > 0.0 ? 1.0 : -1.0) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - rb;
  if ((y > 0.0 ? 1.0 : -1.0) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - ra;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - ra;
}

// A solid between the planes x = lo and x = hi, its edges rounded by r: `outline` is the signed
// distance, within those planes, to its outline, and x the distance along their normal.
double prism(double outline, double x, double lo, double hi, double r) {
  const double u = outline + r, v = std::abs(x - 0.5 * (lo + hi)) - (0.5 * (hi - lo) - r);
  const double uo = std::max(u, 0.0), vo = std::max(v, 0.0);
  return std::min(std::max(u, v), 0.0) + std::sqrt(uo * uo + vo * vo) - r;
}

// Polynomial smooth minimum: the union of two shapes with a fillet of about k.
double smoothUnion(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

double smoothSubtract(double a, double cut, double k) {
  return -smoothUnion(-a, cut, k);
}

double smoothIntersect(double a, double b, double k) {
  return -smoothUnion(-a, -b, k);
}

// A lip along the mouth's curve: cones rounded at their ends from a little past the middle at
// a, through b, to the corner of the mouth at c, joined smoothly with the mirror image of the
// first across the middle.
double lip(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
           double ra, double rb, double rc) {
  const glm::dvec3 m(-p.x, p.y, p.z);
  const double middle = smoothUnion(roundCone(p, a, b, ra, rb), roundCone(m, a, b, ra, rb), 0.004);
  return smoothUnion(middle, roundCone(p, b, c, rb, rc), 0.002);
}

// Coordinates in a frame of orthonormal axes about an origin.
struct Frame {
  glm::dvec3 origin, x, y, z;
  glm::dvec3 local(const glm::dvec3& p) const {
    const glm::dvec3 q = p - origin;
    return {glm::dot(q, x), glm::dot(q, y), glm::dot(q, z)};
  }
};

// Whether a group of shapes, each within `bound` of `centre` and blended with fillets of at
// most k, can change the field d at p: never when p lies further from that ball than |d| + k.
bool reaches(const glm::dvec3& p, const glm::dvec3& centre, double bound, double d, double k) {
  return glm::length(p - centre) - bound < std::abs(d) + k;
}

// The right ear's frame: x out of the ear's outer face (turned a little forwards from the side
// of the head), y up the ear (leaning back), z towards the face.
Frame earFrame() {
  const double flare = 0.30, lean = 0.26;
  const glm::dvec3 out(std::cos(flare), 0.0, std::sin(flare));
  const glm::dvec3 fwd0(-std::sin(flare), 0.0, std::cos(flare));
  const glm::dvec3 up = std::cos(lean) * glm::dvec3(0, 1, 0) - std::sin(lean) * fwd0;
  const glm::dvec3 fwd = std::cos(lean) * fwd0 + std::sin(lean) * glm::dvec3(0, 1, 0);
  return {{0.0725, -0.026, -0.012}, out, up, fwd};
}

// The right ear, in its frame: a solid mass narrowing to the lobe, its outline run from inside
// the head out to the outer face with the outer edge rounded, so that there is no gap behind it
// and nothing thin for the 4 mm collision grid to lose. The outer face carries the ear's forms
// as shallow relief, none of it undercut: the hollow (scapha and fossa) inside the helix's rim,
// the antihelix's ridge within it, the bowl of the concha before the ear canal, and the tragus.
double ear(const glm::dvec3& p) {
  static const Frame frame = earFrame();
  const glm::dvec3 e = frame.local(p);
  const glm::dvec3 inPlane(0.0, e.y, e.z);
  const double face = 0.0085;
  const double outline =
      roundCone(inPlane, {0.0, 0.008, -0.003}, {0.0, -0.019, 0.001}, 0.0155, 0.0085);
  double d = prism(outline, e.x, -0.024, face, 0.005);
  // The hollow inside the rim, its walls sloping gently (one in two) for the meshes.
  const double hollow =
      roundCone(inPlane, {0.0, 0.010, -0.004}, {0.0, -0.004, -0.001}, 0.0095, 0.0060);
  const double sunk = face - 0.0018 - e.x;
  d = smoothSubtract(d, std::max(sunk, (0.5 * hollow + sunk) / std::sqrt(1.25)), 0.003);
  // The antihelix: a ridge from the lower back up to a fork under the rim.
  d = smoothUnion(
      d, capsule(e, {face - 0.0030, -0.010, -0.008}, {face - 0.0025, 0.005, -0.004}, 0.0022),
      0.002);
  d = smoothUnion(
      d, capsule(e, {face - 0.0025, 0.005, -0.004}, {face - 0.0030, 0.014, 0.003}, 0.0018), 0.002);
  // The concha and the tragus.
  d = smoothSubtract(d, sphere(e, {face + 0.0095 - 0.003, -0.007, 0.004}, 0.0095), 0.002);
  d = smoothUnion(
      d, capsule(e, {face - 0.0035, -0.012, 0.009}, {face - 0.0035, -0.006, 0.010}, 0.003), 0.002);
  return d;
}

// The right eye, closed, in its socket: the lower lid over the eyeball and the upper lid a
// little proud of it down to the lash line, which lies below the middle and dips towards the
// front.
double closedEye(const glm::dvec3& p, double d) {
  const glm::dvec3 c{0.031, -0.0135, 0.0612}, r{0.0150, 0.0122, 0.0130};
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.0, 1.0, 0.2));
  const double lower = ellipsoid(p, c, r);
  const double upper =
      smoothIntersect(ellipsoid(p, c, r + 0.0008), 0.0012 - glm::dot(p - c, n), 0.0008);
  return smoothUnion(d, smoothUnion(lower, upper, 0.0004), 0.005);
}

}  // namespace

double mannequinDistance(const glm::dvec3& q) {
  // Left-right symmetric: model the right half (x >= 0) and mirror.
  const glm::dvec3 p(std::abs(q.x), q.y, q.z);
  // Cranium and the face's mass below the forehead.
  double d = ellipsoid(p, {0.0, 0.005, -0.012}, {0.074, 0.095, 0.094});
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.045, 0.025}, {0.060, 0.075, 0.060}), 0.03);
  // The jaw: the mandible's body, its lower edge from the angle to the chin, and the chin.
  if (reaches(p, {0.0, -0.085, 0.035}, 0.072, d, 0.02)) {
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.080, 0.030}, {0.048, 0.036, 0.052}), 0.02);
    d = smoothUnion(d, capsule(p, {0.050, -0.079, -0.004}, {0.021, -0.115, 0.066}, 0.008), 0.02);
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.111, 0.070}, {0.019, 0.016, 0.015}), 0.014);
  }
  // The face's features.
  if (reaches(p, {0.0, -0.040, 0.070}, 0.072, d, 0.02)) {
    // Cheekbones and the brow's ridge.
    d = smoothUnion(d, ellipsoid(p, {0.047, -0.027, 0.056}, {0.017, 0.012, 0.015}), 0.02);
    d = smoothUnion(d, capsule(p, {0.0, 0.004, 0.077}, {0.040, 0.006, 0.071}, 0.011), 0.015);
    // The eye sockets, each with its closed eye.
    d = smoothSubtract(d, capsule(p, {0.025, -0.008, 0.083}, {0.037, -0.008, 0.083}, 0.013), 0.008);
    d = closedEye(p, d);
    // The nose: its bridge, the tip, the wings (alae) about the base, the columella, and the
    // nostrils under them.
    d = smoothUnion(d, roundCone(p, {0.0, -0.007, 0.082}, {0.0, -0.043, 0.103}, 0.0055, 0.0075),
                    0.01);
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.047, 0.100}, {0.0095, 0.0085, 0.0085}), 0.006);
    d = smoothUnion(d, capsule(p, {-0.009, -0.0515, 0.093}, {0.009, -0.0515, 0.093}, 0.0068),
                    0.005);
    d = smoothUnion(d, sphere(p, {0.0125, -0.0515, 0.090}, 0.0055), 0.004);
    d = smoothUnion(d, capsule(p, {0.0, -0.053, 0.100}, {0.0, -0.0565, 0.0905}, 0.0028), 0.004);
    d = smoothSubtract(d, capsule(p, {0.0068, -0.0585, 0.0915}, {0.0068, -0.0585, 0.0955}, 0.003),
                       0.002);
    // The mouth: its muzzle, the philtrum, and the lips meeting along the mouth's line.
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.073, 0.068}, {0.029, 0.021, 0.020}), 0.012);
    d = smoothSubtract(d, capsule(p, {0.0, -0.060, 0.0935}, {0.0, -0.066, 0.0935}, 0.005), 0.003);
    const double upperLip = lip(p, {-0.004, -0.0737, 0.0882}, {0.012, -0.0747, 0.0851},
                                {0.023, -0.0772, 0.0775}, 0.0046, 0.0034, 0.0016);
    const double lowerLip = lip(p, {-0.004, -0.0840, 0.0852}, {0.011, -0.0833, 0.0825},
                                {0.021, -0.0795, 0.0775}, 0.0054, 0.0041, 0.0016);
    d = smoothUnion(d, smoothUnion(upperLip, lowerLip, 0.0012), 0.003);
  }
  // The ears.
  if (reaches(p, {0.074, -0.028, -0.012}, 0.040, d, 0.004)) d = smoothUnion(d, ear(p), 0.004);
  // Neck and shoulders.
  d = smoothUnion(d, capsule(p, {0.0, -0.070, -0.020}, {0.0, -0.250, -0.025}, 0.055), 0.03);
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.305, -0.015}, {0.190, 0.075, 0.095}), 0.06);
  return d;
}

const DistanceGrid& mannequinGrid() {
  // Kept on disk between runs of the same program (sim/head/field_cache.h): 1.9 s of a core.
  static const DistanceGrid grid = cachedSampleDistance(
      "mannequin", mannequinDistance, {-0.215, -0.415, -0.125}, {0.215, 0.115, 0.135}, 0.004);
  return grid;
}

const SurfaceMesh& mannequinMesh() {
  // The collision grid decides the topology; the vertices lie on the function's zero level
  // and take its gradient, which draws the eyelids, nostrils and lips as a finer grid's mesh
  // would (2.75 mm was compared) at half its triangles, which a software rasterizer pays for.
  static const SurfaceMesh mesh = meshZeroLevel(mannequinGrid(), mannequinDistance);
  return mesh;
}

}  // namespace csm
