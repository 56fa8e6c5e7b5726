// What an IncrementalAnalysis keeps between its analyses besides each chunk's voxels: each storey's area
// searches by bands of rows (areas/search_cache.h).
#pragma once
#include "roomsense/analysis.h"
#include "../areas/search_cache.h"
#include "../input/input_view.h"

#include <memory>
#include <optional>
#include <vector>

namespace roomsense::detail {

// What the features and bounds of an analysis were derived from (the grid, the labels' voxels and the storeys'
// levels), and they: an analysis of the same grid, labels and levels has the same (a scan refined within its
// voxels).
struct DerivedFromVoxels {
  GridSpec spec{};
  std::vector<std::uint8_t> cells;
  LabelGrid labels;
  std::vector<FloorCeiling> levels;  // per storey
  std::optional<RoomFeatures> features;
  std::vector<RoomFeatures> other_features;
  bool has_bounds = false;
  BoundsMesh bounds;
  std::vector<BoundsMesh> room_bounds;
};

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
};

// For one AnalysisOptions: an IncrementalAnalysis's own.
struct AnalysisCaches {
  std::vector<std::unique_ptr<SearchCache>> storeys;  // storey i of the latest analysis
  std::optional<DerivedFromVoxels> derived;           // the latest analysis's
  CombinedScan combined;
};

// analyze() (analysis.h), its area searches served by `caches`; `known`, where not null, is what the caller
// knows of `scan` (view_input).
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches,
                       const KnownInput* known = nullptr);

}  // namespace roomsense::detail
