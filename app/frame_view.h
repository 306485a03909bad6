// What the renderer draws of a simulation's frame: the app builds the FrameView
// (render/renderer.h) from the Simulation, so that render/ knows frames, not simulations.
#pragma once

#include "render/position_source.h"
#include "render/renderer.h"
#include "sim/run/simulation.h"

namespace csm {

// The FrameView of a simulation's current frame seen as `view` says, drawn into
// `framebuffer` at width x height.
FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer = 0);

// The FrameView of frame parts: the scene's config, its grown hair (of `generation`), the head at
// `head` and the torso at `torso`, the positions in `positionBuffer` (a shot's cached frame, or a
// simulation's).
FrameView frameViewOf(const Config& scene, const GrownScene& grown, long generation,
                      const Pose& head, const Pose& torso, const ViewConfig& view,
                      unsigned positionBuffer, int width, int height, unsigned framebuffer = 0);

// The SSBO with the simulation's current positions: the solver's own, or (a solver that keeps
// none on the GPU) its positions read back and uploaded into `upload`'s buffer.
unsigned positionsToDraw(const Simulation& sim, PositionSource& upload);

}  // namespace csm
