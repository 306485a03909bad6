#include "sim/head/obj_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "sim/base/file_io.h"
#include "sim/base/obj_text.h"
#include "sim/base/ply.h"

namespace csm::io {
namespace {

using detail::objLines;
using detail::objTokens;
using detail::parseIndex;
using detail::parseNumber;

constexpr uint64_t kMaxBytes = uint64_t(512) << 20;

// Our pass over the lines: every number and index is checked here, with its line, so that
// tinyobjloader (which skips or clamps some of them) only sees what it reads correctly.
// Returns the line of each face, in the file's order.
std::string checkLines(std::string_view text, const std::string& path,
                       std::vector<size_t>& faceLines) {
  const auto all = objLines(text);
  long totals[3] = {0, 0, 0};  // v, vt, vn
  for (const auto& [number, line] : all) {
    const auto t = objTokens(line);
    if (t.empty()) continue;
    if (t[0] == "v") ++totals[0];
    if (t[0] == "vt") ++totals[1];
    if (t[0] == "vn") ++totals[2];
  }
  auto at = [&](size_t number, const std::string& message) {
    return path + ":" + std::to_string(number) + ": " + message;
  };
  // tinyobjloader reads a line only up to a NUL byte: what it saw would not be what is
  // checked below.
  for (const auto& [number, line] : all)
    if (line.find('\0') != std::string_view::npos)
      return at(number, "a NUL byte; an OBJ file is text");
  long seen[3] = {0, 0, 0};
  static const char* kind[3] = {"vertex", "texture coordinate", "normal"};
  static const char* kinds[3] = {"vertices", "texture coordinates", "normals"};
  for (const auto& [number, line] : all) {
    const auto t = objTokens(line);
    if (t.empty()) continue;
    if (t[0] == "v" || t[0] == "vn" || t[0] == "vt") {
      const int k = t[0] == "v" ? 0 : t[0] == "vt" ? 1 : 2;
      ++seen[k];
      const size_t need = k == 1 ? 2 : 4;
      if (t.size() < need)
        return at(number, std::string(kind[k]) + " has " + std::to_string(t.size() - 1) +
                              " coordinates, expected " + std::to_string(need - 1));
      for (size_t i = 1; i < t.size() && i < (k == 0 ? 4u : t.size()); ++i) {
        double v = 0.0;
        if (!parseNumber(t[i], v))
          return at(number, std::string(kind[k]) + " coordinate \"" + std::string(t[i]) +
                                "\" is not a number");
        if (!std::isfinite(v))
          return at(number, std::string(kind[k]) + " coordinate \"" + std::string(t[i]) +
                                "\" is not finite");
      }
    } else if (t[0] == "f") {
      if (t.size() < 4)
        return at(number,
                  "a face needs at least 3 vertices, this one has " + std::to_string(t.size() - 1));
      if (t.size() > 256) return at(number, "a face has more than 255 vertices");
      for (size_t i = 1; i < t.size(); ++i) {
        // v, v/vt, v//vn or v/vt/vn
        std::string_view ref = t[i];
        for (int k = 0; k < 3; ++k) {
          const size_t slash = ref.find('/');
          const std::string_view part = ref.substr(0, slash);
          if (k == 0 || !part.empty()) {
            long index = 0;
            if (!parseIndex(part, index))
              return at(number, "face " + std::string(kind[k]) + " index \"" + std::string(part) +
                                    "\" is not an integer");
            // Negative indices count back from the last one read so far (OBJ's rule).
            const long resolved = index < 0 ? seen[k] + index + 1 : index;
            const long limit = index < 0 ? seen[k] : totals[k];
            if (index == 0 || resolved < 1 || resolved > limit)
              return at(number, "face " + std::string(kind[k]) + " index " + std::to_string(index) +
                                    " is out of range: " + std::to_string(limit) + " " +
                                    (limit == 1 ? kind[k] : kinds[k]) +
                                    (index < 0 ? " before it" : " in the file"));
          }
          if (slash == std::string_view::npos) break;
          ref = ref.substr(slash + 1);
        }
      }
      faceLines.push_back(number);
    }
  }
  if (totals[0] == 0) return path + ": no vertices (no \"v\" lines)";
  if (faceLines.empty()) return path + ": no faces (no \"f\" lines)";
  return {};
}

}  // namespace

ObjReadResult readObjMesh(const std::string& path) {
  std::string error;
  const auto bytes = detail::readFileBytes(path, kMaxBytes, &error);
  if (!bytes) return {std::nullopt, error, 0, {}};
  return parseObjMesh(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                      path);
}

ObjReadResult parseObjMesh(std::string_view data, const std::string& path) {
  ObjReadResult r;
  // NUL bytes after the last line are padding (ZBrush ends its files with one): not text, and
  // not the file's; one anywhere else is refused below.
  size_t end = data.size();
  while (end > 0 && (data[end - 1] == '\0' || data[end - 1] == '\n' || data[end - 1] == '\r' ||
                     data[end - 1] == ' ' || data[end - 1] == '\t'))
    --end;
  const std::string text = std::string(data.substr(0, end)) + "\n";
  std::vector<size_t> faceLines;
  r.error = checkLines(text, path, faceLines);
  if (!r.error.empty()) return r;

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // fans below, so that each triangle keeps its face's line
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    r.error = path + ": " + why;
    return r;
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();

  std::vector<glm::vec3> positions;
  for (size_t v = 0; v + 2 < attrib.vertices.size(); v += 3)
    positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1], attrib.vertices[v + 2]);
  size_t faces = 0;
  for (const tinyobj::shape_t& s : reader.GetShapes()) {
    faces += s.mesh.num_face_vertices.size();
    // Our checks above saw every index in range; tinyobjloader must agree before we index.
    for (const tinyobj::index_t& i : s.mesh.indices)
      if (i.vertex_index < 0 || size_t(i.vertex_index) >= positions.size()) {
        r.error = path + ": a face refers to vertex " + std::to_string(i.vertex_index + 1) +
                  " of the " + std::to_string(positions.size()) +
                  " tinyobjloader read; the file's lines are not plain OBJ";
        return r;
      }
  }
  const bool linesKnown = faces == faceLines.size();
  std::vector<uint32_t> triangles;
  std::vector<std::string> triangleWhere;
  size_t face = 0;
  for (const tinyobj::shape_t& s : reader.GetShapes()) {
    size_t first = 0;
    for (const unsigned char n : s.mesh.num_face_vertices) {
      for (size_t k = 1; k + 1 < n; ++k) {
        triangles.insert(triangles.end(), {uint32_t(s.mesh.indices[first].vertex_index),
                                           uint32_t(s.mesh.indices[first + k].vertex_index),
                                           uint32_t(s.mesh.indices[first + k + 1].vertex_index)});
        triangleWhere.push_back(linesKnown ? ":" + std::to_string(faceLines[face]) : "");
      }
      first += n;
      ++face;
    }
  }
  return finishHeadMesh(std::move(positions), triangles, triangleWhere, path);
}

