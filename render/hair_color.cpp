#include "render/hair_color.h"

namespace csm {

HairColors hairColors(HairColor color, const RenderConfig& custom) {
  // Hair's colour is mostly its melanin: much eumelanin (brown-black) makes black and brown
  // hair, little makes blond, pheomelanin (red-yellow) with little eumelanin makes red, and
  // none at all makes grey-white hair, its colour then the keratin's faint yellow with a few
  // pigmented hairs in the mix. Each is darker at the root, where the strand is denser and
  // less weathered than toward the tip. Brown is the config's default colours.
  //
  // These are the pigment's colour under the white highlight the shader adds, so a tress
  // measured with a colorimeter (highlight included) reads lighter and greyer. Checked against:
  // - black, brown: Scanavez et al., "Measurement of hair luster by diffuse reflectance
  //   spectrophotometry", J. Cosmet. Sci. 51 (2000), tables III-IV: black tresses L* 18-20,
  //   a* 0, b* -0.8 (the surface's neutral reflection, nearly all of it: the pigment under it
  //   is close to black, as here), dark brown L* 22-24, a* 4, b* 5 (less that neutral part,
  //   about sRGB 0.16, 0.07, 0.01: between the brown root and tip);
  // - black, brown, blond roots: the melanin absorption of d'Eon et al. 2011 at the
  //   concentrations pbrt and Chiang et al. 2016 give (eumelanin 8, 1.3, 0.3), turned into a
  //   colour by Chiang et al.'s mapping (azimuthal roughness 0.3): sRGB 0, 0, 0; 0.12, 0.05,
  //   0.005; 0.39, 0.29, 0.16. Red's root is near pheomelanin 1 with eumelanin 0.3 (0.21, 0.10,
  //   0.01). Blond's and red's tips are lighter by judgement: no measured tip colours found;
  // - grey: greying hair matched to Munsell chips, 7.5YR 3/4 (least grey) to 7.5YR 5/2
  //   (greyest), and the keratin's yellow (kynurenines) of unpigmented hair: warm, never
  //   neutral, so the root and tip lean yellow-red (L* 32 and 75, hue 7.5YR, low chroma).
  switch (color) {
    case HairColor::Custom:
      break;
    case HairColor::Black:
      return {{0.020f, 0.016f, 0.014f}, {0.055f, 0.045f, 0.038f}};
    case HairColor::Brown:
      return {RenderConfig{}.rootColor, RenderConfig{}.tipColor};
    case HairColor::Blond:
      return {{0.42f, 0.30f, 0.16f}, {0.85f, 0.70f, 0.46f}};
    case HairColor::Red:
      return {{0.20f, 0.06f, 0.025f}, {0.52f, 0.20f, 0.08f}};
    case HairColor::Grey:
      return {{0.31f, 0.29f, 0.27f}, {0.76f, 0.72f, 0.68f}};
  }
  return {custom.rootColor, custom.tipColor};
}

HairColors hairColors(const RenderConfig& render) {
  return hairColors(render.hairColor, render);
}

}  // namespace csm
