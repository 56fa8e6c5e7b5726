// Splits a room mesh into spatial chunks; see scene_data.h. The per-chunk pose is deliberate: a consumer that
// forgets XrSceneComponentLocationMSFT gets a visibly wrong room, as it would on a real device.
#include "scene_data.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace roomsense::sim {
namespace {

struct Bucket {
  std::vector<std::uint32_t> triangles;  // first index of each triangle
  std::vector<std::uint32_t> lone_vertices;
};

}  // namespace

ChunkCell point_cell(const glm::dvec3& p, double size) {
  return {static_cast<long>(std::floor(p.x / size)), static_cast<long>(std::floor(p.y / size)),
          static_cast<long>(std::floor(p.z / size))};
}

ChunkCell triangle_cell(const Scan& mesh, std::size_t first, double chunk_size) {
  glm::dvec3 centroid(0.0);
  for (int k = 0; k < 3; ++k) centroid += glm::dvec3(mesh.vertices[mesh.indices[first + std::size_t(k)]]);
  return point_cell(centroid / 3.0, chunk_size);
}

std::uint64_t cell_key(const ChunkCell& cell) {
  const auto bits = [](long v) { return static_cast<std::uint64_t>(v) & ((std::uint64_t{1} << 21) - 1); };
  return bits(cell.x) | bits(cell.y) << 21 | bits(cell.z) << 42;
}

std::vector<Chunk> split_into_chunks(const Scan& mesh, double chunk_size) {
  std::map<ChunkCell, Bucket> buckets;  // ordered, so the split is deterministic
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) used[mesh.indices[t + std::size_t(k)]] = true;
    buckets[triangle_cell(mesh, t, chunk_size)].triangles.push_back(static_cast<std::uint32_t>(t));
  }
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v)
    if (!used[v]) buckets[point_cell(glm::dvec3(mesh.vertices[v]), chunk_size)].lone_vertices.push_back(v);

  constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> local(mesh.vertices.size(), unset);
  std::vector<Chunk> chunks;
  chunks.reserve(buckets.size());
  for (const auto& [cell, bucket] : buckets) {
    std::vector<std::uint32_t> globals;  // chunk vertex -> mesh vertex
    std::vector<std::uint32_t> indices;
    auto add = [&](std::uint32_t g) {
      if (local[g] == unset) {
        local[g] = static_cast<std::uint32_t>(globals.size());
        globals.push_back(g);
      }
      return local[g];
    };
    for (std::uint32_t t : bucket.triangles)
      for (int k = 0; k < 3; ++k) indices.push_back(add(mesh.indices[t + k]));
    for (std::uint32_t v : bucket.lone_vertices) add(v);

    Chunk chunk;
    chunk.cell = cell;
    chunk.world_min = glm::dvec3(std::numeric_limits<double>::max());
    chunk.world_max = glm::dvec3(std::numeric_limits<double>::lowest());
    for (std::uint32_t g : globals) {
      chunk.world_min = glm::min(chunk.world_min, glm::dvec3(mesh.vertices[g]));
      chunk.world_max = glm::max(chunk.world_max, glm::dvec3(mesh.vertices[g]));
    }
    // The yaw comes from the cell, not the chunk's place in the list: a chunk keeps its pose while others appear.
    const double yaw = glm::radians(37.0 * static_cast<double>(cell_key(cell) % 9 + 1));
    chunk.pose.rotation = glm::angleAxis(yaw, glm::dvec3(0, 1, 0));
    chunk.pose.translation = (chunk.world_min + chunk.world_max) * 0.5;
    const Rigid to_local = chunk.pose.inverse();
    chunk.mesh.vertices.reserve(globals.size());
    for (std::uint32_t g : globals) {
      const glm::dvec3 p = to_local.apply(glm::dvec3(mesh.vertices[g]));
      chunk.mesh.vertices.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
      local[g] = unset;  // reset for the next chunk
    }
    chunk.mesh.indices = std::move(indices);
    chunks.push_back(std::move(chunk));
  }
  return chunks;
}

}  // namespace roomsense::sim
