// The units of length files come in, and the one nearest a scale: what a reader infers from a
// size (a head's cranium, a groom's roots) and says.
#pragma once

#include <cmath>
#include <span>

namespace csm {

struct LengthUnit {
  const char* symbol;  // "cm", for the log's "units cm"
  const char* name;    // "centimetres", for a sentence
  double metres;       // metres per unit
};

// Metres, decimetres, centimetres, millimetres and inches: the units scans, data sets and DCC
// tools write.
inline constexpr LengthUnit kLengthUnits[] = {{"m", "metres", 1.0},
                                              {"dm", "decimetres", 0.1},
                                              {"cm", "centimetres", 0.01},
                                              {"mm", "millimetres", 0.001},
                                              {"in", "inches", 0.0254}};

// The unit of `units` whose size is nearest `metres` by ratio (the first of two as near).
inline const LengthUnit& nearestUnit(double metres,
                                     std::span<const LengthUnit> units = kLengthUnits) {
  const LengthUnit* nearest = &units[0];
  for (const LengthUnit& u : units)
    if (std::abs(std::log(metres / u.metres)) < std::abs(std::log(metres / nearest->metres)))
      nearest = &u;
  return *nearest;
}

}  // namespace csm
