// The work-group layout of the per-particle path (strand_step.comp, strand_strain.comp): one
// invocation per particle, whole strands to a work group. Strands lie back to back in the
// particle arrays, so a group covers one run of particles [groupFirst[g], groupFirst[g + 1]):
// the strands GpuSolver packed into it, none split (sim/gpu/strand_groups.h). Loads and stores
// of a group are contiguous; sums along a strand are segmented scans in shared memory, and the
// strain limit's sweep runs over the strand held there.
//
// CSM_GROUP_PARTICLES (the group's size, a power of two at least the longest strand) and MAX_N
// (the longest strand, rounded up) are defined by the pass's build.

layout(local_size_x = CSM_GROUP_PARTICLES) in;

layout(std430, binding = CSM_BIND_STRAND_GROUPS) readonly buffer StrandGroups {
  uint groupFirst[];
};

// The groups packed (the dispatch may hold more, a 2D grid past 65535 groups).
uniform uint groups;

// Four vec4 a particle: the scans' terms, then the sweep's state.
shared vec4 shA[CSM_GROUP_PARTICLES];
shared vec4 shB[CSM_GROUP_PARTICLES];
shared vec4 shC[CSM_GROUP_PARTICLES];
shared vec4 shD[CSM_GROUP_PARTICLES];

// Where this invocation's particle lies: p in the particle arrays, its strand s = [a, a + n),
// j its place in the strand, root the group's slot of the strand's first particle. A slot past
// the group's end is not live: it takes part in the barriers and scans (as a strand of its own)
// and writes nothing.
struct Slot {
  uint p, s, a, root;
  int n, j;
  bool live;
};

Slot groupSlot() {
  uint g = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint lid = gl_LocalInvocationID.x;
  uint first = 0u, end = 0u;
  if (g < groups) {
    first = groupFirst[g];
    end = groupFirst[g + 1u];
  }
  Slot o;
  o.p = first + lid;
  o.live = o.p < end;
  o.s = o.live ? particleStrand[o.p] : 0u;
  o.a = o.live ? strandFirst[o.s] : o.p;
  o.n = o.live ? int(strandFirst[o.s + 1u] - o.a) : 1;
  o.j = int(o.p - o.a);
  o.root = lid - uint(o.j);
  return o;
}

// Inclusive scan of four vec4 along each strand of the group: on return slot i of shA..shD
// holds the sums over its strand's slots root..i, and v0..v3 this slot's. The strands are at
// most MAX_N long, so log2(MAX_N) rounds (Hillis and Steele), each adding the slot d back when
// it is of the same strand.
void strandScan(Slot o, inout vec4 v0, inout vec4 v1, inout vec4 v2, inout vec4 v3) {
  uint lid = gl_LocalInvocationID.x;
  shA[lid] = v0;
  shB[lid] = v1;
  shC[lid] = v2;
  shD[lid] = v3;
  barrier();
  for (uint d = 1u; d < uint(MAX_N); d <<= 1u) {
    bool add = uint(o.j) >= d;
    uint from = add ? lid - d : lid;
    vec4 a0 = shA[from], a1 = shB[from], a2 = shC[from], a3 = shD[from];
    barrier();
    if (add) {
      v0 += a0;
      v1 += a1;
      v2 += a2;
      v3 += a3;
      shA[lid] = v0;
      shB[lid] = v1;
      shC[lid] = v2;
      shD[lid] = v3;
    }
    barrier();
  }
}

// The sum over strand slots lo..hi (lo <= hi, places in the strand) of what strandScan left.
vec4 rangeSumA(Slot o, int lo, int hi) {
  return shA[o.root + uint(hi)] - (lo > 0 ? shA[o.root + uint(lo - 1)] : vec4(0.0));
}
vec4 rangeSumB(Slot o, int lo, int hi) {
  return shB[o.root + uint(hi)] - (lo > 0 ? shB[o.root + uint(lo - 1)] : vec4(0.0));
}
vec4 rangeSumC(Slot o, int lo, int hi) {
  return shC[o.root + uint(hi)] - (lo > 0 ? shC[o.root + uint(lo - 1)] : vec4(0.0));
}
vec4 rangeSumD(Slot o, int lo, int hi) {
  return shD[o.root + uint(hi)] - (lo > 0 ? shD[o.root + uint(lo - 1)] : vec4(0.0));
}

