// Binding points shared by the C++ passes and the GLSL in shaders/render/. The shaders get
// them as #defines (HairRenderer::defines()), so each number is written once, here.
#pragma once

namespace csm::bindings {

// Shader storage blocks.
inline constexpr int kPositions = 0;         // vec4 per particle, world space (the solver's)
inline constexpr int kRestPositions = 1;     // vec4 per particle, the head's local frame
inline constexpr int kStrandFirst = 2;       // uint per strand + 1: first particle of strand s
inline constexpr int kStrandAttributes = 3;  // vec4 per strand: groom colour, thickness scale
inline constexpr int kHeadSpheres = 4;       // vec4 per sphere: world centre, radius
// The drawn curves, per spline point (StrandGeometry): written by the render's compute passes.
inline constexpr int kSplineFirst = 5;    // uint per strand + 1: first spline point of strand s
inline constexpr int kPointStrand = 6;    // uint per spline point: its strand
inline constexpr int kGuideLinks = 7;     // 2 vec4 per strand: hairline and neighbour (children)
inline constexpr int kGuidePoints = 8;    // vec4 per spline point: world position, s
inline constexpr int kGuideTangents = 9;  // vec4 per spline point: d position / d parameter
inline constexpr int kGuideFrames = 10;   // vec4 per spline point: unit normal of its frame
inline constexpr int kGuideShade = 11;    // 2 vec4 per spline point: lit factor, highlights
inline constexpr int kChildPoints = 12;   // vec4 per child point: world position, shadow share
inline constexpr int kChildColors = 13;   // uvec4 per child point: colour, coverage, strand id
inline constexpr int kChildFirst = 14;    // uint per strand + 1: first child point of strand s
inline constexpr int kChildStrand = 15;   // uint per child point (of one child): its strand

// Uniform blocks.
inline constexpr int kFrameUniforms = 0;

// Texture units.
inline constexpr int kLightDepthUnit = 0;     // nearest hair from the light (z0 of the DOM)
inline constexpr int kOpacityLayersUnit = 1;  // deep opacity layers, RGBA = layers 0..3
inline constexpr int kHeadShadowUnit = 2;     // head depth from the light (comparison sampler)
inline constexpr int kResolvedUnit = 3;       // the resolved HDR frame, for the final pass
inline constexpr int kScalpUnit = 4;          // where hair grows on each head sphere

}  // namespace csm::bindings
