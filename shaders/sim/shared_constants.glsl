// What the CPU reference and the GPU passes share, in one file both include: C++ through
// sim/gpu/gpu_params.h and sim/solver/*.cpp, GLSL through shaders/sim/common.glsl. Only
// #defines, valid in both. Each number names the two places that use it; the GPU solver's
// parameter block is declared once here, as a list both languages expand into a struct.
#ifndef CSM_SIM_SHARED_CONSTANTS_GLSL
#define CSM_SIM_SHARED_CONSTANTS_GLSL

// ---- Numbers -----------------------------------------------------------------------------------
// Pi to more digits than a double holds, so that C++ rounds it to M_PI and GLSL to the nearest
// float: the wind field (shared_functions.glsl) and the render shaders' lighting and children.
#define CSM_PI 3.14159265358979323846

// ---- The follower push ------------------------------------------------------------------------
// A follower point the blend of its guides put inside the head is moved out along the field's
// normal (or a sphere's radius) to this far (m) outside the surface, in at most this many rounds
// (the field is no exact distance, and a sphere's surface may lie in another):
// sim/groom/followers.cpp (the CPU's followers) and shaders/render/hair_followers.comp.
#define CSM_FOLLOWER_PUSH_ROUNDS 8
#define CSM_FOLLOWER_PUSH_MARGIN 1e-4

// ---- Strand contacts --------------------------------------------------------------------------
// Near a held end a pair asks the free end for its depth over the lever arm; no end moves further
// than this many times the pair's depth in one sweep: sim/solver/contacts.cpp (kLever, which
// says why 2.5), shaders/sim/contact_solve.comp, and the generator's separation
// (sim/groom/hairstyle.cpp, kSeparationLever).
#define CSM_CONTACT_LEVER 2.5

// ---- A strand-contact pair's orientation ------------------------------------------------------
// Its flags (sim/solver/contacts.h pairFlags, shaders/sim/common.glsl): closest points inside both
// segments, closer than 2r, the sign of the triple product, skew enough (the sine of the
// segments' angle above CSM_SKEW_SINE) for that sign to say which side each is on. Closest
// points count as inside a segment further than CSM_PAIR_INSIDE (of its length) from its ends.
#define CSM_PAIR_INTERIOR 1u
#define CSM_PAIR_NEAR 2u
#define CSM_PAIR_POSITIVE 4u
#define CSM_PAIR_SKEW 8u
#define CSM_SKEW_SINE 0.1
#define CSM_PAIR_INSIDE 1e-6
// How far (m) a sweep must move an end to count as one of the particle's segments:
// sim/solver/contacts.cpp (kFullWeight, which says why) and shaders/sim/contact_solve.comp.
#define CSM_FULL_WEIGHT 1e-6

// ---- The contact measures' strand sample ------------------------------------------------------
// A mode without strand contacts measures them only for --metrics and the Stats panel (a candidate
// search a sampled frame, outside the step). Hair of more than CSM_MEASURED_PARTICLES particles is
// measured on 1 strand in ceil(particles / CSM_MEASURED_PARTICLES), chosen by a hash of the strand
// (not its index, which follows the scalp): candidate pairs grow with the square of the hair's
// density, so the whole hair's search costs many steps at 30,000 strands (25x the run's time and
// 6.7x its memory at 2 frames there, 2026-11-28). 40,000 particles: the default preset's hair
// (36,369) is measured whole, and a sample is at least as large. sim/core/measure_sample.h
// (measureStride, inMeasureSample) and shaders/sim/common.glsl (inMeasureSample), the grid passes
// (grid_count.comp, grid_scatter.comp) and the CPU solver's measure (sim/solver/cpu_solver.cpp).
#define CSM_MEASURED_PARTICLES 40000u

// ---- The volume grid ---------------------------------------------------------------------------
// Fixed-point units of the grid's sums: 2^-24 m of strand, 2^-24 m^2/s of length times speed
// (sim/solver/volume.h kVolumeUnit, shaders/sim/common.glsl).
#define CSM_VOLUME_UNIT 16777216.0

