#include "sim/param/param_table.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace csm {
namespace {

using P = ParamType;

std::string fmtNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string jsonKind(const nlohmann::json& v) {
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

std::string outOfRange(const ParamInfo& p, double v) {
  return "value " + fmtNumber(v) + " is out of range [" + fmtNumber(p.min) + ", " +
         fmtNumber(p.max) + "]";
}

std::string readVec3(const ParamInfo& p, const nlohmann::json& v, glm::vec3& out) {
  if (!v.is_array() || v.size() != 3) return "expected an array of 3 numbers, got " + jsonKind(v);
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) return "element " + std::to_string(i) + ": expected a number";
    double x = v[i].get<double>();
    if (!std::isfinite(x) || x < p.min || x > p.max)
      return "element " + std::to_string(i) + ": " + outOfRange(p, x);
    out[i] = static_cast<float>(x);
  }
  return {};
}

// The shortest decimal that reads back as the same float, as a double: JSON then says 0.04,
// not 0.03999999910593033, and reading it gives the float back.
double shortest(float v) {
  if (!std::isfinite(v)) return v;
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf - 1, v);
  *r.ptr = '\0';
  return std::strtod(buf, nullptr);
}

}  // namespace

nlohmann::json valueToJson(const ParamInfo& p, const void* field) {
  using nlohmann::json;
  switch (p.type) {
    case P::Bool:
      return (*static_cast<const bool*>(field));
    case P::Int:
      return (*static_cast<const int*>(field));
    case P::Float:
      return shortest((*static_cast<const float*>(field)));
    case P::Vec3:
    case P::Color: {
      const glm::vec3& v = (*static_cast<const glm::vec3*>(field));
      return json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
    }
    case P::Enum: {
      int i = (*static_cast<const int*>(field));
      return i >= 0 && i < static_cast<int>(p.options.size()) ? json(std::string(p.options[i]))
                                                              : json(i);
    }
    case P::String:
      return (*static_cast<const std::string*>(field));
    case P::Spheres: {
      json a = json::array();
      for (const Sphere& s : (*static_cast<const std::vector<Sphere>*>(field)))
        a.push_back({{"center", {shortest(s.center.x), shortest(s.center.y), shortest(s.center.z)}},
                     {"radius", shortest(s.radius)}});
      return a;
    }
  }
  return nullptr;
}

std::string valueFromJson(const ParamInfo& p, void* field, const nlohmann::json& v) {
  switch (p.type) {
    case P::Bool:
      if (!v.is_boolean()) return "expected true or false, got " + jsonKind(v);
      (*static_cast<bool*>(field)) = v.get<bool>();
      return {};
    case P::Int: {
      if (!v.is_number()) return "expected an integer, got " + jsonKind(v);
      double d = v.get<double>();
      if (!v.is_number_integer() && d != std::floor(d))
        return "expected an integer, got " + fmtNumber(d);
      if (d < p.min || d > p.max) return outOfRange(p, d);
      (*static_cast<int*>(field)) = static_cast<int>(d);
      return {};
    }
    case P::Float: {
      if (!v.is_number()) return "expected a number, got " + jsonKind(v);
      double d = v.get<double>();
      if (!std::isfinite(d) || d < p.min || d > p.max) return outOfRange(p, d);
      (*static_cast<float*>(field)) = static_cast<float>(d);
      return {};
    }
    case P::Vec3:
    case P::Color: {
      glm::vec3 out;
      std::string err = readVec3(p, v, out);
      if (err.empty()) (*static_cast<glm::vec3*>(field)) = out;
      return err;
    }
    case P::Enum: {
      if (!v.is_string()) return "expected one of " + describeType(p) + ", got " + jsonKind(v);
      std::string s = v.get<std::string>();
      for (size_t i = 0; i < p.options.size(); ++i)
        if (p.options[i] == s) {
          (*static_cast<int*>(field)) = static_cast<int>(i);
          return {};
        }
      for (const auto& [name, value] : p.aliases)
        if (name == s) {
          (*static_cast<int*>(field)) = value;
          return {};
        }
      return "\"" + s + "\" is not " + describeType(p);
    }
    case P::String:
      if (!v.is_string()) return "expected a string, got " + jsonKind(v);
      (*static_cast<std::string*>(field)) = v.get<std::string>();
      return {};
    case P::Spheres: {
      if (!v.is_array() || v.empty()) return "expected a non-empty array of spheres";
      if (v.size() > 64) return "at most 64 spheres";
      std::vector<Sphere> out;
      for (size_t i = 0; i < v.size(); ++i) {
        const auto& s = v[i];
        std::string where = "[" + std::to_string(i) + "]";
        if (!s.is_object()) return where + ": expected {\"center\": [x,y,z], \"radius\": r}";
        for (auto it = s.begin(); it != s.end(); ++it)
          if (it.key() != "center" && it.key() != "radius")
            return where + "." + it.key() + ": unknown key (keys: center, radius)";
        if (!s.contains("center") || !s.contains("radius"))
          return where + ": needs both center and radius";
        Sphere sp;
        std::string err = readVec3(p, s["center"], sp.center);
        if (!err.empty()) return where + ".center: " + err;
        if (!s["radius"].is_number()) return where + ".radius: expected a number";
        double r = s["radius"].get<double>();
        if (!(r > 0.0 && r <= 10.0))
          return where + ".radius: value " + fmtNumber(r) + " is out of range (0, 10]";
        sp.radius = static_cast<float>(r);
        out.push_back(sp);
      }
      (*static_cast<std::vector<Sphere>*>(field)) = out;
      return {};
    }
  }
  return "unsupported parameter type";
}

std::string valueFromText(const ParamInfo& p, void* field, std::string_view text) {
  nlohmann::json v = nlohmann::json::parse(text, nullptr, false);
  if (v.is_discarded() || (p.type == P::String && !v.is_string())) {
    v = std::string(text);
    // "x,y,z" for vectors.
    if (p.type == P::Vec3 || p.type == P::Color) {
      nlohmann::json arr = nlohmann::json::parse("[" + std::string(text) + "]", nullptr, false);
      if (!arr.is_discarded()) v = arr;
    }
  }
  return valueFromJson(p, field, v);
}

std::string describeType(const ParamInfo& p) {
  switch (p.type) {
    case P::Bool:
      return "true|false";
    case P::Int:
      return "int in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Float:
      return "number in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Vec3:
      return "[x,y,z] each in [" + fmtNumber(p.min) + ", " + fmtNumber(p.max) + "]";
    case P::Color:
      return "[r,g,b] each in [0, 1]";
    case P::Enum: {
      std::string s = "one of ";
      for (size_t i = 0; i < p.options.size(); ++i) s += (i ? "|" : "") + std::string(p.options[i]);
      return s;
    }
    case P::String:
      return "string";
    case P::Spheres:
      return "[{\"center\": [x,y,z], \"radius\": r}, ...]";
  }
  return "?";
}

}  // namespace csm
