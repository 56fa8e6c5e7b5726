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

VoxelWorkload ChunkFeed::workload(std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids, float voxel_size) {
  const bool mode = triangle_mode(pieces);
  VoxelWorkload w;
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Fed& known = chunks_[ids[i]];
    if (known.key != pieces[i].key || known.triangle_mode != mode) known = facts(pieces[i], mode);
    w.triangles += known.triangles;
    lo = glm::min(lo, known.lo), hi = glm::max(hi, known.hi);
  }
  // As estimate_voxel_workload does over the merged scan.
  if (!(lo.x <= hi.x) || !(voxel_size > 0.0f)) return w;
  const glm::dvec3 n = glm::dvec3(hi - lo) / double(voxel_size) + 1.0;
  w.voxels = std::size_t(std::min(n.x * n.y * n.z, 1e18));
  return w;
}

void ChunkFeed::feed(IncrementalAnalysis& incremental, std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids) {
  const bool mode = triangle_mode(pieces);
  fed_count_ = kept_count_ = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto at = chunks_.find(ids[i]);
    if (at != chunks_.end() && at->second.fed && at->second.key == pieces[i].key && at->second.triangle_mode == mode) {
      ++kept_count_;
      continue;
    }
    Fed known = at != chunks_.end() && at->second.key == pieces[i].key && at->second.triangle_mode == mode
                    ? at->second
                    : facts(pieces[i], mode);
    known.fed = false;  // until the analysis holds it
    chunks_[ids[i]] = known;
    incremental.set_chunk(ids[i], chunk_of(pieces[i], mode));
    chunks_[ids[i]].fed = true;
    ++fed_count_;
  }
  // The chunks of meshes no longer served (or of a call that failed half way).
  for (const std::uint64_t id : incremental.chunk_ids())
    if (!std::binary_search(ids.begin(), ids.end(), id)) incremental.remove_chunk(id);
  std::erase_if(chunks_, [&](const auto& entry) { return !std::binary_search(ids.begin(), ids.end(), entry.first); });
}

}  // namespace roomsense::layer
