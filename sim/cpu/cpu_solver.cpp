#include "sim/cpu/cpu_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/parallel.h"
#include "sim/wind.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

Eigen::Vector3d toEigen(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
glm::dvec3 toGlm(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

Eigen::Quaterniond toEigen(const glm::dquat& q) {
  return {q.w, q.x, q.y, q.z};
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

}  // namespace

void extractRotation(const Eigen::Matrix3d& A, Eigen::Quaterniond& q, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Matrix3d R = q.matrix();
    // The torque that turns R's columns toward A's, scaled like a Newton step.
    const Eigen::Vector3d torque =
        R.col(0).cross(A.col(0)) + R.col(1).cross(A.col(1)) + R.col(2).cross(A.col(2));
    const double scale =
        std::abs(R.col(0).dot(A.col(0)) + R.col(1).dot(A.col(1)) + R.col(2).dot(A.col(2))) + 1e-9;
    const Eigen::Vector3d omega = torque / scale;
    const double angle = omega.norm();
    if (angle < 1e-9) break;
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
}

void CpuSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  time_ = 0.0;
  head_ = head;
  const HairState st = makeHairState(groom, config.sim, head);
  const size_t n = st.particleCount(), strands = st.strandCount();
  first_ = st.strandFirst;
  strandOf_ = st.particleStrand;
  rest_.resize(n);
  mass_.resize(n);
  x_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    rest_[i] = glm::dvec3(glm::vec3(st.rest[i]));
    mass_[i] = st.rest[i].w;
    x_[i] = head.apply(rest_[i]);
  }
  restLength_.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i)
    if (strandOf_[i] == strandOf_[i + 1]) restLength_[i] = glm::length(rest_[i + 1] - rest_[i]);
  v_.assign(n, glm::dvec3(0.0));
  xOld_ = x_;
  xPred_ = x_;
  goal_ = x_;
  contactForce_.assign(n, glm::dvec3(0.0));
  q_.assign(n, toEigen(head.rotation));
  contacts_ = {};
  stages_.clear();

  const size_t m = n + strands;
  prefMass_.assign(m, 0.0);
  prefMassRest_.assign(m, Eigen::Vector3d::Zero());
  prefMassX_.assign(m, Eigen::Vector3d::Zero());
  prefA_.assign(m, Eigen::Matrix3d::Zero());
  prefR_.assign(m, Eigen::Matrix3d::Zero());
  prefT_.assign(m, Eigen::Vector3d::Zero());
  regionC_.assign(n, Eigen::Vector3d::Zero());
  regionCRest_.assign(n, Eigen::Vector3d::Zero());
  // Static prefix sums: masses and mass-weighted rest positions (relative to the root).
  for (size_t s = 0; s < strands; ++s) {
    const uint32_t a = first_[s], b = first_[s + 1];
    const size_t pb = a + s;
    for (uint32_t i = a; i < b; ++i) {
      const size_t j = pb + (i - a);
      prefMass_[j + 1] = prefMass_[j] + mass_[i];
      prefMassRest_[j + 1] = prefMassRest_[j] + mass_[i] * toEigen(rest_[i] - rest_[a]);
    }
  }
}

void CpuSolver::clearStages() {
  stages_ = {
      {"integrate", 0.0}, {"shape_matching", 0.0}, {"strain_limiting", 0.0}, {"contacts", 0.0}};
}

void CpuSolver::stepFrame(const Pose& from, const Pose& to) {
  clearStages();
  const int substeps = std::max(1, config_.sim.substeps);
  const double h = double(config_.sim.dt) / substeps;
  for (int k = 0; k < substeps; ++k) step(h, interpolate(from, to, double(k + 1) / substeps));
  auto t0 = Clock::now();
  if (config_.collision.mode == CollisionMode::Full) {
    collide();
  } else {
    std::fill(contactForce_.begin(), contactForce_.end(), glm::dvec3(0.0));
    contacts_ = {};
  }
  stages_[3].ms += msSince(t0);
}

