#include "sim/groom/research_formats.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "sim/base/ply.h"

namespace csm::io {
namespace {

using detail::errorAt;
using detail::loadLE;

// A strand of fewer than two points, dropped by the reader and named in the repair's notes.
void dropShort(GroomRepair& repair, std::string_view name, const std::string& where, size_t s,
               uint64_t points) {
  ++repair.droppedStrands;
  if (repair.notes.size() < GroomRepair::kMaxNotes)
    repair.notes.push_back(std::string(name) + ": " + where + ": strand " + std::to_string(s) +
                           " dropped: it has " + std::to_string(points) +
                           (points == 1 ? " point" : " points"));
}

template <class T>
void append(std::vector<std::byte>& out, T v) {
  const auto* p = reinterpret_cast<const std::byte*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

// What every writer refuses: a broken structure, no strand, a point that is not finite.
std::string unwritable(const Groom& groom) {
  if (std::string problem = checkGroomStructure(groom); !problem.empty()) return problem;
  if (groom.strandCount() == 0) return "the groom has no strands";
  for (size_t i = 0; i < groom.pointCount(); ++i) {
    const glm::vec3& p = groom.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return "point " + std::to_string(i) + " is not finite";
  }
  return {};
}

}  // namespace

GroomReadResult readStrandArrays(std::span<const std::byte> bytes, std::string_view name,
                                 int floats) {
  GroomReadResult result;
  auto fail = [&](uint64_t offset, const std::string& message) {
    result.error = errorAt(name, offset, message);
    return result;
  };
  const uint64_t size = bytes.size();
  const uint64_t pointBytes = 4 * uint64_t(floats);
  if (size < 4)
    return fail(
        0, "expected an int32 strand count, the data has only " + std::to_string(size) + " bytes");
  const int32_t count = loadLE<int32_t>(bytes, 0);
  if (count <= 0)
    return fail(0, "strand count " + std::to_string(count) + "; expected at least 1 strand");
  if (uint64_t(count) > kMaxStrands)
    return fail(0, "strand count " + std::to_string(count) + " exceeds the limit of " +
                       std::to_string(kMaxStrands));
  if (4 + 4 * uint64_t(count) > size)
    return fail(0, "strand count " + std::to_string(count) + " needs at least " +
                       std::to_string(4 + 4 * uint64_t(count)) + " bytes, the file has " +
                       std::to_string(size));
  Groom groom;
  std::vector<uint64_t> pointAt;  // the byte of each kept point's x
  std::vector<size_t> fileStrand;
  std::vector<glm::vec3> strand;
  uint64_t at = 4;
  for (int32_t s = 0; s < count; ++s) {
    if (at + 4 > size)
      return fail(at, "the file ends before strand " + std::to_string(s) + " of the " +
                          std::to_string(count) + " its first 4 bytes count");
    const int32_t n = loadLE<int32_t>(bytes, at);
    if (n < 0)
      return fail(at, "strand " + std::to_string(s) + " has " + std::to_string(n) +
                          " points; expected 0 or more");
    if (groom.points.size() + uint64_t(n) > kMaxPoints)
      return fail(
          at, "the strands so far exceed the limit of " + std::to_string(kMaxPoints) + " points");
    const uint64_t need = uint64_t(n) * pointBytes;
    if (at + 4 + need > size)
      return fail(at, "strand " + std::to_string(s) + "'s " + std::to_string(n) + " points (" +
                          std::to_string(need) + " bytes of " + std::to_string(floats) +
                          " float32 a point) run past the end of the file (size " +
                          std::to_string(size) + ")");
    const uint64_t strandAt = at;
    at += 4;
    if (n < 2) {
      dropShort(result.repair, name, "byte " + std::to_string(strandAt), size_t(s), uint64_t(n));
      at += need;
      continue;
    }
    strand.clear();
    for (int32_t i = 0; i < n; ++i, at += pointBytes) {
      strand.emplace_back(loadLE<float>(bytes, at), loadLE<float>(bytes, at + 4),
                          loadLE<float>(bytes, at + 8));
      pointAt.push_back(at);
    }
    groom.addStrand(strand);
    fileStrand.push_back(size_t(s));
  }
  if (at != size)
    return fail(at, std::to_string(size - at) +
                        " unexpected bytes after the last strand; the file's counts (" +
                        std::to_string(count) + " strands) account for " + std::to_string(at) +
                        " bytes");
  if (groom.strandCount() == 0)
    return fail(0, "no strand has 2 points or more (all " + std::to_string(count) + " dropped)");
  detail::finishGroom(
      result, std::move(groom), name,
      [pointAt](size_t point, int axis) {
        return "byte " +
               std::to_string((point < pointAt.size() ? pointAt[point] : 0) + 4 * uint64_t(axis));
      },
      std::move(fileStrand));
  return result;
}

std::optional<std::vector<std::byte>> encodeStrandArrays(const Groom& groom, int floats,
                                                         std::string* error) {
  if (const std::string problem = unwritable(groom); !problem.empty()) {
    if (error) *error = "strand writer: " + problem;
    return std::nullopt;
  }
  std::vector<std::byte> out;
  out.reserve(4 + 4 * groom.strandCount() + 4 * size_t(floats) * groom.pointCount());
  append(out, int32_t(groom.strandCount()));
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    append(out, int32_t(groom.strandSize(s)));
    for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) {
      const glm::vec3& p = groom.points[i];
      append(out, p.x);
      append(out, p.y);
      append(out, p.z);
      for (int k = 3; k < floats; ++k) append(out, 0.0f);
    }
  }
  return out;
}

