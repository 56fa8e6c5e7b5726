// What an IncrementalAnalysis keeps between its analyses besides each chunk's voxels: each storey's area
// searches by bands of rows (areas/search_cache.h).
#pragma once
#include "roomsense/analysis.h"
#include "../areas/search_cache.h"
#include "../bounds/mesh_memo.h"
#include "../input/input_view.h"
#include "surface_heights.h"

#include <map>

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

// The surface heights' sums (surface_heights.h) of a combined scan's bands, chunk by chunk: a band's sum is the
// sum of its chunks' (ExactSum), and a chunk's is kept while the chunk and the band are as before, so an
// analysis passes over the triangles of the chunks that changed, not all of them.
class ChunkBandSums {
 public:
  using Limits = std::pair<float, float>;  // band_limits
  struct Band {
    Limits limits;
    std::vector<BandSum> chunks;  // per placed chunk
  };
  // The band's sums in each chunk of `c` (its triangles as they are: the input checks removed nothing), the
  // kept ones where they are known. May run side by side with other calls of band().
  Band band(const CombinedScan& c, Limits limits) const;
  // Keeps `bands` (of c's chunks) for the next analysis, and no others.
  void keep(const CombinedScan& c, const std::vector<Band>& bands);

 private:
  struct Kept {
    std::uint64_t hash = 0;
    std::vector<std::pair<Limits, BandSum>> bands;
  };
  std::map<std::uint64_t, Kept> chunks_;  // by chunk id
};

// For one AnalysisOptions: an IncrementalAnalysis's own.
struct AnalysisCaches {
  std::vector<std::unique_ptr<SearchCache>> storeys;  // storey i of the latest analysis
  std::optional<DerivedFromVoxels> derived;           // the latest analysis's
  CombinedScan combined;
  ChunkBandSums band_sums;  // of `combined`
  std::vector<MeshMemo> bounds;  // the home's bounds mesh, then each room's (AnalysisResult::room_bounds)
};

// analyze() (analysis.h), served by `caches` where not null: its area searches, features and bounds always;
// its input checks and surface heights where `scan` is caches->combined.scan.
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches);

}  // namespace roomsense::detail
