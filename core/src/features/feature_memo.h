// Beyond the thesis (issue 19): what detect_features derived for one storey in an IncrementalAnalysis's previous
// analysis. The steps that read the whole storey at once (the walls' heights, the walls' closure, the ceiling's
// facets, the split into rooms) are functions of a few column arrays and parameters alone; a change that leaves
// those as they were (furniture added, a wall refined within its columns) finds each such step's result kept
// instead of deriving it again. The steps that read a column, or the columns a reach away along the axes
// (furniture tops, free tiles, wall normals, openings: column_steps.h), are derived again only near the columns
// whose voxels or entries changed; the flood under the ceiling, only in the clusters of columns a change reaches
// (CeilingSteps). Each is reused only for inputs equal to those it was derived from, so every result is the
// step's own.
#pragma once
#include "roomsense/features.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>
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

// The grid an analysis reads against the one the analysis before it read, each analysis known by a serial number
// (AnalysisCaches::serial): `changed` holds 1 for each column whose voxels differ, where both grids are known.
struct GridChange {
  std::uint64_t before = 0, now = 0;
  const std::vector<std::uint8_t>* changed = nullptr;
};

// What a memo of per-column results read besides the grid: the analysis whose grid it was, the levels and
// parameters (`Scalars`), and per-column entries (walls, the inside, ...).
template <class Scalars, class... Entries>
class ColumnInputs {
 public:
  // The columns whose results must be derived again on the grid `change` describes with these scalars and
  // entries; nullopt where every column must be (no grid read before, another one, other scalars). Keeps
  // these as the memo's inputs; until done(), every column must be derived again next time.
  std::optional<std::vector<std::uint32_t>> begin(const GridChange& change, Scalars scalars,
                                                  const Entries&... entries) {
    std::optional<std::vector<std::uint32_t>> out;
    if (change.changed != nullptr && grid_ != 0 && grid_ == change.before && scalars_ == scalars) {
      out.emplace();
      for (std::size_t c = 0; c < change.changed->size(); ++c)
        if ((*change.changed)[c] ||
            std::apply([&](const auto&... kept) { return ((kept[c] != entries[c]) || ...); }, entries_))
          out->push_back(std::uint32_t(c));
    }
    grid_ = 0;
    derived_ = out ? out->size() : std::get<0>(std::tie(entries...)).size();
    scalars_ = std::move(scalars);  // taken by value: the openings' scalars hold the walls and the labels' voxels
    entries_ = std::tie(entries...);
    return out;
  }
  void done(const GridChange& change) { grid_ = change.now; }
  // The grid read is `change.now`'s too (the same voxels): what the memo holds still stands.
  void same_grid(const GridChange& change) {
    if (grid_ != 0 && grid_ == change.before) grid_ = change.now;
  }
  std::size_t derived() const { return derived_; }  // the columns the latest begin() asked for

 private:
  std::uint64_t grid_ = 0;  // the analysis whose grid it read; 0: none
  std::size_t derived_ = 0;
  Scalars scalars_{};
  std::tuple<Entries...> entries_;
};

// The column steps (column_steps.h) of the latest analysis: what they read, and their results.
struct ColumnSteps {
  struct Scalars {
    GridSpec spec;
    FloorCeiling levels;
    int y_end = 0, furniture_clear = 0, ceiling_clear = 0, rough = 0;
    bool operator==(const Scalars&) const = default;
  };
  // walls, the inside, the ceiling
  ColumnInputs<Scalars, std::vector<std::uint8_t>, std::vector<std::uint8_t>, std::vector<int>> inputs;
  std::vector<int> furniture;                          // C, before it is cut to the inside and to the labels
  std::vector<std::uint8_t> free_floor, free_ceiling;  // D and E, before the labels and the facets
};

