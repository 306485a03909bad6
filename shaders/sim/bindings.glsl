// Shader storage binding points of the GPU solver, shared by C++ (sim/gpu/gpu_solver.cpp
// includes this file) and GLSL (shaders/sim/common.glsl): only #defines, valid in both.
// Each pass declares the blocks it uses; the numbers are unique so that every buffer stays
// bound at its own point for the whole frame. GL 4.3 guarantees 8 blocks per compute shader
// (no pass here declares more) but only 8 binding points; every driver we run on has more
// than the 30 used here, 0-29 (llvmpipe 80, NVIDIA 96, AMD and Intel 32 or more).
#ifndef CSM_SIM_BINDINGS_GLSL
#define CSM_SIM_BINDINGS_GLSL

// The hair state, in HairState's layout (sim/core/hair_state.h).
#define CSM_BIND_REST 0             // vec4: rest xyz in the head frame, w the clamp field's
                                    // tau (clamp_field.glsl; the GPU reads no mass from it)
#define CSM_BIND_POSITION 1         // vec4: world position (the renderer draws from it)
#define CSM_BIND_VELOCITY 2         // vec4
#define CSM_BIND_STRAND_FIRST 3     // uint: strand s owns [first[s], first[s+1])
#define CSM_BIND_PARTICLE_STRAND 4  // uint: strand of each particle
// Solver state.
#define CSM_BIND_PREDICTED 5     // vec4: x* of the current step
#define CSM_BIND_ROTATION 6      // vec4: quaternion (xyz, w) of each particle's region, warm start
#define CSM_BIND_STRAND_ORDER 7  // uint: strands by length, for the per-strand passes
#define CSM_BIND_HEAD_FIELD 28  // vec4 per node of the head's distance field (CSM_STORAGE_READS)
#define CSM_BIND_VOLUME_REST 29  // float per node of the volume: the rest groom's fraction (ditto)
#define CSM_BIND_STRAND_GROUPS \
  27  // uint per work group + 1 of the per-particle passes: the first particle of each
      // (sim/gpu/strand_groups.h, shaders/sim/strand_group.glsl)
#define CSM_BIND_PARAMS 8        // SimParams + one Substep per substep
// The same buffer as a uniform block (binding point of GL_UNIFORM_BUFFER), for the passes built
// with CSM_PARAMS_UNIFORM (on a GPU: a uniform block's reads, the same for every invocation,
// come from the constant cache).
#define CSM_UNIFORM_PARAMS 3  // (the renderer's frame block is at 0: render/bindings.h)
#define CSM_BIND_REGION \
  22  // vec4 per particle: its region (sim/solver/stiffness.h): x per-region
      // mass, y 1 / J (0: no extent), z first (negative: that many
      // ghosts and particles from 0), w last particle of the region
      // (indices within the strand, exact in float)
#define CSM_BIND_STRAND_STIFFNESS \
  23  // vec4 per strand: x calibrated rate k (1/s^2), y per-region
      // mass of a ghost, z pinned particles, w the end of the clamp
      // field's fit particles (clamp_field.glsl; none when <= z)
#define CSM_BIND_MEASURE \
  24                        // uvec4 x2 per CSM_MEASURE_GROUP particles: the measures of the
                            // group (measure.comp), read back behind a fence
#define CSM_BIND_SPHERES 9  // vec4: world head spheres (centre, radius) per substep
// Hair-hair collision.
#define CSM_BIND_CORRECTION \
  10  // vec4 x2 per segment: this substep's strand-contact corrections of
      // its two particles (w: how many contacts sent each, or for
      // collision.solve = sweep up to 1, as one segment)
#define CSM_BIND_SEGMENT_PAIRS \
  11  // uint per particle: candidate pairs its segment is in (counted by
      // candidates.comp, back to 0 after pair_scatter.comp)
#define CSM_BIND_SEGMENT_BASE \
  12                            // uint per particle + 4: exclusive scan of those, where its
                                // pairs start in PAIR_SIDES
#define CSM_BIND_GRID_COUNT 13  // uint per bucket: entries in it (back to 0 after scatter)
#define CSM_BIND_GRID_START \
  14                             // uint per bucket + 4: exclusive scan of the counts; entry
                                 // `buckets` is the total the grid needed
