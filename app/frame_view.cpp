#include "app/frame_view.h"

namespace csm {

FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer) {
  FrameView v;
  v.scene = &sim.config();
  v.look = &view;
  v.groom = &sim.groom();
  v.followers = sim.followers();
  v.generation = sim.generation();
  v.head = &sim.head();
  v.headPose = sim.headPose();
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
