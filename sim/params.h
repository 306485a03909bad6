// The one list of parameters. Each is declared once, with its key (a dotted path that
// mirrors the preset's JSON), label, group, type, range, default (the value in Config{}),
// description and what a change needs. JSON reading and writing, --set, --list-params and
// the ImGui panels all walk this list; no other code names a parameter field by hand.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/config.h"

namespace csm {

enum class ParamType { Bool, Int, Float, Vec3, Color, Enum, String, Spheres };

// What a change of the parameter asks for.
enum class Effect {
  Live,     // takes effect on the next step
  Rebuild,  // the hair's shape changes: regrow the groom and reset the solver
  Render,   // only the picture changes
  Info      // describes the preset; changes nothing that runs
};

struct Param {
  std::string_view key;    // "sim.stiffness_window"
  std::string_view label;  // "Stiffness window w"
  std::string_view group;  // "Simulation" or "Simulation|Collision"
  ParamType type;
  double min = 0.0;  // numeric range, per component for vectors
  double max = 0.0;
  std::string_view description;
  Effect effect = Effect::Live;
  void* (*field)(Config&) = nullptr;
  std::vector<std::string_view> options{};  // names of enum values, in enum order
  bool logarithmic = false;                 // a slider hint for wide ranges
  // When it does something: null = always. The panels grey it out otherwise (the stiffness
  // model's parameters apply to one model each).
  bool (*applies)(const Config&) = nullptr;
  // How the panels show a number: value x displayScale, in `unit` (the key's unit stays SI).
  double displayScale = 1.0;
  std::string_view unit{};

  template <class T>
  T& ref(Config& c) const {
    return *static_cast<T*>(field(c));
  }
  template <class T>
  const T& ref(const Config& c) const {
    return *static_cast<const T*>(field(const_cast<Config&>(c)));
  }
};

const std::vector<Param>& params();
const Param* findParam(std::string_view key);

// The value of a parameter as JSON (enums by name).
nlohmann::json paramToJson(const Param& p, const Config& c);
// Sets a parameter from JSON after checking its type and range. On failure returns a message
// saying what is wrong (without the key; callers prefix where it came from) and leaves c as is.
std::string paramFromJson(const Param& p, Config& c, const nlohmann::json& value);
// Sets from command-line text: JSON when it parses as JSON, otherwise a bare string
// (enum names, "x,y,z" vectors).
std::string paramFromText(const Param& p, Config& c, std::string_view text);
// "int in [1, 64]", "one of off|head|full", ...
std::string describeType(const Param& p);
// Compact text of the current value, for --list-params and messages.
std::string valueText(const Param& p, const Config& c);
bool sameValue(const Param& p, const Config& a, const Config& b);

}  // namespace csm
