// The text of a Wavefront OBJ file as both OBJ readers see it (heads: obj_mesh.h; hair curves:
// obj_curves.h): numbered lines without comments, whitespace-separated tokens, and numbers
// that must be whole tokens.
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

namespace csm::io::detail {

// The lines of the file with their 1-based numbers, comments ('#' to the end of the line)
// cut. A line ends at "\n", "\r\n" or a lone "\r", as tinyobjloader reads them: a split of our
// own would check other lines than the ones it reads.
std::vector<std::pair<size_t, std::string_view>> objLines(std::string_view text);

// The text without a UTF-8 byte order mark, which some Windows tools write before the first line.
std::string_view withoutBom(std::string_view text);

// The tokens of a line, split at spaces and tabs.
std::vector<std::string_view> objTokens(std::string_view line);

// Whether the whole token is a number (strtod's syntax) or an integer (base 10).
bool parseNumber(std::string_view token, double& value);
bool parseIndex(std::string_view token, long& value);

}  // namespace csm::io::detail
