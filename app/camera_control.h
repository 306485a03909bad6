// Mouse navigation for the viewer: orbit, pan and zoom of the preset's orbit camera
// (camera.* parameters, so the panel and the mouse edit the same values), framing the head,
// and turning the head about the neck with the mouse. Pure math: no window, no ImGui.
#pragma once

#include "render/view_config.h"
#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "sim/head/head_model.h"

namespace csm {

// Degrees of yaw and pitch per pixel of mouse motion.
inline constexpr float kOrbitDegreesPerPixel = 0.3f;
// Degrees the head turns per pixel of drag.
inline constexpr double kHeadDegreesPerPixel = 0.25;

// Dragging right turns the camera around the target to the left, as if the scene were
// grabbed; pitch stays within the parameter's range.
void orbitCamera(CameraConfig& camera, float dxPixels, float dyPixels);
// Moves the target so the point under the cursor (at the target's depth) follows it.
void panCamera(CameraConfig& camera, float dxPixels, float dyPixels, int viewportHeight);
// Positive steps (wheel up) move closer; each step is 10 %. Clamped to the distance's range.
void zoomCamera(CameraConfig& camera, float steps);
// Aims at the head as it is now and backs off until the head spheres and the longest
// strands around the scalp fit the view.
void frameHead(CameraConfig& camera, const Config& config, const HeadModel& model,
               const Pose& head);

// The user's extra head pose after a drag of (dx, dy) pixels: horizontal motion turns the
// head about the vertical axis (shaking no), vertical motion about the camera's right axis
// (nodding), both through the neck pivot (head.pivot) where the head is now.
Pose dragHead(const Pose& user, const CameraConfig& camera, const HeadConfig& head, float dxPixels,
              float dyPixels);

}  // namespace csm
