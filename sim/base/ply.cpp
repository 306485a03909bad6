#include "sim/base/ply.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>

#include "sim/base/obj_text.h"

namespace csm::io {
namespace {

struct TypeName {
  const char* name;
  PlyType type;
};
// Both spellings of the specification (the original's and the sized ones).
constexpr TypeName kTypes[] = {
    {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64}};

bool typeOf(std::string_view word, PlyType& type) {
  for (const TypeName& t : kTypes)
    if (word == t.name) {
      type = t.type;
      return true;
    }
  return false;
}

size_t sizeOf(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 4;
}

bool isInteger(PlyType t) {
  return t != PlyType::Float32 && t != PlyType::Float64;
}

// The range of an integer type, for ASCII values.
void rangeOf(PlyType t, double& lo, double& hi) {
  switch (t) {
    case PlyType::Int8:
      lo = -128, hi = 127;
      break;
    case PlyType::UInt8:
      lo = 0, hi = 255;
      break;
    case PlyType::Int16:
      lo = -32768, hi = 32767;
      break;
    case PlyType::UInt16:
      lo = 0, hi = 65535;
      break;
    case PlyType::Int32:
      lo = -2147483648.0, hi = 2147483647.0;
      break;
    case PlyType::UInt32:
      lo = 0, hi = 4294967295.0;
      break;
    default:
      lo = -HUGE_VAL, hi = HUGE_VAL;
  }
}

template <class T>
T loadAs(const std::byte* p, bool swap) {
  std::array<std::byte, sizeof(T)> b;
  std::memcpy(b.data(), p, sizeof(T));
  if (swap) std::reverse(b.begin(), b.end());
  T v;
  std::memcpy(&v, b.data(), sizeof(T));
  return v;
}

double loadValue(const std::byte* p, PlyType t, bool swap) {
  switch (t) {
    case PlyType::Int8:
      return loadAs<int8_t>(p, swap);
    case PlyType::UInt8:
      return loadAs<uint8_t>(p, swap);
    case PlyType::Int16:
      return loadAs<int16_t>(p, swap);
    case PlyType::UInt16:
      return loadAs<uint16_t>(p, swap);
    case PlyType::Int32:
      return loadAs<int32_t>(p, swap);
    case PlyType::UInt32:
      return loadAs<uint32_t>(p, swap);
    case PlyType::Float32:
      return loadAs<float>(p, swap);
    case PlyType::Float64:
      return loadAs<double>(p, swap);
  }
  return 0.0;
}

// The header's lines: each ends at "\n" (a "\r" before it is dropped); `end` is the byte after.
struct HeaderLine {
  std::string_view text;
  uint64_t end;
};

bool nextHeaderLine(std::string_view all, uint64_t& at, HeaderLine& out) {
  if (at >= all.size()) return false;
  const size_t nl = all.find('\n', at);
  const size_t stop = nl == std::string_view::npos ? all.size() : nl;
  std::string_view text = all.substr(at, stop - at);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  out = {text, nl == std::string_view::npos ? all.size() : nl + 1};
  at = out.end;
  return true;
}

// Wanted columns of one element, in its property order (-1: passed over).
std::vector<int> wantedOf(const PlyElement& e, const std::set<std::string>& wanted) {
  std::vector<int> k;
  for (const PlyProperty& p : e.properties)
    k.push_back(wanted.count(e.name + "." + p.name) ? 1 : 0);
  return k;
}

}  // namespace

const PlyProperty* PlyElement::property(std::string_view n) const {
  for (const PlyProperty& p : properties)
    if (p.name == n) return &p;
  return nullptr;
}

const PlyElement* PlyHeader::element(std::string_view n) const {
  for (const PlyElement& e : elements)
    if (e.name == n) return &e;
  return nullptr;
}

const PlyColumn* PlyData::column(std::string_view element, std::string_view property) const {
  auto it = columns.find(std::string(element) + "." + std::string(property));
  return it == columns.end() ? nullptr : &it->second;
}

std::string PlyData::where(std::string_view element, uint64_t row) const {
  const bool ascii = header.format == PlyFormat::Ascii;
  auto it = rowAt.find(std::string(element));
  if (it == rowAt.end() || row >= it->second.size()) return ascii ? "line ?" : "byte ?";
  return (ascii ? "line " : "byte ") + std::to_string(it->second[row]);
}

const char* plyTypeName(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return "char";
    case PlyType::UInt8:
      return "uchar";
    case PlyType::Int16:
      return "short";
    case PlyType::UInt16:
      return "ushort";
    case PlyType::Int32:
      return "int";
    case PlyType::UInt32:
      return "uint";
    case PlyType::Float32:
      return "float";
    case PlyType::Float64:
      return "double";
  }
  return "float";
}

