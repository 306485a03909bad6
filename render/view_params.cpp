#include "render/view_params.h"

namespace csm {
namespace {

bool interactiveQuality(const ViewConfig& v) {
  return v.render.interactive;
}
bool widthInPixels(const ViewConfig& v) {
  return v.render.strandWidthM <= 0.0f;
}
bool hasChildren(const ViewConfig& v) {
  return v.render.children > 0;
}
bool customHairColor(const ViewConfig& v) {
  return v.render.hairColor == HairColor::Custom;
}

std::vector<Param<ViewConfig>> build() {
  return {
      param("render.shadows", "Shadows", "Rendering", &ViewConfig::render, &RenderConfig::shadows,
            0, 1, "Deep opacity map self-shadowing.", Effect::Render),
      param("render.strand_width", "Strand width", "Rendering", &ViewConfig::render,
            &RenderConfig::strandWidth, 0.1, 8.0,
            "Width of a drawn strand (pixels), when render.strand_width_m is 0.", Effect::Render)
          .onlyWhen(widthInPixels),
      param("render.strand_width_m", "Metric strand width", "Rendering", &ViewConfig::render,
            &RenderConfig::strandWidthM, 0.0, 0.002,
            "Width of a drawn strand in metres, narrower on screen as the camera moves away "
            "(under 1.5 pixels it covers less of each pixel instead), and the width its shadow "
            "takes; a drawn strand may stand for several real hairs (each 0.05-0.1 mm). 0: "
            "render.strand_width pixels on screen, shadows as of 0.9 mm strands.",
            Effect::Render)
          .display(1000.0, "mm"),
      param("render.subdivision", "Subdivision", "Rendering", &ViewConfig::render,
            &RenderConfig::subdivision, 1, 16, "Spline segments drawn per simulated segment.",
            Effect::Render),
      param("render.children", "Children", "Rendering|Children", &ViewConfig::render,
            &RenderConfig::children, 0, 64,
            "Hairs drawn around each simulated strand, made on the GPU each frame and not "
            "simulated. Every strand is drawn narrower by sqrt(1 + children): 1 + n strands "
            "cover sqrt(1 + n) times the guides' area.",
            Effect::Render),
      param("render.show_guides", "Guides alone", "Rendering", &ViewConfig::render,
            &RenderConfig::showGuides, 0, 1,
            "A groom simulated through guides (hairstyle.guides): draw the simulated strands "
            "alone, highlighted, instead of every strand drawn from them.",
            Effect::Render),
      param("render.child_radius", "Child radius", "Rendering|Children", &ViewConfig::render,
            &RenderConfig::childRadius, 0.0, 0.05,
            "Children's distance from their guide at the root (m); 0: the typical distance "
            "between neighbouring roots.",
            Effect::Render)
          .display(1000.0, "mm")
          .onlyWhen(hasChildren),
      param("render.child_clump", "Clump", "Rendering|Children", &ViewConfig::render,
            &RenderConfig::childClump, 0.0, 1.0,
            "Share of the children's distance from their guide closed at the tip: 1 gathers "
            "them into a point.",
            Effect::Render)
          .onlyWhen(hasChildren),
      param("render.child_noise", "Child noise", "Rendering|Children", &ViewConfig::render,
            &RenderConfig::childNoise, 0.0, 0.05,
            "How far (m) each child wanders from its place at the tip, growing from the root.",
            Effect::Render)
          .display(1000.0, "mm")
          .onlyWhen(hasChildren),
      param("render.child_length", "Child length variation", "Rendering|Children",
            &ViewConfig::render, &RenderConfig::childLength, 0.0, 0.9,
            "Children are up to this share shorter than their guide.", Effect::Render)
          .onlyWhen(hasChildren),
      param("render.child_interpolation", "Interpolated children", "Rendering|Children",
            &ViewConfig::render, &RenderConfig::childInterpolation, 0.0, 1.0,
            "Share of children lying between their guide and its neighbour, following both "
            "unless the two part (a parting stays a parting).",
            Effect::Render)
          .onlyWhen(hasChildren),
      param("render.hair_color", "Hair colour", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::hairColor, 0, 0,
            "A natural hair colour, darker at the root: black, brown, blond, red (auburn) or "
            "grey; custom: render.root_color and render.tip_color.",
            Effect::Render)
          .choices({"custom", "black", "brown", "blond", "red", "grey"}),
      param("render.root_color", "Root colour", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::rootColor, 0, 1, "Hair colour at the root (render.hair_color custom).",
            Effect::Render)
          .asColor()
          .onlyWhen(customHairColor),
      param("render.tip_color", "Tip colour", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::tipColor, 0, 1, "Hair colour at the tip (render.hair_color custom).",
            Effect::Render)
          .asColor()
          .onlyWhen(customHairColor),
      param("render.color_variation", "Colour variation", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::colorVariation, 0.0, 1.0, "Per-strand random variation of brightness.",
            Effect::Render),
      param("render.specular_shift1", "Primary shift", "Rendering|Specular", &ViewConfig::render,
            &RenderConfig::specularShift1, -1.0, 1.0,
            "Shift of the primary (white) highlight along the strand normal.", Effect::Render),
      param("render.specular_shift2", "Secondary shift", "Rendering|Specular", &ViewConfig::render,
            &RenderConfig::specularShift2, -1.0, 1.0, "Shift of the secondary (tinted) highlight.",
            Effect::Render),
      param("render.specular_exponent1", "Primary exponent", "Rendering|Specular",
            &ViewConfig::render, &RenderConfig::specularExponent1, 1.0, 1000.0,
            "Sharpness of the primary highlight.", Effect::Render)
          .logScale(),
      param("render.specular_exponent2", "Secondary exponent", "Rendering|Specular",
            &ViewConfig::render, &RenderConfig::specularExponent2, 1.0, 1000.0,
            "Sharpness of the secondary highlight.", Effect::Render)
          .logScale(),
      param("render.specular_strength1", "Primary strength", "Rendering|Specular",
            &ViewConfig::render, &RenderConfig::specularStrength1, 0.0, 4.0,
            "Brightness of the primary highlight.", Effect::Render),
      param("render.specular_strength2", "Secondary strength", "Rendering|Specular",
            &ViewConfig::render, &RenderConfig::specularStrength2, 0.0, 4.0,
            "Brightness of the secondary highlight.", Effect::Render),
      param("render.opacity", "Opacity", "Rendering|Shadows", &ViewConfig::render,
            &RenderConfig::opacity, 0.01, 1.0, "Opacity of one strand, for coverage and shadows.",
            Effect::Render),
      param("render.layer_spacing", "Layer spacing", "Rendering|Shadows", &ViewConfig::render,
            &RenderConfig::layerSpacing, 0.0005, 0.2, "Depth between deep opacity map layers (m).",
            Effect::Render),
      param("render.shadow_map_size", "Shadow map size", "Rendering|Shadows", &ViewConfig::render,
            &RenderConfig::shadowMapSize, 128, 4096,
            "Resolution of the deep opacity maps: sharper shadows, equally dark at every size.",
            Effect::Render),
      param("render.head_color", "Head colour", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::headColor, 0, 1, "Colour of the head.", Effect::Render)
          .asColor(),
      param("render.iris_color", "Iris colour", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::irisColor, 0, 1, "Colour of the mannequin's irises.", Effect::Render)
          .asColor(),
      param("render.background", "Background", "Rendering|Colour", &ViewConfig::render,
            &RenderConfig::background, 0, 1, "Background colour.", Effect::Render)
          .asColor(),
      param("render.samples", "MSAA samples", "Rendering", &ViewConfig::render,
            &RenderConfig::samples, 1, 16, "Multisampling for hair thinner than a pixel.",
            Effect::Render),
      param("render.interactive", "Interactive quality", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactive, 0, 1,
            "While the camera moves or the hair simulates, draw less: a share of the strands, "
            "a plainer curve, fewer samples, a smaller shadow map. A still view and every capture "
            "are drawn in "
            "full.",
            Effect::Render),
      param("render.interactive_amount", "Strands drawn", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactiveAmount, 0.01, 1.0,
            "Interactive quality: the share of the strands drawn (children go first; the "
            "rest are drawn wider to keep the coverage).",
            Effect::Render)
          .onlyWhen(interactiveQuality),
      param("render.interactive_budget_ms", "Frame budget (ms)", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactiveBudgetMs, 0.0, 1000.0,
            "Interactive quality: the time the scene's drawing may take, measured over the last "
            "frames; over it, fewer children and followers are drawn (a guided groom's guides "
            "stand in for all), under it more. 0: no budget.",
            Effect::Render)
          .onlyWhen(interactiveQuality),
      param("render.interactive_subdivision", "Subdivision", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactiveSubdivision, 1, 16,
            "Interactive quality: spline segments drawn per simulated segment (1: straight "
            "segments between the particles).",
            Effect::Render)
          .onlyWhen(interactiveQuality),
      param("render.interactive_samples", "Samples", "Rendering|Interactive", &ViewConfig::render,
            &RenderConfig::interactiveSamples, 1, 16, "Interactive quality: MSAA samples.",
            Effect::Render)
          .onlyWhen(interactiveQuality),
      param("render.interactive_shadow_map_size", "Shadow map size", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactiveShadowMapSize, 64, 4096,
            "Interactive quality: resolution of the deep opacity maps.", Effect::Render)
          .onlyWhen(interactiveQuality),
      param("render.interactive_resolution", "Resolution", "Rendering|Interactive",
            &ViewConfig::render, &RenderConfig::interactiveResolution, 0.25, 1.0,
            "Interactive quality: the image drawn, a share of the window's width and height, "
            "scaled up to the window (a software renderer's time goes with the pixels).",
            Effect::Render)
          .onlyWhen(interactiveQuality),
      param("camera.target", "Target", "Camera", &ViewConfig::camera, &CameraConfig::target, -10,
            10, "Point the camera looks at (m).", Effect::Render),
      param("camera.distance", "Distance", "Camera", &ViewConfig::camera, &CameraConfig::distance,
            0.05, 20.0, "Distance from the target (m).", Effect::Render),
      param("camera.yaw", "Yaw", "Camera", &ViewConfig::camera, &CameraConfig::yaw, -360.0, 360.0,
            "Angle about y (degrees).", Effect::Render),
      param("camera.pitch", "Pitch", "Camera", &ViewConfig::camera, &CameraConfig::pitch, -89.0,
            89.0, "Angle above the horizon (degrees).", Effect::Render),
      param("camera.fov", "Field of view", "Camera", &ViewConfig::camera, &CameraConfig::fov, 5.0,
            120.0, "Vertical field of view (degrees).", Effect::Render),
      param("light.direction", "Direction", "Light", &ViewConfig::light, &LightConfig::direction,
            -1, 1, "Direction the light travels (normalised when used).", Effect::Render),
      param("light.color", "Colour", "Light", &ViewConfig::light, &LightConfig::color, 0, 1,
            "Light colour.", Effect::Render)
          .asColor(),
      param("light.intensity", "Intensity", "Light", &ViewConfig::light, &LightConfig::intensity,
            0.0, 10.0, "Light intensity.", Effect::Render),
      param("light.ambient", "Ambient", "Light", &ViewConfig::light, &LightConfig::ambient, 0.0,
            2.0, "Ambient light.", Effect::Render),
  };
}

}  // namespace

const std::vector<Param<ViewConfig>>& viewParams() {
  static const std::vector<Param<ViewConfig>> list = build();
  return list;
}

}  // namespace csm
