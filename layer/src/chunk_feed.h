// What an analyzer last gave its IncrementalAnalysis under each chunk id (issue 19, item 2). A compute gives it
// only the meshes whose content, runtime labels or triangle mode changed since: the others are neither merged,
// copied nor hashed again by the analysis, and the bounds the voxel stage's choice reads are kept per mesh.
#pragma once
#include "mesh.h"

#include "roomsense/backend.h"
#include "roomsense/incremental.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

namespace roomsense::layer {

// One mesh of a compute: its triangles, the runtime's label of each (null: none) and its key, a hash of both
// (piece_key), which the analyzer also folds into the compute's input hash.
struct FedPiece {
  const MeshPiece* mesh = nullptr;
  const std::vector<SurfaceLabel>* labels = nullptr;
  std::uint64_t key = 0;
};
std::uint64_t piece_key(const MeshPiece& mesh, const std::vector<SurfaceLabel>* labels);

// The chunk of piece `p` as merge() and add_labelled() make it: its vertices, its triangles (in triangle mode a
// point cloud's vertices each a degenerate triangle, as merge() gives them) and its labelled triangles.
Scan chunk_of(const FedPiece& p, bool triangle_mode);

class ChunkFeed {
 public:
  // The voxel stage's workload for the pieces merged (estimate_voxel_workload of merge()), from each piece's kept
  // bounds where it is as it was fed.
  VoxelWorkload workload(std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids, float voxel_size);
  // Piece i becomes chunk ids[i] (ascending) where it changed, and every other chunk is removed.
  void feed(IncrementalAnalysis& incremental, std::span<const FedPiece> pieces, std::span<const std::uint64_t> ids);
  // Counts of the latest feed: the pieces given to the analysis, and those kept as they were.
  std::size_t fed() const { return fed_count_; }
  std::size_t kept() const { return kept_count_; }

 private:
  struct Fed {
    std::uint64_t key = 0;
    bool triangle_mode = false;
    std::size_t triangles = 0;  // in the merged scan (a point cloud's vertices count as triangles in triangle mode)
    glm::vec3 lo{INFINITY}, hi{-INFINITY};  // of the finite vertices
    bool fed = false;                        // given to the analysis as it is (else only measured)
  };
  static bool triangle_mode(std::span<const FedPiece> pieces);
  Fed facts(const FedPiece& p, bool triangle_mode) const;
  // The entry of chunk `id` for piece `p`: as it stands where it has p's key and triangle mode, else p's facts,
  // not fed.
  Fed& known(std::uint64_t id, const FedPiece& p, bool triangle_mode);
  std::map<std::uint64_t, Fed> chunks_;  // by chunk id
  std::size_t fed_count_ = 0, kept_count_ = 0;
};

}  // namespace roomsense::layer
