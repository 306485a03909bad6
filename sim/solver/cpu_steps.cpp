// The CPU twins of the GLSL step functions (sim/solver/cpu_steps.h says which is whose).
#include "sim/solver/cpu_steps.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/solver/contacts.h"
#include "sim/solver/wind.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {
namespace {

Eigen::Vector3d toEigen(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
glm::dvec3 toGlm(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

Eigen::Quaterniond toEigen(const glm::dquat& q) {
  return {q.w, q.x, q.y, q.z};
}

// The same for the body's distance field (sim/head/distance_grid.h), each part read in its own
// frame: p moves along the field's normal out of the surface inflated by `radius` (the nearer
// part's at each read, so a point pushed out of one part and into the other goes on out of
// both), and when that is out of reach of prev, onto the nearest point of the circle where the
// surface's tangent plane there meets the ball of reach. `normal` gets the outward normal
// (world); `clearance` the field's distance where p is left, where the push read it (p
// untouched, or the projection), else NaN (the circle's point).
bool pushOutOfBodyField(const HeadCollider& h, glm::dvec3& p, const glm::dvec3& prev,
                        double maxLength, glm::dvec3& normal, double& clearance) {
  glm::dvec3 grad;
  double d = bodySample(h, p, &grad);
  clearance = d;
  if (!(d < h.radius)) return false;  // outside, or not finite
  // The field is close to a distance, not exactly one (smooth unions, interpolation): a second
  // step takes what the first left.
  const glm::dvec3 up = h.head.rotation * glm::dvec3(0.0, 1.0, 0.0);
  glm::dvec3 target = p, n = up;
  // With a torso, up to eight: a step out of one part may end in the other, in the crease where
  // they meet, and the steps then go back and forth between the two, closing in.
  const int steps = h.torsoField ? 8 : 2;
  for (int step = 0; step < steps && d < h.radius; ++step) {
    const double len = glm::length(grad);
    n = len > 1e-12 ? grad / len : up;
    target += (h.radius - d) * n;
    d = bodySample(h, target, &grad);
  }
  clearance = d;
  normal = n;
  p = target;
  if (maxLength <= 0.0 || glm::length(target - prev) <= maxLength) return true;
  const double above = glm::dot(prev - target, normal);
  if (std::abs(above) >= maxLength) return true;  // no circle: keep the projection
  const glm::dvec3 centre = prev - above * normal;
  const glm::dvec3 side = target - centre;
  const double sideLen = glm::length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (std::sqrt(maxLength * maxLength - above * above) / sideLen);
  clearance = NAN;
  return true;
}

// A part's field read at world point q: its distance and gradient (world).
double partSample(const DistanceGrid& g, const Pose& pose, const glm::dvec3& q,
                  glm::dvec3* gradient) {
  const glm::dquat back = glm::inverse(pose.rotation);
  glm::dvec3 local;
  const double d = g.sample(back * (q - pose.translation), gradient ? &local : nullptr);
  if (gradient) *gradient = pose.rotation * local;
  return d;
}

}  // namespace

void extractRotation(const Eigen::Matrix3d& A, double J, Eigen::Quaterniond& q, int iterations,
                     const Eigen::Vector3d& axis, double twistStep) {
  if (!(J > 0.0)) return;
  // A rotation made non-finite by a non-finite step would stay so for good through the warm
  // start: start again from no rotation, and leave q as it is when A is not finite.
  if (!q.coeffs().allFinite()) q = Eigen::Quaterniond::Identity();
  const double axisLength = axis.norm();
  const bool twist = twistStep < 1.0 && axisLength > 0.0;
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Matrix3d R = q.matrix();
    // The torque that turns R's columns toward A's, over the rest moment: a Newton step near
    // convergence, where sum r.a = J.
    const Eigen::Vector3d torque =
        R.col(0).cross(A.col(0)) + R.col(1).cross(A.col(1)) + R.col(2).cross(A.col(2));
    Eigen::Vector3d omega = torque / J;
    if (twist) {
      const Eigen::Vector3d e = R * (axis / axisLength);
      omega -= (1.0 - twistStep) * omega.dot(e) * e;
    }
    const double angle = omega.norm();
    if (!(angle >= 1e-12) || !std::isfinite(angle)) break;
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
}

// Pushes p out of one sphere onto its surface. With a strain limit, the push keeps the
// segment from `prev` no longer than maxLength: when the radial projection is out of reach,
// take the nearest point of the circle where the sphere meets the ball of reach around prev.
// (Moving along the chord toward prev instead would jump: a chord between two points on the
// sphere always cuts through it.)
bool pushOutOfSphere(glm::dvec3& p, const glm::dvec3& prev, const glm::dvec3& c, double radius,
                     double maxLength) {
  const glm::dvec3 d = p - c;
  const double len2 = glm::dot(d, d);
  if (len2 >= radius * radius) return false;
  const double len = std::sqrt(len2);
  const glm::dvec3 target = c + (len > 1e-15 ? d / len : glm::dvec3(0, 1, 0)) * radius;
  p = target;
  if (maxLength <= 0.0 || glm::length(target - prev) <= maxLength) return true;
  const glm::dvec3 toPrev = prev - c;
  const double dist = glm::length(toPrev);
  // No circle when prev is inside the sphere, or out of reach of it; keep the projection.
  if (dist < 1e-15 || dist + maxLength < radius || dist - radius > maxLength) return true;
  const glm::dvec3 u = toPrev / dist;
  const double a = (radius * radius - maxLength * maxLength + dist * dist) / (2.0 * dist);
  const double rho = std::sqrt(std::max(0.0, radius * radius - a * a));
  const glm::dvec3 centre = c + a * u;
  glm::dvec3 side = target - centre;
  side -= glm::dot(side, u) * u;
  const double sideLen = glm::length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (rho / sideLen);
  return true;
}

double bodySample(const HeadCollider& h, const glm::dvec3& q, glm::dvec3* gradient, int* part) {
  double d = partSample(*h.field, h.head, q, gradient);
  if (part) *part = 0;
  if (!h.torsoField) return d;
  glm::dvec3 g;
  const double t = partSample(*h.torsoField, *h.torso, q, gradient ? &g : nullptr);
  if (!(t < d)) return d;
  if (gradient) *gradient = g;
  if (part) *part = 1;
  return t;
}

int partAt(const HeadCollider& h, const glm::dvec3& q) {
  int part = 0;
  if (h.field) {
    bodySample(h, q, nullptr, &part);
    return part;
  }
  double best = INFINITY;
  for (size_t k = 0; k < h.spheres.size(); ++k) {
    const double d = glm::length(q - glm::dvec3(h.spheres[k].center)) - h.spheres[k].radius;
    if (d < best) best = d, part = k < h.headSpheres ? 0 : 1;
  }
  return part;
}

double outsideHead(const HeadCollider& h, const glm::dvec3& q) {
  if (h.field) return bodySample(h, q);
  double d = INFINITY;
  for (const Sphere& sp : h.spheres)
    d = std::min(d, glm::length(q - glm::dvec3(sp.center)) - double(sp.radius));
  return d;
}

bool pushHead(const HeadCollider& h, glm::dvec3& p, const glm::dvec3& prev, double maxLength,
              glm::dvec3& normal, double& clearance) {
  clearance = NAN;
  if (h.field) return pushOutOfBodyField(h, p, prev, maxLength, normal, clearance);
  // Overlapping spheres can push a particle into each other: repeat until it is clear.
  bool touching = false;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (const Sphere& sp : h.spheres)
      moved |= pushOutOfSphere(p, prev, glm::dvec3(sp.center), sp.radius + h.radius, maxLength);
    touching |= moved;
    if (!moved) break;
  }
  return touching;
}

bool pushOutOfHead(const HeadCollider& h, glm::dvec3& p, const glm::dvec3& prev, double maxLength,
                   glm::dvec3& normal) {
  double clearance;
  if (!pushHead(h, p, prev, maxLength, normal, clearance)) return false;
  if (maxLength <= 0.0) return true;
  double level = NAN;  // min(0, how far prev lies outside), read once when needed
  for (int pass = 0;; ++pass) {
    const double length = glm::length(p - prev);
    const bool reach = length <= maxLength * (1.0 + CSM_REACH_SLACK_DOUBLE);
    // The push's own last read where it has one (the field's projection): no second read.
    const double depth = std::isnan(clearance) ? outsideHead(h, p) : clearance;
    if (reach && depth >= 0.0) return true;
    if (std::isnan(level)) level = std::min(0.0, outsideHead(h, prev));
    if (reach && depth >= level) return true;
    if (!reach) p = prev + (p - prev) * (maxLength / length);
    if (pass == 2) break;
    pushHead(h, p, prev, maxLength, normal, clearance);
  }
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 20; ++k) {
    const double mid = 0.5 * (lo + hi);
    (outsideHead(h, prev + mid * (p - prev)) >= level ? lo : hi) = mid;
  }
  p = prev + lo * (p - prev);
  if (h.field) {
    glm::dvec3 grad;
    bodySample(h, p, &grad);
    const double len = glm::length(grad);
    if (len > 1e-12) normal = grad / len;
  }
  return true;
}

