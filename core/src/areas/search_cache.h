// Beyond the thesis (issue 19): what find_areas found for one storey, kept between the analyses of an
// IncrementalAnalysis: the 12 searches' rectangles by bands of grid rows (search.h's RowBands), so that an
// analysis searches again only the bands whose rectangles may read a row whose features changed, and in a
// band only the rectangles within reach of a changed column, taking from the band's previous rectangles what
// one that reads no changed column would find (search.h's BandedSearch::previous); each rectangle's packing
// decision and rank (a square's kept where its centre was not searched again), for packing's replay (reduce.h);
// each area type's reduction, for a type nothing of which changed; each type's growth, replayed area by area (grow.h);
// the reach lists' areas in metres, and what reach found (classify.h's ReachMemo); packing's square sample
// runs (reduce.h's SquareSampleRuns). Every result equals the whole analysis's exactly
// (tests/unit/incremental_test.cpp replays rooms chunk by chunk against full analyses; search_cache_test.cpp
// tests each rule's edges).
#pragma once
#include "classify.h"
#include "grow.h"
#include "reduce.h"
#include "ring_offsets.h"
#include "search.h"

#include <array>
#include <atomic>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace roomsense::detail {

class SearchCache {
 public:
  static constexpr int kBandRows = 8;

  // Before an analysis's searches: compares the features they and growth read with the previous analysis's,
  // row by row. Everything is derived again where the grid, the levels, I_yEnd or the facets' levels changed.
  void begin(const GridSpec& spec, const RoomFeatures& features);
  // search_walls for size class `size`, and search_squares for type 1-3 (Surface) and `size`, from the kept
  // bands where nothing they read changed. Calls for different searches may run side by side.
  Candidates walls(std::size_t size, const GridSpec& spec, const RoomFeatures& features, const NormalCounts& normals,
                   const SizeRange& range, float fill, const std::stop_token& stop);
  Candidates squares(std::size_t type, std::size_t size, const GridSpec& spec, const RoomFeatures& features,
                     const SizeRange& range, float fill, double dominant_deg, const std::stop_token& stop);
  // What find_areas derives from one type's searches before it turns them into areas in metres: a function of
  // the features they read, the parameters and, for squares, the room's main direction.
  // On cache lines of its own (alignas): find_areas holds one per type side by side, and the types' tasks grow their
  // vectors at once.
  struct alignas(64) TypeReduction {
    std::vector<Sized> kept;       // packed, in find_areas's order
    std::vector<Sized> for_reach;  // deduplicated: V_Wall for walls, V_Floor for floors (reach); else empty
    std::size_t found = 0, deduplicated = 0;
    std::array<bool, 3> skipped{};  // per size: not searched (too many corner pairs)
    double dominant_deg = 0.0;      // walls: the main direction they give; squares: the one they were searched in
  };
  // The previous analysis's reduction of `type` where nothing its searches read changed since, `params` are its
  // own and, for squares, `dominant_deg` is the one it was searched in (the type's kept bands and packing then
  // hold as they are); otherwise nullptr, and find_areas searches and reduces the type.
  const TypeReduction* unchanged_type(std::size_t type, const AreaParams& params, double dominant_deg);
  void keep_type(std::size_t type, TypeReduction reduction, const AreaParams& params);
  // Growth (grow.h) of a type's packed areas, `before` growing, where the previous analysis grew the same areas
  // (bit for bit) over the same features with the same parameters: the areas it grew them into; else nullptr.
  const std::vector<Area>* grown(std::size_t type, const std::vector<Area>& before, const AreaParams& params);
  // Otherwise what the type's growth may replay of the previous analysis's (grow.h): none where the grid, the
  // levels or the parameters changed.
  GrowthReplay growth_replay(std::size_t type, const AreaParams& params) const;
  void keep_grown(std::size_t type, GrowthRecord record, const AreaParams& params);
  // V_Wall's (type 0) and V_Floor's (type 1) areas for reach: `for_reach` in metres by `place` (to_area), a
  // rectangle the previous analysis placed taken from it where its place reads nothing changed. A floor's reads
  // its rectangle and the grid alone (not the floor's height: reach reads X-Z); a wall's also the wall normals
  // and wall columns around it (to_area's wall_normal). Calls for the two may run side by side. The list is the
  // cache's, valid until the next call for the same type.
  const std::vector<ReachFloor>& reach_floors(const std::vector<Sized>& for_reach,
                                              const std::function<ReachFloor(const Sized&)>& place);
  const std::vector<ReachWall>& reach_walls(const std::vector<Sized>& for_reach,
                                            const std::function<ReachWall(const Sized&)>& place);
  // Packing (reduce.h) of the list walls() or squares() returned for (type, size) in this analysis: its replay
  // against the previous analysis's packing, or nullptr where that is not known; and what it packed (indices
  // into the list) and, for squares, each one's rank, recorded for the next analysis.
  const PackReplay* replay(std::size_t type, std::size_t size) const;
  void record_packing(std::size_t type, std::size_t size, std::span<const std::size_t> packed,
                      std::span<const std::uint32_t> ranks = {});
  // What reach found in the previous analysis (classify.h).
  ReachMemo& reach_memo() { return reach_memo_; }
  // Packing's square sample runs (reduce.h) for type 1-3's packer, kept from one analysis to the next.
  SquareSampleRuns& sample_runs(std::size_t type) { return sample_runs_[type]; }
  // Over the searches since begin(): the bands searched, and the bands there were.
  std::size_t bands_searched() const { return searched_; }
  std::size_t bands_total() const { return total_; }

