#include "sim/groom/hairstyle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/constants.hpp>

#include "sim/base/random.h"
#include "sim/core/segment_pairs.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/groom/growth_head.h"
#include "sim/groom/resample.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {
namespace {

// Landmarks of the head frame the groom is laid out by (METHOD.md section 9: y up, the face
// towards +z): the crown's depth, a side parting's offset from the middle, the brow's height.
// (The brow's is the head's own: ScalpMarks.)
constexpr double kCrownZ = -0.02, kSideParting = 0.035;

// Roots follow the R2 low-discrepancy sequence (Roberts 2018) over the scalp cap: evenly spread
// for any prefix, so 10,000 strands are the first 10,000 of 20,000 and still cover the scalp.
struct RootSampler {
  const HairstyleConfig& h;
  const ScalpMarks* marks;
  uint64_t index = 0;
  double offsetU, offsetV;

  RootSampler(const HairstyleConfig& cfg, const ScalpMarks* scalp)
      : h(cfg),
        marks(scalp),
        offsetU(random01(cfg.seed, ~0ull, 1)),
        offsetV(random01(cfg.seed, ~0ull, 2)) {}

  glm::dvec3 next() {
    const double g = 1.32471795724474602596;  // the plastic number
    const double maxTheta = glm::radians(double(h.scalpAngle));
    for (;;) {
      ++index;
      const double u = std::fmod(offsetU + index / g, 1.0);
      const double v = std::fmod(offsetV + index / (g * g), 1.0);
      const double cosTheta = 1.0 - u * (1.0 - std::cos(maxTheta));  // uniform over the cap
      const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
      const double phi = 2.0 * glm::pi<double>() * v;
      glm::dvec3 d(sinTheta * std::sin(phi), cosTheta, sinTheta * std::cos(phi));
      if (onScalp(h, d, marks)) return d;
    }
  }
};

// The direction hair lies in at p (head frame) before it hangs free: down, away from the
// parting (or from the crown's axis) on top of the head, and back from the face; a fringe
// forward over the forehead.
glm::dvec3 combDirection(const HairstyleConfig& h, const glm::dvec3& p, bool fringe) {
  const glm::dvec3 down(0.0, -1.0, 0.0);
  if (fringe) return glm::normalize(down + glm::dvec3(p.x / 0.1, 0.0, 0.3));
  const glm::dvec3 radial(p.x, 0.0, p.z - kCrownZ);
  glm::dvec3 away = glm::length(radial) > 1e-9 ? glm::normalize(radial) : glm::dvec3(0, 0, -1);
  if (h.parting != Parting::None) {
    const double line = h.parting == Parting::Left    ? kSideParting
                        : h.parting == Parting::Right ? -kSideParting
                                                      : 0.0;
    const glm::dvec3 side(p.x >= line ? 1.0 : -1.0, 0.0, 0.0);
    // The parting runs from the forehead back to the crown; behind it hair falls from the crown.
    away = glm::normalize(glm::mix(away, side, glm::smoothstep(kCrownZ - 0.04, kCrownZ, p.z)));
  }
  const double top = std::clamp((p.y + 0.02) / 0.08, 0.0, 1.0);
  const double front = std::clamp(p.z / 0.06, 0.0, 1.0);
  return glm::normalize(down + 2.0 * top * away + h.sweep * front * glm::dvec3(0.0, 0.3, -5.0));
}

// Strands from the front patch of the scalp make the fringe, when the style has one.
bool inFringe(const HairstyleConfig& h, const glm::dvec3& dir) {
  return h.fringe && dir.z > 0.4 && std::abs(dir.x) < 0.6 * dir.z;
}

std::vector<glm::dvec3> growStrand(const HairstyleConfig& h, const GrowthHead& head, double margin,
                                   uint64_t s, const glm::dvec3& dir) {
  const glm::dvec3 root = head.root(dir);
  const bool fringe = inFringe(h, dir);
  // A fringe hanging straight from its root ends at the brow.
  const double length =
      fringe ? std::max(0.02, root.y - head.browY())
             : glm::mix(double(h.lengthMin), double(h.lengthMax), random01(h.seed, s, 3));
  // Hair from higher roots lies further out, over the hair from lower roots: layers by root
  // height, so that strands draped over the head pass over each other instead of through.
  // Toward the face hair lies close (standing off the forehead, it would fall over the face).
  const double layer = margin + double(h.volume) * std::clamp((root.y + 0.03) / 0.13, 0.0, 1.0) *
                                    (1.0 - std::clamp(2.0 * dir.z, 0.0, 1.0));

  // Centreline: leaves along the scalp normal, turns at a rate set by `fall` toward the comb
  // direction (which hangs down once off the top of the head), drapes over the head where it
  // meets it.
  const double ds = std::min(0.002, length / 64.0);
  const int steps = std::max(2, int(std::ceil(length / ds)));
  const double turn = 4.0 + 60.0 * h.fall * h.fall;  // 1/m
  const glm::dvec3 down(0.0, -1.0, 0.0);
  // A little per-strand disorder so the hair does not look combed by a machine.
  const glm::dvec3 jitter(random01(h.seed, s, 4) - 0.5, 0.0, random01(h.seed, s, 5) - 0.5);
  // The comb lies along the head: its part away from the surface is dropped, so hair on the
  // sides lies on them instead of standing out.
  auto combAt = [&](const glm::dvec3& at) {
    glm::dvec3 comb = combDirection(h, at, fringe) + 0.3 * jitter;
    const glm::dvec3 n = head.normal(at);
    comb -= std::max(0.0, glm::dot(comb, n)) * n;
    return glm::normalize(comb + 1e-9 * down);
  };
  // The root leaves between the normal and the comb: a strand that left along the normal could
  // swing about it freely (its pinned first segment holds no twist) and fall over the face.
  const glm::dvec3 leave =
      glm::normalize(glm::mix(head.normal(root), combAt(root), double(h.fall)));
  std::vector<glm::dvec3> centre{root};
  glm::dvec3 p = root, t = leave;
  for (int i = 1; i <= steps; ++i) {
    const double along = i * ds;
    const double blend = 1.0 - std::exp(-turn * along);
    glm::dvec3 want = glm::normalize(glm::mix(leave, combAt(p), blend));
    if (!fringe) want = head.steer(p, want);
    t = glm::normalize(glm::mix(t, want, 0.5));
    glm::dvec3 next = p + t * (length / steps);
    glm::dvec3 before = next;
    if (i > 1 && head.pushOut(next, layer)) {
      // Follow the surface: keep the tangential part of the direction.
      glm::dvec3 n = glm::normalize(next - before + 1e-12 * t);
      t = glm::normalize(t - glm::dot(t, n) * n + 1e-9 * down);
      next = p + t * (length / steps);
      head.pushOut(next, layer);
    }
    // On top of the head hair lies on it: a strand above its layer is drawn back down to it,
    // so hair from the crown does not stand off as a dome (down the sides it drapes).
    glm::dvec3 n;
    const double above = head.distance(next, n) - layer;
    if (i > 1 && above > 0.0 && n.y > 0.5) {
      next -= n * std::min(above, 0.25 * length / steps);
      t = glm::normalize(next - p);
    }
    p = next;
    centre.push_back(p);
  }

  // Curl: a helix about the centreline whose radius ramps up from curl_start toward the tip,
  // in a frame carried along the curve by parallel transport.
  if (h.curlRadius <= 0.0f) return centre;
  const double phase = 2.0 * glm::pi<double>() * random01(h.seed, s, 6);
  const double start = h.curlStart * length;
  const double ramp = std::max(1e-6, std::min(2.0 * h.curlPitch, length - start));
  glm::dvec3 tangent = glm::normalize(centre[1] - centre[0]);
  glm::dvec3 normal = glm::normalize(glm::cross(tangent, glm::dvec3(0.31, 0.87, 0.38)));
  std::vector<glm::dvec3> curled{centre[0]};
  double along = 0.0;
  for (size_t i = 1; i < centre.size(); ++i) {
    glm::dvec3 tNew = glm::normalize(centre[i] - centre[i - 1]);
    along += glm::length(centre[i] - centre[i - 1]);
    glm::dvec3 axis = glm::cross(tangent, tNew);
    double sinA = glm::length(axis);
    if (sinA > 1e-12) {
      axis /= sinA;
      double angle = std::atan2(sinA, glm::dot(tangent, tNew));
      normal = normal * std::cos(angle) + glm::cross(axis, normal) * std::sin(angle) +
               axis * glm::dot(axis, normal) * (1.0 - std::cos(angle));
    }
    tangent = tNew;
    normal = glm::normalize(normal - glm::dot(normal, tangent) * tangent);
    const glm::dvec3 binormal = glm::cross(tangent, normal);
    const double x = std::clamp((along - start) / ramp, 0.0, 1.0);
    const double radius = h.curlRadius * x * x * (3.0 - 2.0 * x);
    const double a = phase + 2.0 * glm::pi<double>() * along / h.curlPitch;
    glm::dvec3 q = centre[i] + radius * (std::cos(a) * normal + std::sin(a) * binormal);
    head.pushOut(q, margin);
    curled.push_back(q);
  }
  return curled;
}

// Separation (hairstyle.separate_passes): grown strands lie through each other, more the
// denser the hair (Fig. 1: 1,814 pairs of segments closer than r at 1,000 strands, 7,319 at
// 2,000). Each pass finds the pairs closer than kSeparation r and pushes each apart to that
// distance, pair by pair in their sorted order (Gauss-Seidel: each pair sees where the pairs
// before it left the particles; the same groom every time), kSweeps times; then each strand,
// root to tip, takes back its grown segment lengths, leaves the head, and keeps no particle
// further than the limit from where it grew. A strand's root stays; its second particle may
// move (the solver holds the first segment as the separated groom has it): held in place, the
// roots of strands that others lie across stood through them
// (docs/BENCHMARKS_HISTORY.md, "Strands pushed apart at rest").
constexpr double kSeparation = 2.2;
constexpr int kSweeps = 3;
// As in the contact solve (sim/solver/contacts.cpp, kLever): near a root, a pair asks the free end
// for its depth over the lever arm; no end moves further than this many times the pair's depth.
constexpr double kSeparationLever = CSM_CONTACT_LEVER;

void pushApart(std::vector<glm::dvec3>& x, const std::vector<double>& w, uint32_t a, uint32_t b,
               double target) {
  double s, t;
  const double d = std::sqrt(closestSegmentPoints(x[a], x[a + 1], x[b], x[b + 1], s, t));
  if (d >= target) return;
  const double ga0 = w[a] * (1 - s), ga1 = w[a + 1] * s, gb0 = w[b] * (1 - t), gb1 = w[b + 1] * t;
  const double W = ga0 * (1 - s) + ga1 * s + gb0 * (1 - t) + gb1 * t;
  if (W < 1e-12) return;  // both ends held, or the contact at a held root
  const glm::dvec3 n = separationDirection(x[a], x[a + 1], x[b], x[b + 1], s, t, d);
  const double depth = target - d;
  const double most = std::max({ga0, ga1, gb0, gb1}) / W;  // the furthest end's move a depth
  const double lambda = depth / W * std::min(1.0, kSeparationLever / most);
  x[a] += lambda * ga0 * n;
  x[a + 1] += lambda * ga1 * n;
  x[b] -= lambda * gb0 * n;
  x[b + 1] -= lambda * gb1 * n;
}

void separateStrands(Groom& g, const GrowthHead& head, double radius, int passes, double limit) {
  if (limit <= 0.0) return;
  const double target = kSeparation * radius, margin = 2.0 * radius;
  const size_t n = g.pointCount();
  std::vector<glm::dvec3> x(n);
  std::vector<uint32_t> strandOf(n);
  std::vector<double> w(n, 1.0), length(n, 0.0);
  for (size_t s = 0; s < g.strandCount(); ++s) {
    w[g.first[s]] = 0.0;
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i) {
      x[i] = glm::dvec3(g.points[i]);
      strandOf[i] = uint32_t(s);
      if (i > g.first[s]) length[i - 1] = glm::length(x[i] - x[i - 1]);
    }
  }
  const std::vector<glm::dvec3> grown = x;
  for (int pass = 0; pass < passes; ++pass) {
    const std::vector<SegmentPair> pairs = findContactsGrid(x, strandOf, target);
    if (pairs.empty()) break;
    for (int sweep = 0; sweep < kSweeps; ++sweep)
      for (const SegmentPair& p : pairs) pushApart(x, w, p.a, p.b, target);
    for (size_t s = 0; s < g.strandCount(); ++s)
      for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i) {
        const glm::dvec3 d = x[i] - x[i - 1];
        const double len = glm::length(d);
        if (len > 1e-12) x[i] = x[i - 1] + d * (length[i - 1] / len);
        head.pushOut(x[i], margin);
        // Last, so that it holds: the lengths give way by what it takes back.
        const glm::dvec3 moved = x[i] - grown[i];
        const double far = glm::length(moved);
        if (far > limit) x[i] = grown[i] + moved * (limit / far);
      }
  }
  for (size_t i = 0; i < n; ++i) g.points[i] = glm::vec3(x[i]);
}

}  // namespace