void predictParticle(StepHair& hair, const StepForces& forces, uint32_t i, uint32_t b, bool held,
                     const Pose& head, double h) {
  hair.xOld[i] = hair.x[i];
  if (held) {
    // Kinematic roots (and held tips) follow the head.
    hair.xPred[i] = head.apply(hair.rest[i]);
    return;
  }
  glm::dvec3 acc = forces.gravity;
  if (forces.wind) {
    // Drag acts on the wind across the strand, not along it; implicit in the velocity, so it
    // neither overshoots nor depends on the step: c / (1 + h c) instead of c.
    const glm::dvec3 d = hair.x[std::min(i + 1, b - 1)] - hair.x[i - 1];
    const double len = glm::length(d);
    const glm::dvec3 t = len > 1e-12 ? d / len : glm::dvec3(0.0);
    const glm::dvec3 rel = windVelocity(*forces.wind, hair.x[i], forces.time) - hair.v[i];
    const double c = forces.wind->drag;
    acc += c / (1.0 + h * c) * (rel - glm::dot(rel, t) * t);
  }
  if (forces.volume)
    hair.v[i] += forces.volume->velocityChange(hair.x[i], hair.v[i], h, forces.volumeSettings);
  hair.v[i] += h * acc;
  hair.xPred[i] = hair.x[i] + h * hair.v[i];
}

