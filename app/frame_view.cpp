#include "app/frame_view.h"

#include <algorithm>

#include "render/camera.h"

namespace csm {

FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer) {
  return frameViewOf(sim.config(), sim.scene(), sim.generation(), sim.headPose(), sim.torsoPose(),
                     view, positionBuffer, width, height, framebuffer);
}

FrameView frameViewOf(const Config& scene, const GrownScene& grown, long generation,
                      const Pose& head, const Pose& torso, const ViewConfig& view,
                      unsigned positionBuffer, int width, int height, unsigned framebuffer) {
  FrameView v;
  v.scene = &scene;
  v.look = &view;
  v.groom = grown.groom.get();
  v.followers = grown.followers.get();
  v.generation = generation;
  v.head = grown.head.get();
  v.headPose = head;
  v.torsoPose = torso;
  v.positionBuffer = positionBuffer;
  v.width = width;
  v.height = height;
  v.targetFramebuffer = framebuffer;
  if (!scene.motion.clip.empty()) {
    // A clip carries the character through the world: the camera follows its horizontal travel
    // (the neck's), so it stays in view as it walks and the hair's motion reads against it.
    const glm::dvec3 pivot(scene.head.pivot);
    glm::vec3 travel(head.apply(pivot) - pivot);
    travel.y = 0.0f;
    CameraConfig camera = view.camera;
    camera.target += travel;
    v.useCameraMatrices = true;
    v.view = cameraView(camera);
    v.projection = cameraProjection(camera, float(width) / float(std::max(height, 1)));
  }
  return v;
}

unsigned positionsToDraw(const Simulation& sim, PositionSource& upload) {
  if (const unsigned own = sim.positionBuffer(); own != 0) return own;
  sim.readPositions(upload.scratch());
  return upload.upload(upload.scratch());
}

}  // namespace csm
