// Binding points shared by the C++ passes and the GLSL in shaders/render/, as C++ constants: the
// numbers, and what each binds, are in shaders/render/bindings.glsl, which both languages include.
#pragma once

#include "shaders/render/bindings.glsl"

namespace csm::bindings {

// Shader storage blocks.
inline constexpr int kPositions = CSM_RENDER_POSITIONS;
inline constexpr int kRestPositions = CSM_RENDER_REST_POSITIONS;
inline constexpr int kStrandFirst = CSM_RENDER_STRAND_FIRST;
inline constexpr int kStrandAttributes = CSM_RENDER_STRAND_ATTRIBUTES;
inline constexpr int kHeadSpheres = CSM_RENDER_HEAD_SPHERES;
// The drawn curves, per spline point (StrandGeometry): written by the render's compute passes.
inline constexpr int kSplineFirst = CSM_RENDER_SPLINE_FIRST;
inline constexpr int kPointStrand = CSM_RENDER_POINT_STRAND;
inline constexpr int kGuideLinks = CSM_RENDER_GUIDE_LINKS;
inline constexpr int kGuidePoints = CSM_RENDER_GUIDE_POINTS;
inline constexpr int kGuideTangents = CSM_RENDER_GUIDE_TANGENTS;
inline constexpr int kGuideFrames = CSM_RENDER_GUIDE_FRAMES;
inline constexpr int kGuideShade = CSM_RENDER_GUIDE_SHADE;
inline constexpr int kChildPoints = CSM_RENDER_CHILD_POINTS;
inline constexpr int kChildColors = CSM_RENDER_CHILD_COLORS;
inline constexpr int kChildFirst = CSM_RENDER_CHILD_FIRST;
inline constexpr int kChildStrand = CSM_RENDER_CHILD_STRAND;
// The follower pass.
inline constexpr int kFollowGuidePositions = CSM_RENDER_FOLLOW_GUIDE_POSITIONS;
inline constexpr int kFollowDrawnRest = CSM_RENDER_FOLLOW_DRAWN_REST;
inline constexpr int kFollowDrawnFirst = CSM_RENDER_FOLLOW_DRAWN_FIRST;
inline constexpr int kFollowGuideStrand = CSM_RENDER_FOLLOW_GUIDE_STRAND;
inline constexpr int kFollowGuideFirst = CSM_RENDER_FOLLOW_GUIDE_FIRST;
inline constexpr int kFollowGuideTurns = CSM_RENDER_FOLLOW_GUIDE_TURNS;
inline constexpr int kFollowBoundGuides = CSM_RENDER_FOLLOW_BOUND_GUIDES;
inline constexpr int kFollowBoundWeights = CSM_RENDER_FOLLOW_BOUND_WEIGHTS;
inline constexpr int kFollowDrawnPositions = CSM_RENDER_FOLLOW_DRAWN_POSITIONS;
inline constexpr int kFollowHead = CSM_RENDER_FOLLOW_HEAD;
inline constexpr int kFollowPushed = CSM_RENDER_FOLLOW_PUSHED;

// Uniform blocks.
inline constexpr int kFrameUniforms = CSM_RENDER_FRAME_UNIFORMS;

// Texture units.
inline constexpr int kLightDepthUnit = CSM_RENDER_LIGHT_DEPTH_UNIT;
inline constexpr int kOpacityLayersUnit = CSM_RENDER_OPACITY_LAYERS_UNIT;
inline constexpr int kHeadShadowUnit = CSM_RENDER_HEAD_SHADOW_UNIT;
inline constexpr int kResolvedUnit = CSM_RENDER_RESOLVED_UNIT;
inline constexpr int kScalpUnit = CSM_RENDER_SCALP_UNIT;

}  // namespace csm::bindings
