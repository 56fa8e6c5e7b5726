// Compares what the runtime served (chunks in component space + located poses) with the room file.
#pragma once
#include "xr_harness.h"

#include "roomsense/scan.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace simtest {

struct MeshComparison {
  std::size_t served_vertices = 0;     // summed over chunks (seams repeat vertices)
  std::size_t matched_file_vertices = 0;  // distinct file vertices the served ones land on
  std::size_t served_triangles = 0;
  bool same_triangles = false;         // the served triangles, mapped to file vertices, are the file's
  double max_error = 0.0;              // metres, served vertex (posed) to nearest file vertex
  double max_error_without_pose = 0.0; // what a consumer that ignores the pose would be off by
};

inline glm::dvec3 posed(const XrPosef& pose, const XrVector3f& v) {
  const glm::dquat q(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  return q * glm::dvec3(v.x, v.y, v.z) + glm::dvec3(pose.position.x, pose.position.y, pose.position.z);
}

// The file's mesh with vertices of equal position joined, in first-seen order (what assimp's loader gave
// before scanio read OBJ and PLY itself): a runtime serves each position once per chunk, so the comparison
// below maps served vertices to distinct file positions.
inline roomsense::Scan join_identical_vertices(const roomsense::Scan& file) {
  roomsense::Scan joined;
  std::map<std::array<float, 3>, uint32_t> ids;
  std::vector<uint32_t> to_joined(file.vertices.size());
  for (std::size_t v = 0; v < file.vertices.size(); ++v) {
    const glm::vec3& p = file.vertices[v];
    const auto [it, fresh] = ids.emplace(std::array<float, 3>{p.x, p.y, p.z}, uint32_t(joined.vertices.size()));
    if (fresh) joined.vertices.push_back(p);
    to_joined[v] = it->second;
  }
  joined.indices.reserve(file.indices.size());
  for (const uint32_t i : file.indices) joined.indices.push_back(to_joined[i]);
  return joined;
}

inline MeshComparison compare_with_file(const roomsense::Scan& file, const std::vector<ComponentMesh>& served) {
  // Hash grid over the file's vertices, 1 cm cells.
  constexpr double cell = 0.01;
  auto key = [&](const glm::dvec3& p) {
    return std::array<long, 3>{long(std::floor(p.x / cell)), long(std::floor(p.y / cell)), long(std::floor(p.z / cell))};
  };
  std::map<std::array<long, 3>, std::vector<uint32_t>> grid;
  for (uint32_t i = 0; i < file.vertices.size(); ++i) grid[key(glm::dvec3(file.vertices[i]))].push_back(i);
  auto nearest = [&](const glm::dvec3& p, double& distance) {
    const auto k = key(p);
    uint32_t best = UINT32_MAX;
    distance = 1e300;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (uint32_t i : it->second) {
            const double d = glm::length(glm::dvec3(file.vertices[i]) - p);
            if (d < distance) distance = d, best = i;
          }
        }
    return best;
  };

  MeshComparison result;
  std::set<uint32_t> matched;
  std::multiset<std::array<uint32_t, 3>> served_triangles;
  for (const ComponentMesh& m : served) {
    std::vector<uint32_t> to_file(m.vertices.size(), UINT32_MAX);
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      double d = 0;
      to_file[v] = nearest(posed(m.pose, m.vertices[v]), d);
      result.max_error = std::max(result.max_error, to_file[v] == UINT32_MAX ? 1e300 : d);
      if (to_file[v] != UINT32_MAX) {
        matched.insert(to_file[v]);
        const glm::dvec3 raw(m.vertices[v].x, m.vertices[v].y, m.vertices[v].z);
        result.max_error_without_pose = std::max(result.max_error_without_pose, glm::length(raw - glm::dvec3(file.vertices[to_file[v]])));
      }
    }
    result.served_vertices += m.vertices.size();
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      std::array<uint32_t, 3> tri{to_file[m.indices[t]], to_file[m.indices[t + 1]], to_file[m.indices[t + 2]]};
      std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());  // keeps the winding
      served_triangles.insert(tri);
      ++result.served_triangles;
    }
  }
  result.matched_file_vertices = matched.size();
  std::multiset<std::array<uint32_t, 3>> file_triangles;
  for (std::size_t t = 0; t + 2 < file.indices.size(); t += 3) {
    std::array<uint32_t, 3> tri{file.indices[t], file.indices[t + 1], file.indices[t + 2]};
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    file_triangles.insert(tri);
  }
  result.same_triangles = served_triangles == file_triangles;
  return result;
}

}  // namespace simtest
