// Parameters, each declared once: a row naming the field it sets by pointer to member, with
// its key (a dotted path that mirrors the preset's JSON), label, group, range, description and
// what a change needs. The row's type comes from the field's C++ type, so a row cannot
// disagree with its field (an unsupported type is a compile error), and defaults are the
// config structs' own. Each module declares the parameters of its own config
// (sim/param/sim_params.h, render/view_params.h); the program lifts them into one list over the
// whole preset (app/params.h), which the JSON reader and writer, --set, --list-params and the
// panels walk.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "sim/core/config.h"

namespace csm {

enum class ParamType { Bool, Int, Float, Vec3, Color, Enum, String, Spheres };

// What a change of the parameter asks for.
enum class Effect {
  Live,     // takes effect on the next step
  Rebuild,  // the hair's shape changes: regrow the groom and reset the solver
  Render,   // only the picture changes
  Info      // describes the preset; changes nothing that runs
};

// Everything about a parameter but where it lives.
struct ParamInfo {
  std::string_view key;    // "sim.window_length"
  std::string_view label;  // "Stiffness window"
  std::string_view group;  // "Simulation" or "Simulation|Collision"
  ParamType type = ParamType::Float;
  double min = 0.0;  // numeric range, per component for vectors
  double max = 0.0;
  std::string_view description;
  Effect effect = Effect::Live;
  std::vector<std::string_view> options;  // names of enum values, in enum order
  // Further names read as a value (older spellings); never written.
  std::vector<std::pair<std::string_view, int>> aliases;
  bool logarithmic = false;  // a slider hint for wide ranges
  // How the panels show a number: value x displayScale, in `unit` (the key's unit stays SI).
  double displayScale = 1.0;
  std::string_view unit;
};

namespace detail {

template <class T>
constexpr ParamType paramTypeOf() {
  if constexpr (std::is_same_v<T, bool>)
    return ParamType::Bool;
  else if constexpr (std::is_same_v<T, int>)
    return ParamType::Int;
  else if constexpr (std::is_same_v<T, float>)
    return ParamType::Float;
  else if constexpr (std::is_same_v<T, glm::vec3>)
    return ParamType::Vec3;
  else if constexpr (std::is_enum_v<T>) {
    static_assert(std::is_same_v<std::underlying_type_t<T>, int>, "enum parameters are int-based");
    return ParamType::Enum;
  } else if constexpr (std::is_same_v<T, std::string>)
    return ParamType::String;
  else if constexpr (std::is_same_v<T, std::vector<Sphere>>)
    return ParamType::Spheres;
  else
    static_assert(!sizeof(T), "no parameter type for this field type");
}

template <class T>
constexpr bool storedAs(ParamType type) {
  switch (type) {
    case ParamType::Bool:
      return std::is_same_v<T, bool>;
    case ParamType::Int:
    case ParamType::Enum:
      return std::is_same_v<T, int>;
    case ParamType::Float:
      return std::is_same_v<T, float>;
    case ParamType::Vec3:
    case ParamType::Color:
      return std::is_same_v<T, glm::vec3>;
    case ParamType::String:
      return std::is_same_v<T, std::string>;
    case ParamType::Spheres:
      return std::is_same_v<T, std::vector<Sphere>>;
  }
  return false;
}

}  // namespace detail

// A parameter of a config `Root`.
template <class Root>
struct Param : ParamInfo {
  std::function<void*(Root&)> at;              // the field in a Root
  std::function<bool(const Root&)> appliesTo;  // when it does something; null = always

  bool applies(const Root& r) const { return !appliesTo || appliesTo(r); }

  // The field as the C++ type it is stored as (enums as int). Throws on a mismatch, which
  // only a row declared against its field could cause.
  template <class T>
  T& ref(Root& r) const {
    if (!detail::storedAs<T>(type)) throw std::logic_error("parameter type mismatch");
    return *static_cast<T*>(at(r));
  }
  template <class T>
  const T& ref(const Root& r) const {
    return ref<T>(const_cast<Root&>(r));
  }

