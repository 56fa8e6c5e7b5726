// What an IncrementalAnalysis keeps between its analyses besides each chunk's voxels: each storey's area
// searches by bands of rows (areas/search_cache.h).
#pragma once
#include "roomsense/analysis.h"
#include "../areas/search_cache.h"

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

// For one AnalysisOptions: an IncrementalAnalysis's own.
struct AnalysisCaches {
  std::vector<std::unique_ptr<SearchCache>> storeys;  // storey i of the latest analysis
  std::optional<DerivedFromVoxels> derived;           // the latest analysis's
};

// analyze() (analysis.h), its area searches served by `caches`.
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches);

}  // namespace roomsense::detail
