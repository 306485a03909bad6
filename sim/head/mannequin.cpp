#include "sim/head/mannequin.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/field_cache.h"
#include "sim/head/surface_mesh.h"

namespace csm {

namespace {

// The neck, where the two parts meet: its radius, the top of the head's part and the end of its
// neck inside the torso's, and the top of the torso's, so that the two necks cross at
// head.pivot's height (y = -0.15) and each ends inside the other.
constexpr double kNeckRadius = 0.058;
constexpr glm::dvec3 kNeckTop{0.0, -0.070, -0.018};
constexpr glm::dvec3 kHeadNeckEnd{0.0, -0.200, -0.022};
constexpr glm::dvec3 kTorsoNeckTop{0.0, -0.110, -0.020};

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
// A shape reaching out of the ball would end at its edge, its gradient pointing anywhere there
// (a speck in the drawn mesh; tests/cpu/head_shape_test.cpp finds one).
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

// The right eye, open, in its socket: the eyeball (its cornea a little proud of it) between the
// lids, each a shell over the ball ending at its lash line, the upper lid's lower and more
// arched, the two meeting at the corners, where the opening narrows to nothing.
double openEye(const glm::dvec3& p, double d) {
  const MannequinFace& face = kMannequinFace;
  const glm::dvec3 c = face.eye;
  const double ball = sphere(p, c, face.ball);
  const double cornea = sphere(p, c + glm::dvec3(0.0, 0.0, face.corneaOffset), face.cornea);
  const double eye = smoothUnion(ball, cornea, 0.002);
  // The lids: a shell 2 mm over the ball, cut along the opening, an almond whose half-height
  // falls from 5.2 mm at its middle to nothing at its corners, 15 mm either side, its margins
  // rounded by 1.6 mm (the drawing grid's 2 mm keeps them whole); the upper lid's edge a little
  // proud of the lower's, its crease a soft groove under the brow.
  const glm::dvec3 q = p - c;
  const double across = std::clamp(q.x / 0.0150, -1.0, 1.0);
  const double half = 0.0052 * (1.0 - across * across);
  const double middle = 0.0008;  // the opening's middle, a little above the ball's centre
  const double opening = std::abs(q.y - middle) - half;
  const double shell =
      ellipsoid(p, c + glm::dvec3(0.0, 0.0006, 0.0), glm::dvec3(0.0142, 0.0140, 0.0142));
  const double lids = smoothIntersect(shell, -opening, 0.0016);
  double outer = smoothUnion(eye, lids, 0.0016);
  outer = smoothSubtract(outer,
                         capsule(p, c + glm::dvec3(-0.011, 0.0125, 0.0105),
                                 c + glm::dvec3(0.011, 0.0115, 0.0095), 0.0020),
                         0.0025);
  return smoothUnion(d, outer, 0.003);
}

}  // namespace

double mannequinHeadDistance(const glm::dvec3& q) {
  // Left-right symmetric: model the right half (x >= 0) and mirror.
  const glm::dvec3 p(std::abs(q.x), q.y, q.z);
  // Cranium and the face's mass below the forehead.
  double d = ellipsoid(p, {0.0, 0.005, -0.012}, {0.074, 0.095, 0.094});
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.045, 0.025}, {0.064, 0.075, 0.060}), 0.03);
  // The jaw: the mandible's body, its lower edge from the angle to the chin, and the chin.
  if (reaches(p, {0.0, -0.085, 0.035}, 0.080, d, 0.02)) {
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.080, 0.030}, {0.054, 0.036, 0.052}), 0.02);
    d = smoothUnion(d, capsule(p, {0.055, -0.076, -0.006}, {0.022, -0.113, 0.064}, 0.009), 0.02);
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.110, 0.068}, {0.020, 0.016, 0.015}), 0.014);
  }
  // The face's features.
  if (reaches(p, {0.0, -0.040, 0.070}, 0.082, d, 0.025)) {
    // Cheekbones and the brow's ridge.
    d = smoothUnion(d, ellipsoid(p, {0.048, -0.030, 0.046}, {0.016, 0.010, 0.022}), 0.025);
    d = smoothUnion(d, capsule(p, {0.0, 0.005, 0.0745}, {0.040, 0.007, 0.068}, 0.0105), 0.015);
    // The eye sockets, each with its open eye.
    d = smoothSubtract(d, capsule(p, {0.025, -0.011, 0.083}, {0.038, -0.011, 0.081}, 0.0130),
                       0.008);
    d = openEye(p, d);
    // The nose: its bridge, the tip, the wings (alae) about the base, the columella, and the
    // nostrils under them.
    d = smoothUnion(d, roundCone(p, {0.0, -0.007, 0.082}, {0.0, -0.043, 0.103}, 0.0055, 0.0075),
                    0.01);
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.047, 0.100}, {0.0095, 0.0085, 0.0085}), 0.006);
    d = smoothUnion(d, capsule(p, {-0.009, -0.0515, 0.093}, {0.009, -0.0515, 0.093}, 0.0068),
                    0.005);
    d = smoothUnion(d, sphere(p, {0.0125, -0.0515, 0.090}, 0.0055), 0.006);
    d = smoothUnion(d, capsule(p, {0.0, -0.053, 0.100}, {0.0, -0.0565, 0.0905}, 0.0028), 0.004);
    d = smoothSubtract(d, capsule(p, {0.0068, -0.0585, 0.0915}, {0.0068, -0.0585, 0.0955}, 0.003),
                       0.002);
    // The mouth at rest: its muzzle, the philtrum, and full lips lying on it, closed along a
    // gently curved line, the corners tucked in.
    d = smoothUnion(d, ellipsoid(p, {0.0, -0.074, 0.066}, {0.030, 0.022, 0.021}), 0.012);
    d = smoothSubtract(d, capsule(p, {0.0, -0.060, 0.0925}, {0.0, -0.066, 0.0925}, 0.005), 0.003);
    const double upperLip = lip(p, {-0.004, -0.0744, 0.0868}, {0.012, -0.0752, 0.0840},
                                {0.0230, -0.0772, 0.0765}, 0.0044, 0.0034, 0.0024);
    const double lowerLip = lip(p, {-0.004, -0.0836, 0.0856}, {0.011, -0.0830, 0.0828},
                                {0.0210, -0.0787, 0.0765}, 0.0050, 0.0040, 0.0024);
    d = smoothUnion(d, smoothUnion(upperLip, lowerLip, 0.0006), 0.003);
    // The line where the lips meet, and the corners' small hollows.
    d = smoothSubtract(d, capsule(p, {0.0, -0.0790, 0.0945}, {0.0200, -0.0785, 0.0820}, 0.0024),
                       0.0020);
  }
  // The ears.
  if (reaches(p, {0.074, -0.028, -0.012}, 0.040, d, 0.004)) d = smoothUnion(d, ear(p), 0.004);
  // The upper neck, narrowing into the torso's (mannequinTorsoDistance), the two crossing at
  // head.pivot.
  d = smoothUnion(d, roundCone(p, kNeckTop, kHeadNeckEnd, kNeckRadius, kNeckRadius - 0.006), 0.018);
  return d;
}

