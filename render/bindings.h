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

// Uniform blocks.
inline constexpr int kFrameUniforms = 0;

// Texture units.
inline constexpr int kLightDepthUnit = 0;     // nearest hair from the light (z0 of the DOM)
inline constexpr int kOpacityLayersUnit = 1;  // deep opacity layers, RGBA = layers 0..3
inline constexpr int kHeadShadowUnit = 2;     // head depth from the light (comparison sampler)
inline constexpr int kResolvedUnit = 3;       // the resolved HDR frame, for the final pass
inline constexpr int kScalpUnit = 4;          // where hair grows on each head sphere

}  // namespace csm::bindings