bool isPly(std::span<const std::byte> bytes) {
  const std::string_view s(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  return s.substr(0, 4) == "ply\n" || s.substr(0, 5) == "ply\r\n";
}

std::optional<PlyHeader> readPlyHeader(std::span<const std::byte> bytes, std::string_view name,
                                       std::string* error) {
  const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  auto fail = [&](size_t line, const std::string& message) -> std::optional<PlyHeader> {
    if (error) *error = std::string(name) + ":" + std::to_string(line) + ": " + message;
    return std::nullopt;
  };
  PlyHeader h;
  uint64_t at = 0;
  size_t line = 0;
  HeaderLine l;
  bool format = false;
  while (nextHeaderLine(all, at, l)) {
    ++line;
    if (l.text.find('\0') != std::string_view::npos)
      return fail(line, "a NUL byte in the PLY header");
    const auto t = detail::objTokens(l.text);
    if (line == 1) {
      if (t.size() != 1 || t[0] != "ply")
        return fail(1, "expected \"ply\", the first line of a PLY file");
      continue;
    }
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() != 3)
        return fail(line, "expected \"format ascii|binary_little_endian|binary_big_endian 1.0\"");
      if (t[1] == "ascii")
        h.format = PlyFormat::Ascii;
      else if (t[1] == "binary_little_endian")
        h.format = PlyFormat::BinaryLittleEndian;
      else if (t[1] == "binary_big_endian")
        h.format = PlyFormat::BinaryBigEndian;
      else
        return fail(line, "unknown PLY format \"" + std::string(t[1]) +
                              "\"; expected ascii, binary_little_endian or binary_big_endian");
      if (t[2] != "1.0" && t[2] != "1")
        return fail(line, "PLY version \"" + std::string(t[2]) + "\"; expected 1.0");
      format = true;
    } else if (t[0] == "element") {
      long count = 0;
      if (t.size() != 3 || !detail::parseIndex(t[2], count) || count < 0 ||
          count > long(UINT32_MAX))
        return fail(line, "expected \"element NAME COUNT\" with a count from 0 to 4294967295");
      for (const PlyElement& e : h.elements)
        if (e.name == t[1]) return fail(line, "a second element \"" + std::string(t[1]) + "\"");
      h.elements.push_back({std::string(t[1]), uint64_t(count), {}, line});
    } else if (t[0] == "property") {
      if (h.elements.empty()) return fail(line, "a property before any element");
      PlyProperty p;
      if (t.size() == 5 && t[1] == "list") {
        p.list = true;
        if (!typeOf(t[2], p.countType) || !isInteger(p.countType))
          return fail(line,
                      "a list's count type \"" + std::string(t[2]) + "\" is not an integer type");
        if (!typeOf(t[3], p.type)) return fail(line, "unknown type \"" + std::string(t[3]) + "\"");
        p.name = std::string(t[4]);
      } else if (t.size() == 3 && t[1] != "list") {
        if (!typeOf(t[1], p.type))
          return fail(line, "unknown type \"" + std::string(t[1]) +
                                "\"; expected char, uchar, short, ushort, int, uint, float or "
                                "double (or int8 ... float64)");
        p.name = std::string(t[2]);
      } else {
        return fail(line, "expected \"property TYPE NAME\" or \"property list COUNT ITEM NAME\"");
      }
      PlyElement& e = h.elements.back();
      if (e.property(p.name))
        return fail(line, "a second property \"" + p.name + "\" of element \"" + e.name + "\"");
      e.properties.push_back(std::move(p));
    } else if (t[0] == "end_header") {
      if (!format) return fail(line, "end_header before a format line");
      h.bodyAt = l.end;
      h.bodyLine = line + 1;
      return h;
    } else {
      return fail(line, "unknown header line \"" + std::string(t[0]) +
                            "\"; expected format, element, property, comment or end_header");
    }
  }
  return fail(line, "the file ends before end_header");
}

