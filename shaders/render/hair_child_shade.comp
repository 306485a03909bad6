// Children's colour and coverage, once the guides are lit (hair_shade.comp): each child
// point takes the light of the guide point it sits beside, its own albedo (per-strand
// variation), and covers the share of a pixel its width does (a child is drawn as a line
// one pixel wide). Written as half floats with the drawn strand id, so the children's
// vertices read two vectors and nothing else.
#include "render/hair_common.glsl"
#include "render/hair_compute.glsl"

uniform uint uItems;  // a child's points over all guides, times the children

void main() {
  uint j = invocationIndex();
  if (j >= uItems) return;
  ChildItem c = childItem(j);
  vec4 point = childPoints[j];
  uint shade = c.first + min(uint(round(childGuidePoint(c))), c.count - 1u);
  float s = guidePoints[shade].w;
  vec3 color = hairAlbedo(c.guide, c.id, s) * guideShade[2u * shade].rgb +
               guideShade[2u * shade + 1u].rgb;
  float width = screenWidth(uViewProj * vec4(point.xyz, 1.0), c.guide, s);
  float coverage = point.w < 0.0 ? 0.0 : uTipColor.a * min(width, 1.0);
  childColors[j] = uvec4(packHalf2x16(color.rg), packHalf2x16(vec2(color.b, coverage)), c.id, 0u);
}
