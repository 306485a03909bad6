// A CSV file written row by row: a header, then cells of text or numbers.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace csm::bench {

class Csv {
 public:
  explicit Csv(std::vector<std::string> header) : header_(std::move(header)) {}

  Csv& add(const std::string& text) {
    row_.push_back(quote(text));
    return *this;
  }
  Csv& add(const char* text) { return add(std::string(text)); }
  Csv& add(double v) {
    char buf[64];
    if (std::isnan(v)) return row_.push_back(""), *this;  // empty cell: no value
    std::snprintf(buf, sizeof buf, "%.6g", v);
    row_.push_back(buf);
    return *this;
  }
  Csv& add(int v) { return add(double(v)); }
  Csv& add(long v) { return add(double(v)); }
  Csv& add(unsigned long v) { return add(double(v)); }
  Csv& add(unsigned long long v) { return add(double(v)); }
  Csv& add(bool v) { return add(v ? 1.0 : 0.0); }
  void endRow() {
    rows_.push_back(std::move(row_));
    row_.clear();
  }

  bool write(const std::string& path) const {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "csmhair-bench: cannot write %s\n", path.c_str());
      return false;
    }
    writeRow(f, header_);
    for (const auto& r : rows_) writeRow(f, r);
    return std::fclose(f) == 0;
  }

 private:
  static std::string quote(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  }
  static void writeRow(FILE* f, const std::vector<std::string>& r) {
    for (size_t i = 0; i < r.size(); ++i) std::fprintf(f, "%s%s", i ? "," : "", r[i].c_str());
    std::fprintf(f, "\n");
  }
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::string> row_;
};

}  // namespace csm::bench