 private:
  // On cache lines of its own, as TypeReduction: one per search, and the searches' tasks run side by side.
  struct alignas(64) Kept {
    std::uint64_t generation = 0;  // of the begin() whose features its pieces were found on; 0: none
    double min_d = 0, max_d = 0, height_ratio = 0, dominant_deg = 0;
    float fill = 0;
    int layers = 0, bands = 0;
    std::vector<RingOffset> ring;  // the search's offsets (ring_offsets), found once
    std::vector<std::vector<Candidates::Item>> pieces;  // slot layer * bands + band
    // Per slot and rectangle, its packing in the analysis of packed_generation (PackReplay's kUnknown: not in the
    // list), and for squares its rank in packing order.
    std::vector<std::vector<std::int8_t>> states;
    std::vector<std::vector<std::uint32_t>> ranks;
    std::uint64_t packed_generation = 0;
    // This analysis's list (walls(), squares()), and its packing's replay. Walls: each rectangle's slot and index
    // (a wall whose centre an earlier one has is not in the list). Squares: every slot's rectangles, slot by slot,
    // slot s's from list index slot_begin[s] on.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> source;
    std::vector<std::size_t> slot_begin;
    PackReplay replay;
    bool replay_known = false;
  };
  // What a kept rectangle takes: itself, its packing state and its rank.
  static constexpr std::size_t kBytesEach = sizeof(Candidates::Item) + sizeof(std::int8_t) + sizeof(std::uint32_t);
  // What a search replaced in a slot, as it was: its rectangles within the columns searched (of squares, those
  // not found again with their packing and rank).
  struct Replaced {
    std::size_t slot;
    std::vector<Candidates::Item> items;
    std::vector<std::int8_t> states;
  };
  // Which bands to search: all where `kept` does not match, else those within `reach` rows of a changed row,
  // each over the columns from `columns_before` before to `columns_after` after the changed columns of those
  // rows.
  RowBands plan(Kept& kept, std::size_t type, int layers, const SizeRange& range, float fill, double dominant_deg,
                int reach, int columns_before, int columns_after);
  void drop(Kept& kept);
  // Puts the searched bands' pieces of `found` (of search `type`) in place of the kept ones (the band's columns
  // searched), and returns what they replaced and did not find again.
  std::vector<Replaced> replace(Kept& kept, std::size_t type, const RowBands& bands, const Candidates& found,
                                const std::vector<Piece>& pieces);
  // A banded search of `kept` (of search `type`) by `bands`, its pieces to `pieces`, from the kept pieces where
  // they are the previous analysis's (search.h's BandedSearch::previous).
  BandedSearch from_previous(const Kept& kept, std::size_t type, const RowBands& bands, std::vector<Piece>& pieces) const;
  // The columns changed_rows_[type] holds.
  ChangedRegion changed_columns(std::size_t type) const;
  // The search's list from the kept pieces, with its packing's replay; drops everything when the cache would
  // outgrow its bound.
  Candidates assemble(Kept& kept, const Candidates& found, std::vector<Replaced> replaced, bool walls);

  std::array<Kept, 12> kept_;  // search t: type t / 3, size t % 3
  std::array<SquareSampleRuns, 4> sample_runs_;  // by type: the types' packers run side by side
  struct Grown {
    std::uint64_t generation = 0;
    GrowthRecord record;
    AreaParams params;
  };
  std::array<Grown, 4> grown_;
  struct KeptType {
    std::uint64_t generation = 0;
    TypeReduction reduction;
    AreaParams params;
  };
  std::array<KeptType, 4> types_;
  // The reach lists' rectangles of the latest analysis, and their areas in metres.
  template <class Reach>
  struct Placed {
    std::uint64_t generation = 0;
    std::vector<Sized> rectangles;
    std::vector<Reach> areas;
  };
  template <class Reach>
  const std::vector<Reach>& place_for_reach(Placed<Reach>& kept, const std::vector<Sized>& for_reach, bool walls,
                                            const std::function<Reach(const Sized&)>& place);
  Placed<ReachFloor> floors_for_reach_;
  Placed<ReachWall> walls_for_reach_;
  ReachMemo reach_memo_;
  // Counts begin()s. A search's pieces are reused only when kept in the previous one: one skipped (too many
  // corner pairs) or cut short (a stop, an error) since searches everything again.
  std::uint64_t generation_ = 0;
  bool all_changed_ = true;
  // Per type and row z: the span of columns whose features (the type's searches') changed; empty (x > y) where none.
  std::array<std::vector<glm::ivec2>, 4> changed_rows_;
  // Per type: how the tiles its squares read changed (types 1 and 2; Mixed for the others, and where unknown).
  std::array<TileChange, 4> tile_change_{};
  std::vector<std::uint8_t> furniture_levels_changed_;  // per level y (BandedSearch::levels_changed)
  // What the searches read, as the previous analysis had it.
  GridSpec spec_{};
  FloorCeiling levels_{};
  int y_end_ = 0;
  std::vector<int> facet_levels_;
  std::vector<std::uint8_t> walls_, normals_, wall_blocked_, free_floor_, free_ceiling_;
  std::vector<int> furniture_, ceiling_facet_, ceiling_;
  std::atomic<std::size_t> searched_ = 0, total_ = 0, kept_bytes_ = 0;
};

// find_areas (areas.h), its searches served by `cache` where there is one (one per storey).
AreaResult find_areas(const VoxelGrid& grid, const RoomFeatures& features, const SurfaceLevels& surfaces,
                      const AreaParams& params, const FeatureParams& feature_params, unsigned threads,
                      std::stop_token stop, SearchCache* cache);

}  // namespace roomsense::detail
