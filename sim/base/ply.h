// The Stanford PLY format as the hair and head tools write it: a text header naming elements
// (vertex, face, strand, edge, ...) and their properties, then the rows in ASCII or binary
// (little or big endian). Properties come in any order and any of the eight scalar types; a list
// property (a face's vertex_indices) has a count type and an item type. Only the columns asked
// for are kept (as doubles, which hold every PLY type exactly); the rest are passed over. Every
// error names the header line, or the body's byte (binary) or line (ASCII).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace csm::io {

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyFormat : uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // a list's items
  bool list = false;
  PlyType countType = PlyType::UInt8;  // a list's count
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  size_t line = 0;  // of its "element" line in the header

  const PlyProperty* property(std::string_view name) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  uint64_t bodyAt = 0;  // the byte after "end_header"'s line
  size_t bodyLine = 0;  // the body's first line (ASCII)

  const PlyElement* element(std::string_view name) const;
};

// One property of one element: a value a row, or for a list the values of row r in
// [first[r], first[r + 1]).
struct PlyColumn {
  std::vector<double> values;
  std::vector<uint64_t> first;  // lists only
};

struct PlyData {
  PlyHeader header;
  // "element.property" -> its column, for those asked for that the file has.
  std::map<std::string, PlyColumn> columns;
  // Per element asked for: where each row starts (a byte of the file, or a line of it).
  std::map<std::string, std::vector<uint64_t>> rowAt;

  const PlyColumn* column(std::string_view element, std::string_view property) const;
  // "byte N" or "line N" of row `row` of `element` (one asked for).
  std::string where(std::string_view element, uint64_t row) const;
};

// Whether the bytes start as a PLY file does ("ply" and a line end).
bool isPly(std::span<const std::byte> bytes);

// The header alone; nullopt with *error "name:line: ..." when it is not one.
std::optional<PlyHeader> readPlyHeader(std::span<const std::byte> bytes, std::string_view name,
                                       std::string* error);

// The header and the columns named in `wanted` ("vertex.x", "face.vertex_indices": those the
// file lacks are left out; the caller decides what it needs). The body is checked whole: a file
// that ends inside an element, a token that is not a number of its type, or bytes left after the
// last element are errors. Nothing is allocated before the counts have been checked against the
// file's size.
std::optional<PlyData> readPly(std::span<const std::byte> bytes, std::string_view name,
                               const std::vector<std::string>& wanted, std::string* error);

// The type's name as a header writes it ("float", "uchar", ...).
const char* plyTypeName(PlyType type);

}  // namespace csm::io
