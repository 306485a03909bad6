#include "sim/base/obj_text.h"

#include <cstdlib>
#include <string>

namespace csm::io::detail {
namespace {

bool blank(char c) {
  return c == ' ' || c == '\t';
}

}  // namespace

bool LineCursor::next(size_t& number, std::string_view& line) {
  if (done_) return false;
  size_t end = text_.find_first_of("\r\n", at_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(at_, end - at_);
  number = ++number_;
  for (const char c : line)
    if (!blank(c)) {
      lastNonBlank_ = number;
      break;
    }
  if (end == text_.size()) {
    done_ = true;
  } else {
    at_ = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
  return true;
}

std::string_view withoutComment(std::string_view line) {
  const size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

std::vector<std::pair<size_t, std::string_view>> objLines(std::string_view text) {
  std::vector<std::pair<size_t, std::string_view>> out;
  LineCursor lines(text);
  size_t number = 0;
  std::string_view line;
  while (lines.next(number, line)) out.emplace_back(number, withoutComment(line));
  return out;
}

std::string_view withoutBom(std::string_view text) {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

std::vector<std::string_view> objTokens(std::string_view line, size_t most) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size() && out.size() < most) {
    while (i < line.size() && blank(line[i])) ++i;
    size_t j = i;
    while (j < line.size() && !blank(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool ElementTokens::next(std::string_view& token) {
  for (;;) {
    size_t i = 0;
    while (i < rest_.size() && blank(rest_[i])) ++i;
    if (i == rest_.size()) return false;
    size_t j = i;
    while (j < rest_.size() && !blank(rest_[j])) ++j;
    token = rest_.substr(i, j - i);
    rest_ = rest_.substr(j);
    size_t after = 0;
    while (after < rest_.size() && blank(rest_[after])) ++after;
    if (token != "\\" || after < rest_.size()) return true;
    // A lone "\" ends the line: the element goes on on the next.
    size_t number = 0;
    std::string_view line;
    if (!lines_.next(number, line)) return false;
    rest_ = withoutComment(line);
  }
}

void ElementTokens::drain() {
  std::string_view token;
  while (next(token)) {
  }
}

bool parseNumber(std::string_view token, double& value) {
  const std::string text(token);
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && end == text.c_str() + text.size();
}

bool parseIndex(std::string_view token, long& value) {
  const std::string text(token);
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return end != text.c_str() && end == text.c_str() + text.size();
}

}  // namespace csm::io::detail