// What the wall normals F of the latest analysis read (the normals themselves are the analysis's result).
struct NormalSteps {
  struct Scalars {
    GridSpec spec;
    FloorCeiling levels;
    int reach = 0;
    bool operator==(const Scalars&) const = default;
  };
  // walls, the inside, the ceiling, the furniture tops
  ColumnInputs<Scalars, std::vector<std::uint8_t>, std::vector<std::uint8_t>, std::vector<int>, std::vector<int>> inputs;
};

// What the wall openings of the latest analysis read (the blocked voxels are the analysis's result).
struct OpeningSteps {
  struct Scalars {
    GridSpec spec;
    FloorCeiling levels;
    int recess = 0, max_opening = 0;
    std::vector<std::uint8_t> walls;  // doors read whole lines of them: any change derives every column again
    LabelMask present = 0;
    std::vector<LabelMask> labels;  // the labels' voxels
    bool operator==(const Scalars&) const = default;
  };
  ColumnInputs<Scalars, std::vector<std::uint8_t>> inputs;  // the inside
};

// The flood under the ceiling (column_ceilings, raised_ceiling): each column's runs of empty levels, and the
// highest level the flood reaches in it.
struct FloodRuns {
  struct Run {
    int y0, y1;
  };
  std::vector<std::uint8_t> open;   // per column: empty over every level the flood reads (it lists no runs)
  std::vector<std::size_t> first;   // the runs of column c: [first[c], first[c + 1])
  std::vector<Run> runs;
  std::vector<int> highest;         // per column: the highest level the flood reaches, or -1
};

// column_ceilings of the latest analysis: its flood, and the ceiling that gave. A part of the flood is a function
// of the runs of one cluster of columns that hold runs (4-connected) and of which columns beside it are open, so
// a change floods again only the clusters that hold, or lie beside, a column whose voxels or room changed.
struct CeilingSteps {
  struct Scalars {
    GridSpec spec;
    FloorCeiling levels;
    int cap = 0;
    bool operator==(const Scalars&) const = default;
  };
  ColumnInputs<Scalars, std::vector<std::uint8_t>> inputs;  // the room B
  FloodRuns flood;
  std::vector<int> ceiling;
};

// One storey's steps, each with the inputs detect_features gives it.
struct FeatureMemo {
  using Columns = std::vector<std::uint8_t>;
  using Levels = std::vector<int>;
  StepMemo<Levels, GridSpec, FloorCeiling, Levels, Columns, std::size_t> over_walls;  // wall_ceilings
  StepMemo<Columns, GridSpec, Columns, Columns, int> enclosed;                      // detect_enclosed
  StepMemo<CeilingFacets, GridSpec, FloorCeiling, Levels, Columns, std::size_t> facets;
  StepMemo<RoomSplit, GridSpec, Columns, Columns, float, float> rooms;  // split_rooms
  CeilingSteps ceilings;
  ColumnSteps columns;
  NormalSteps normals;
  OpeningSteps openings;
};

// column_ceilings (features.h), through `memo` where not null: the flood derived again only in the clusters of
// columns a change can reach (CeilingSteps).
std::vector<int> column_ceilings(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& room,
                                 int cap, CeilingSteps* memo, const GridChange& change);

// detect_features (features.h), through `memo` where not null: its whole-storey steps kept where their inputs
// are, its local steps derived again only near the columns `change` and their entries say changed. `previous`:
// the features of the analysis before (`change.before`) on these levels, where it has them; the wall normals and
// openings are its own, updated (without it they are derived whole). `area_features` false (without a memo only):
// C, D, F and the openings, which only the areas and the placement queries read, are left empty
// (AnalysisOptions::area_features).
RoomFeatures detect_features(const VoxelGrid& grid, const FloorCeiling& levels,
                             const std::vector<std::uint32_t>& column_counts,
                             const std::vector<std::uint8_t>& column_any, const FeatureParams& params,
                             unsigned threads, const std::stop_token& stop, const LabelGrid& labels,
                             FeatureMemo* memo, const GridChange& change, const RoomFeatures* previous,
                             bool area_features = true);

}  // namespace roomsense::detail