namespace {

// The strands of a PLY that has no strand element, from its edges: chains through the vertices
// they share, each from its end with the lower vertex number. Empty string or the error.
std::string chainEdges(const PlyData& d, const PlyColumn* a, const PlyColumn* b,
                       const PlyColumn* list, uint64_t vertices,
                       std::vector<std::vector<uint32_t>>& chains) {
  struct Links {
    int64_t edge[2] = {-1, -1};
    int count = 0;
  };
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  std::vector<uint64_t> edgeRow;
  auto add = [&](double x, double y, uint64_t row) -> std::string {
    if (!(x >= 0 && x < double(vertices)) || !(y >= 0 && y < double(vertices)))
      return d.where("edge", row) + ": edge " + std::to_string(row) + " joins vertices " +
             std::to_string(int64_t(x)) + " and " + std::to_string(int64_t(y)) + ", of the " +
             std::to_string(vertices) + " the file has (counted from 0)";
    if (x != y) {
      edges.emplace_back(uint32_t(x), uint32_t(y));
      edgeRow.push_back(row);
    }
    return {};
  };
  if (a && b) {
    for (size_t r = 0; r < a->values.size(); ++r)
      if (std::string e = add(a->values[r], b->values[r], r); !e.empty()) return e;
  } else {
    for (size_t r = 0; r + 1 < list->first.size(); ++r)
      for (uint64_t k = list->first[r]; k + 1 < list->first[r + 1]; ++k)
        if (std::string e = add(list->values[k], list->values[k + 1], r); !e.empty()) return e;
  }
  std::vector<Links> links(vertices);
  for (size_t e = 0; e < edges.size(); ++e)
    for (const uint32_t v : {edges[e].first, edges[e].second}) {
      Links& l = links[v];
      if (l.count == 2)
        return d.where("edge", edgeRow[e]) + ": vertex " + std::to_string(v) +
               " has a third edge here: a strand cannot branch";
      l.edge[l.count++] = int64_t(e);
    }
  std::vector<bool> used(edges.size(), false);
  auto other = [&](int64_t e, uint32_t v) {
    return edges[size_t(e)].first == v ? edges[size_t(e)].second : edges[size_t(e)].first;
  };
  for (uint64_t v = 0; v < vertices; ++v) {
    const Links& l = links[v];
    if (l.count != 1 || used[size_t(l.edge[0])]) continue;
    std::vector<uint32_t> chain{uint32_t(v)};
    int64_t e = l.edge[0];
    uint32_t at = uint32_t(v);
    while (e >= 0) {
      used[size_t(e)] = true;
      at = other(e, at);
      chain.push_back(at);
      const Links& n = links[at];
      int64_t next = -1;
      for (int i = 0; i < n.count; ++i)
        if (n.edge[i] != e) next = n.edge[i];
      e = next;
    }
    chains.push_back(std::move(chain));
  }
  for (size_t e = 0; e < edges.size(); ++e)
    if (!used[e])
      return d.where("edge", edgeRow[e]) +
             ": this edge is part of a closed loop: a strand has a root and a tip";
  return {};
}

}  // namespace