double mannequinTorsoDistance(const glm::dvec3& q) {
  const glm::dvec3 p(std::abs(q.x), q.y, q.z);
  // The lower neck, widening into the shoulders.
  double d =
      roundCone(p, kTorsoNeckTop, {0.0, -0.25, -0.026}, kNeckRadius - 0.006, kNeckRadius + 0.002);
  // The trapezius, from the neck's base out to the shoulder, and the shoulders' mass with the
  // deltoids at its ends.
  d = smoothUnion(d, capsule(p, {0.02, -0.215, -0.035}, {0.150, -0.262, -0.025}, 0.040), 0.04);
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.300, -0.015}, {0.185, 0.070, 0.095}), 0.05);
  d = smoothUnion(d, sphere(p, {0.175, -0.300, -0.015}, 0.048), 0.04);
  // The upper chest and back below the collarbones.
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.345, -0.010}, {0.165, 0.075, 0.105}), 0.04);
  d = smoothUnion(d, capsule(p, {0.015, -0.255, 0.052}, {0.120, -0.272, 0.035}, 0.010), 0.02);
  return d;
}

double mannequinDistance(const glm::dvec3& p) {
  return std::min(mannequinHeadDistance(p), mannequinTorsoDistance(p));
}

const DistanceGrid& mannequinGrid() {
  // Kept on disk between runs of the same program (sim/head/field_cache.h): 1.9 s of a core.
  static const DistanceGrid grid = cachedSampleDistance(
      "mannequin", mannequinDistance, {-0.235, -0.440, -0.135}, {0.235, 0.115, 0.135}, 0.004);
  return grid;
}

const DistanceGrid& mannequinHeadGrid() {
  static const DistanceGrid grid =
      cachedSampleDistance("mannequin-head", mannequinHeadDistance, {-0.105, -0.285, -0.130},
                           {0.105, 0.115, 0.135}, 0.004);
  return grid;
}

const DistanceGrid& mannequinTorsoGrid() {
  // Up past the lower neck's top (y = -0.058), so that its zero level closes inside the box.
  static const DistanceGrid grid =
      cachedSampleDistance("mannequin-torso", mannequinTorsoDistance, {-0.235, -0.440, -0.135},
                           {0.235, -0.040, 0.110}, 0.004);
  return grid;
}

const SurfaceMesh& mannequinMesh() {
  // The collision grid decides the topology; the vertices lie on the function's zero level
  // and take its gradient, which draws the eyelids, nostrils and lips as a finer grid's mesh
  // would (2.75 mm was compared) at half its triangles, which a software rasterizer pays for.
  static const SurfaceMesh mesh = meshZeroLevel(mannequinGrid(), mannequinDistance);
  return mesh;
}

const SurfaceMesh& mannequinHeadMesh() {
  // Drawn from a grid of its own, finer than the collision's: the lids, the lash lines and the
  // lips are a few millimetres, which a 4 mm grid's topology breaks into holes.
  static const DistanceGrid drawn =
      cachedSampleDistance("mannequin-head-drawn", mannequinHeadDistance, {-0.105, -0.285, -0.130},
                           {0.105, 0.115, 0.135}, 0.002);
  static const SurfaceMesh mesh = [] {
    SurfaceMesh m = meshZeroLevel(drawn, mannequinHeadDistance);
    relaxFolds(m, mannequinHeadDistance);
    return m;
  }();
  return mesh;
}

const SurfaceMesh& mannequinTorsoMesh() {
  static const SurfaceMesh mesh = [] {
    SurfaceMesh m = meshZeroLevel(mannequinTorsoGrid(), mannequinTorsoDistance);
    relaxFolds(m, mannequinTorsoDistance);
    return m;
  }();
  return mesh;
}

}  // namespace csm
