#include "chunk_feed.h"

#include "roomsense/content_hash.h"

#include <algorithm>
#include <cmath>

namespace roomsense::layer {

std::uint64_t piece_key(const MeshPiece& mesh, const std::vector<SurfaceLabel>* labels) {
  ContentHash h;
  h.add(std::span<const glm::vec3>(mesh.vertices));
  h.add(std::span<const std::uint32_t>(mesh.indices));
  h.add(labels ? std::span<const SurfaceLabel>(*labels) : std::span<const SurfaceLabel>());
  return h.value();
}

Scan chunk_of(const FedPiece& p, bool triangle_mode) {
  Scan chunk;
  chunk.vertices = p.mesh->vertices;
  if (triangle_mode && !p.mesh->indices.empty()) {
    chunk.indices = p.mesh->indices;
  } else if (triangle_mode) {
    chunk.indices.reserve(3 * p.mesh->vertices.size());
    for (std::uint32_t i = 0; i < p.mesh->vertices.size(); ++i) chunk.indices.insert(chunk.indices.end(), 3, i);
  }
  if (p.labels) add_labelled(chunk.labels, *p.mesh, *p.labels);
  return chunk;
}

bool ChunkFeed::triangle_mode(std::span<const FedPiece> pieces) {
  return std::any_of(pieces.begin(), pieces.end(), [](const FedPiece& p) { return !p.mesh->indices.empty(); });
}

ChunkFeed::Fed ChunkFeed::facts(const FedPiece& p, bool triangle_mode) const {
  Fed f;
  f.key = p.key;
  f.triangle_mode = triangle_mode;
  f.triangles = !triangle_mode ? 0 : p.mesh->indices.empty() ? p.mesh->vertices.size() : p.mesh->indices.size() / 3;
  for (const glm::vec3& v : p.mesh->vertices)
    if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) f.lo = glm::min(f.lo, v), f.hi = glm::max(f.hi, v);
  return f;
}

ChunkFeed::Fed& ChunkFeed::known(std::uint64_t id, const FedPiece& p, bool triangle_mode) {
  Fed& f = chunks_[id];
  if (f.key != p.key || f.triangle_mode != triangle_mode) f = facts(p, triangle_mode);  // not fed as it is
  return f;
}

VoxelWorkload ChunkFeed::workload(std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids, float voxel_size) {
  const bool mode = triangle_mode(pieces);
  std::size_t triangles = 0;
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Fed& f = known(ids[i], pieces[i], mode);
    triangles += f.triangles;
    lo = glm::min(lo, f.lo), hi = glm::max(hi, f.hi);
  }
  return voxel_workload(lo, hi, triangles, voxel_size);
}

void ChunkFeed::feed(IncrementalAnalysis& incremental, std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids) {
  const bool mode = triangle_mode(pieces);
  fed_count_ = kept_count_ = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Fed& f = known(ids[i], pieces[i], mode);
    if (f.fed) {
      ++kept_count_;
      continue;
    }
    incremental.set_chunk(ids[i], chunk_of(pieces[i], mode));
    f.fed = true;  // only once the analysis holds it
    ++fed_count_;
  }
  // The chunks of meshes no longer served (or of a call that failed half way).
  for (const std::uint64_t id : incremental.chunk_ids())
    if (!std::binary_search(ids.begin(), ids.end(), id)) incremental.remove_chunk(id);
  std::erase_if(chunks_, [&](const auto& entry) { return !std::binary_search(ids.begin(), ids.end(), entry.first); });
}

}  // namespace roomsense::layer
