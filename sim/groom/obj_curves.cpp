#include "sim/groom/obj_curves.h"

#include <algorithm>
#include <charconv>
#include <span>
#include <string>
#include <vector>

#include "sim/base/file_io.h"
#include "sim/base/obj_text.h"

namespace csm::io {
namespace {

// A number token, fast for the millions a large groom has; strtod for what from_chars does not
// take (a leading '+').
bool number(std::string_view token, double& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec == std::errc() && ptr == end) return true;
  return detail::parseNumber(token, value);
}

// One undirected edge between two vertices (0-based), with the line that gave it.
struct Edge {
  uint32_t a, b;
  size_t line;
};

// Each vertex's edges: at most two in a chain (indices into the edge list; -1: none).
struct Links {
  int32_t edge[2] = {-1, -1};
  int32_t count = 0;
};

}  // namespace

GroomReadResult readObjCurves(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult result;
  const std::string_view text = detail::withoutBom(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  auto fail = [&](size_t line, const std::string& message) {
    result.error = std::string(name) + ":" + std::to_string(line) + ": " + message;
    return result;
  };

  // Read element by element; nothing held grows faster than the vertices (each has at most two
  // edges, checked as each edge comes), whatever the file holds.
  std::vector<glm::vec3> positions;
  std::vector<size_t> vertexLine;
  std::vector<Links> links;
  std::vector<Edge> edges;
  GroomRepair notes;
  detail::LineCursor lines(text);
  size_t line = 0;
  std::string_view raw, keyword, token;
  while (lines.next(line, raw)) {
    detail::ElementTokens t(lines, detail::withoutComment(raw));
    if (!t.next(keyword)) continue;
    if (keyword.find('\0') != std::string_view::npos) return fail(line, "a NUL byte; OBJ is text");
    if (keyword == "v") {
      double v[3];
      for (int c = 0; c < 3; ++c) {
        if (!t.next(token))
          return fail(line, "a vertex needs 3 coordinates, this one has " + std::to_string(c));
        if (!number(token, v[c]))
          return fail(line, "vertex coordinate \"" + std::string(token) + "\" is not a number");
      }
      t.drain();  // w, or the colours some tools write
      if (positions.size() >= kMaxPoints)
        return fail(line, "more than " + std::to_string(kMaxPoints) + " vertices");
      positions.emplace_back(float(v[0]), float(v[1]), float(v[2]));
      vertexLine.push_back(line);
      links.emplace_back();
    } else if (keyword == "l") {
      long previous = -1;
      size_t count = 0;
      while (t.next(token)) {
        ++count;
        const std::string_view ref = token.substr(0, token.find('/'));  // v or v/vt
        long index = 0;
        if (!detail::parseIndex(ref, index))
          return fail(line, "line element index \"" + std::string(ref) + "\" is not an integer");
        // Negative indices count back from the last vertex read so far (OBJ's rule).
        const long vertices = long(positions.size());
        const long resolved = index < 0 ? vertices + index + 1 : index;
        if (index == 0 || resolved < 1 || resolved > vertices)
          return fail(line, "line element index " + std::to_string(index) +
                                " is out of range: " + std::to_string(vertices) +
                                (vertices == 1 ? " vertex" : " vertices") + " before it");
        const long v = resolved - 1;
        const long from = previous;
        previous = v;
        if (from < 0 || v == from) continue;  // the first vertex, or a point to itself
        // The same edge again is read once; a third edge at a vertex is a branch.
        Links &la = links[size_t(from)], &lb = links[size_t(v)];
        bool again = false;
        for (int i = 0; i < la.count; ++i) {
          const Edge& e = edges[size_t(la.edge[i])];
          again = again || e.a == uint32_t(v) || e.b == uint32_t(v);
        }
        if (again) {
          if (notes.notes.size() < GroomRepair::kMaxNotes)
            notes.notes.push_back(std::string(name) + ":" + std::to_string(line) + ": the edge " +
                                  std::to_string(from + 1) + "-" + std::to_string(v + 1) +
                                  " is given again: read once");
          continue;
        }
        for (const long end : {from, v}) {
          const Links& l = links[size_t(end)];
          if (l.count < 2) continue;
          const size_t a = edges[size_t(l.edge[0])].line, b = edges[size_t(l.edge[1])].line;
          const std::string before =
              a == b ? "two on line " + std::to_string(a)
                     : "lines " + std::to_string(a) + " and " + std::to_string(b);
          return fail(line, "vertex " + std::to_string(end + 1) + " (line " +
                                std::to_string(vertexLine[size_t(end)]) +
                                ") has a third edge here, after " + before +
                                ": a strand cannot branch");
        }
        la.edge[la.count++] = int32_t(edges.size());
        lb.edge[lb.count++] = int32_t(edges.size());
        edges.push_back({uint32_t(from), uint32_t(v), line});
      }
      if (count < 2)
        return fail(line, "a line element needs at least 2 vertices, this one has " +
                              std::to_string(count));
    } else if (keyword == "cstype" || keyword == "curv" || keyword == "curv2") {
      return fail(line, "free-form curves (\"" + std::string(keyword) +
                            "\") are not read; export the hair as polylines (\"l\" elements)");
    } else {
      // f, o, g, s, vt, vn, mtllib, usemtl, p and the rest: not hair curves.
      t.drain();
    }
  }
  if (edges.empty())
    return fail(lines.lastNonBlank(),
                "no line elements (\"l\"): hair is read from a groom's curves; a head mesh "
                "goes in head.mesh");

  auto other = [&](size_t e, uint32_t v) { return edges[e].a == v ? edges[e].b : edges[e].a; };
  // The edge of v that is not `from` (-1: v ends the chain).
  auto next = [&](uint32_t v, int64_t from) {
    const Links& l = links[v];
    for (int i = 0; i < l.count; ++i)
      if (l.edge[i] != from) return int64_t(l.edge[i]);
    return int64_t(-1);
  };

  // Chains in the order of their first edge in the file, from the end met first.
  Groom groom;
  std::vector<uint32_t> order;  // the file's vertex of each point, for the notes
  std::vector<bool> used(edges.size(), false);
  std::vector<glm::vec3> strand;
  for (size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    // Back from the edge's first vertex to the end of the chain.
    uint32_t start = edges[first].a;
    int64_t via = int64_t(first);
    for (;;) {
      const int64_t e = next(start, via);
      if (e < 0) break;
      if (e == int64_t(first))
        return fail(edges[first].line, "the edges from this line close a loop through vertex " +
                                           std::to_string(start + 1) +
                                           ": a strand has a root and a tip");
      start = other(size_t(e), start);
      via = e;
    }
    // Then forward to the other end.
    strand.clear();
    uint32_t v = start;
    int64_t e = next(v, -1);
    strand.push_back(positions[v]);
    order.push_back(v);
    while (e >= 0) {
      used[size_t(e)] = true;
      v = other(size_t(e), v);
      strand.push_back(positions[v]);
      order.push_back(v);
      e = next(v, e);
    }
    if (groom.points.size() > kMaxPoints)
      return fail(edges[first].line,
                  "the strands exceed the limit of " + std::to_string(kMaxPoints) + " points");
    groom.addStrand(strand);
  }
  result.repair = notes;
  result.rootsKnown = false;
  detail::finishGroom(result, std::move(groom), name, [order, vertexLine](size_t point, int) {
    return "line " + std::to_string(vertexLine[order[point]]);
  });
  return result;
}

GroomReadResult readObjCurves(const std::string& path) {
  return detail::readGroomFile(path, [](std::span<const std::byte> bytes, std::string_view name) {
    return readObjCurves(bytes, name);
  });
}

std::string encodeObjCurves(const Groom& groom) {
  std::string out;
  out.reserve(64 + groom.pointCount() * 48);
  out += "# csmhair: " + std::to_string(groom.strandCount()) + " strands, " +
         std::to_string(groom.pointCount()) + " points; metres, y up; one \"l i j\" an edge\n";
  out += "o hair\n";
  char buf[32];
  // The shortest text that reads back to the same float (to_chars' round trip).
  auto put = [&](float value) {
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    out += ' ';
    out.append(buf, ec == std::errc() ? end : buf);
  };
  for (const glm::vec3& p : groom.points) {
    out += 'v';
    put(p.x);
    put(p.y);
    put(p.z);
    out += '\n';
  }
  for (size_t s = 0; s < groom.strandCount(); ++s)
    for (uint32_t i = groom.first[s] + 1; i < groom.first[s + 1]; ++i) {
      out += "l ";
      out += std::to_string(i);  // OBJ counts vertices from 1: points i - 1 and i
      out += ' ';
      out += std::to_string(i + 1);
      out += '\n';
    }
  return out;
}

bool writeObjCurves(const std::string& path, const Groom& groom, std::string* error) {
  const std::string text = encodeObjCurves(groom);
  return detail::writeFileAtomically(
      path, std::as_bytes(std::span<const char>(text.data(), text.size())), error);
}

}  // namespace csm::io