void CpuSolver::step(double h, const Pose& head) {
  if (stages_.size() < 4) clearStages();  // a single step called directly
  const Pose before = head_;
  const std::vector<Sphere> spheres = worldSpheres(config_.head.spheres, head);
  auto t0 = Clock::now();
  predict(h, head);
  stages_[0].ms += msSince(t0);
  t0 = Clock::now();
  shapeMatch();
  stages_[1].ms += msSince(t0);
  t0 = Clock::now();
  integrate(h);
  stages_[0].ms += msSince(t0);
  t0 = Clock::now();
  limitStrain(h, spheres, head, before);
  stages_[2].ms += msSince(t0);
  time_ += h;
  head_ = head;
}

void CpuSolver::predict(double h, const Pose& head) {
  const SimConfig& sim = config_.sim;
  const glm::dvec3 gravity(sim.gravity);
  const bool wind = config_.wind.strength > 0.0f && config_.wind.drag > 0.0f;
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      for (uint32_t i = a; i < b; ++i) {
        xOld_[i] = x_[i];
        if (int(i - a) < sim.pinned) {
          // Kinematic roots follow the head.
          xPred_[i] = head.apply(rest_[i]);
          continue;
        }
        glm::dvec3 acc = gravity + contactForce_[i] / mass_[i];
        if (wind) {
          // Drag acts on the wind across the strand, not along it.
          const glm::dvec3 t = glm::normalize(x_[std::min(i + 1, b - 1)] - x_[i - 1]);
          const glm::dvec3 rel = windVelocity(config_.wind, x_[i], time_) - v_[i];
          acc += double(config_.wind.drag) * (rel - glm::dot(rel, t) * t);
        }
        v_[i] += h * acc;
        xPred_[i] = x_[i] + h * v_[i];
      }
    }
  });
}

void CpuSolver::shapeMatch() {
  const int w = std::max(1, config_.sim.stiffnessWindow);
  const int iterations = std::max(1, config_.sim.rotationIterations);
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      const int n = int(b - a);
      const size_t pb = a + s;
      // Root-relative coordinates keep the prefix sums' differences exact enough in float on the
      // GPU; the CPU uses the same formulation so the two compare term by term.
      const glm::dvec3 origin = xPred_[a];
      for (int j = 0; j < n; ++j) {
        const double m = mass_[a + j];
        const Eigen::Vector3d y = toEigen(xPred_[a + j] - origin);
        const Eigen::Vector3d yr = toEigen(rest_[a + j] - rest_[a]);
        prefMassX_[pb + j + 1] = prefMassX_[pb + j] + m * y;
        prefA_[pb + j + 1] = prefA_[pb + j] + m * y * yr.transpose();
      }
      for (int k = 0; k < n; ++k) {
        const int lo = std::max(0, k - w), hi = std::min(n - 1, k + w);
        double M;
        Eigen::Vector3d sumX, sumRest;
        Eigen::Matrix3d sumA;
        if (sums_ == RegionSums::Prefix) {
          M = prefMass_[pb + hi + 1] - prefMass_[pb + lo];
          sumX = prefMassX_[pb + hi + 1] - prefMassX_[pb + lo];
          sumRest = prefMassRest_[pb + hi + 1] - prefMassRest_[pb + lo];
          sumA = prefA_[pb + hi + 1] - prefA_[pb + lo];
        } else {
          M = 0.0;
          sumX.setZero();
          sumRest.setZero();
          sumA.setZero();
          for (int j = lo; j <= hi; ++j) {
            const double m = mass_[a + j];
            const Eigen::Vector3d y = toEigen(xPred_[a + j] - origin);
            const Eigen::Vector3d yr = toEigen(rest_[a + j] - rest_[a]);
            M += m;
            sumX += m * y;
            sumRest += m * yr;
            sumA += m * y * yr.transpose();
          }
        }
        const Eigen::Vector3d c = sumX / M, cRest = sumRest / M;
        const Eigen::Matrix3d A = sumA - M * c * cRest.transpose();
        extractRotation(A, q_[a + k], iterations);
        const Eigen::Matrix3d R = q_[a + k].matrix();
        regionC_[a + k] = c;
        regionCRest_[a + k] = cRest;
        prefR_[pb + k + 1] = prefR_[pb + k] + R;
        prefT_[pb + k + 1] = prefT_[pb + k] + (c - R * cRest);
      }
      // Goals (paper eq. 1) averaged over the regions that contain each particle:
      // g_i = ((sum R_k) xr_i + sum (c_k - R_k cr_k)) / |K_i|, both sums prefix differences.
      for (int i = 0; i < n; ++i) {
        const int lo = std::max(0, i - w), hi = std::min(n - 1, i + w);
        const Eigen::Vector3d yr = toEigen(rest_[a + i] - rest_[a]);
        Eigen::Matrix3d sumR;
        Eigen::Vector3d sumT;
        if (sums_ == RegionSums::Prefix) {
          sumR = prefR_[pb + hi + 1] - prefR_[pb + lo];
          sumT = prefT_[pb + hi + 1] - prefT_[pb + lo];
        } else {
          sumR.setZero();
          sumT.setZero();
          for (int k = lo; k <= hi; ++k) {
            const Eigen::Matrix3d R = q_[a + k].matrix();
            sumR += R;
            sumT += regionC_[a + k] - R * regionCRest_[a + k];
          }
        }
        goal_[a + i] = origin + toGlm((sumR * yr + sumT) / double(hi - lo + 1));
      }
    }
  });
}