std::optional<PlyData> readPly(std::span<const std::byte> bytes, std::string_view name,
                               const std::vector<std::string>& wantedList, std::string* error) {
  std::optional<PlyHeader> header = readPlyHeader(bytes, name, error);
  if (!header) return std::nullopt;
  PlyData d;
  d.header = std::move(*header);
  const std::set<std::string> wanted(wantedList.begin(), wantedList.end());
  const uint64_t size = bytes.size();
  auto failByte = [&](uint64_t byte, const std::string& message) -> std::optional<PlyData> {
    if (error) *error = std::string(name) + ": byte " + std::to_string(byte) + ": " + message;
    return std::nullopt;
  };
  auto failLine = [&](size_t line, const std::string& message) -> std::optional<PlyData> {
    if (error) *error = std::string(name) + ":" + std::to_string(line) + ": " + message;
    return std::nullopt;
  };

  // Room for what each element needs at least, before anything is allocated: a binary row its
  // scalars and list counts; an ASCII value a digit and a space.
  {
    uint64_t need = 0;
    const bool ascii = d.header.format == PlyFormat::Ascii;
    for (const PlyElement& e : d.header.elements) {
      uint64_t row = 0;
      for (const PlyProperty& p : e.properties)
        row += ascii ? 2 : sizeOf(p.list ? p.countType : p.type);
      // Rows of nothing are nothing to read: an element of rows without a property is a
      // header's mistake (and millions of empty rows would be read one at a time).
      if (row == 0 && e.count > 0)
        return failLine(e.line, "element \"" + e.name + "\" has " + std::to_string(e.count) +
                                    " rows but no property");
      if (row > 0 && e.count > (size - d.header.bodyAt) / row + 1)
        return failLine(e.line, "element \"" + e.name + "\" has " + std::to_string(e.count) +
                                    " rows, more than the " +
                                    std::to_string(size - d.header.bodyAt) +
                                    " bytes after the header can hold");
      need += row * e.count;
      if (need > 2 * size + 2)
        return failLine(
            e.line, "the elements need more than the file's " + std::to_string(size) + " bytes");
    }
  }
  // Columns for the wanted properties, sized for the rows.
  for (const PlyElement& e : d.header.elements) {
    bool any = false;
    for (const PlyProperty& p : e.properties) {
      const std::string key = e.name + "." + p.name;
      if (!wanted.count(key)) continue;
      any = true;
      PlyColumn& c = d.columns[key];
      if (p.list) {
        c.first.reserve(e.count + 1);
        c.first.push_back(0);
      } else {
        c.values.reserve(e.count);
      }
    }
    if (any) d.rowAt[e.name].reserve(e.count);
  }

  if (d.header.format != PlyFormat::Ascii) {
    const bool swap = (d.header.format == PlyFormat::BinaryBigEndian) !=
                      (std::endian::native == std::endian::big);
    uint64_t at = d.header.bodyAt;
    for (const PlyElement& e : d.header.elements) {
      const std::vector<int> keep = wantedOf(e, wanted);
      std::vector<PlyColumn*> cols;
      for (const PlyProperty& p : e.properties) {
        auto it = d.columns.find(e.name + "." + p.name);
        cols.push_back(it == d.columns.end() ? nullptr : &it->second);
      }
      auto rows = d.rowAt.find(e.name);
      for (uint64_t r = 0; r < e.count; ++r) {
        if (rows != d.rowAt.end()) rows->second.push_back(at);
        for (size_t k = 0; k < e.properties.size(); ++k) {
          const PlyProperty& p = e.properties[k];
          uint64_t items = 1;
          if (p.list) {
            const size_t cs = sizeOf(p.countType);
            if (at + cs > size)
              return failByte(at, "the file ends inside row " + std::to_string(r) + " of the " +
                                      std::to_string(e.count) + " of element \"" + e.name + "\"");
            const double n = loadValue(bytes.data() + at, p.countType, swap);
            if (n < 0)
              return failByte(at, "list \"" + p.name + "\" of row " + std::to_string(r) +
                                      " of element \"" + e.name + "\" has a negative count");
            items = uint64_t(n);
            at += cs;
          }
          const size_t is = sizeOf(p.type);
          if (items > (size - std::min(size, at)) / is)
            return failByte(at, "the file ends inside row " + std::to_string(r) + " of the " +
                                    std::to_string(e.count) + " of element \"" + e.name +
                                    "\" (property \"" + p.name + "\")");
          if (keep[k]) {
            PlyColumn& c = *cols[k];
            for (uint64_t i = 0; i < items; ++i)
              c.values.push_back(loadValue(bytes.data() + at + i * is, p.type, swap));
            if (p.list) c.first.push_back(c.values.size());
          }
          at += items * is;
        }
      }
    }
    if (at != size)
      return failByte(at, std::to_string(size - at) +
                              " bytes after the last element; the header's counts account for " +
                              std::to_string(at));
    return d;
  }

  // ASCII: values are tokens separated by spaces, tabs and line ends.
  const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  uint64_t at = d.header.bodyAt;
  size_t line = d.header.bodyLine;
  size_t lastLine = d.header.bodyLine - 1;  // of the last token read: where a short file ends
  auto token = [&](std::string_view& out) {
    while (at < all.size()) {
      const char c = all[at];
      if (c == '\n') {
        ++line;
        ++at;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++at;
      } else {
        break;
      }
    }
    if (at >= all.size()) return false;
    const uint64_t start = at;
    while (at < all.size() && all[at] != ' ' && all[at] != '\t' && all[at] != '\r' &&
           all[at] != '\n')
      ++at;
    out = all.substr(start, at - start);
    lastLine = line;
    return true;
  };
  auto value = [&](PlyType t, std::string_view tok, double& v) {
    if (isInteger(t)) {
      long long i = 0;
      const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), i);
      if (ec != std::errc() || p != tok.data() + tok.size()) return false;
      double lo, hi;
      rangeOf(t, lo, hi);
      v = double(i);
      return v >= lo && v <= hi;
    }
    const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec == std::errc() && p == tok.data() + tok.size()) return true;
    return detail::parseNumber(tok, v);
  };
  for (const PlyElement& e : d.header.elements) {
    const std::vector<int> keep = wantedOf(e, wanted);
    std::vector<PlyColumn*> cols;
    for (const PlyProperty& p : e.properties) {
      auto it = d.columns.find(e.name + "." + p.name);
      cols.push_back(it == d.columns.end() ? nullptr : &it->second);
    }
    auto rows = d.rowAt.find(e.name);
    for (uint64_t r = 0; r < e.count; ++r) {
      bool first = true;
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        std::string_view tok;
        auto get = [&](PlyType t, const char* what, double& v) {
          if (!token(tok)) return false;
          if (first && rows != d.rowAt.end()) rows->second.push_back(line);
          first = false;
          if (!value(t, tok, v)) {
            if (error)
              *error = std::string(name) + ":" + std::to_string(line) + ": " + what + " \"" +
                       std::string(tok) + "\" of property \"" + p.name + "\" (row " +
                       std::to_string(r) + " of element \"" + e.name + "\") is not " +
                       (isInteger(t) ? "an integer of type " : "a number of type ") +
                       plyTypeName(t);
            return false;
          }
          return true;
        };
        auto ended = [&]() {
          return failLine(lastLine, "the file ends inside row " + std::to_string(r) + " of the " +
                                        std::to_string(e.count) + " of element \"" + e.name + "\"");
        };
        uint64_t items = 1;
        double v = 0.0;
        if (p.list) {
          if (!get(p.countType, "the count", v)) return tok.empty() ? ended() : std::nullopt;
          if (v < 0) return failLine(line, "list \"" + p.name + "\" has a negative count");
          items = uint64_t(v);
          if (items > all.size() - at)
            return failLine(line, "list \"" + p.name + "\" counts " + std::to_string(items) +
                                      " items, more than the rest of the file holds");
        }
        for (uint64_t i = 0; i < items; ++i) {
          tok = {};
          if (!get(p.type, "the value", v)) return tok.empty() ? ended() : std::nullopt;
          if (keep[k]) cols[k]->values.push_back(v);
        }
        if (keep[k] && p.list) cols[k]->first.push_back(cols[k]->values.size());
      }
    }
  }
  std::string_view rest;
  if (token(rest))
    return failLine(line, "\"" + std::string(rest.substr(0, 32)) +
                              "\" after the last element; the header's counts account for "
                              "everything before it");
  return d;
}

}  // namespace csm::io