// ---- The head's push within reach --------------------------------------------------------------
// A particle pushed out of the head counts as within reach of its parent while the segment is no
// longer than its limit times (1 + this): sim/solver/cpu_steps.cpp in double, where 1e-6 is far
// above the rounding of a length; shaders/sim/strain_limit.comp in float, where a length of a few
// centimetres rounds by ~1e-7 relative and the push and the clamp each add some: 1e-5.
#define CSM_REACH_SLACK_DOUBLE 1e-6
#define CSM_REACH_SLACK_FLOAT 1e-5
// ... and, in float, give or take this much of the larger coordinate of the two: a float position
// rounds by up to 2^-24 of its size (6e-8 m at a head 1 m from the origin, 5e-7 m at a character
// that walked 8 m), each push and clamp adding some, which a length of 2 cm would not cover
// (without it, a travelling character's particles on the head fell through to the last resort of
// the push and were flung: docs/BENCHMARKS.md, "Hair on a moving character").
#define CSM_REACH_ROUNDING_FLOAT 1e-6

// ---- The clamp's field -------------------------------------------------------------------------
// Behind the clamp the field keeps its value deeper than this many fit reaches (tau):
// sim/solver/stiffness.h (kClampDepth, which says why 1.5) and shaders/sim/clamp_field.glsl.
#define CSM_CLAMP_DEPTH 1.5

// ---- A strand's held particles -----------------------------------------------------------------
// A strand's per-strand vec4 (CSM_BIND_STRAND_STIFFNESS) holds in z its pinned particles from the
// root, plus CSM_TIP_HELD when the head holds its last particle too (Groom::tipHeld, a strand tied
// at both ends): sim/gpu/strand_buffers.cpp and shaders/sim/common.glsl (pinnedOf, tipHeldOf).
// Pinned counts stay below it (kMaxStrandParticles, 256).
#define CSM_TIP_HELD 1024
// The sweeps back from a held tip and forth from the root (pairs of them) that share out the
// stretch the strain limit's sweep leaves such a strand, at most: limitStrainStrand
// (sim/solver/cpu_steps.cpp), shaders/sim/strain_limit.comp and strand_group.glsl.
#define CSM_TIED_SWEEPS 4

// ---- Stiffness models (StiffnessModel, sim/core/config.h; shaders/sim/shape_match.comp) --------
#define CSM_STIFFNESS_PAPER 0
#define CSM_STIFFNESS_CALIBRATED 1