void ShapeMatchSums::prepare(const StepHair& hair) {
  const size_t n = hair.rest.size(), m = n + hair.first.size() - 1;
  mass.assign(m, 0.0);
  massRest.assign(m, Eigen::Vector3d::Zero());
  massX.assign(m, Eigen::Vector3d::Zero());
  A.assign(m, Eigen::Matrix3d::Zero());
  R.assign(m, Eigen::Matrix3d::Zero());
  T.assign(m, Eigen::Vector3d::Zero());
  c.assign(n, Eigen::Vector3d::Zero());
  cRest.assign(n, Eigen::Vector3d::Zero());
  // Static prefix sums: per-region masses and mass-weighted rest positions (root-relative).
  for (size_t s = 0; s + 1 < hair.first.size(); ++s) {
    const uint32_t a = hair.first[s], b = hair.first[s + 1];
    const size_t pb = a + s;
    for (uint32_t i = a; i < b; ++i) {
      const size_t j = pb + (i - a);
      const double w = hair.regions.mass[i];
      mass[j + 1] = mass[j] + w;
      massRest[j + 1] = massRest[j] + w * toEigen(hair.rest[i] - hair.rest[a]);
    }
  }
}

void shapeMatchStrand(StepHair& hair, ShapeMatchSums& sums, std::vector<Eigen::Quaterniond>& q,
                      const SimConfig& sim, const ShapeMatchSettings& settings, size_t s,
                      const Pose& head, double h) {
  const std::vector<int>& lo = hair.regions.lo;
  const std::vector<int>& hi = hair.regions.hi;
  const Eigen::Matrix3d headRotation = toEigen(head.rotation).toRotationMatrix();
  const uint32_t a = hair.first[s], b = hair.first[s + 1];
  const int n = int(b - a);
  const size_t pb = a + s;
  // Ghosts behind the root (sim/solver/stiffness.h): -j d at rest, -j D now, root-relative.
  const double mg = hair.regions.ghostMass[s];
  const Eigen::Vector3d d =
      n > 1 ? toEigen(hair.rest[a + 1] - hair.rest[a]) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d D = headRotation * d;
  // Root-relative coordinates keep the prefix sums' differences exact enough in float on the
  // GPU; the CPU uses the same formulation so the two compare term by term.
  const glm::dvec3 origin = hair.xPred[a];
  // The built-in end (ClampField, sim/solver/stiffness.h): behind the clamp the regions see
  // the free strand's displacement continued, not the rest shape.
  const int pinned = hair.regions.pinned[s];
  const std::vector<glm::dvec2>& fit = hair.regions.clampFit;
  ClampField field;
  for (int j = pinned; j < hair.regions.fitEnd[s]; ++j)
    field.a += fit[a + j].x * (hair.xPred[a + j] - head.apply(hair.rest[a + j]));
  if (n > 1) field.reflect(toGlm(D));
  const glm::dvec3 pull = field.across(toGlm(D));
  auto behind = [&](int j) { return j < pinned ? field.at(fit[a + j].y) : glm::dvec3(0.0); };
  const double tau0 = fit[a].y, ghostTau = n > 1 ? fit[a + 1].y - tau0 : 0.0;
  auto ghostShift = [&](int g) { return toEigen(field.at(tau0 - g * ghostTau)); };
  // Each particle's coordinates in the sums, root-relative.
  auto yOf = [&](int j) { return toEigen(hair.xPred[a + j] + behind(j) - origin); };
  auto yrOf = [&](int j) { return toEigen(hair.rest[a + j] - hair.rest[a]); };
  for (int j = 0; j < n; ++j) {
    const double m = hair.regions.mass[a + j];
    const Eigen::Vector3d y = yOf(j);
    const Eigen::Vector3d yr = yrOf(j);
    sums.massX[pb + j + 1] = sums.massX[pb + j] + m * y;
    sums.A[pb + j + 1] = sums.A[pb + j] + m * y * yr.transpose();
  }
  for (int k = 0; k < n; ++k) {
    const int ghosts = std::max(0, -lo[a + k]);
    const int l0 = std::max(0, lo[a + k]), l1 = hi[a + k];
    double M;
    Eigen::Vector3d sumX, sumRest;
    Eigen::Matrix3d sumA;
    if (settings.prefixSums) {
      M = sums.mass[pb + l1 + 1] - sums.mass[pb + l0];
      sumX = sums.massX[pb + l1 + 1] - sums.massX[pb + l0];
      sumRest = sums.massRest[pb + l1 + 1] - sums.massRest[pb + l0];
      sumA = sums.A[pb + l1 + 1] - sums.A[pb + l0];
      if (ghosts > 0) {
        const double s1 = mg * ghostSum1(ghosts), s2 = mg * ghostSum2(ghosts);
        M += mg * ghosts;
        sumX -= s1 * D;
        sumRest -= s1 * d;
        sumA += s2 * D * d.transpose();
        for (int g = 1; g <= ghosts; ++g) {
          const Eigen::Vector3d shift = ghostShift(g);
          sumX += mg * shift;
          sumA -= (mg * g) * shift * d.transpose();
        }
      }
    } else {
      M = 0.0;
      sumX.setZero();
      sumRest.setZero();
      sumA.setZero();
      for (int j = -ghosts; j <= l1; ++j) {
        const double m = j < 0 ? mg : hair.regions.mass[a + j];
        const Eigen::Vector3d y = j < 0 ? Eigen::Vector3d(j * D + ghostShift(-j)) : yOf(j);
        const Eigen::Vector3d yr = j < 0 ? Eigen::Vector3d(j * d) : yrOf(j);
        if (j >= 0 && j < l0) continue;
        M += m;
        sumX += m * y;
        sumRest += m * yr;
        sumA += m * y * yr.transpose();
      }
    }
    const Eigen::Vector3d c = sumX / M, cRest = sumRest / M;
    const Eigen::Matrix3d A = sumA - M * c * cRest.transpose();
    // The twist axis: the region's rest chord (ghosts continue the root segment).
    const int first = lo[a + k];
    const Eigen::Vector3d chord =
        yrOf(hi[a + k]) - (first >= 0 ? yrOf(first) : Eigen::Vector3d(first * d));
    extractRotation(A, hair.regions.inertia[a + k], q[a + k], settings.iterations, chord,
                    settings.twistStep);
    const Eigen::Matrix3d R = q[a + k].matrix();
    sums.c[a + k] = c;
    sums.cRest[a + k] = cRest;
    sums.R[pb + k + 1] = sums.R[pb + k] + R;
    sums.T[pb + k + 1] = sums.T[pb + k] + (c - R * cRest);
  }
  // Goals (paper eq. 1) averaged over the regions that contain each particle, which are the
  // regions lo[i]..hi[i] (regions are symmetric):
  // g_i = ((sum R_k) xr_i + sum (c_k - R_k cr_k)) / |K_i|, both sums prefix differences.
  for (int i = 0; i < n; ++i) {
    const int l0 = std::max(0, lo[a + i]), l1 = hi[a + i];
    const Eigen::Vector3d yr = toEigen(hair.rest[a + i] - hair.rest[a]);
    Eigen::Matrix3d sumR;
    Eigen::Vector3d sumT;
    if (settings.prefixSums) {
      sumR = sums.R[pb + l1 + 1] - sums.R[pb + l0];
      sumT = sums.T[pb + l1 + 1] - sums.T[pb + l0];
    } else {
      sumR.setZero();
      sumT.setZero();
      for (int k = l0; k <= l1; ++k) {
        const Eigen::Matrix3d R = q[a + k].matrix();
        sumR += R;
        sumT += sums.c[a + k] - R * sums.cRest[a + k];
      }
    }
    hair.goal[a + i] = origin + toGlm((sumR * yr + sumT) / double(l1 - l0 + 1)) +
                       hair.regions.clampPull[a + i] * pull;
  }
  // Integration (paper eq. 2-3): toward the goals by alpha, the velocity from the positions.
  const double alpha = stepAlpha(sim, hair.regions.rate[s], h);
  for (uint32_t i = a; i < b; ++i) {
    const bool pinned = hair.regions.held(s, int(i - a), int(b - a));
    hair.x[i] = pinned ? hair.xPred[i] : hair.xPred[i] + alpha * (hair.goal[i] - hair.xPred[i]);
    hair.v[i] = (hair.x[i] - hair.xOld[i]) / h;
    if (!pinned) hair.v[i] *= settings.keep;
  }
}

