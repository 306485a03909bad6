// The GPU solver's parameter block: the C++ twin of SimParams and Substep in
// shaders/sim/common.glsl (std430: every member a 16-byte vec4, ivec4, uvec4 or mat4, so
// the layouts agree without padding rules). tests/gpu/gpu_solver_test.cpp checks the offsets
// against the linked program's.
#pragma once

#include <cstddef>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace csm::gpu {

struct SimParams {
  glm::vec4 gravity;    // xyz, w unused
  glm::vec4 windDir;    // xyz unit direction, w strength (m/s)
  glm::vec4 windShape;  // x gusts, y gust frequency (Hz), z turbulence, w turbulence scale (m)
  glm::vec4 stepping;   // x alpha, y strain limit epsilon, z hair radius r, w head friction
  glm::vec4 contact;    // x candidate distance 2r + margin (m), y compliance (m/N), z friction,
                        // w 1 when collision.solve is sweep, 0 for jacobi
  glm::vec4 misc;       // x DFTL, y wind drag (1/s), z, w unused
  glm::ivec4 ints;      // x unused, y stiffness model, z rotation iterations, w head spheres
  glm::uvec4 flags;     // x strain limiting, y head collision, z wind, w strand contacts this frame
  glm::uvec4 counts;    // x particles, y strands, z segments, w unused
  glm::uvec4 grid;      // x bucket mask, y entry capacity, z pair list capacity, w this frame's
                        // half of CANDIDATE_RANGE
  glm::vec4 cells;      // x cell edge (m), y 1 / edge, z box padding (m), w unused
  glm::vec4 origin;     // xyz the grid's origin (the head's position this frame), w unused
  // The volume mode (sim/solver/volume.h): its grid is fixed to the head where the frame starts.
  glm::mat4 volumeToHead;   // world to that head frame
  glm::mat4 volumeToWorld;  // and back
  glm::vec4 volumeOrigin;   // xyz the grid's lowest node (head frame), w node spacing (m)
  glm::uvec4 volumeDims;    // xyz nodes per axis, w volume forces this frame
  glm::vec4 volume;         // x friction (1/s), y stiffness (m^2/s^2), z fraction allowed, w volume
                            // fraction per fixed-point unit of strand length at a node
  // The head's distance field (sim/head/head_shape.h), in the head's frame.
  glm::vec4 headField;       // xyz the field's lowest node, w node spacing (m)
  glm::uvec4 headFieldDims;  // xyz nodes per axis, w 1 when the head is the field (else spheres)
};

struct Substep {
  glm::mat4 head;       // head pose at the end of the step
  glm::mat4 headDelta;  // start-of-step pose after the inverse of the end pose
  glm::vec4 time;       // x time at the start, y h, z twist step, w velocity kept by damping
};

static_assert(sizeof(SimParams) == 12 * 16 + 2 * 64 + 5 * 16);
static_assert(offsetof(SimParams, cells) == 10 * 16);
static_assert(sizeof(Substep) == 144);

}  // namespace csm::gpu