ObjReadResult finishHeadMesh(std::vector<glm::vec3> positions,
                             const std::vector<uint32_t>& triangles,
                             const std::vector<std::string>& triangleWhere,
                             const std::string& path) {
  ObjReadResult r;
  // One vertex per position: exporters repeat positions where texture coordinates change.
  SurfaceMesh m;
  std::vector<uint32_t> welded(positions.size());
  std::map<std::array<float, 3>, uint32_t> byPosition;
  for (size_t v = 0; v < welded.size(); ++v) {
    const std::array<float, 3> p{positions[v].x, positions[v].y, positions[v].z};
    auto [it, added] = byPosition.try_emplace(p, uint32_t(m.positions.size()));
    if (added) m.positions.emplace_back(p[0], p[1], p[2]);
    welded[v] = it->second;
  }
  std::vector<std::string> triangleLine;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = welded[triangles[t]], b = welded[triangles[t + 1]],
                   c = welded[triangles[t + 2]];
    if (a == b || b == c || c == a) continue;  // no area, no edges
    m.indices.insert(m.indices.end(), {a, b, c});
    triangleLine.push_back(t / 3 < triangleWhere.size() ? triangleWhere[t / 3] : "");
  }
  auto at = [&](size_t triangle, const std::string& message) {
    return path + (triangle < triangleLine.size() ? triangleLine[triangle] : std::string()) + ": " +
           message;
  };
  if (m.indices.empty()) {
    r.error = path + ": no faces with area (every face repeats a vertex)";
    return r;
  }

  // A scan open at the neck (or anywhere): each hole closed by a fan, so that the surface has an
  // inside; what still does not close is refused below.
  if (openEdges(m) > 0) {
    const size_t before = m.indices.size() / 3;
    r.cappedHoles = capHoles(m, &r.holes);
    for (size_t t = before; t < m.indices.size() / 3; ++t) triangleLine.push_back("");
  }
  if (const size_t open = openEdges(m); open > 0) {
    // The first face with an edge not met once the other way round.
    std::unordered_map<uint64_t, int> directed;
    const uint64_t n = m.positions.size();
    for (size_t t = 0; t < m.indices.size(); t += 3)
      for (int e = 0; e < 3; ++e) ++directed[m.indices[t + e] * n + m.indices[t + (e + 1) % 3]];
    size_t bad = 0;
    for (size_t t = 0; t < m.indices.size() && !bad; t += 3)
      for (int e = 0; e < 3; ++e) {
        const uint64_t a = m.indices[t + e], b = m.indices[t + (e + 1) % 3];
        auto reverse = directed.find(b * n + a);
        if (directed[a * n + b] != 1 || reverse == directed.end() || reverse->second != 1) {
          bad = t / 3 + 1;
          break;
        }
      }
    r.error = at(bad ? bad - 1 : 0,
                 "the surface is not closed: " + std::to_string(open) +
                     " edges are not shared by exactly two faces turning the same way (the first "
                     "on this line); a head must be a closed, consistently oriented surface to "
                     "have an inside");
    return r;
  }

  double volume = 0.0;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    volume += glm::dot(glm::dvec3(m.positions[m.indices[t]]),
                       glm::cross(glm::dvec3(m.positions[m.indices[t + 1]]),
                                  glm::dvec3(m.positions[m.indices[t + 2]]))) /
              6.0;
  if (!(std::abs(volume) > 1e-12)) {
    r.error = path + ": the surface encloses no volume";
    return r;
  }
  if (volume < 0.0)  // the faces turn inwards: turn them out
    for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);

  // Normals weighted by the angle at each corner (independent of how the surface is split).
  std::vector<glm::dvec3> normals(m.positions.size(), glm::dvec3(0.0));
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::dvec3 p[3] = {glm::dvec3(m.positions[m.indices[t]]),
                             glm::dvec3(m.positions[m.indices[t + 1]]),
                             glm::dvec3(m.positions[m.indices[t + 2]])};
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(n);
    if (len < 1e-30) continue;
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3 u = p[(c + 1) % 3] - p[c], v = p[(c + 2) % 3] - p[c];
      const double lu = glm::length(u), lv = glm::length(v);
      if (lu < 1e-30 || lv < 1e-30) continue;
      const double angle = std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
      normals[m.indices[t + c]] += angle * n / len;
    }
  }
  m.normals.reserve(normals.size());
  for (const glm::dvec3& n : normals)
    m.normals.emplace_back(glm::length(n) > 1e-30 ? glm::normalize(n) : glm::dvec3(0, 1, 0));
  r.mesh = std::move(m);
  return r;
}