bool limitToward(glm::dvec3& x, glm::dvec3& v, const glm::dvec3& anchor, double restLength,
                 double strainLimit, double h) {
  const glm::dvec3 d = x - anchor;
  const double len = glm::length(d), most = (1.0 + strainLimit) * restLength;
  if (!(len > most)) return false;
  const glm::dvec3 to = anchor + d * (most / len);
  v += (to - x) / h;
  x = to;
  return true;
}

void sweepParticle(StepHair& hair, const HeadCollider& head, const SweepSettings& settings,
                   uint32_t i, bool contacts, const glm::dvec3& moved, bool parentFree, double h) {
  std::vector<glm::dvec3>& x = hair.x;
  std::vector<glm::dvec3>& v = hair.v;
  const double maxLength =
      settings.limit ? (1.0 + settings.strainLimit) * hair.restLength[i - 1] : 0.0;
  if (contacts) {
    // The strand contacts' correction (sim/solver/contacts.h), a change of velocity too.
    x[i] += moved;
    v[i] += moved / h;
  }
  const glm::dvec3 start = x[i];
  if (settings.limit) {
    const glm::dvec3 d = x[i] - x[i - 1];
    const double len = glm::length(d);
    if (len > maxLength) x[i] = x[i - 1] + d * (maxLength / len);
  }
  const glm::dvec3 strained = x[i];
  glm::dvec3 fieldNormal(0.0);
  // A non-finite particle stays so, for the NaN check to see: the pushes below would put it
  // on the head (their fallback normal) as if nothing had happened.
  const bool collide = settings.headCollide && std::isfinite(x[i].x + x[i].y + x[i].z);
  const bool touching = collide && pushOutOfHead(head, x[i], x[i - 1], maxLength, fieldNormal);
  const glm::dvec3 vBeforeHead = v[i] + (strained - start) / h;
  v[i] = vBeforeHead + (x[i] - strained) / h;
  if (touching) {
    // Coulomb friction against the moving head: the tangential speed relative to the
    // surface loses at most mu times the normal speed the contact took away this step,
    // so a resting strand feels mu g_n whatever the step.
    // The part it touches: where its surface point was at the step's start.
    const bool torso = head.torso && settings.torsoBefore && partAt(head, x[i]) == 1;
    const Pose& now = torso ? *head.torso : head.head;
    const Pose& was = torso ? *settings.torsoBefore : *settings.before;
    const glm::dvec3 local = glm::inverse(now.rotation) * (x[i] - now.translation);
    const glm::dvec3 surfaceVel = (x[i] - was.apply(local)) / h;
    glm::dvec3 n = fieldNormal;
    if (!head.field) {
      const Sphere* nearest = &head.spheres.front();
      double best = 1e300;
      for (const Sphere& sp : head.spheres) {
        double dist = glm::length(x[i] - glm::dvec3(sp.center)) - sp.radius;
        if (dist < best) best = dist, nearest = &sp;
      }
      n = glm::normalize(x[i] - glm::dvec3(nearest->center));
    }
    const double vnBefore = glm::dot(vBeforeHead - surfaceVel, n);
    const glm::dvec3 rel = v[i] - surfaceVel;
    const double vn = std::max(0.0, glm::dot(rel, n));
    const glm::dvec3 vt = rel - glm::dot(rel, n) * n;
    const double vtLen = glm::length(vt);
    const double taken = settings.friction * std::max(0.0, vn - vnBefore);
    const double keepT = vtLen > taken ? 1.0 - taken / vtLen : 0.0;
    v[i] = surfaceVel + vn * n + keepT * vt;
  }
  // Dynamic follow-the-leader (Mueller et al. 2012): the parent takes back part of the
  // velocity its child got from the strain-limit correction, against the heavy-tip look.
  if (settings.dftl > 0.0 && parentFree) v[i - 1] -= settings.dftl * (strained - start) / h;
}

