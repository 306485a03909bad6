// This frame's candidate lists (CANDIDATES: per slot, the other segment with the pair's flags,
// and its contact distance's bits), seen through one image view, or, built with
// CSM_SPLIT_VIEWS, through two: CANDIDATES_HIGH from slot listSplit on (bindings.glsl). The
// includer may define CSM_CANDIDATES_ACCESS (default readonly) as nothing to write them.
#ifndef CSM_CANDIDATES_ACCESS
#define CSM_CANDIDATES_ACCESS readonly
#endif
layout(binding = CSM_IMAGE_CANDIDATES, rg32ui) CSM_CANDIDATES_ACCESS uniform uimageBuffer
    candidates;
#ifdef CSM_SPLIT_VIEWS
layout(binding = CSM_IMAGE_CANDIDATES_HIGH, rg32ui) CSM_CANDIDATES_ACCESS uniform uimageBuffer
    candidatesHigh;
uniform uint listSplit;  // the first slot of each *_HIGH view
#endif

uvec2 candidateAt(uint i) {
#ifdef CSM_SPLIT_VIEWS
  if (i >= listSplit) return imageLoad(candidatesHigh, int(i - listSplit)).xy;
#endif
  return imageLoad(candidates, int(i)).xy;
}
