// What the renderer (render/hair_renderer.h: deep opacity maps, Yuksel & Keyser 2008; Kajiya-Kay
// hair, 1989; the head) draws of a frame: the FrameView the app builds from a simulation
// (app/frame_view.h), and how much of the look. Hair is drawn straight from a positions SSBO (the
// GPU solver's own buffer): no CPU copy.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "render/camera.h"
#include "render/view_config.h"
#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/core/results.h"
#include "sim/groom/guides.h"
#include "sim/head/head_model.h"

namespace csm {

// How much of the look to draw. Full for captures and a still view; the viewer's interactive
// quality (RenderConfig::interactive*) while the camera moves or the hair simulates.
struct DrawAmount {
  float strands = 1.0f;     // share of the drawn strands: children go first, then guides
  int subdivision = 0;      // spline segments per simulated segment; 0: render.subdivision
  int samples = 0;          // MSAA samples; 0: render.samples
  int shadowMapSize = 0;    // 0: render.shadow_map_size
  bool fullHead = true;     // the head's mesh in full, else its coarser one (HeadMesh)
  float resolution = 1.0f;  // of the target's width and height: drawn smaller, scaled up
  // Of the strands drawn beyond the simulated ones (children; a guided groom's followers): 0
  // draws the simulated strands alone (the guides standing in for their followers), each wider
  // to stand for those left out (InteractiveBudget).
  float extra = 1.0f;
  bool operator==(const DrawAmount&) const = default;
};
// The interactive amount a look asks for (full when render.interactive is off).
DrawAmount interactiveAmount(const RenderConfig& render);

struct FrameView {
  const Config* scene = nullptr;     // head.spheres
  const ViewConfig* look = nullptr;  // render.*, camera.*, light.*
  const Groom* groom = nullptr;      // topology (strand offsets) and per-strand colours
  // When the groom is simulated through guides: the strands drawn and how they follow `groom`
  // (the guides, whose positions positionBuffer holds). Null: `groom` is drawn as simulated.
  const FollowerBinding* followers = nullptr;
  long generation = 0;              // changes when the groom is regrown: rebuild topology buffers
  const HeadModel* head = nullptr;  // the scene's head: what is drawn, where hair grows
  Pose headPose;                    // where the head is this frame
  Pose torsoPose;                   // and the torso (HeadModel::articulated)
  unsigned positionBuffer = 0;      // SSBO: vec4 per particle, world positions
  int width = 1280, height = 720;   // target size in pixels
  unsigned targetFramebuffer = 0;   // GL framebuffer to draw into (0 = the window's)
  DrawAmount amount;                // all of it unless the viewer asks for less
  // Camera: when `useCameraMatrices` is false, derived from look->camera.
  bool useCameraMatrices = false;
  glm::mat4 view{1.0f}, projection{1.0f};
};

// Strands on screen for a groom of `strands` drawn strands (the simulated ones, or the guides and
// their followers): each one plus its render.children children. For the stats next to the
// simulated count.
std::size_t drawnStrandCount(std::size_t strands, const RenderConfig& render);

}  // namespace csm
