#include "mesh.h"

#include "roomsense/content_hash.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace roomsense::layer {

std::vector<glm::vec3> transformed(const XrVector3f* vertices, std::size_t count, const Rigid& pose) {
  std::vector<glm::vec3> out(count);
  const bool identity = pose.identity();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 v(vertices[i].x, vertices[i].y, vertices[i].z);
    out[i] = identity ? v : glm::vec3(pose.apply(glm::dvec3(v)));
  }
  return out;
}

void transform_in_place(std::vector<glm::vec3>& vertices, const Rigid& pose) {
  if (pose.identity()) return;
  for (glm::vec3& v : vertices) v = glm::vec3(pose.apply(glm::dvec3(v)));
}

std::uint64_t content_hash(const XrVector3f* vertices, std::size_t vertex_count, const std::uint32_t* indices,
                           std::size_t index_count) {
  ContentHash h;
  h.add_bytes(vertices, vertex_count * sizeof(XrVector3f));
  h.add_bytes(indices, index_count * sizeof(std::uint32_t));
  return h.value();
}

std::uint64_t content_hash(const MeshPiece& mesh) {
  static_assert(sizeof(glm::vec3) == sizeof(XrVector3f));
  return content_hash(reinterpret_cast<const XrVector3f*>(mesh.vertices.data()), mesh.vertices.size(), mesh.indices.data(),
                      mesh.indices.size());
}

Scan merge(const std::vector<const MeshPiece*>& pieces) {
  Scan scan;
  bool any_triangles = false;
  std::size_t vertices = 0, indices = 0;
  for (const MeshPiece* p : pieces) {
    any_triangles = any_triangles || !p->indices.empty();
    vertices += p->vertices.size();
    indices += p->indices.empty() ? 3 * p->vertices.size() : p->indices.size();
  }
  if (vertices > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("more vertices than 32-bit indices can address");
  scan.vertices.reserve(vertices);
  if (any_triangles) scan.indices.reserve(indices);
  for (const MeshPiece* p : pieces) {
    const auto base = static_cast<std::uint32_t>(scan.vertices.size());
    scan.vertices.insert(scan.vertices.end(), p->vertices.begin(), p->vertices.end());
    if (!any_triangles) continue;
    if (p->indices.empty()) {
      for (std::uint32_t i = 0; i < p->vertices.size(); ++i) scan.indices.insert(scan.indices.end(), 3, base + i);
    } else {
      for (std::uint32_t i : p->indices) scan.indices.push_back(base + i);
    }
  }
  return scan;
}

void add_labelled(LabelledTriangles& out, const MeshPiece& piece, const std::vector<SurfaceLabel>& labels) {
  if (labels.empty() || piece.indices.size() != 3 * labels.size()) return;
  if (out.vertices.size() + piece.vertices.size() > std::numeric_limits<std::uint32_t>::max()) return;
  out.add(piece.vertices, piece.indices, labels);
}

}  // namespace roomsense::layer