Groom growHairstyle(const Config& c, const HeadModel& head) {
  return growHairstyle(c.hairstyle, head.spheres(), c.collision.radius, head.field(),
                       &head.scalpMarks());
}

bool onScalp(const HairstyleConfig& h, const glm::dvec3& d, const ScalpMarks* marks) {
  const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
  const double horizontal = std::hypot(d.x, d.z);
  const double front = horizontal > 1e-9 ? std::max(0.0, d.z / horizontal) : 0.0;
  // The hairline comes lower at the back and sides than at the forehead (+z is the face).
  // On a head of its own the forehead's line moves with that head's brow.
  const double hairline = double(h.hairlineFront) + (marks ? marks->hairlineShift : 0.0);
  const double limit = glm::radians(glm::mix(
      double(h.scalpAngle), std::min(double(h.scalpAngle), hairline), std::pow(front, 1.5)));
  if (theta > limit) return false;
  if (!marks) return true;
  // Above and behind the ears: no roots within 30 degrees of either ear's direction, so the
  // hairline runs over them and the hair can fall behind them.
  const glm::dvec3 ear = glm::normalize(marks->ear);
  return glm::dot(glm::dvec3(std::abs(d.x), d.y, d.z), ear) < std::cos(glm::radians(30.0));
}

int particlesForLength(const HairstyleConfig& h, double arcLength) {
  if (h.particlesPerStrand > 0) return h.particlesPerStrand;
  const int n = int(std::lround(arcLength / h.segmentLength)) + 1;
  return std::clamp(n, h.minParticles, h.maxParticles);
}

