// The text of a Wavefront OBJ file as the OBJ readers see it (heads: obj_mesh.h; hair curves:
// obj_curves.h; TressFX's text form reads with the same pieces): numbered lines, comments cut,
// whitespace-separated tokens, numbers that must be whole tokens. Nothing here holds more than
// a line's worth of the file: a hostile file's size is not multiplied.
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

namespace csm::io::detail {

// The file's lines one at a time, numbered from 1, as views into the text. A line ends at "\n",
// "\r\n" or a lone "\r", as tinyobjloader reads them: a split of our own would check other lines
// than the ones it reads.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  // The next line as it is (comments not cut); false after the last.
  bool next(size_t& number, std::string_view& line);
  // The last line with anything but spaces on it so far (1 before any), for messages about
  // where a file ends.
  size_t lastNonBlank() const { return lastNonBlank_; }

 private:
  std::string_view text_;
  size_t at_ = 0, number_ = 0, lastNonBlank_ = 1;
  bool done_ = false;
};

// The line without its comment ('#' to the end).
std::string_view withoutComment(std::string_view line);

// Every line with its number, comments cut (the OBJ head reader's pass, which sees a head's few
// thousand lines twice).
std::vector<std::pair<size_t, std::string_view>> objLines(std::string_view text);

// The text without a UTF-8 byte order mark, which some Windows tools write before the first line.
std::string_view withoutBom(std::string_view text);

// The tokens of a line, split at spaces and tabs; at most `most` of them.
std::vector<std::string_view> objTokens(std::string_view line, size_t most = size_t(-1));

// The tokens of one OBJ element: those of its line, and of the lines after while a line ends
// in a lone "\" (the specification's continuation), read one at a time.
class ElementTokens {
 public:
  ElementTokens(LineCursor& lines, std::string_view line) : lines_(lines), rest_(line) {}
  bool next(std::string_view& token);
  // Reads to the element's end, so that the cursor stands at its last line.
  void drain();

 private:
  LineCursor& lines_;
  std::string_view rest_;
};

// Whether the whole token is a number (strtod's syntax) or an integer (base 10).
bool parseNumber(std::string_view token, double& value);
bool parseIndex(std::string_view token, long& value);

}  // namespace csm::io::detail
