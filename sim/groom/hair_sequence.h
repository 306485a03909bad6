// Simulated hair out to other tools: a frame's strands as a cyHair groom, and a sequence of
// frames as DIR/frame_00001.hair, frame_00002.hair, ... (one file a frame, the same strands
// with the same point counts in each, so a reader can match them up by index).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/groom.h"

namespace csm::io {

// `groom` with its points moved to `positions` (a solver's read-back, one per point, in the
// groom's order); its strands, colours and thickness kept.
Groom posedGroom(const Groom& groom, const std::vector<glm::vec4>& positions);
Groom posedGroom(const Groom& groom, const std::vector<glm::vec3>& positions);

// "frame_00001.hair" for n = 1.
std::string sequenceFrameName(long n);

// Makes `dir` when missing (false, with *error, when it cannot be made or is not a folder).
bool prepareSequenceDir(const std::string& dir, std::string* error);

// Writes frame n of a sequence: dir/sequenceFrameName(n), whole or not at all (writeCyHair).
bool writeSequenceFrame(const std::string& dir, long n, const Groom& groom,
                        const std::vector<glm::vec4>& positions, std::string* error);
bool writeSequenceFrame(const std::string& dir, long n, const Groom& groom,
                        const std::vector<glm::vec3>& positions, std::string* error);

}  // namespace csm::io
