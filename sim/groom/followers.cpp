#include "sim/groom/followers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "sim/base/shortest_turn.h"
#include "sim/groom/growth_head.h"
#include "sim/head/distance_grid.h"
#include "shaders/sim/shared_constants.glsl"

namespace csm {
namespace {

// a (1 - t) + b t, written out: exactly a at t = 0 and b at t = 1 (the shader does the same).
glm::vec3 blend(const glm::vec3& a, const glm::vec3& b, float t) {
  return a * (1.0f - t) + b * t;
}

// The way along strand points [first, first + n) at point j: central differences inside,
// one-sided at the ends.
glm::vec3 tangentAt(const glm::vec3* p, std::uint32_t n, std::uint32_t j) {
  const std::uint32_t lo = j > 0 ? j - 1 : 0, hi = std::min(j + 1, n - 1);
  return p[hi] - p[lo];
}

// One part of the body: its field, else its spheres (its own frame), at its pose.
struct Part {
  const DistanceGrid* field;
  const std::vector<Sphere>& spheres;
  Pose pose;
  bool empty() const { return !field && spheres.empty(); }
  // How deep a world point lies inside: 0 outside.
  double depth(const glm::dvec3& world) const {
    glm::dvec3 normal;
    return std::max(0.0, -GrowthHead{spheres, field}.distance(inverse(pose).apply(world), normal));
  }
  // Moves a world point CSM_FOLLOWER_PUSH_MARGIN out of the surface; true when it moved.
  bool push(glm::dvec3& world) const {
    if (empty()) return false;
    glm::dvec3 local = inverse(pose).apply(world);
    bool moved = false;
    if (field) {
      glm::dvec3 gradient;
      const double d = field->sample(local, &gradient);
      if (d < 0.0 && glm::length(gradient) > 0.0) {
        local -= glm::normalize(gradient) * (d - CSM_FOLLOWER_PUSH_MARGIN);
        moved = true;
      }
    } else {
      for (const Sphere& sp : spheres) {
        const glm::dvec3 r = local - glm::dvec3(sp.center);
        const double l = glm::length(r);
        if (l < sp.radius && l > 0.0) {
          local = glm::dvec3(sp.center) + r * ((sp.radius + CSM_FOLLOWER_PUSH_MARGIN) / l);
          moved = true;
        }
      }
    }
    if (moved) world = pose.apply(local);
    return moved;
  }
};

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float l = glm::length(v);
  return l > 1e-12f ? v / l : fallback;
}

}  // namespace

std::vector<glm::quat> guideTurns(const FollowerBinding& b,
                                  const std::vector<glm::vec3>& guidePositions, const Pose& head) {
  const glm::quat h(head.rotation);
  std::vector<glm::quat> turns(guidePositions.size(), h);
  std::uint32_t first = 0;
  for (const std::uint32_t s : b.guideStrand) {
    const std::uint32_t n = b.drawn.strandSize(s);
    if (first + n > guidePositions.size()) break;
    const glm::vec3* rest = &b.drawn.points[b.drawn.first[s]];
    const glm::vec3* now = &guidePositions[first];
    for (std::uint32_t j = 0; j < n && n >= 2; ++j) {
      const glm::vec3 a = unitOr(h * tangentAt(rest, n, j), glm::vec3(0.0f, -1.0f, 0.0f));
      const glm::vec3 c = unitOr(tangentAt(now, n, j), a);
      turns[first + j] = shortestTurn(a, c) * h;
    }
    first += n;
  }
  return turns;
}

FollowerStats makeFollowers(const FollowerBinding& b, const std::vector<glm::vec3>& guidePositions,
                            const Pose& head, const SceneHead& collider,
                            std::vector<glm::vec3>& out) {
  return makeFollowers(b, guidePositions, BodyPose{head, head}, collider, out);
}

FollowerStats makeFollowers(const FollowerBinding& b, const std::vector<glm::vec3>& guidePositions,
                            const BodyPose& body, const SceneHead& collider,
                            std::vector<glm::vec3>& out) {
  const Pose& head = body.head;
  const Groom& g = b.drawn;
  out.assign(g.pointCount(), glm::vec3(0.0f));
  const std::vector<glm::quat> turns = guideTurns(b, guidePositions, head);
  std::vector<std::uint32_t> guideFirst(b.guideStrand.size() + 1, 0);
  for (std::size_t k = 0; k < b.guideStrand.size(); ++k)
    guideFirst[k + 1] = guideFirst[k] + g.strandSize(b.guideStrand[k]);
  if (guideFirst.back() != guidePositions.size()) return {};
  const glm::quat h(head.rotation);
  const Part parts[2] = {{collider.field, collider.spheres, head},
                         {collider.torsoField, collider.torsoSpheres, body.torso}};
  FollowerStats stats;
  for (std::size_t s = 0; s < g.strandCount(); ++s) {
    const std::uint32_t first = g.first[s], n = g.strandSize(s);
    for (std::uint32_t i = 0; i < n; ++i) {
      const glm::vec3 rest = g.points[first + i];
      const float u = b.share[first + i];
      glm::vec3 sum(0.0f);
      for (int k = 0; k < kFollowerGuides; ++k) {
        const float w = b.weights[s][k];
        if (w == 0.0f) continue;
        const std::uint32_t guide = b.guides[s][k];
        const std::uint32_t gs = b.guideStrand[guide], gn = g.strandSize(gs);
        const std::uint32_t gRest = g.first[gs], gNow = guideFirst[guide];
        // The guide's segment holding share u: the last j <= gn - 2 with share <= u.
        const float* sh = &b.share[gRest];
        std::uint32_t lo = 0, hi = gn - 2;
        while (lo < hi) {
          const std::uint32_t mid = (lo + hi + 1) / 2;
          if (sh[mid] <= u)
            lo = mid;
          else
            hi = mid - 1;
        }
        const std::uint32_t j = lo;
        const float span = sh[j + 1] - sh[j];
        const float t = span > 0.0f ? std::clamp((u - sh[j]) / span, 0.0f, 1.0f) : 0.0f;
        const glm::vec3 offset = rest - blend(g.points[gRest + j], g.points[gRest + j + 1], t);
        // The root's offset turns with the head alone, so that roots stay on the scalp.
        const glm::quat ta = i == 0 ? h : turns[gNow + j], tb = i == 0 ? h : turns[gNow + j + 1];
        const glm::vec3 turned = blend(ta * offset, tb * offset, t);
        sum += w * (blend(guidePositions[gNow + j], guidePositions[gNow + j + 1], t) + turned);
      }
      out[first + i] = sum;
    }
    // Out of the body: each part's field's surface, else its spheres', in its own frame, in
    // turn, a few rounds (the field is no exact distance, a sphere's surface may lie in another
    // and a push out of one part may end in the other).
    for (std::uint32_t i = 1; i < n; ++i) {
      glm::dvec3 x(out[first + i]);
      bool moved = false;
      for (int round = 0; round < CSM_FOLLOWER_PUSH_ROUNDS; ++round) {
        bool again = false;
        for (const Part& part : parts) again = part.push(x) || again;
        moved = moved || again;
        if (!again) break;
      }
      if (moved) {
        out[first + i] = glm::vec3(x);
        ++stats.pushed;
      }
      for (const Part& part : parts)
        if (!part.empty()) stats.deepest = std::max(stats.deepest, part.depth(x));
    }
  }
  return stats;
}

}  // namespace csm
