// Geometric checks of a bounds mesh against the volume it was made from, beyond closure: the triangles
// cover each voxel face exactly once (no fold, no overlap, no gap), and no vertex sits inside a flat patch.
#pragma once
#include "roomsense/bounds.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace roomsense::test {

// Signed volume by the divergence theorem: positive when the faces point out of the solid.
inline double signed_volume(const BoundsMesh& m) {
  double v = 0.0;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::dvec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// The area of the faces between a solid voxel and an empty one (or the grid's outside), in m².
inline double voxel_face_area(const GridSpec& s, const std::vector<std::uint8_t>& volume) {
  std::size_t faces = 0;
  const auto solid = [&](int x, int y, int z) { return s.contains(x, y, z) && volume[s.index(x, y, z)] != 0; };
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      for (int y = 0; y < s.ny; ++y) {
        if (!solid(x, y, z)) continue;
        faces += !solid(x - 1, y, z) + !solid(x + 1, y, z) + !solid(x, y - 1, z) + !solid(x, y + 1, z) +
                 !solid(x, y, z - 1) + !solid(x, y, z + 1);
      }
  return double(faces) * double(s.voxel_size) * double(s.voxel_size);
}

struct TriangleStats {
  double area = 0.0;                 // sum of |triangle area|, m²
  std::size_t degenerate = 0;        // triangles of (near) zero area
  std::size_t flat_vertices = 0;     // vertices all of whose triangles face one way: removable
};

inline TriangleStats triangle_stats(const BoundsMesh& m, double voxel_size) {
  TriangleStats st;
  std::map<std::uint32_t, std::set<std::tuple<int, int, int>>> normals;
  const double tiny = 1e-3 * voxel_size * voxel_size;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::dvec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(n);
    st.area += area;
    if (area < tiny) ++st.degenerate;
    const glm::dvec3 u = n / std::max(glm::length(n), 1e-30);
    const std::tuple<int, int, int> key{int(std::lround(u.x)), int(std::lround(u.y)), int(std::lround(u.z))};
    for (int k = 0; k < 3; ++k) normals[m.indices[t + std::size_t(k)]].insert(key);
  }
  for (const auto& [vertex, dirs] : normals) st.flat_vertices += dirs.size() == 1 ? 1 : 0;
  return st;
}

}  // namespace roomsense::test