// ---- The parameter block ------------------------------------------------------------------------
// SimParams: the frame's parameters, written by GpuSolver::writeParams (sim/gpu/gpu_solver.cpp)
// and ContactSearch (the grid's fields), read as `P` by every pass. Fields in groups of 16 bytes
// (std430: a vec3 takes the first 12 of its group and a scalar may follow it; mat4 whole
// groups), so that C++ (glm, no padding) and GLSL agree; tests/gpu/gpu_solver_test.cpp checks
// every offset against the linked program's. By group:
//   gravity (m/s^2)
//   windDirection (unit), windStrength (m/s)
//   gusts, gustFrequency (Hz), turbulence, turbulenceScale (m)
//   alpha (the paper's), strainLimit (epsilon), radius (hair radius r, m), headFriction
//   candidateDistance (2 contactRadius + margin, m), compliance (m/N), friction, sweepSolve (1: collision.solve
//     sweep, 0: jacobi)
//   dftl, windDrag (1/s), penaltyStiffness (1/s^2), penaltyDamping (1/s)
//   torsoSphereFirst (the first of the spheres that are the torso's: headSpheres when none),
//     stiffnessModel (CSM_STIFFNESS_*), rotationIterations, headSpheres (count: the head's and
//     the torso's)
//   strainLimiting, headCollision, windOn, strandContacts (this frame's constraints, which the
//     strain limit's sweep applies; 0 with the penalty model): 0 or 1
//   particles, strands, segments, torsoIsField (1: the body has a torso field, after the head's)
//   bucketMask (buckets - 1), entryCapacity, pairListCapacity, listHalf (this frame's half of the
//     candidate range: 0 or 1)
//   cellEdge (m), inverseCellEdge, cellPadding (the box padding, m), contactRadius (the radius
//     strands touch at, m: radius, or a guide's wisp's, contactRadius in sim/solver/contacts.h)
//   gridOrigin: the grid's origin, the head's position this frame
//   volumeToHead, volumeToWorld: the volume grid, fixed to the head where the frame starts
//     (sim/solver/volume.h), and back
//   volumeOrigin (its lowest node, head frame), volumeCell (node spacing, m)
//   volumeDims (nodes per axis), volumeForces (this frame: 0 or 1)
//   volumeFriction (1/s), volumeStiffness (m^2/s^2), volumeAllowed (fraction), volumePerUnit
//     (volume fraction per fixed-point unit of strand length at a node)
//   headFieldOrigin (the head's distance field's lowest node, head frame), headFieldCell (m)
//   headFieldDims (nodes per axis), headIsField (1: the head is the field, else spheres)
//   torsoFieldOrigin (the torso's field's lowest node, torso frame), torsoFieldCell (m)
//   torsoFieldDims, torsoFieldOffset (its first node in the field's buffer, after the head's)
#define CSM_SIM_PARAMS(F)                                                                        \
  F(vec3, gravity) F(float, unused0)                                                             \
  F(vec3, windDirection) F(float, windStrength)                                                  \
  F(float, gusts) F(float, gustFrequency) F(float, turbulence) F(float, turbulenceScale)         \
  F(float, alpha) F(float, strainLimit) F(float, radius) F(float, headFriction)                  \
  F(float, candidateDistance) F(float, compliance) F(float, friction) F(float, sweepSolve)       \
  F(float, dftl) F(float, windDrag) F(float, penaltyStiffness) F(float, penaltyDamping)         \
  F(int, torsoSphereFirst) F(int, stiffnessModel) F(int, rotationIterations)                    \
  F(int, headSpheres)                                                                            \
  F(uint, strainLimiting) F(uint, headCollision) F(uint, windOn) F(uint, strandContacts)         \
  F(uint, particles) F(uint, strands) F(uint, segments) F(uint, torsoIsField)                    \
  F(uint, bucketMask) F(uint, entryCapacity) F(uint, pairListCapacity) F(uint, listHalf)         \
  F(float, cellEdge) F(float, inverseCellEdge) F(float, cellPadding) F(float, contactRadius)     \
  F(vec3, gridOrigin) F(float, unused6)                                                          \
  F(mat4, volumeToHead) F(mat4, volumeToWorld)                                                   \
  F(vec3, volumeOrigin) F(float, volumeCell)                                                     \
  F(uvec3, volumeDims) F(uint, volumeForces)                                                     \
  F(float, volumeFriction) F(float, volumeStiffness) F(float, volumeAllowed)                     \
  F(float, volumePerUnit)                                                                        \
  F(vec3, headFieldOrigin) F(float, headFieldCell)                                               \
  F(uvec3, headFieldDims) F(uint, headIsField)                                                   \
  F(vec3, torsoFieldOrigin) F(float, torsoFieldCell)                                             \
  F(uvec3, torsoFieldDims) F(uint, torsoFieldOffset)

// Substep: one per substep of the frame, after SimParams (`S[k]`).
//   head: the head's pose at the end of the step (pinned roots follow it)
//   headDelta: the start-of-step pose after the inverse of the end pose (head friction)
//   stepStart (s), h (s), twistStep (twistStepOf), velocityKept (by damping: exp(-c h))
//   torsoRotation (a unit quaternion, xyz w), torsoTranslation (xyz): the torso's pose at the
//     end of the step; torsoDeltaRotation, torsoDeltaTranslation: its headDelta (quaternions,
//     not matrices, to keep CSM_MAX_SUBSTEPS steps within a uniform block's 64 KiB)
#define CSM_SUBSTEP(F)                                                                           \
  F(mat4, head) F(mat4, headDelta)                                                               \
  F(float, stepStart) F(float, h) F(float, twistStep) F(float, velocityKept)                     \
  F(vec4, torsoRotation) F(vec4, torsoTranslation)                                               \
  F(vec4, torsoDeltaRotation) F(vec4, torsoDeltaTranslation)

// Substeps a frame may hold (sim.max_substeps at most): the size of the uniform block's array
// (common.glsl, CSM_PARAMS_UNIFORM).
#define CSM_MAX_SUBSTEPS 256

// A field of the list as a struct member (both languages).
#define CSM_MEMBER(type, name) type name;

#endif