glm::dvec3 intoBothBalls(const glm::dvec3& x, const glm::dvec3& a, double ra, const glm::dvec3& b,
                         double rb) {
  auto into = [&](const glm::dvec3& c, double r) {
    const double len = glm::length(x - c);
    return len > r ? c + (x - c) * (r / len) : x;
  };
  auto inside = [](const glm::dvec3& p, const glm::dvec3& c, double r) {
    return glm::length(p - c) <= r * (1.0 + 1e-12);
  };
  const glm::dvec3 pa = into(a, ra);
  if (inside(pa, b, rb)) return pa;
  const glm::dvec3 pb = into(b, rb);
  if (inside(pb, a, ra)) return pb;
  // Neither ball's nearest point is in the other: the nearest point of both is on the circle
  // where their spheres meet.
  const glm::dvec3 ab = b - a;
  const double d = glm::length(ab);
  if (!(d > 0.0) || d >= ra + rb) return a + ab * (ra / std::max(ra + rb, 1e-300));
  const glm::dvec3 u = ab / d;
  const double along = (d * d + ra * ra - rb * rb) / (2.0 * d);
  const double ring = std::sqrt(std::max(0.0, ra * ra - along * along));
  glm::dvec3 w = (x - a) - glm::dot(x - a, u) * u;
  if (glm::length(w) < 1e-300) w = std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  w -= glm::dot(w, u) * u;
  return a + along * u + ring * glm::normalize(w);
}