GroomReadResult readPlyStrands(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult result;
  std::string error;
  const std::vector<std::string> wanted = {"vertex.x",         "vertex.y",           "vertex.z",
                                           "vertex.red",       "vertex.green",       "vertex.blue",
                                           "vertex.thickness", "strand.nsegs",       "edge.vertex1",
                                           "edge.vertex2",     "edge.vertex_indices"};
  std::optional<PlyData> d = readPly(bytes, name, wanted, &error);
  if (!d) {
    result.error = error;
    return result;
  }
  auto fail = [&](const std::string& where, const std::string& message) {
    result.error = std::string(name) + ": " + where + ": " + message;
    return result;
  };
  const PlyElement* vertex = d->header.element("vertex");
  if (!vertex || !vertex->property("x") || !vertex->property("y") || !vertex->property("z"))
    return fail("header", "no element \"vertex\" with properties x, y and z: not strands");
  for (const char* axis : {"x", "y", "z"})
    if (vertex->property(axis)->list)
      return fail("line " + std::to_string(vertex->line),
                  std::string("vertex property \"") + axis + "\" is a list; expected a number");
  const uint64_t vertices = vertex->count;
  if (vertices > kMaxPoints)
    return fail(
        "line " + std::to_string(vertex->line),
        std::to_string(vertices) + " vertices exceed the limit of " + std::to_string(kMaxPoints));
  const PlyColumn* xs = d->column("vertex", "x");
  const PlyColumn* ys = d->column("vertex", "y");
  const PlyColumn* zs = d->column("vertex", "z");

  // Strands as runs of consecutive vertices: from nsegs, or from chained edges.
  std::vector<std::vector<uint32_t>> chains;
  const PlyElement* strandElement = d->header.element("strand");
  const PlyColumn* nsegs = d->column("strand", "nsegs");
  if (strandElement && nsegs && !strandElement->property("nsegs")->list) {
    uint64_t next = 0;
    for (size_t s = 0; s < nsegs->values.size(); ++s) {
      const double n = nsegs->values[s];
      if (!(n >= 0) || n != std::floor(n))
        return fail(d->where("strand", s), "nsegs of strand " + std::to_string(s) + " is " +
                                               std::to_string(n) + "; expected 0 or more");
      const uint64_t points = uint64_t(n) + 1;
      if (next + points > vertices)
        return fail(d->where("strand", s), "strand " + std::to_string(s) + " ends at vertex " +
                                               std::to_string(next + points) + ", past the " +
                                               std::to_string(vertices) + " vertices of the file");
      std::vector<uint32_t> chain(points);
      for (uint64_t i = 0; i < points; ++i) chain[i] = uint32_t(next + i);
      chains.push_back(std::move(chain));
      next += points;
    }
    if (next != vertices)
      return fail(d->where("strand", 0), "the strands' nsegs account for " + std::to_string(next) +
                                             " vertices, the file has " + std::to_string(vertices));
  } else {
    const PlyColumn* a = d->column("edge", "vertex1");
    const PlyColumn* b = d->column("edge", "vertex2");
    const PlyColumn* list = d->column("edge", "vertex_indices");
    if (!(a && b) && !(list && !list->first.empty()))
      return fail("header",
                  "no element \"strand\" with nsegs and no element \"edge\" with vertex1 and "
                  "vertex2 (or vertex_indices): the strands cannot be told apart");
    if (std::string e = chainEdges(*d, a, b, a && b ? nullptr : list, vertices, chains);
        !e.empty()) {
      result.error = std::string(name) + ": " + e;
      return result;
    }
  }

  // Colour as 0-1 from an integer type's range or a float as it is; thickness as written.
  const PlyColumn* colour[3] = {d->column("vertex", "red"), d->column("vertex", "green"),
                                d->column("vertex", "blue")};
  const bool hasColour = colour[0] && colour[1] && colour[2];
  double colourScale = 1.0;
  if (hasColour) {
    const PlyType t = vertex->property("red")->type;
    colourScale = t == PlyType::UInt8                              ? 1.0 / 255.0
                  : t == PlyType::UInt16                           ? 1.0 / 65535.0
                  : t == PlyType::Float32 || t == PlyType::Float64 ? 1.0
                                                                   : 1.0 / 255.0;
  }
  const PlyColumn* thickness = d->column("vertex", "thickness");
  Groom groom;
  std::vector<uint32_t> order;  // the file's vertex of each kept point
  std::vector<size_t> fileStrand;
  std::vector<glm::vec3> strand;
  for (size_t s = 0; s < chains.size(); ++s) {
    const std::vector<uint32_t>& c = chains[s];
    if (c.size() < 2) {
      dropShort(result.repair, name, d->where(nsegs ? "strand" : "edge", s), s, c.size());
      continue;
    }
    strand.clear();
    double sum[3] = {0, 0, 0}, width = 0;
    for (const uint32_t v : c) {
      strand.emplace_back(float(xs->values[v]), float(ys->values[v]), float(zs->values[v]));
      order.push_back(v);
      for (int k = 0; k < 3 && hasColour; ++k) sum[k] += colour[k]->values[v];
      if (thickness) width += thickness->values[v];
    }
    groom.addStrand(strand);
    fileStrand.push_back(s);
    const double n = double(c.size());
    if (hasColour)
      groom.color.emplace_back(std::clamp(float(sum[0] * colourScale / n), 0.0f, 1.0f),
                               std::clamp(float(sum[1] * colourScale / n), 0.0f, 1.0f),
                               std::clamp(float(sum[2] * colourScale / n), 0.0f, 1.0f));
    if (thickness) groom.thickness.push_back(std::max(0.0f, float(width / n)));
  }
  if (groom.strandCount() == 0) return fail("header", "no strand has 2 vertices or more");
  const PlyData& data = *d;
  detail::finishGroom(
      result, std::move(groom), name,
      [&data, order](size_t point, int) {
        return data.where("vertex", point < order.size() ? order[point] : 0);
      },
      std::move(fileStrand));
  return result;
}

