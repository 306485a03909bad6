// The follower pass (render/follower_pass.h): every drawn strand made from its guides' positions,
// the GPU twin of sim/groom/followers.cpp. Built twice: with GUIDE_TURNS, one invocation per
// guide particle writes its turn (the head's rotation, then the shortest rotation from its rest
// tangent turned with the head to its tangent now); without, one invocation per drawn point
// blends, from each of its strand's guides, the guide's point at the same rest-length share plus
// its own rest offset from there, turned as the guide has turned, and moves a point left inside
// the head out to the surface.
#include "render/bindings.glsl"
#include "render/hair_compute.glsl"
#include "sim/shared_constants.glsl"

layout(std430, binding = CSM_RENDER_FOLLOW_GUIDE_POSITIONS) readonly buffer GuidePositions {
  vec4 guidePositions[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_DRAWN_REST) readonly buffer DrawnRest {
  vec4 drawnRest[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_DRAWN_FIRST) readonly buffer DrawnFirst {
  uint drawnFirst[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_GUIDE_STRAND) readonly buffer GuideStrand {
  uint guideStrand[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_GUIDE_FIRST) readonly buffer GuideFirst {
  uint guideFirst[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_GUIDE_TURNS) buffer GuideTurns { vec4 guideTurns[]; };

uniform uint uItems;
uniform uint uGuides;
uniform uint uStrands;
uniform vec4 uHeadRotation;  // quaternion: xyz, w
uniform vec3 uHeadTranslation;

// q v q*, as glm's quat * vec3.
vec3 turn(vec4 q, vec3 v) {
  vec3 uv = cross(q.xyz, v);
  vec3 uuv = cross(q.xyz, uv);
  return v + ((uv * q.w) + uuv) * 2.0;
}

// a (1 - t) + b t: exactly a at t = 0 and b at t = 1.
vec3 blend(vec3 a, vec3 b, float t) {
  return a * (1.0 - t) + b * t;
}

// The guide whose particles hold particle i: the last g with guideFirst[g] <= i.
uint guideOf(uint i) {
  uint lo = 0u, hi = uGuides;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (guideFirst[mid] <= i) lo = mid;
    else hi = mid - 1u;
  }
  return lo;
}

// The drawn strand holding point i: the last s with drawnFirst[s] <= i.
uint strandOf(uint i) {
  uint lo = 0u, hi = uStrands;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (drawnFirst[mid] <= i) lo = mid;
    else hi = mid - 1u;
  }
  return lo;
}

#ifdef GUIDE_TURNS

vec3 unitOr(vec3 v, vec3 fallback) {
  float l = length(v);
  return l > 1e-12 ? v / l : fallback;
}

vec4 shortestTurn(vec3 a, vec3 b) {
  float c = dot(a, b);
  if (!(c > -0.9999)) return vec4(0.0, 0.0, 0.0, 1.0);
  return normalize(vec4(cross(a, b), 1.0 + c));
}

// a after b.
vec4 product(vec4 a, vec4 b) {
  return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

void main() {
  uint i = invocationIndex();
  if (i >= uItems) return;
  uint g = guideOf(i);
  uint first = guideFirst[g], n = guideFirst[g + 1u] - first, j = i - first;
  if (n < 2u) {
    guideTurns[i] = uHeadRotation;
    return;
  }
  uint lo = j > 0u ? j - 1u : 0u, hi = min(j + 1u, n - 1u);
  uint rest = drawnFirst[guideStrand[g]];
  vec3 a = unitOr(turn(uHeadRotation, drawnRest[rest + hi].xyz - drawnRest[rest + lo].xyz),
                  vec3(0.0, -1.0, 0.0));
  vec3 b = unitOr(guidePositions[first + hi].xyz - guidePositions[first + lo].xyz, a);
  guideTurns[i] = product(shortestTurn(a, b), uHeadRotation);
}

#else

layout(std430, binding = CSM_RENDER_FOLLOW_BOUND_GUIDES) readonly buffer BoundGuides {
  uvec4 boundGuides[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_BOUND_WEIGHTS) readonly buffer BoundWeights {
  vec4 boundWeights[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_DRAWN_POSITIONS) writeonly buffer DrawnPositions {
  vec4 drawnPositions[];
};
layout(std430, binding = CSM_RENDER_FOLLOW_HEAD) readonly buffer Head { vec4 head[]; };
layout(std430, binding = CSM_RENDER_FOLLOW_PUSHED) buffer Pushed { uint pushed; };

// The body's parts, each 0: nothing, 1: a field, 2: spheres, in head[]: the head's from 0, the
// torso's from uTorsoFirst (its field's nodes, or its uTorsoSpheres spheres), at its own pose.
uniform int uHeadShape;
uniform ivec3 uFieldDims;
uniform vec3 uFieldOrigin;
uniform float uFieldCell;
uniform int uSpheres;
uniform int uTorsoShape;
uniform ivec3 uTorsoFieldDims;
uniform vec3 uTorsoFieldOrigin;
uniform float uTorsoFieldCell;
uniform int uTorsoFirst;
uniform int uTorsoSpheres;
uniform vec4 uTorsoRotation;
uniform vec3 uTorsoTranslation;

// The field's gradient (xyz) and distance (w) at p (head frame): the solver's sample
// (shaders/sim/head_field_sample.glsl) of the nodes in head[].
#define headFieldNode(i) head[i]
#include "sim/head_field_sample.glsl"

// Moves world point x CSM_FOLLOWER_PUSH_MARGIN out of one part (shape, its field's grid or its
// spheres from `first`, at pose rotation/translation); true when it moved.
bool pushOutOfPart(inout vec3 x, int shape, ivec3 dims, vec3 origin, float cell, int first,
                   int spheres, vec4 rotation, vec3 translation) {
  if (shape == 0) return false;
  vec3 local = turn(vec4(-rotation.xyz, rotation.w), x - translation);
  bool moved = false;
  if (shape == 1) {
    vec4 v = headFieldAt(dims, origin, cell, local, first);
    if (v.w < 0.0 && dot(v.xyz, v.xyz) > 0.0) {
      local -= normalize(v.xyz) * (v.w - CSM_FOLLOWER_PUSH_MARGIN);
      moved = true;
    }
  } else {
    for (int k = first; k < first + spheres; ++k) {
      vec3 r = local - head[k].xyz;
      float l = length(r);
      if (l < head[k].w && l > 0.0) {
        local = head[k].xyz + r * ((head[k].w + CSM_FOLLOWER_PUSH_MARGIN) / l);
        moved = true;
      }
    }
  }
  if (moved) x = turn(rotation, local) + translation;
  return moved;
}

void main() {
  uint i = invocationIndex();
  if (i >= uItems) return;
  uint s = strandOf(i);
  uint first = drawnFirst[s];
  vec3 rest = drawnRest[i].xyz;
  float u = drawnRest[i].w;
  uvec4 guides = boundGuides[s];
  vec4 weights = boundWeights[s];
  vec3 sum = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    float w = weights[k];
    if (w == 0.0) continue;
    uint g = guides[k];
    uint gRest = drawnFirst[guideStrand[g]], gNow = guideFirst[g];
    uint gn = guideFirst[g + 1u] - gNow;
    uint lo = 0u, hi = gn - 2u;
    while (lo < hi) {
      uint mid = (lo + hi + 1u) / 2u;
      if (drawnRest[gRest + mid].w <= u) lo = mid;
      else hi = mid - 1u;
    }
    uint j = lo;
    float a = drawnRest[gRest + j].w, span = drawnRest[gRest + j + 1u].w - a;
    float t = span > 0.0 ? clamp((u - a) / span, 0.0, 1.0) : 0.0;
    vec3 offset = rest - blend(drawnRest[gRest + j].xyz, drawnRest[gRest + j + 1u].xyz, t);
    // The root's offset turns with the head alone, so that roots stay on the scalp.
    vec4 ta = i == first ? uHeadRotation : guideTurns[gNow + j];
    vec4 tb = i == first ? uHeadRotation : guideTurns[gNow + j + 1u];
    vec3 turned = blend(turn(ta, offset), turn(tb, offset), t);
    sum += w * (blend(guidePositions[gNow + j].xyz, guidePositions[gNow + j + 1u].xyz, t) + turned);
  }
  if (i != first && (uHeadShape != 0 || uTorsoShape != 0)) {
    bool moved = false;
    // A few rounds, each putting the point CSM_FOLLOWER_PUSH_MARGIN out of each part in turn: the
    // field is no exact distance, a sphere's surface may lie in another, and a push out of one
    // part may end in the other (followers.cpp does the same).
    for (int round = 0; round < CSM_FOLLOWER_PUSH_ROUNDS; ++round) {
      bool again = pushOutOfPart(sum, uHeadShape, uFieldDims, uFieldOrigin, uFieldCell, 0,
                                 uSpheres, uHeadRotation, uHeadTranslation);
      again = pushOutOfPart(sum, uTorsoShape, uTorsoFieldDims, uTorsoFieldOrigin,
                            uTorsoFieldCell, uTorsoFirst, uTorsoSpheres, uTorsoRotation,
                            uTorsoTranslation) || again;
      moved = moved || again;
      if (!again) break;
    }
    if (moved) atomicAdd(pushed, 1u);
  }
  drawnPositions[i] = vec4(sum, 1.0);
}

#endif