  // Chained refinements of a row.
  Param logScale() const {
    Param p = *this;
    p.logarithmic = true;
    return p;
  }
  Param choices(std::vector<std::string_view> names) const {
    Param p = *this;
    p.options = std::move(names);
    return p;
  }
  Param alias(std::string_view name, int value) const {
    Param p = *this;
    p.aliases.emplace_back(name, value);
    return p;
  }
  Param onlyWhen(bool (*predicate)(const Root&)) const {
    Param p = *this;
    p.appliesTo = predicate;
    return p;
  }
  Param display(double scale, std::string_view unitName) const {
    Param p = *this;
    p.displayScale = scale;
    p.unit = unitName;
    return p;
  }
  Param asColor() const {
    Param p = *this;
    if (p.type == ParamType::Vec3) p.type = ParamType::Color;
    return p;
  }
};

namespace detail {
template <class Root, class T>
Param<Root> row(std::string_view key, std::string_view label, std::string_view group, double min,
                double max, std::string_view description, Effect effect,
                std::function<void*(Root&)> at) {
  Param<Root> p;
  p.key = key;
  p.label = label;
  p.group = group;
  p.type = paramTypeOf<T>();
  p.min = min;
  p.max = max;
  p.description = description;
  p.effect = effect;
  p.at = std::move(at);
  return p;
}
}  // namespace detail

// A row for the field `Root::*member` or `Root::*outer.*inner`: its type from the field's.
template <class Root, class T>
Param<Root> param(std::string_view key, std::string_view label, std::string_view group,
                  T Root::*member, double min, double max, std::string_view description,
                  Effect effect) {
  return detail::row<Root, T>(key, label, group, min, max, description, effect,
                              [member](Root& r) -> void* { return &(r.*member); });
}
template <class Root, class A, class T>
Param<Root> param(std::string_view key, std::string_view label, std::string_view group,
                  A Root::*outer, T A::*inner, double min, double max, std::string_view description,
                  Effect effect) {
  return detail::row<Root, T>(key, label, group, min, max, description, effect,
                              [outer, inner](Root& r) -> void* { return &((r.*outer).*inner); });
}

// The rows of a part of `Outer` (its member `part`), as rows of `Outer`.
template <class Outer, class Inner>
std::vector<Param<Outer>> lift(Inner Outer::*part, const std::vector<Param<Inner>>& rows) {
  std::vector<Param<Outer>> out;
  out.reserve(rows.size());
  for (const Param<Inner>& row : rows) {
    Param<Outer> p;
    static_cast<ParamInfo&>(p) = row;
    p.at = [part, at = row.at](Outer& o) { return at(o.*part); };
    if (row.appliesTo)
      p.appliesTo = [part, applies = row.appliesTo](const Outer& o) { return applies(o.*part); };
    out.push_back(std::move(p));
  }
  return out;
}

template <class Root>
const Param<Root>* findParam(const std::vector<Param<Root>>& list, std::string_view key) {
  for (const Param<Root>& p : list)
    if (p.key == key) return &p;
  return nullptr;
}

// ---- Values, whatever the config: the field as a void* of the parameter's type ------------

// The value as JSON (enums by name; floats as the shortest decimal that reads back the same).
nlohmann::json valueToJson(const ParamInfo& p, const void* field);
// Sets the field from JSON after checking its type and range. On failure returns what is wrong
// (without the key; callers prefix where it came from) and leaves the field as it is.
std::string valueFromJson(const ParamInfo& p, void* field, const nlohmann::json& value);
// From command-line text: JSON when it parses as JSON, otherwise a bare string (enum names,
// "x,y,z" vectors).
std::string valueFromText(const ParamInfo& p, void* field, std::string_view text);
// "int in [1, 64]", "one of off|head|full", ...
std::string describeType(const ParamInfo& p);

template <class Root>
nlohmann::json paramToJson(const Param<Root>& p, const Root& r) {
  return valueToJson(p, p.at(const_cast<Root&>(r)));
}
template <class Root>
std::string paramFromJson(const Param<Root>& p, Root& r, const nlohmann::json& value) {
  return valueFromJson(p, p.at(r), value);
}
template <class Root>
std::string paramFromText(const Param<Root>& p, Root& r, std::string_view text) {
  return valueFromText(p, p.at(r), text);
}
// Compact text of the current value, for --list-params and messages.
template <class Root>
std::string valueText(const Param<Root>& p, const Root& r) {
  return paramToJson(p, r).dump();
}
template <class Root>
bool sameValue(const Param<Root>& p, const Root& a, const Root& b) {
  return paramToJson(p, a) == paramToJson(p, b);
}

}  // namespace csm
