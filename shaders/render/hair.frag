// Hair fragments: the colour shaded per vertex (hair.vert), and transparency as coverage.
#include "render/frame.glsl"

#ifdef CHILD_LINES
// Children are depth-tested before shading against the head and the guides (drawn first,
// with depth writes) and write no depth themselves: most of a head's children lie behind
// its outer layer and cost no shading, and a child's uncovered samples hide nothing.
layout(early_fragment_tests) in;
#endif

in vec3 vColor;
in float vCoverage;
flat in uint vStrand;
out vec4 fragColor;

void main() {
  // Stochastic transparency (Enderton et al. 2010) with one sample pattern per strand:
  // overlapping strands pick different samples and add up to opaque hair, no noise runs
  // along a strand, and nothing needs sorting.
  uint h = pcgHash(vStrand ^ 0x9e3779b9u);
#if SAMPLES > 1
  int count = int(floor(clamp(vCoverage, 0.0, 1.0) * float(SAMPLES) + hashToUnit(h)));
  if (count <= 0) discard;
  count = min(count, SAMPLES);
  uint full = (1u << uint(SAMPLES)) - 1u;
  uint mask = (1u << uint(count)) - 1u;
  uint turn = (h >> 4u) % uint(SAMPLES);
  mask = ((mask << turn) | (mask >> (uint(SAMPLES) - turn))) & full;
  gl_SampleMask[0] = int(mask);
#else
  if (hashToUnit(h) >= vCoverage) discard;
#endif
  fragColor = vec4(vColor, 1.0);
}