#define CSM_BIND_SCAN_BLOCKS 15  // uint per CSM_SCAN_LEAF buckets: block sums, then their scan
#define CSM_BIND_COUNTERS \
  18                                  // uint[CSM_COUNTERS]: the CSM_COUNTER_* below
#define CSM_BIND_DISPATCH \
  19  // uvec4 per indirect dispatch (dispatch_size.comp): the work groups x, y, z of a pass
      // whose item count only the GPU knows (CSM_DISPATCH_*)
#define CSM_BIND_CANDIDATE_RANGE \
  20  // uvec2 per particle, twice (this frame's half and the last
      // frame's, P.listHalf says which): where each segment's candidates
      // start in CANDIDATES (LAST_CANDIDATES for last frame's), and how
      // many
#define CSM_BIND_PARTICLE_CONSTANTS \
  16  // vec2 per particle, set with the regions: x its inverse mass as the
      // strand contacts see it, 0 when the head holds it
      // (csm::contactInverseMass), y the clamp's pull (csm::Regions::clampPull)
#define CSM_BIND_SEGMENT_ORDER \
  17  // uint per particle: the segments of each run of CSM_PARTICLE_GROUP by
      // candidate count, most first (segment_order.comp), for the list pass
      // and the contact solve
#define CSM_BIND_VOLUME_SUMS \
  21  // int x4 per node of the volume grid: strand length (2^-24 m), length
      // times velocity (2^-24 m^2/s), x y z (sim/solver/volume.h); then two ivec4,
      // the nodes the splat reached (volumeBox in common.glsl)
#define CSM_BIND_VOLUME_LENGTH 25  // float per particle: its share of strand length (m)
#define CSM_BIND_VOLUME_FIELD \
  26  // vec4 x 2 per node, from this frame's sums (volume_field.comp):
      // length times velocity x y z and length, as floats; the gradient of
      // the volume fraction over what is allowed (1/m, head frame), 0

// Texture units of buffer textures (samplerBuffer views of the buffers above), for reads
// that differ per invocation: on llvmpipe a texel fetch is a vector gather where a storage
// load is a loop over the SIMD lanes (gl/buffer_texture.h).
#define CSM_TEX_POSITION 0
#define CSM_TEX_VELOCITY 1
#define CSM_TEX_REST 2
#define CSM_TEX_ENTRIES 3
#define CSM_TEX_GRID_START 4
#define CSM_TEX_VOLUME_FIELD 5
#define CSM_TEX_PREDICTED 6
#define CSM_TEX_REGION 7
#define CSM_TEX_PARTICLE_CONSTANTS 8
#define CSM_TEX_VOLUME_SUMS 9
#define CSM_TEX_VOLUME_REST 10  // float per node: the volume fraction the rest groom fills
#define CSM_TEX_HEAD_FIELD 11   // vec4 per node of the head's distance field: gradient, distance

// Image units of the buffers that grow with the hair's density (imageBuffer views, read and
// written with imageLoad / imageStore): a view holds GL_MAX_TEXTURE_BUFFER_SIZE texels (2^27 on
// llvmpipe and NVIDIA) where a storage block holds GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes (128
// MiB on llvmpipe and Intel's Mesa: 8.4 M candidate pairs). The sides and the lists, two texels
// a pair, are each seen through two views, the second from texel `listSplit` on (a uniform of
// the passes that use them, the texels of one view): 2^27 pairs in all (134 M). Those passes
// are built twice, with CSM_SPLIT_VIEWS defined and without; the second view is used only when
// the lists outgrow the first. GL 4.3 guarantees 8 image units and 8 images per compute
// shader: these are units 0-7, and no pass declares more than 6.
#define CSM_IMAGE_ENTRIES 0     // rgba32ui per grid entry (packEntry in common.glsl); read by
                                // texelFetch through CSM_TEX_ENTRIES
#define CSM_IMAGE_PAIR_LIST 1   // rgba32ui per candidate pair, in no order: a, b | flags << 28,
                                // the contact distance (float bits), unused
