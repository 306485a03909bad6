// The volume mode on the GPU (METHOD.md section 2.6; sim/solver/volume.h is the CPU reference):
// once a frame, volume_splat.comp splats each particle's length and momentum onto the grid's
// nodes, volume_dispatch.comp sizes the next pass to the box of nodes the splat reached, and
// volume_field.comp (indirect) turns each node's sums into its field, which the step's passes
// read (predict.comp, strand_step.comp). The grid's geometry, each particle's length and the
// rest fractions come from the CPU reference, set up once per groom.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "sim/core/config.h"
#include "sim/core/hair_state.h"
#include "sim/core/pose.h"
#include "sim/gpu/compute_pass.h"
#include "sim/gpu/gpu_params.h"
#include "sim/solver/volume.h"

namespace csm::gpu {

class VolumePasses {
 public:
  // `device`: defines every pass is built with (GpuSolver's reads).
  bool build(const std::vector<gl::Define>& device, std::string* error);
  // The grid for the groom of `state` under `collision` (its geometry, the particles' lengths,
  // the rest fractions), the sums and the field zeroed. A mode without the volume keeps no grid:
  // its buffers shrink to one element.
  void reset(const HairState& state, const CollisionConfig& collision);
  // The sums, lengths, rest fractions and field at their points, storage and texel views both.
  void bind() const;
  // The volume's lanes of the frame's parameters: the grid fixed to the head where the frame
  // starts (`frameStart`).
  void writeParams(SimParams& p, const CollisionConfig& collision, const Pose& frameStart) const;
  // The frame's splat and field from the bound state (the timer's stage is the caller's): the
  // field pass dispatched from `dispatch` (ContactSearch's indirect arguments), which
  // volume_dispatch.comp sizes.
  void run(uint32_t particles, const gl::Buffer& dispatch);
  // Nodes of the grid: none unless collision.mode is a volume mode.
  size_t nodes() const { return grid_.nodes(); }
  // Nodes the field pass ran on in the last frame: the box the splat reached (reads back the
  // indirect arguments in `dispatch`).
  size_t nodesVisited(const gl::Buffer& dispatch) const;
  // The bytes of its buffers.
  uint64_t bytes() const { return sums_.size() + length_.size() + rest_.size() + field_.size(); }

 private:
  ComputePass splatPass_, dispatchPass_, fieldPass_;
  // The grid's geometry (the CPU reference's), its sums, per-particle lengths, rest fractions
  // and each node's field (CSM_BIND_VOLUME_FIELD), read by texel fetches.
  VolumeGrid grid_;
  gl::Buffer sums_{gl::NoCreate}, length_{gl::NoCreate}, rest_{gl::NoCreate}, field_{gl::NoCreate};
  gl::BufferTexture sumsTex_{gl::NoCreate}, restTex_{gl::NoCreate}, fieldTex_{gl::NoCreate};
};

}  // namespace csm::gpu
