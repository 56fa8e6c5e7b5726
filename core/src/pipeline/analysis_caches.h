// What an IncrementalAnalysis keeps between its analyses besides each chunk's voxels: its combined scan with each
// chunk's input summary and surface sums, each storey's feature steps (features/feature_memo.h) and area searches
// by bands of rows (areas/search_cache.h), the labels' voxels of the latest result (whose features and bounds it
// reads, not copies), each bounds mesh's slices (bounds/mesh_memo.h) and the analyses' threads.
#pragma once
#include "roomsense/analysis.h"
#include "../areas/search_cache.h"
#include "../bounds/mesh_memo.h"
#include "../features/feature_memo.h"
#include "../semantics/label_voxels.h"
#include "../input/input_view.h"
#include "../worker_pool.h"
#include "surface_heights.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <memory>
#include <vector>

namespace roomsense::detail {

// An IncrementalAnalysis's chunks in id order as one scan, kept between analyses. An analysis reads each chunk's
// own arrays where it can (the input checks, the voxels, the surface heights' sums, the labels' voxels): the
// chunks' arrays placed end to end (whole()) are made only for a step that reads the scan whole (input checks that
// renumber, a ridge's or an inexact surface height, a sloped ceiling's planes, labels not their chunk's own), and
// then copied again only from the first chunk not in its place since they were last made. So a change costs the
// chunks it changed, not a copy of the room, and the chunks are not held twice.
struct CombinedScan {
  struct Placed {
    std::uint64_t id = 0, hash = 0;
    // Where the chunk's arrays begin in the whole scan's.
    std::size_t vertex = 0, index = 0, label_vertex = 0, label_index = 0, label = 0;
  };
  std::vector<Placed> placed;        // each chunk, in order
  Placed end;                        // where the last chunk's arrays end: the whole scan's sizes
  std::vector<const Scan*> chunks;   // each placed chunk's own arrays (its IncrementalAnalysis's)
  KnownInput known;                  // a run per placed chunk; every index in range
  // Per placed chunk, whether its labelled triangles index its own label vertices alone: where all do, a chunk's
  // labels read alone are what they are in the whole scan.
  std::vector<std::uint8_t> own_labels;
  bool labels_own() const { return std::find(own_labels.begin(), own_labels.end(), 0) == own_labels.end(); }
  // The chunks' arrays end to end, brought up to `placed` (the first `in_place` chunks are there already), copied
  // on up to `threads` workers.
  const Scan& whole(unsigned threads);
  // whole(), moved out.
  Scan take_whole(unsigned threads);
  // What analyze() is given for these chunks: an address, whose arrays only whole() brings up to date.
  const Scan& handle() const { return scan; }
  // After a change: the chunks before `first` are where the whole scan had them.
  void moved_from(std::size_t first) { in_place = std::min(in_place, first); }
  void clear() { *this = {}; }

 private:
  Scan scan;
  std::size_t in_place = 0;
};

// The surface heights' sums (surface_heights.h) of a combined scan's bands, chunk by chunk: a band's sum is the
// sum of its chunks' (ExactSum), and a chunk's are kept while the chunk and the bands are as before, so an
// analysis passes over the triangles of the chunks that changed, not all of them.
class ChunkBandSums {
 public:
  // Each band's sums over c's chunks (their triangles as they are: the input checks removed nothing): the kept
  // ones where they are known, the others one pass over the chunk each, `threads` chunks at a time. Keeps these
  // for the next analysis, and no others.
  std::vector<BandSum> sums(const CombinedScan& c, std::span<const BandLimits> bands, unsigned threads);

 private:
  struct Kept {
    std::uint64_t hash = 0;
    std::vector<BandLimits> bands;
    std::vector<BandSum> sums;  // per band
  };
  std::map<std::uint64_t, Kept> chunks_;  // by chunk id
};

// The labels' voxels (voxelize_labels) of a combined scan, chunk by chunk: a chunk's labelled voxels are kept
// while the chunk and the grid are as before, and the grid is the union of every chunk's, so an analysis tests the
// labelled triangles of the chunks that changed against the voxels, not all of them (a headset that labels every
// triangle, as Android XR does, labels the whole room).
class ChunkLabelVoxels {
 public:
  // voxelize_labels(spec, c.whole().labels, test_budget, warnings), equal in result and warnings. Keeps each
  // chunk's voxels for the next analysis, and no others; where they would hold more entries than the grid has
  // voxels (the chunks' labelled triangles overlap a lot), keeps none and voxelizes the labels whole, as a full
  // analysis does. `threads`: for c.whole(), where it is needed.
  LabelGrid grid(CombinedScan& c, const GridSpec& spec, std::uint64_t test_budget, std::vector<std::string>& warnings,
                 unsigned threads);

 private:
  struct Kept {
    std::uint64_t hash = 0;
    GridSpec spec;
    std::uint64_t tests = 0;
    std::size_t dropped = 0;
    LabelMask present = 0;  // the labels of its boxes
    bool any_box = false;
    TouchedVoxels voxels;
  };
  std::map<std::uint64_t, Kept> chunks_;  // by chunk id
  std::vector<LabelMask> scratch_;        // touched_voxels's, all zero between calls
};

// For one AnalysisOptions: an IncrementalAnalysis's own.
struct AnalysisCaches {
  std::vector<std::unique_ptr<SearchCache>> storeys;  // storey i of the latest analysis
  std::vector<FeatureMemo> features;                  // storey i's feature steps, the main one first
  // The latest complete analysis's result (IncrementalAnalysis::result() keeps it alive through the next
  // analysis; null where there is none) and the labels' voxels of its scan: an analysis of the same grid,
  // labels and storey levels has its features and bounds (a scan refined within its voxels), copied from it.
  const AnalysisResult* previous = nullptr;
  std::uint64_t serial = 0;  // the analyses begun: the latest's number
  LabelGrid previous_labels;
  // The horizontal counts (storeys.h) of analysis number horizontal_serial's grid.
  std::vector<std::uint32_t> horizontal;
  std::uint64_t horizontal_serial = 0;
  // The column counts (count_columns) on each storey's levels that analysis number counts_serial counted itself
  // (those the voxel stage did not): a home's storeys are counted again only in the columns that changed.
  struct StoreyCounts {
    FloorCeiling levels{};
    std::vector<std::uint32_t> counts;
    std::vector<std::uint8_t> any;
  };
  std::vector<StoreyCounts> storey_counts;
  std::uint64_t counts_serial = 0;
  CombinedScan combined;
  ChunkBandSums band_sums;  // of `combined`
  ChunkLabelVoxels label_voxels;  // of `combined`
  QuantileGuess quantiles;  // where the latest analysis's input checks found the outlier quantiles
  std::vector<MeshMemo> bounds;  // the home's bounds mesh, then each room's (AnalysisResult::room_bounds)
  // The IncrementalAnalysis's voxel stage. analyze() gives it `combined` as it is in triangle mode with
  // VoxelizeRequest::grid_vertices left empty, and nothing else so: it maps the chunks it voxelizes again itself.
  const VoxelStage* chunk_stage = nullptr;
  std::unique_ptr<WorkerPool> workers;  // the analyses' threads, kept between them
};

// analyze() (analysis.h), served by `caches` where not null: its area searches, features and bounds always;
// its input checks, voxels, surface heights and labels chunk by chunk where `scan` is caches->combined.handle().
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches);

}  // namespace roomsense::detail
