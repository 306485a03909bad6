#include "app/frame_view.h"

namespace csm {

FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer) {
  return frameViewOf(sim.config(), sim.scene(), sim.generation(), sim.headPose(), view,
                     positionBuffer, width, height, framebuffer);
}

FrameView frameViewOf(const Config& scene, const GrownScene& grown, long generation,
                      const Pose& head, const ViewConfig& view, unsigned positionBuffer, int width,
                      int height, unsigned framebuffer) {
  FrameView v;
  v.scene = &scene;
  v.look = &view;
  v.groom = grown.groom.get();
  v.followers = grown.followers.get();
  v.generation = generation;
  v.head = grown.head.get();
  v.headPose = head;
  v.positionBuffer = positionBuffer;
  v.width = width;
  v.height = height;
  v.targetFramebuffer = framebuffer;
  return v;
}

unsigned positionsToDraw(const Simulation& sim, PositionSource& upload) {
  if (const unsigned own = sim.positionBuffer(); own != 0) return own;
  sim.readPositions(upload.scratch());
  return upload.upload(upload.scratch());
}

}  // namespace csm
