// Binding points shared by the C++ passes (render/bindings.h, as csm::bindings constants) and
// the GLSL in shaders/render/ (through frame.glsl): each number written once, here, as a #define
// valid in both languages (as shaders/sim/bindings.glsl does for the solver).
#ifndef CSM_RENDER_BINDINGS_GLSL
#define CSM_RENDER_BINDINGS_GLSL

// Shader storage blocks.
#define CSM_RENDER_POSITIONS 0  // vec4 per particle, world space (the solver's)
#define CSM_RENDER_REST_POSITIONS 1  // vec4 per particle, the head's local frame
#define CSM_RENDER_STRAND_FIRST 2  // uint per strand + 1: first particle of strand s
#define CSM_RENDER_STRAND_ATTRIBUTES 3  // vec4 per strand: groom colour, thickness scale
#define CSM_RENDER_HEAD_SPHERES 4  // two vec4 a placement: world centre, scale; its turn
// The drawn curves, per spline point (StrandGeometry): written by the render's compute passes.
#define CSM_RENDER_SPLINE_FIRST 5  // uint per strand + 1: first spline point of strand s
#define CSM_RENDER_POINT_STRAND 6  // uint per spline point: its strand
#define CSM_RENDER_GUIDE_LINKS 7  // 2 vec4 per strand: hairline and neighbour (children)
#define CSM_RENDER_GUIDE_POINTS 8  // vec4 per spline point: world position, s
#define CSM_RENDER_GUIDE_TANGENTS 9  // vec4 per spline point: d position / d parameter
#define CSM_RENDER_GUIDE_FRAMES 10  // vec4 per spline point: unit normal of its frame
#define CSM_RENDER_GUIDE_SHADE 11  // 2 vec4 per spline point: lit factor, highlights
#define CSM_RENDER_CHILD_POINTS 12  // vec4 per child point: world position, shadow share
#define CSM_RENDER_CHILD_COLORS 13  // uvec4 per child point: colour, coverage, strand id
#define CSM_RENDER_CHILD_FIRST 14  // uint per strand + 1: first child point of strand s
#define CSM_RENDER_CHILD_STRAND 15  // uint per child point (of one child): its strand
// The follower pass (render/follower_pass.h): drawn strands made from their guides.
#define CSM_RENDER_FOLLOW_GUIDE_POSITIONS 16  // vec4 per guide particle: the solver's, world
#define CSM_RENDER_FOLLOW_DRAWN_REST 17  // vec4 per drawn point: rest (head frame), share
#define CSM_RENDER_FOLLOW_DRAWN_FIRST 18  // uint per drawn strand + 1: its first point
#define CSM_RENDER_FOLLOW_GUIDE_STRAND 19  // uint per guide: its drawn strand
#define CSM_RENDER_FOLLOW_GUIDE_FIRST 20  // uint per guide + 1: its first particle
#define CSM_RENDER_FOLLOW_GUIDE_TURNS 21  // vec4 per guide particle: its turn (quaternion)
#define CSM_RENDER_FOLLOW_BOUND_GUIDES 22  // uvec4 per drawn strand: its guides
#define CSM_RENDER_FOLLOW_BOUND_WEIGHTS 23  // vec4 per drawn strand: their weights
#define CSM_RENDER_FOLLOW_DRAWN_POSITIONS 24  // vec4 per drawn point: world (the pass's output)
#define CSM_RENDER_FOLLOW_HEAD 25  // vec4 per field node (gradient, distance) or per sphere
#define CSM_RENDER_FOLLOW_PUSHED 26  // uint: points moved out of the head

// Uniform blocks.
#define CSM_RENDER_FRAME_UNIFORMS 0

// Texture units.
#define CSM_RENDER_LIGHT_DEPTH_UNIT 0  // nearest hair from the light (z0 of the DOM)
#define CSM_RENDER_OPACITY_LAYERS_UNIT 1  // deep opacity layers, RGBA = layers 0..3
#define CSM_RENDER_HEAD_SHADOW_UNIT 2  // head depth from the light (comparison sampler)
#define CSM_RENDER_RESOLVED_UNIT 3  // the resolved HDR frame, for the final pass
#define CSM_RENDER_SCALP_UNIT 4  // where hair grows on each head sphere

#endif
