// The render passes' per-frame block, one std140 list both languages expand: GLSL's block
// (frame.glsl, each field by its GLSL name) and C++'s struct (render/frame_uniforms.h, by its C++
// name), so that neither can gain a field the other lacks; tests/gpu/render_uniforms_test.cpp
// checks every offset against the linked program's. Only mat4, vec4 and ivec4: std140 then pads
// nothing, as glm's structs do not. F(type, C++ name, GLSL name), by field:
//   viewProj; lightViewProj (world -> light clip space, orthographic); headRotation (the head
//     pose's rotation: the strands' frames turn with it)
//   eye: xyz the camera's position
//   lightDir: xyz the direction the light travels (unit); w intensity
//   lightColor: rgb; a ambient
//   rootColor: rgb; a per-strand colour variation
//   tipColor: rgb; a the opacity of one strand
//   specShift: x, y primary and secondary shift; z, w their exponents
//   specStrength: x, y primary and secondary strength; z strand width (px); w deep opacity
//     layer spacing (m)
//   headColor: rgb; a 1 when shadows are on
//   background: rgb
//   viewport: width, height, 1/width, 1/height
//   lightRange: x metres per unit of light depth; y map size; z 1/size; w a texel's side (m)
//   children: x children's distance from their guide at the root (m); y clump, the share of it
//     closed at the tip; z opacity scale of the shadow passes (1 / share of strands drawn); w
//     noise (m)
//   children2: x length variation; y share of children between two guides; z children each
//     child drawn into the opacity maps stands for
//   counts: x subdivision; y children per guide; z a child's step in its guide's spline points;
//     w strand flags (1 groom colours, 2 thickness)
//   counts2: x spline points; y head spheres
//   width: x strand width on screen (m; 0: specStrength.z pixels instead); y pixels per metre at
//     view depth 1; z the width (m) a strand stands for in the shadow maps
//   faceEye: xyz the mannequin's right eyeball's centre from the head's placement centre (head
//     frame; sim/head/mannequin.h kMannequinFace); w 1 when the mannequin's face is painted
//   faceEyeSizes: x the ball's radius; y the cornea's offset along the gaze; z its radius; w the
//     iris's radius
//   faceMouth: xyz the middle of the lips' meeting line (as faceEye); w the pupil's radius
//   faceLips: x, y the lips' red's half width and half height; z, w unused
//   irisColor: rgb the iris's colour
#ifndef CSM_RENDER_FRAME_UNIFORMS_GLSL
#define CSM_RENDER_FRAME_UNIFORMS_GLSL

#define CSM_FRAME_UNIFORMS(F)                                                              \
  F(mat4, viewProj, uViewProj) F(mat4, lightViewProj, uLightViewProj)                      \
  F(mat4, headRotation, uHeadRotation) F(vec4, eye, uEye) F(vec4, lightDir, uLightDir)     \
  F(vec4, lightColor, uLightColor) F(vec4, rootColor, uRootColor)                          \
  F(vec4, tipColor, uTipColor) F(vec4, specShift, uSpecShift)                              \
  F(vec4, specStrength, uSpecStrength) F(vec4, headColor, uHeadColor)                      \
  F(vec4, background, uBackground) F(vec4, viewport, uViewport)                            \
  F(vec4, lightRange, uLightRange) F(vec4, children, uChildren)                            \
  F(vec4, children2, uChildren2) F(ivec4, counts, uCounts) F(ivec4, counts2, uCounts2)     \
  F(vec4, width, uWidth) F(vec4, faceEye, uFaceEye) F(vec4, faceEyeSizes, uFaceEyeSizes)       \
  F(vec4, faceMouth, uFaceMouth) F(vec4, faceLips, uFaceLips) F(vec4, irisColor, uIrisColor)

// A field of the list as a member, by its GLSL name and by its C++ name.
#define CSM_GLSL_FIELD(type, cppName, glslName) type glslName;
#define CSM_CPP_FIELD(type, cppName, glslName) type cppName;

#endif
