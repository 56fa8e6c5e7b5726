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

#include <map>
#include <string>
#include <utility>
#include <memory>
#include <vector>

namespace roomsense::detail {

// An IncrementalAnalysis's chunks in id order as one scan, kept between analyses: a change copies the chunks
// from the first one that changed on, not all of them, and summarizes each chunk's vertices once.
struct CombinedScan {
  struct Placed {
    std::uint64_t id = 0, hash = 0;
    // Where the chunk's arrays begin in `scan`'s.
    std::size_t vertex = 0, index = 0, label_vertex = 0, label_index = 0, label = 0;
  };
  Scan scan;
  std::vector<Placed> placed;  // each chunk in `scan`, in order
  KnownInput known;            // a run per placed chunk; every index in range
  // Where chunk k's vertices and indices end in `scan`'s.
  std::size_t vertex_end(std::size_t k) const { return k + 1 < placed.size() ? placed[k + 1].vertex : scan.vertices.size(); }
  std::size_t index_end(std::size_t k) const { return k + 1 < placed.size() ? placed[k + 1].index : scan.indices.size(); }
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
  // voxelize_labels(spec, c.scan.labels, test_budget, warnings), equal in result and warnings. Keeps each chunk's
  // voxels for the next analysis, and no others; where they would hold more entries than the grid has voxels (the
  // chunks' labelled triangles overlap a lot), keeps none and voxelizes the labels whole, as a full analysis does.
  LabelGrid grid(const CombinedScan& c, const GridSpec& spec, std::uint64_t test_budget, std::vector<std::string>& warnings);

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
// its input checks and surface heights where `scan` is caches->combined.scan.
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches);

}  // namespace roomsense::detail