void CpuSolver::integrate(double h) {
  const double alpha = config_.sim.stiffness;
  const double keep = std::max(0.0, 1.0 - double(config_.sim.damping) * h);
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      for (uint32_t i = a; i < b; ++i) {
        const bool pinned = int(i - a) < config_.sim.pinned;
        x_[i] = pinned ? xPred_[i] : xPred_[i] + alpha * (goal_[i] - xPred_[i]);
        v_[i] = (x_[i] - xOld_[i]) / h;
        if (!pinned) v_[i] *= keep;
      }
    }
  });
}

void CpuSolver::limitStrain(double h, const std::vector<Sphere>& spheres, const Pose& head,
                            const Pose& before) {
  const SimConfig& sim = config_.sim;
  const bool limit = sim.strainLimiting;
  const bool headCollide = config_.collision.mode != CollisionMode::Off;
  const double r = config_.collision.radius;
  const double friction = config_.collision.headFriction;
  const double dftl = sim.dftl;
  parallelFor(strandCount(), 64, [&](size_t first, size_t last) {
    for (size_t s = first; s < last; ++s) {
      const uint32_t a = first_[s], b = first_[s + 1];
      // One sweep from root to tip: each segment is fixed against an already final parent, so
      // no iteration is needed (paper section 3.2).
      for (uint32_t i = a + std::max(1, sim.pinned); i < b; ++i) {
        const glm::dvec3 start = x_[i];
        const double maxLength = limit ? (1.0 + sim.strainLimit) * restLength_[i - 1] : 0.0;
        if (limit) {
          const glm::dvec3 d = x_[i] - x_[i - 1];
          const double len = glm::length(d);
          if (len > maxLength) x_[i] = x_[i - 1] + d * (maxLength / len);
        }
        bool touching = false;
        if (headCollide) {
          // Overlapping spheres can push a particle into each other: repeat until it is clear.
          for (int pass = 0; pass < 4; ++pass) {
            bool moved = false;
            for (const Sphere& sp : spheres)
              moved |= pushOutOfSphere(x_[i], x_[i - 1], glm::dvec3(sp.center), sp.radius + r,
                                       maxLength);
            touching |= moved;
            if (!moved) break;
          }
        }
        const glm::dvec3 correction = x_[i] - start;
        v_[i] += correction / h;
        if (touching && friction > 0.0) {
          // Friction against the moving head: damp the sliding part of the relative velocity.
          const glm::dvec3 local = glm::inverse(head.rotation) * (x_[i] - head.translation);
          const glm::dvec3 surfaceVel = (x_[i] - before.apply(local)) / h;
          glm::dvec3 rel = v_[i] - surfaceVel;
          const Sphere* nearest = &spheres.front();
          double best = 1e300;
          for (const Sphere& sp : spheres) {
            double dist = glm::length(x_[i] - glm::dvec3(sp.center)) - sp.radius;
            if (dist < best) best = dist, nearest = &sp;
          }
          const glm::dvec3 n = glm::normalize(x_[i] - glm::dvec3(nearest->center));
          const double vn = glm::dot(rel, n);
          const glm::dvec3 vt = rel - vn * n;
          v_[i] = surfaceVel + std::max(0.0, vn) * n + (1.0 - friction) * vt;
        }
        // Dynamic follow-the-leader (Mueller et al. 2012): the parent takes back part of the
        // velocity its child got from the correction, against the heavy-tip look.
        if (dftl > 0.0 && int(i - 1 - a) >= sim.pinned) v_[i - 1] -= dftl * correction / h;
      }
    }
  });
}

