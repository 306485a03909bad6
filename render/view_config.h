// How a scene is viewed: the look of hair and head, the camera, the light. Not the
// simulation's business (sim/core/config.h): the renderer and the viewer read these.
#pragma once

#include <glm/vec3.hpp>

namespace csm {

// Natural hair colours (render/hair_color.h), or the preset's own root and tip colours.
enum class HairColor : int { Custom = 0, Black, Brown, Blond, Red, Grey };

struct RenderConfig {
  bool shadows = true;
  float strandWidth = 1.5f;   // pixels
  float strandWidthM = 0.0f;  // metres; 0: strandWidth pixels
  int subdivision = 4;        // spline segments drawn per simulated segment
  // Children: hairs drawn around each simulated strand, made on the GPU each frame
  // (shaders/render/hair_children.comp).
  int children = 0;
  // A groom simulated through guides (hairstyle.guides): draw the guides alone, highlighted,
  // instead of every strand drawn from them.
  bool showGuides = false;
  float childRadius = 0.0f;                 // from the guide at the root (m); 0: the roots' spacing
  float childClump = 0.5f;                  // share of that closed at the tip
  float childNoise = 0.002f;                // wander at the tip (m)
  float childLength = 0.15f;                // children up to this share shorter than their guide
  float childInterpolation = 0.5f;          // share of children between two neighbouring guides
  HairColor hairColor = HairColor::Custom;  // custom: rootColor and tipColor
  glm::vec3 rootColor{0.10f, 0.06f, 0.035f};
  glm::vec3 tipColor{0.35f, 0.22f, 0.12f};
  float colorVariation = 0.15f;
  float specularShift1 = -0.08f;  // along the normal, in tangent units (primary, white)
  float specularShift2 = 0.12f;   // secondary, tinted
  // The primary (white) lobe narrow and faint, the secondary (tinted) one broader: where hair
  // lies flat a wide white lobe turns brown hair grey.
  float specularExponent1 = 250.0f;
  float specularExponent2 = 40.0f;
  float specularStrength1 = 0.12f;
  float specularStrength2 = 0.45f;
  float opacity = 0.6f;        // per strand
  float layerSpacing = 0.01f;  // deep opacity map layer spacing, metres
  int shadowMapSize = 1024;
  glm::vec3 headColor{0.80f, 0.62f, 0.52f};
  glm::vec3 irisColor{0.36f, 0.25f, 0.15f};  // the mannequin's eyes
  glm::vec3 background{0.55f, 0.60f, 0.66f};
  int samples = 4;  // multisampling
  // Interactive quality, while the camera moves or the hair simulates (the viewer; captures
  // and a still view are drawn in full): a share of the strands, children first, wider
  // to keep the coverage; a plainer curve; fewer samples; a smaller shadow map; a smaller
  // image, scaled up to the window.
  bool interactive = true;
  float interactiveAmount = 0.3f;
  int interactiveSubdivision = 1;
  int interactiveSamples = 1;
  int interactiveShadowMapSize = 256;
  float interactiveResolution = 0.5f;  // of the window's width and height
  // The draw time (ms, measured) interactive quality holds by drawing fewer children and
  // followers (render/interactive_budget.h); 0: no budget.
  float interactiveBudgetMs = 33.0f;
};

struct CameraConfig {
  glm::vec3 target{0.0f, -0.05f, 0.0f};
  float distance = 0.75f;
  float yaw = 30.0f;    // degrees about y
  float pitch = 10.0f;  // degrees above the horizon
  float fov = 40.0f;    // vertical, degrees
};

struct LightConfig {
  glm::vec3 direction{-0.5f, -0.7f, -0.5f};  // the direction light travels
  glm::vec3 color{1.0f, 0.97f, 0.92f};
  float intensity = 2.2f;
  float ambient = 0.25f;
};

struct ViewConfig {
  RenderConfig render;
  CameraConfig camera;
  LightConfig light;
};

}  // namespace csm