Groom growHairstyle(const HairstyleConfig& h, const std::vector<Sphere>& spheres,
                    float collisionRadius, const DistanceGrid* field, const ScalpMarks* marks) {
  Groom g;
  if ((spheres.empty() && !field) || h.strands <= 0) return g;
  const double margin = 2.0 * collisionRadius;
  static const ScalpMarks mannequin = mannequinScalpMarks();
  const ScalpMarks* scalp = field ? (marks ? marks : &mannequin) : nullptr;
  const GrowthHead head{spheres, field, scalp};
  RootSampler roots(h, scalp);
  std::vector<glm::vec3> strand;
  for (int s = 0; s < h.strands; ++s) {
    const glm::dvec3 dir = roots.next();
    std::vector<glm::dvec3> dense = growStrand(h, head, margin, uint64_t(s), dir);
    double arc = 0.0;
    for (size_t i = 1; i < dense.size(); ++i) arc += glm::length(dense[i] - dense[i - 1]);
    std::vector<glm::dvec3> pts = io::resamplePolyline(dense, particlesForLength(h, arc));
    strand.clear();
    for (size_t i = 0; i < pts.size(); ++i) {
      if (i > 0) head.pushOut(pts[i], margin);
      strand.emplace_back(pts[i]);
    }
    g.addStrand(strand);
  }
  if (h.separatePasses > 0)
    separateStrands(g, head, collisionRadius, h.separatePasses, h.separateLimit);
  return g;
}

}  // namespace csm