std::optional<std::vector<std::byte>> encodePlyStrands(const Groom& groom, bool ascii,
                                                       std::string* error) {
  if (std::string problem = unwritable(groom); !problem.empty()) {
    if (error) *error = "PLY writer: " + problem;
    return std::nullopt;
  }
  for (size_t s = 0; s < groom.strandCount(); ++s)
    if (groom.strandSize(s) - 1 > std::numeric_limits<uint16_t>::max()) {
      if (error) *error = "PLY writer: strand " + std::to_string(s) + " has more than 65536 points";
      return std::nullopt;
    }
  const bool colour = !groom.color.empty(), width = !groom.thickness.empty();
  std::string header = "ply\nformat ";
  header += ascii ? "ascii 1.0\n" : "binary_little_endian 1.0\n";
  header += "comment csmhair strands: metres, y up, face +z; each strand root first\n";
  header += "element vertex " + std::to_string(groom.pointCount()) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  if (colour) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (width) header += "property float thickness\n";
  header += "element strand " + std::to_string(groom.strandCount()) + "\n";
  header += "property ushort nsegs\nend_header\n";
  std::vector<std::byte> out;
  const auto* h = reinterpret_cast<const std::byte*>(header.data());
  out.insert(out.end(), h, h + header.size());
  auto unorm = [](float c) { return uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  std::string text;
  char buf[32];
  auto put = [&](float v) {
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    text.append(buf, ec == std::errc() ? end : buf);
  };
  for (size_t s = 0; s < groom.strandCount(); ++s)
    for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) {
      const glm::vec3& p = groom.points[i];
      if (ascii) {
        text.clear();
        put(p.x);
        text += ' ';
        put(p.y);
        text += ' ';
        put(p.z);
        if (colour)
          for (int k = 0; k < 3; ++k) text += ' ' + std::to_string(unorm(groom.color[s][k]));
        if (width) {
          text += ' ';
          put(groom.thickness[s]);
        }
        text += '\n';
        const auto* t = reinterpret_cast<const std::byte*>(text.data());
        out.insert(out.end(), t, t + text.size());
      } else {
        append(out, p.x);
        append(out, p.y);
        append(out, p.z);
        if (colour)
          for (int k = 0; k < 3; ++k) append(out, unorm(groom.color[s][k]));
        if (width) append(out, groom.thickness[s]);
      }
    }
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const uint16_t nsegs = uint16_t(groom.strandSize(s) - 1);
    if (ascii) {
      const std::string line = std::to_string(nsegs) + "\n";
      const auto* t = reinterpret_cast<const std::byte*>(line.data());
      out.insert(out.end(), t, t + line.size());
    } else {
      append(out, nsegs);
    }
  }
  return out;
}

}  // namespace csm::io
