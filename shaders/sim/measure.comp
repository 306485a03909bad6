// The measures of sim/solver/accuracy.cpp (measureAccuracy) on the GPU: per particle, then reduced per
// work group in shared memory into one record of two uvec4, so that a sample reads back a few
// bytes per CSM_MEASURE_GROUP particles and no positions. No atomics: the reduction runs in a
// fixed order, and GpuSolver::takeSample combines the records in order on the CPU.
//   record[2g]:     x max strain (float bits, ordered as unsigned: see orderedKey),
//                   y segments measured, z particles inside the head, w non-finite particles
//   record[2g + 1]: x sum of |strain| (float bits), y max speed (float bits), z particles inside
//                   the torso (and not the head), w unused
#include "sim/common.glsl"
#include "sim/head_field.glsl"

layout(local_size_x = CSM_MEASURE_GROUP) in;

#include "sim/particle_reads.glsl"
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};
layout(std430, binding = CSM_BIND_MEASURE) writeonly buffer Measure { uvec4 record[]; };

uniform uint sphereBase;  // the head spheres of the frame's last step
uniform uint lastStep;    // and its index, for the head's pose and the torso's

shared uint sMaxStrain[CSM_MEASURE_GROUP];
shared uint sSegments[CSM_MEASURE_GROUP];
shared uint sInside[CSM_MEASURE_GROUP];
shared uint sInsideTorso[CSM_MEASURE_GROUP];
shared uint sNonFinite[CSM_MEASURE_GROUP];
shared float sStrainSum[CSM_MEASURE_GROUP];
shared float sMaxSpeed[CSM_MEASURE_GROUP];

// Float bits made to sort as unsigned integers, negatives included.
uint orderedKey(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

float maxAbs(vec3 v) { return max(abs(v.x), max(abs(v.y), abs(v.z))); }

// isnan and isinf, not a comparison: a compiler may assume comparisons see no NaN.
bool finite3(vec3 v) {
  return !any(isnan(v)) && !any(isinf(v));
}

void main() {
  uint i = globalIndex();
  uint l = gl_LocalInvocationID.x;
  uint maxStrain = 0u, segments = 0u, inside = 0u, insideTorso = 0u, nonFinite = 0u;
  float strainSum = 0.0, speed = 0.0;
  if (i < P.particles) {
    uint s = particleStrand[i];
    uint a = strandFirst[s], b = strandFirst[s + 1u];
    vec3 x = readPosition(int(i)).xyz;
    vec3 v = readVelocity(int(i)).xyz;
    if (!finite3(x) || !finite3(v)) {
      nonFinite = 1u;
    } else {
      speed = length(v);
      if (int(i - a) >= pinnedOf(strandStiffness[s]) && headIsField()) {
        inside = headFieldSample(toHeadFrame(S[lastStep].head, x)).w < 0.0 ? 1u : 0u;
        if (inside == 0u && P.torsoIsField != 0u) {
          Substep st = S[lastStep];
          vec3 q = quatUnturn(st.torsoRotation, x - st.torsoTranslation.xyz);
          insideTorso = torsoFieldSample(q).w < 0.0 ? 1u : 0u;
        }
      } else if (int(i - a) >= pinnedOf(strandStiffness[s])) {
        for (int k = 0; k < P.headSpheres; ++k) {
          vec4 sp = spheres[sphereBase + uint(k)];
          if (length(x - sp.xyz) < sp.w * (1.0 - 1e-6)) {
            if (k < P.torsoSphereFirst) {
              inside = 1u;
              break;
            }
            insideTorso = 1u;
          }
        }
        if (inside != 0u) insideTorso = 0u;
      }
      if (i + 1u < b) {
        float rest = length(readRest(int(i) + 1).xyz - readRest(int(i)).xyz);
        vec3 next = readPosition(int(i) + 1).xyz;
        if (rest > 0.0 && finite3(next)) {
          // Less what float positions cannot resolve: floatBlur in sim/solver/accuracy.cpp.
          float blur = 1.1920929e-7 * (maxAbs(x) + maxAbs(next));  // 2^-23
          float stretch = length(next - x) - rest;
          stretch = stretch > blur ? stretch - blur : stretch < -blur ? stretch + blur : 0.0;
          float strain = stretch / rest;
          maxStrain = orderedKey(strain);
          strainSum = abs(strain);
          segments = 1u;
        }
      }
    }
  }
  sMaxStrain[l] = maxStrain;
  sSegments[l] = segments;
  sInside[l] = inside;
  sInsideTorso[l] = insideTorso;
  sNonFinite[l] = nonFinite;
  sStrainSum[l] = strainSum;
  sMaxSpeed[l] = speed;
  barrier();
  for (uint half_ = CSM_MEASURE_GROUP / 2u; half_ > 0u; half_ >>= 1u) {
    if (l < half_) {
      sMaxStrain[l] = max(sMaxStrain[l], sMaxStrain[l + half_]);
      sSegments[l] += sSegments[l + half_];
      sInside[l] += sInside[l + half_];
      sInsideTorso[l] += sInsideTorso[l + half_];
      sNonFinite[l] += sNonFinite[l + half_];
      sStrainSum[l] += sStrainSum[l + half_];
      sMaxSpeed[l] = max(sMaxSpeed[l], sMaxSpeed[l + half_]);
    }
    barrier();
  }
  if (l == 0u) {
    uint g = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    record[2u * g] = uvec4(sMaxStrain[0], sSegments[0], sInside[0], sNonFinite[0]);
    record[2u * g + 1u] =
        uvec4(floatBitsToUint(sStrainSum[0]), floatBitsToUint(sMaxSpeed[0]), sInsideTorso[0], 0u);
  }
}
