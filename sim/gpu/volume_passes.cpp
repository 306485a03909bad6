#include "sim/gpu/volume_passes.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "gl/gl.h"
#include "sim/gpu/buffer_fill.h"
#include "shaders/sim/bindings.glsl"

namespace csm::gpu {

bool VolumePasses::build(const std::vector<gl::Define>& device, std::string* error) {
  return splatPass_.build("sim/volume_splat.comp", CSM_PARTICLE_GROUP, device, error) &&
         dispatchPass_.build("sim/volume_dispatch.comp", 1, device, error) &&
         fieldPass_.build("sim/volume_field.comp", CSM_PARTICLE_GROUP, device, error);
}

void VolumePasses::reset(const HairState& state, const CollisionConfig& collision) {
  if (volumeForces(collision.mode)) {
    std::vector<glm::dvec3> rest(state.rest.size());
    for (size_t i = 0; i < rest.size(); ++i) rest[i] = glm::dvec3(glm::vec3(state.rest[i]));
    grid_.reset(rest, state.strandFirst, state.weight, collision.volumeCell, collision.radius);
  } else {
    grid_.release();
  }
  std::vector<float> length(grid_.particleLength().begin(), grid_.particleLength().end());
  fill(length_, length);
  fill(rest_, grid_.restFraction());
  // The nodes' sums, then the box of the nodes the splat reached (volumeBox in common.glsl).
  zeroed<glm::ivec4>(sums_, grid_.empty() ? 0 : grid_.nodes() + 2);
  zeroed<glm::vec4>(field_, 2 * grid_.nodes());
  view(sumsTex_, sums_, gl::TextureFormat::Rgba32i);
  view(restTex_, rest_, gl::TextureFormat::R32f);
  view(fieldTex_, field_, gl::TextureFormat::Rgba32f);
}

void VolumePasses::bind() const {
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  sums_.bindBase(ssbo, CSM_BIND_VOLUME_SUMS);
  length_.bindBase(ssbo, CSM_BIND_VOLUME_LENGTH);
  field_.bindBase(ssbo, CSM_BIND_VOLUME_FIELD);
  sumsTex_.bind(CSM_TEX_VOLUME_SUMS);
  restTex_.bind(CSM_TEX_VOLUME_REST);
  fieldTex_.bind(CSM_TEX_VOLUME_FIELD);
  rest_.bindBase(ssbo, CSM_BIND_VOLUME_REST);
}

void VolumePasses::writeParams(SimParams& p, const CollisionConfig& collision,
                               const Pose& frameStart) const {
  glm::dmat4 toWorld = glm::mat4_cast(frameStart.rotation);
  toWorld[3] = glm::dvec4(frameStart.translation, 1.0);
  p.volumeToWorld = glm::mat4(toWorld);
  p.volumeToHead = glm::mat4(glm::inverse(toWorld));
  p.volumeOrigin = glm::vec3(grid_.origin());
  p.volumeCell = float(grid_.cell());
  p.volumeDims = glm::uvec3(grid_.dims());
  p.volumeForces = volumeForces(collision.mode) && !grid_.empty() ? 1u : 0u;
  p.volumeFriction = collision.volumeFriction;
  p.volumeStiffness = collision.volumeStiffness;
  p.volumeAllowed = collision.volumeFraction;
  p.volumePerUnit = float(grid_.fillPerUnit());
}

void VolumePasses::run(uint32_t particles, const gl::Buffer& dispatch) {
  sums_.clearToZero();
  gl::memoryBarrier(kPassBarrier);
  splatPass_.run(particles);
  gl::memoryBarrier(kPassBarrier);
  // Only the nodes of the box the hair reached: sized on the GPU.
  dispatchPass_.set("groupSize", uint32_t(CSM_PARTICLE_GROUP)).run(1);
  gl::memoryBarrier(gl::Barrier::Command);
  fieldPass_.runIndirect(dispatch, CSM_DISPATCH_VOLUME_FIELD);
  gl::memoryBarrier(kPassBarrier);
}

size_t VolumePasses::nodesVisited(const gl::Buffer& dispatch) const {
  const std::vector<glm::uvec4> d = dispatch.download<glm::uvec4>(CSM_DISPATCHES);
  return size_t(d[CSM_DISPATCH_VOLUME_FIELD].x) * d[CSM_DISPATCH_VOLUME_FIELD].y *
         CSM_PARTICLE_GROUP;
}

}  // namespace csm::gpu