#define CSM_IMAGE_PAIR_SIDES 2  // rg32ui x 2 per candidate pair: each segment's candidates (as
                                // in CANDIDATES), from its SEGMENT_BASE on, in no order
#define CSM_IMAGE_PAIR_SIDES_HIGH 3  // the same from texel listSplit on
#define CSM_IMAGE_CANDIDATES 4  // rg32ui x 2 per slot of the pair list: this frame's lists, each
                                // segment's candidates in ascending order, x the other segment
                                // | flags << 28 (sim/solver/contacts.h), y the contact distance (float
                                // bits)
#define CSM_IMAGE_CANDIDATES_HIGH 5
#define CSM_IMAGE_LAST_CANDIDATES 6  // the same, last frame's (the two buffers swap each frame)
#define CSM_IMAGE_LAST_CANDIDATES_HIGH 7

// Slots of the COUNTERS buffer.
#define CSM_COUNTER_ENTRIES 0
#define CSM_COUNTER_CONTACTS 1
#define CSM_COUNTER_PENETRATIONS 2
#define CSM_COUNTER_CROSSINGS_CLOSE 3  // of those below, pairs the groom put closer than 2r
#define CSM_COUNTER_OVERSIZE 4
#define CSM_COUNTER_CANDIDATES 5  // pairs within 2r + margin
#define CSM_COUNTER_CROSSINGS 6   // pairs whose orientation flipped since the last frame
#define CSM_COUNTER_CROWDED 7     // segments left without candidates in a crowd (more than
                                  // CSM_MAX_CANDIDATES, or a grid cell too full to test)
#define CSM_COUNTER_MAX_DEPTH 8   // deepest penetration in r (float bits: positive floats
                                  // order as their bits)
#define CSM_COUNTER_PAIR_LIST 9   // candidate pairs the pair list needed (over its capacity:
                                  // the last list stays)
#define CSM_COUNTER_DEPTH 16      // csm::kDepthBins bins of penetration depth (sim/solver/contacts.h)
#define CSM_DEPTH_BINS 64
#define CSM_DEPTH_BINS_PER_R 32
#define CSM_COUNTERS_PER_FRAME 80  // the slots above, cleared by each candidate search
#define CSM_COUNTER_OVERFLOWS 80  // searches since the grid's reset whose grid or pair list did
                                  // not fit (those kept the last list): kept
#define CSM_COUNTERS 84

// Slots of the DISPATCH buffer.
#define CSM_DISPATCH_CANDIDATES 0    // the candidate pass: one invocation per grid entry
#define CSM_DISPATCH_PAIR_SCATTER 1  // the pair scatter: one per listed pair
#define CSM_DISPATCH_VOLUME_FIELD 2  // the volume's node pass: one per node of the hair's box
#define CSM_DISPATCHES 3

// Candidate lists (sim/solver/contacts.h).
#define CSM_MAX_SEGMENT_CELLS 64   // cells a segment may enter (see segmentCells)
#define CSM_CANDIDATE_SHIFT 28     // the flags' place in a candidate
// Candidates a segment's list may hold. A segment with more (in a crowd no hair has) is in no
// pair this frame, on either side, and counted (CSM_COUNTER_CROWDED): the list pass then stays
// within the loop iterations a driver allows one invocation (llvmpipe cuts every loop of an
// invocation short, silently, after 65,535 in all: its LP_MAX_TGSI_LOOP_ITERATIONS).
#define CSM_MAX_CANDIDATES 2048

// Work group sizes.
#define CSM_PARTICLE_GROUP 128  // per-particle and per-segment passes
#define CSM_STRAND_GROUP 64     // per-strand passes
#define CSM_CONTACT_GROUP 64    // the candidate pass
#define CSM_MEASURE_GROUP 256   // the measure pass: particles reduced into one record
#define CSM_SCAN_GROUP 256      // invocations of the block-sum scan group; each scans 2 sums
#define CSM_SCAN_BLOCK 512      // block sums per round of that scan (2 x CSM_SCAN_GROUP)
#define CSM_SCAN_LEAF 64        // bucket counts summed by one invocation (a power of two)

#endif
