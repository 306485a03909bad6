#include "render/hair_color.h"

namespace csm {

HairColors hairColors(HairColor color, const RenderConfig& custom) {
  // Hair's colour is mostly its melanin: much eumelanin (brown-black) makes black and brown
  // hair, little makes blond, pheomelanin (red-yellow) with little eumelanin makes red, and
  // none at all makes grey-white hair, its colour then the keratin's faint yellow with a few
  // pigmented hairs in the mix. Each is darker at the root, where the strand is denser and
  // less weathered than toward the tip. Brown is the config's default colours.
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
      return {{0.30f, 0.29f, 0.28f}, {0.74f, 0.73f, 0.70f}};
  }
  return {custom.rootColor, custom.tipColor};
}

HairColors hairColors(const RenderConfig& render) {
  return hairColors(render.hairColor, render);
}

}  // namespace csm