ObjReadResult parsePlyMesh(std::span<const std::byte> bytes, const std::string& path) {
  ObjReadResult r;
  std::optional<PlyData> d = readPly(
      bytes, path, {"vertex.x", "vertex.y", "vertex.z", "face.vertex_indices", "face.vertex_index"},
      &r.error);
  if (!d) return r;
  const PlyColumn* xyz[3] = {d->column("vertex", "x"), d->column("vertex", "y"),
                             d->column("vertex", "z")};
  if (!xyz[0] || !xyz[1] || !xyz[2] || d->header.element("vertex")->property("x")->list) {
    r.error = path + ": no element \"vertex\" with properties x, y and z";
    return r;
  }
  const PlyColumn* faces = d->column("face", "vertex_indices");
  if (!faces) faces = d->column("face", "vertex_index");
  if (!faces || faces->first.empty()) {
    r.error = path +
              ": no element \"face\" with a list vertex_indices: a head is a surface (strands "
              "go in hairstyle.file)";
    return r;
  }
  const size_t vertices = xyz[0]->values.size();
  if (vertices == 0) {
    r.error = path + ": no vertices";
    return r;
  }
  std::vector<glm::vec3> positions;
  for (size_t v = 0; v < vertices; ++v) {
    const glm::vec3 p(float(xyz[0]->values[v]), float(xyz[1]->values[v]), float(xyz[2]->values[v]));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      r.error =
          path + ": " + d->where("vertex", v) + ": vertex " + std::to_string(v) + " is not finite";
      return r;
    }
    positions.push_back(p);
  }
  std::vector<uint32_t> triangles;
  std::vector<std::string> where;
  for (size_t f = 0; f + 1 < faces->first.size(); ++f) {
    const uint64_t a = faces->first[f], b = faces->first[f + 1];
    const std::string at = ": face " + std::to_string(f) + " (" + d->where("face", f) + ")";
    if (b - a < 3) {
      r.error =
          path + at + ": a face needs at least 3 vertices, this one has " + std::to_string(b - a);
      return r;
    }
    for (uint64_t k = a; k < b; ++k) {
      const double i = faces->values[k];
      if (!(i >= 0.0 && i < double(vertices))) {
        r.error = path + at + ": vertex index " + std::to_string(int64_t(i)) +
                  " is out of range: " + std::to_string(vertices) + " vertices (counted from 0)";
        return r;
      }
    }
    for (uint64_t k = a + 1; k + 1 < b; ++k) {
      triangles.insert(triangles.end(), {uint32_t(faces->values[a]), uint32_t(faces->values[k]),
                                         uint32_t(faces->values[k + 1])});
      where.push_back(at);
    }
  }
  return finishHeadMesh(std::move(positions), triangles, where, path);
}

ObjReadResult readHeadMeshFile(const std::string& path) {
  std::string error;
  const auto bytes = detail::readFileBytes(path, kMaxBytes, &error);
  if (!bytes) return {std::nullopt, error, 0, {}};
  if (isPly(*bytes)) return parsePlyMesh(*bytes, path);
  return parseObjMesh(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                      path);
}

}  // namespace csm::io