void limitStrainStrand(StepHair& hair, const std::vector<glm::dvec4>& correction,
                       const HeadCollider& head, const SweepSettings& settings, size_t s,
                       double h) {
  const uint32_t a = hair.first[s], b = hair.first[s + 1];
  const int pinned = hair.regions.pinned[s];
  // One sweep from root to tip: each segment is fixed against an already final parent, so
  // no iteration is needed (paper section 3.2). A held tip stays where the head put it.
  const uint32_t end = b - (hair.regions.tipHeld[s] != 0 ? 1u : 0u);
  const uint32_t first = a + std::max(1, pinned);
  const bool contacts = !correction.empty();
  for (uint32_t i = first; i < end; ++i) {
    const glm::dvec3 moved = contacts ? particleCorrection(correction, i, a, b) : glm::dvec3(0.0);
    sweepParticle(hair, head, settings, i, contacts, moved, int(i - 1 - a) >= pinned, h);
  }
  if (!settings.limit || end >= b) return;
  // Held at both ends: the sweep from the root left what stretch there is to the last free
  // segment, the one into the held tip. Sweeps back from the tip, then forth from the root,
  // each limiting a segment against its already final neighbour, share it out along the
  // strand; they stop once one moves nothing.
  std::vector<glm::dvec3>& x = hair.x;
  std::vector<glm::dvec3>& v = hair.v;
  const double limit = settings.strainLimit;
  for (int pass = 0; pass < CSM_TIED_SWEEPS; ++pass) {
    bool moved = false;
    for (uint32_t i = end; i-- > first;)
      moved = limitToward(x[i], v[i], x[i + 1], hair.restLength[i], limit, h) || moved;
    if (!moved) break;
    moved = false;
    for (uint32_t i = first; i < end; ++i)
      moved = limitToward(x[i], v[i], x[i - 1], hair.restLength[i - 1], limit, h) || moved;
    if (!moved) break;
  }
  // What the sweeps left: one more from the root, each particle within its segment's reach of
  // its final parent and within the rest of the strand's reach of the held tip. While the root
  // is within the whole strand's reach of the tip (the rest shape is the fitted one, so it is
  // while the head holds both), the two reaches meet, and the last segment ends at the tip
  // within the limit.
  double reach = 0.0;
  for (uint32_t i = first - 1; i < end; ++i) reach += (1.0 + limit) * hair.restLength[i];
  for (uint32_t i = first; i < end; ++i) {
    reach -= (1.0 + limit) * hair.restLength[i - 1];
    const glm::dvec3 to =
        intoBothBalls(x[i], x[i - 1], (1.0 + limit) * hair.restLength[i - 1], x[end], reach);
    v[i] += (to - x[i]) / h;
    x[i] = to;
  }
}

}  // namespace csm