void CpuSolver::collide() {
  const CollisionConfig& col = config_.collision;
  const double r = col.radius;
  const double dt = config_.sim.dt;
  std::fill(contactForce_.begin(), contactForce_.end(), glm::dvec3(0.0));
  const std::vector<SegmentPair> pairs = findContactsGrid(x_, strandOf_, 2.0 * r);
  contacts_ = {pairs.size(), 0};
  for (const SegmentPair& p : pairs) {
    if (p.distance < r) ++contacts_.penetrations;
    const glm::dvec3 pa = glm::mix(x_[p.a], x_[p.a + 1], p.s);
    const glm::dvec3 pb = glm::mix(x_[p.b], x_[p.b + 1], p.t);
    glm::dvec3 n = pa - pb;
    if (p.distance > 1e-12) {
      n /= p.distance;
    } else {
      // Crossing exactly: push apart across both directions.
      n = glm::cross(x_[p.a + 1] - x_[p.a], x_[p.b + 1] - x_[p.b]);
      const double len = glm::length(n);
      n = len > 1e-15 ? n / len : glm::dvec3(0, 1, 0);
    }
    const glm::dvec3 va = glm::mix(v_[p.a], v_[p.a + 1], p.s);
    const glm::dvec3 vb = glm::mix(v_[p.b], v_[p.b + 1], p.t);
    const glm::dvec3 rel = va - vb;
    const double vn = glm::dot(rel, n);
    const double an = std::max(0.0, col.stiffness * (2.0 * r - p.distance) - col.damping * vn);
    const glm::dvec3 vt = rel - vn * n;
    const double vtLen = glm::length(vt);
    glm::dvec3 acc = an * n;
    if (vtLen > 1e-12) acc -= std::min(col.friction * an, vtLen / dt) * (vt / vtLen);
    const double massA = 0.5 * (mass_[p.a] + mass_[p.a + 1]);
    const double massB = 0.5 * (mass_[p.b] + mass_[p.b + 1]);
    const glm::dvec3 f = 0.5 * (massA + massB) * acc;
    contactForce_[p.a] += (1.0 - p.s) * f;
    contactForce_[p.a + 1] += p.s * f;
    contactForce_[p.b] -= (1.0 - p.t) * f;
    contactForce_[p.b + 1] -= p.t * f;
  }
}

void CpuSolver::readPositions(std::vector<glm::vec4>& out) {
  out.resize(x_.size());
  for (size_t i = 0; i < x_.size(); ++i) out[i] = glm::vec4(glm::vec3(x_[i]), 1.0f);
}

void CpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  out.resize(v_.size());
  for (size_t i = 0; i < v_.size(); ++i) out[i] = glm::vec4(glm::vec3(v_[i]), 0.0f);
}

}  // namespace csm
