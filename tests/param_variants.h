// Other values of a parameter, for the tests that every parameter takes effect: the ends and
// middle of its range and a factor of two either side of the current value (numbers), the
// other value (bools), every other option (enums), each component moved (vectors). Only
// values in range that differ from the current one.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/param/param_table.h"

namespace csm::test {

template <class Root>
std::vector<Root> paramVariants(const Param<Root>& p, const Root& base) {
  std::vector<Root> out;
  auto keep = [&](Root r) {
    if (sameValue(p, r, base)) return;
    for (const Root& o : out)
      if (sameValue(p, r, o)) return;
    out.push_back(std::move(r));
  };
  auto numbers = [&](double current) {
    std::vector<double> v = {p.max, p.min, 0.5 * (p.min + p.max), 2.0 * current, 0.5 * current};
    if (p.logarithmic && p.min > 0.0) v.push_back(std::sqrt(p.min * p.max));
    std::vector<double> in;
    for (double x : v)
      if (x >= p.min && x <= p.max) in.push_back(x);
    return in;
  };
  switch (p.type) {
    case ParamType::Bool: {
      Root r = base;
      p.template ref<bool>(r) = !p.template ref<bool>(base);
      keep(r);
      break;
    }
    case ParamType::Int:
      for (double x : numbers(p.template ref<int>(base))) {
        Root r = base;
        p.template ref<int>(r) = int(std::lround(x));
        keep(r);
      }
      break;
    case ParamType::Float:
      for (double x : numbers(p.template ref<float>(base))) {
        Root r = base;
        p.template ref<float>(r) = float(x);
        keep(r);
      }
      break;
    case ParamType::Enum:
      for (size_t i = 0; i < p.options.size(); ++i) {
        Root r = base;
        p.template ref<int>(r) = int(i);
        keep(r);
      }
      break;
    case ParamType::Vec3:
    case ParamType::Color:
      for (int axis = 0; axis < 3; ++axis)
        for (double step : {0.25, -0.25}) {
          Root r = base;
          glm::vec3& v = p.template ref<glm::vec3>(r);
          v[axis] = float(std::clamp(double(v[axis]) + step * (p.max - p.min), p.min, p.max));
          keep(r);
        }
      break;
    case ParamType::String:
    case ParamType::Spheres:
      break;  // not live in any module
  }
  return out;
}

}  // namespace csm::test
