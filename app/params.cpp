#include "app/params.h"

#include "render/view_params.h"
#include "sim/param/sim_params.h"

namespace csm {
namespace {

std::vector<PresetParam> build() {
  std::vector<PresetParam> list = {
      param("name", "Name", "Preset", &Preset::name, 0, 0, "Short name of the preset.",
            Effect::Info),
      param("description", "Description", "Preset", &Preset::description, 0, 0,
            "What the scene shows.", Effect::Info),
  };
  for (PresetParam& p : lift(&Preset::scene, simParams())) list.push_back(std::move(p));
  for (PresetParam& p : lift(&Preset::view, viewParams())) list.push_back(std::move(p));
  return list;
}

}  // namespace

const std::vector<PresetParam>& params() {
  static const std::vector<PresetParam> list = build();
  return list;
}

const PresetParam* findParam(std::string_view key) {
  return findParam(params(), key);
}

}  // namespace csm
