// Beyond the thesis (issue 19): what detect_features derived for one storey in an IncrementalAnalysis's previous
// analysis. The steps that read the whole storey at once (the walls' heights, the walls' closure, the ceiling's
// facets, the split into rooms) are functions of a few column arrays and parameters alone; a change that leaves
// those as they were (furniture added, a wall refined within its columns) finds each such step's result kept
// instead of deriving it again. A kept result is returned only for inputs equal to those it was derived from,
// so it is the step's own.
#pragma once
#include "roomsense/features.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

namespace roomsense::detail {

// One step's latest result and the inputs it was derived from.
template <class Result, class... Inputs>
class StepMemo {
 public:
  // The kept result where `inputs` equal the kept ones; else derive()'s, kept with a copy of `inputs`.
  template <class Derive>
  const Result& get(const Derive& derive, const Inputs&... inputs) {
    if (!inputs_ || *inputs_ != std::tie(inputs...)) {
      inputs_.reset();  // should derive() throw, nothing stays kept
      result_ = derive();
      inputs_.emplace(inputs...);
      ++derived_;
    }
    return result_;
  }
  std::size_t derived() const { return derived_; }  // how often get() derived the result

 private:
  std::optional<std::tuple<Inputs...>> inputs_;
  Result result_{};
  std::size_t derived_ = 0;
};

// The ceiling's facets (find_ceiling_facets): each column's facet and the facets.
struct CeilingFacets {
  std::vector<int> facet_of;
  std::vector<CeilingFacet> facets;
};

// The column steps (column_steps.h) of the latest analysis: their results, and the per-column entries and the
// levels they read besides the grid.
struct ColumnSteps {
  struct Scalars {
    GridSpec spec;
    FloorCeiling levels;
    int y_end = 0, furniture_clear = 0, ceiling_clear = 0, rough = 0;
    bool operator==(const Scalars&) const = default;
  };
  std::uint64_t grid = 0;  // the analysis whose grid they read (GridChange); 0: none, derive every column
  std::size_t derived = 0;  // the columns the latest run derived
  Scalars scalars;
  std::vector<std::uint8_t> walls, inside;
  std::vector<int> ceiling;
  std::vector<int> furniture;                      // C, before it is cut to the inside and to the labels
  std::vector<std::uint8_t> free_floor, free_ceiling;  // D and E, before the labels and the facets
};

// One storey's steps, each with the inputs detect_features gives it.
struct FeatureMemo {
  using Columns = std::vector<std::uint8_t>;
  using Levels = std::vector<int>;
  StepMemo<Levels, GridSpec, FloorCeiling, Levels, Columns, std::size_t> over_walls;  // wall_ceilings
  StepMemo<Columns, GridSpec, Columns, Columns, int> enclosed;                      // detect_enclosed
  StepMemo<CeilingFacets, GridSpec, FloorCeiling, Levels, Columns, std::size_t> facets;
  StepMemo<RoomSplit, GridSpec, Columns, Columns, float, float> rooms;  // split_rooms
  ColumnSteps columns;
};

// The grid an analysis reads against the one the analysis before it read, each analysis known by a serial number
// (AnalysisCaches::serial): `changed` holds 1 for each column whose voxels differ, where both grids are known.
struct GridChange {
  std::uint64_t before = 0, now = 0;
  const std::vector<std::uint8_t>* changed = nullptr;
};

// 1 for each column whose voxels differ between `a` and `b`, grids of one GridSpec.
std::vector<std::uint8_t> changed_columns(const VoxelGrid& a, const VoxelGrid& b);

// detect_features (features.h), its whole-storey steps served by `memo` where not null, and its column steps
// derived again only at the columns `change` and their entries say changed.
RoomFeatures detect_features(const VoxelGrid& grid, const FloorCeiling& levels,
                             const std::vector<std::uint32_t>& column_counts,
                             const std::vector<std::uint8_t>& column_any, const FeatureParams& params,
                             unsigned threads, const std::stop_token& stop, const LabelGrid& labels,
                             FeatureMemo* memo, const GridChange& change);

}  // namespace roomsense::detail
