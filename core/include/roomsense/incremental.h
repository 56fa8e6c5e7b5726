// Beyond the thesis (issue 19): a room that arrives in chunks, as headsets deliver it while the user looks
// around, and re-sends chunks as they refine them.
//
// An IncrementalAnalysis holds chunks by id (added, replaced, removed) and answers result(): the analysis of
// all its chunks, in id order, as one scan. That result equals analyze(combined_scan(), options) exactly,
// timings aside. What it reuses between results, each only where what it reads is as before:
// - each chunk's voxels (its triangles' marks on the grid, kept per chunk while the grid and the chunk are
//   unchanged): a change voxelizes only the chunks it touched; and the level counts, column counts and
//   horizontal-surface counts, counted again only in the columns of the chunks voxelized again or dropped;
// - each chunk's input checks (its finite vertices' bounds, against the outlier ranges) and its surface heights'
//   sums (exact in any grouping), so unchanged chunks cost those passes nothing; the input checks, voxels, sums
//   and labels read each chunk's own arrays, and the chunks are copied end to end into one scan only for what reads
//   it whole (input to renumber, a ridge's height or one past the exact sums, a sloped ceiling's planes), then
//   again only from the first chunk (in id order) not in its place;
// - the features and bounds, where the grid, the labels' voxels and the storeys' levels are the previous
//   result's (a chunk refined within its voxels);
// - otherwise, each storey's feature steps that read the whole storey (the walls' heights, the walls' closure,
//   the ceiling's facets, the rooms) where the column arrays they read are as before, and the steps that read a
//   column alone (furniture tops, free floor and ceiling tiles) or the columns a reach along the axes (wall
//   normals, openings) away from the columns whose voxels or entries changed (features/feature_memo.h);
// - each area search's rectangles by bands of 8 grid rows: a band is searched again only within the search's
//   reach of a row whose features changed, and a square search's band only within reach of the columns that
//   changed (areas/search_cache.h);
// - an area type's whole reduction (deduplication, packing) where nothing its searches read changed, and its
//   growth where its packed areas are also as before; otherwise each area's growth where nothing it read
//   changed, floor and ceiling areas matched across a refined height (areas/grow.h);
// - packing's decisions away from the rectangles that changed (areas/reduce.h: PackReplay), and each rotated
//   square shape's samples (SquareSampleRuns);
// - what each area sees for its reach where the wall areas are as before (whatever the floor's height): kept
//   while the floor area that decided it is there, and tested only against the floor areas added
//   (areas/classify.h: ReachMemo);
// - each bounds mesh's slices (the home's, each room's): only the slices through voxel layers whose bounds
//   volume changed are meshed again (bounds/mesh_memo.h).
// The levels' choice, the ceilings and walls, areas and bounds volumes are derived again.
// An unchanged set of chunks returns the previous result at once.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/scan.h"

#include <cstdint>
#include <map>
#include <memory>
#include <stop_token>

namespace roomsense {
namespace detail {
struct AnalysisCaches;
}

class IncrementalAnalysis {
 public:
  // options.voxel_stage is not used: the chunks' voxels come from the CPU stage (the reference).
  explicit IncrementalAnalysis(AnalysisOptions options = {});
  ~IncrementalAnalysis();
  IncrementalAnalysis(IncrementalAnalysis&&) noexcept;
  IncrementalAnalysis& operator=(IncrementalAnalysis&&) noexcept;

  // Adds the chunk, or replaces the chunk of that id. Indices are checked when the result is computed, as
  // analyze() checks them.
  void set_chunk(std::uint64_t id, Scan chunk);
  // Returns false when there is no chunk of that id.
  bool remove_chunk(std::uint64_t id);
  std::size_t chunk_count() const { return chunks_.size(); }
  // The chunks' ids, ascending.
  std::vector<std::uint64_t> chunk_ids() const;
  // The stop token of the next result() (AnalysisOptions::stop): a stop request cancels it, and changes nothing
  // but the result, which the next call computes again.
  void set_stop(std::stop_token stop) { options_.stop = std::move(stop); }

  // The analysis of every chunk. Throws as analyze() does (Error for bad input, Cancelled on a stop request);
  // an empty set of chunks is EmptyInput. The reference stays valid until the next call that changes chunks.
  const AnalysisResult& result();

  // The chunks in id order as one scan: what result() analyses.
  Scan combined_scan() const;

  // How many chunks the latest result() voxelized (the others' voxels were kept), and whether it reused the
  // previous result whole (no chunk changed).
  std::size_t revoxelized_chunks() const;
  bool reused_result() const { return reused_; }
  // Of the latest result() that ran: how many bands of rows its area searches searched (the others' rectangles
  // were kept from the result before), and how many there were.
  std::size_t area_bands_searched() const;
  std::size_t area_bands_total() const;

 private:
  struct Chunk {
    Scan scan;
    std::uint64_t hash = 0;  // of its vertices, indices and labels
  };
  class ChunkVoxelStage;
  // Brings the kept combined scan (detail::CombinedScan) up to the chunks.
  void update_combined();

  AnalysisOptions options_;
  std::map<std::uint64_t, Chunk> chunks_;
  std::unique_ptr<ChunkVoxelStage> stage_;
  std::unique_ptr<detail::AnalysisCaches> caches_;
  std::optional<AnalysisResult> result_;
  bool dirty_ = true, reused_ = false;
};

// The scan cut into square tiles of the floor plan (`tile` metres, by each triangle's centroid), as a
// headset's mesh blocks: each tile's triangles with their own vertices (a point cloud's vertices by position),
// and its labelled triangles likewise; the key orders tiles by x, then z. For replaying a recorded room chunk
// by chunk (tests, benchmarks).
std::map<std::uint64_t, Scan> split_into_blocks(const Scan& scan, float tile = 2.0f);

}  // namespace roomsense