#ifdef CSM_SWEEP
// The strain limit's sweep over the strands of the group, held in shared memory: shA the
// positions, shB the velocities, shC the rest positions (xyz) of each slot, shD the strand
// contacts' correction sent to it. The root's slot sweeps its strand; the others wait at the
// barrier after. As strain_limit.comp's loop, particle for particle.
void sweepStrands(Slot o, uint substep) {
  if (o.live && o.j == 0) {
    vec4 stiff = strandStiffness[o.s];
    int pinned = pinnedOf(stiff);
    int first = max(1, pinned);
    int end = o.n - (tipHeldOf(stiff) ? 1 : 0);  // a held tip stays where the head put it
    if (end > first) {
      Substep st = S[substep];
      bool contacts = P.strandContacts != 0u;
      uint sphereBase = substep * uint(P.headSpheres);
      uint r = o.root;
      vec3 restPrev = shC[r + uint(first - 1)].xyz;
      vec3 xPrev = shA[r + uint(first - 1)].xyz;
      vec3 vPrev = shB[r + uint(first - 1)].xyz;
      bool prevFree = first - 1 >= pinned;
      for (int i = first; i < end; ++i) {
        uint k = r + uint(i);
        vec3 restHere = shC[k].xyz;
        vec3 x = shA[k].xyz;
        vec3 v = shB[k].xyz;
        sweepParticle(restHere, restPrev, contacts, shD[k], xPrev, prevFree, st, sphereBase, x,
                      v, vPrev);
        shB[k - 1u] = vec4(vPrev, 0.0);
        shA[k] = vec4(x, 1.0);
        restPrev = restHere;
        xPrev = x;
        vPrev = v;
        prevFree = i >= pinned;
      }
      shB[r + uint(end - 1)] = vec4(vPrev, 0.0);
      // Held at both ends: sweeps back from the tip and forth from the root (limitToward).
      bool tied = P.strainLimiting != 0u && end < o.n;
      for (int pass = 0; tied && pass < CSM_TIED_SWEEPS; ++pass) {
        for (int back = 0; tied && back < 2; ++back) {
          bool moved = false;
          for (int k = 0; k < end - first; ++k) {
            int i = back == 0 ? end - 1 - k : first + k;
            uint p = r + uint(i), q = back == 0 ? p + 1u : p - 1u;
            vec3 x = shA[p].xyz, v = shB[p].xyz;
            if (limitToward(x, v, shA[q].xyz, length(shC[p].xyz - shC[q].xyz), st.h)) {
              shA[p] = vec4(x, 1.0);
              shB[p] = vec4(v, 0.0);
              moved = true;
            }
          }
          tied = moved;
        }
      }
      // What the sweeps left: one more from the root, within reach of the parent and the tip.
      if (P.strainLimiting != 0u && end < o.n) {
        float grow = 1.0 + P.strainLimit, reach = 0.0;
        for (int i = first - 1; i < end; ++i)
          reach += grow * length(shC[r + uint(i + 1)].xyz - shC[r + uint(i)].xyz);
        vec3 tip = shA[r + uint(end)].xyz;
        vec3 parent = shA[r + uint(first - 1)].xyz;
        for (int i = first; i < end; ++i) {
          uint k = r + uint(i);
          float segment = grow * length(shC[k].xyz - shC[k - 1u].xyz);
          reach -= segment;
          vec3 x = shA[k].xyz;
          vec3 to = intoBothBalls(x, parent, segment, tip, reach);
          shB[k] = vec4(shB[k].xyz + (to - x) / st.h, 0.0);
          shA[k] = vec4(to, 1.0);
          parent = to;
        }
      }
    }
  }
  barrier();
}
#endif
