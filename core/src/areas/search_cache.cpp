// SearchCache (search_cache.h): what each band of a search reads lies within the search's reach of its rows
// (wall_search_reach, square_search_reach), so a band none of whose rows within that reach changed finds what
// it found before; and what a square's centre reads lies within that reach of its cell, so a centre no changed
// column is within reach of finds what it found before.
#include "search_cache.h"
#include "list_match.h"

#include "../key_table.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace roomsense::detail {
namespace {

// Widens row z's span of changed columns to every column where a per-column (`per_column` 1) or per-voxel (ny)
// array differs from its previous copy. Returns the rows that differ (of arrays of one size).
template <class T>
std::vector<int> mark_changed(const std::vector<T>& now, const std::vector<T>& before, std::size_t per_column,
                              const GridSpec& spec, std::vector<glm::ivec2>& rows) {
  std::vector<int> differing;
  if (now.size() != before.size()) {  // one of them empty (wall_blocked): every column
    std::fill(rows.begin(), rows.end(), glm::ivec2(0, spec.nx - 1));
    return differing;
  }
  if (now.empty()) return differing;
  const std::size_t row = std::size_t(spec.nx) * per_column;
  const auto differs = [&](std::size_t z, int x) {
    const std::size_t at = z * row + std::size_t(x) * per_column;
    return std::memcmp(now.data() + at, before.data() + at, per_column * sizeof(T)) != 0;
  };
  for (int z = 0; z < spec.nz; ++z) {
    const std::size_t at = std::size_t(z) * row;
    if (std::memcmp(now.data() + at, before.data() + at, row * sizeof(T)) == 0) continue;
    differing.push_back(z);
    glm::ivec2& span = rows[std::size_t(z)];
    int first = 0, last = spec.nx - 1;
    while (!differs(std::size_t(z), first)) ++first;
    while (!differs(std::size_t(z), last)) --last;
    span = glm::ivec2(std::min(span.x, first), std::max(span.y, last));
  }
  return differing;
}

// `before` made equal to `now`, of which only `rows` differ where both have one size (mark_changed's): a change
// copies the rows it reached, not a room's every feature.
template <class T>
void copy_rows(const std::vector<T>& now, std::vector<T>& before, std::size_t per_column, const GridSpec& spec,
               const std::vector<int>& rows) {
  if (now.size() != before.size()) {
    before = now;
    return;
  }
  const std::size_t row = std::size_t(spec.nx) * per_column;
  for (const int z : rows) {
    const auto at = std::ptrdiff_t(std::size_t(z) * row);
    std::copy_n(now.begin() + at, row, before.begin() + at);
  }
}

// How the tiles `now` (first corners, nonzero) and the walls changed from `before` over the changed rows' spans
// (TileChange): walls are never tiles, so a column that lost a tile or gained a wall lost, and the reverse gained.
TileChange tile_change(const std::vector<std::uint8_t>& tiles_now, const std::vector<std::uint8_t>& tiles_before,
                       const std::vector<std::uint8_t>& walls_now, const std::vector<std::uint8_t>& walls_before,
                       const GridSpec& spec, const std::vector<glm::ivec2>& rows) {
  const std::size_t columns = spec.column_count();
  if (tiles_now.size() != columns || tiles_before.size() != columns || walls_now.size() != columns ||
      walls_before.size() != columns)
    return TileChange::Mixed;
  bool lost = false, gained = false;
  for (std::size_t z = 0; z < rows.size(); ++z)
    for (int x = rows[z].x; x <= rows[z].y; ++x) {
      const std::size_t col = spec.column(x, int(z));
      const bool tile_now = tiles_now[col] != 0, tile_before = tiles_before[col] != 0;
      const bool wall_now = walls_now[col] != 0, wall_before = walls_before[col] != 0;
      lost = lost || (tile_before && !tile_now) || (wall_now && !wall_before);
      gained = gained || (tile_now && !tile_before) || (wall_before && !wall_now);
    }
  return lost == gained ? TileChange::Mixed : lost ? TileChange::Lost : TileChange::Gained;
}

bool any_changed(const std::vector<glm::ivec2>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const glm::ivec2& span) { return span.x <= span.y; });
}

}  // namespace

void SearchCache::begin(const GridSpec& spec, const RoomFeatures& features) {
  ++generation_;
  searched_ = 0, total_ = 0;
  std::vector<int> facet_levels;
  for (const CeilingFacet& f : features.facets) facet_levels.push_back(f.level);
  all_changed_ = spec != spec_ || features.levels != levels_ || features.y_end != y_end_ ||
                 facet_levels != facet_levels_;
  tile_change_.fill(TileChange::Mixed);
  const glm::ivec2 none(spec.nx, -1), all(0, spec.nx - 1);
  for (std::vector<glm::ivec2>& rows : changed_rows_) rows.assign(std::size_t(spec.nz), all_changed_ ? all : none);
  if (!all_changed_) {
    const auto ny = std::size_t(spec.ny);
    std::vector<glm::ivec2> walls(std::size_t(spec.nz), none);
    const std::vector<int> wall_rows = mark_changed(features.walls, walls_, 1, spec, walls);
    for (std::vector<glm::ivec2>& rows : changed_rows_) rows = walls;  // no type's rectangle covers a wall
    std::vector<glm::ivec2>& wall_type = changed_rows_[0];
    const std::vector<int> normal_rows = mark_changed(features.normals, normals_, ny, spec, wall_type);
    const std::vector<int> blocked_rows = mark_changed(features.wall_blocked, wall_blocked_, ny, spec, wall_type);
    const std::vector<int> ceiling_rows = mark_changed(features.ceiling, ceiling_, 1, spec, wall_type);  // walls grow to it
    const std::vector<int> floor_rows = mark_changed(features.free_floor, free_floor_, 1, spec, changed_rows_[1]);
    const std::vector<int> free_ceiling_rows =
        mark_changed(features.free_ceiling, free_ceiling_, 1, spec, changed_rows_[2]);
    const std::vector<int> facet_rows = mark_changed(features.ceiling_facet, ceiling_facet_, 1, spec, changed_rows_[2]);
    const std::vector<int> furniture_rows = mark_changed(features.furniture, furniture_, 1, spec, changed_rows_[3]);
    tile_change_[1] = tile_change(features.free_floor, free_floor_, features.walls, walls_, spec, changed_rows_[1]);
    // Furniture's levels at which a column's class changed: a top at f is a first corner at level f and a tile
    // one level up at f - 1; a wall, at every level.
    furniture_levels_changed_.assign(std::size_t(std::max(spec.ny, 0)) + 2, any_changed(walls) ? 1 : 0);
    if (features.furniture.size() == spec.column_count() && furniture_.size() == spec.column_count())
      for (std::size_t z = 0; z < changed_rows_[3].size(); ++z)
        for (int x = changed_rows_[3][z].x; x <= changed_rows_[3][z].y; ++x) {
          const std::size_t col = spec.column(x, int(z));
          if (features.furniture[col] == furniture_[col]) continue;
          for (const int level : {furniture_[col], furniture_[col] - 1, features.furniture[col], features.furniture[col] - 1})
            if (level >= 0 && std::size_t(level) < furniture_levels_changed_.size())
              furniture_levels_changed_[std::size_t(level)] = 1;
        }
    else
      std::fill(furniture_levels_changed_.begin(), furniture_levels_changed_.end(), std::uint8_t{1});
    // A ceiling's layer is its column's facet.
    tile_change_[2] = !facet_rows.empty() || features.ceiling_facet.size() != ceiling_facet_.size()
                          ? TileChange::Mixed
                          : tile_change(features.free_ceiling, free_ceiling_, features.walls, walls_, spec, changed_rows_[2]);
    // The copies kept for the next analysis: the rows that changed.
    copy_rows(features.walls, walls_, 1, spec, wall_rows);
    copy_rows(features.normals, normals_, ny, spec, normal_rows);
    copy_rows(features.wall_blocked, wall_blocked_, ny, spec, blocked_rows);
    copy_rows(features.ceiling, ceiling_, 1, spec, ceiling_rows);
    copy_rows(features.free_floor, free_floor_, 1, spec, floor_rows);
    copy_rows(features.free_ceiling, free_ceiling_, 1, spec, free_ceiling_rows);
    copy_rows(features.ceiling_facet, ceiling_facet_, 1, spec, facet_rows);
    copy_rows(features.furniture, furniture_, 1, spec, furniture_rows);
  } else {
    walls_ = features.walls, normals_ = features.normals, wall_blocked_ = features.wall_blocked;
    free_floor_ = features.free_floor, free_ceiling_ = features.free_ceiling;
    furniture_ = features.furniture, ceiling_facet_ = features.ceiling_facet, ceiling_ = features.ceiling;
  }
  spec_ = spec, levels_ = features.levels, y_end_ = features.y_end, facet_levels_ = std::move(facet_levels);
}

const SearchCache::TypeReduction* SearchCache::unchanged_type(std::size_t type, const AreaParams& params,
                                                              double dominant_deg) {
  KeptType& kept_type = types_[type];
  if (all_changed_ || kept_type.generation + 1 != generation_ || !(params == kept_type.params) ||
      (type > 0 && kept_type.reduction.dominant_deg != dominant_deg) || any_changed(changed_rows_[type]))
    return nullptr;
  kept_type.generation = generation_;
  // The searches would find what they kept, and packing decide as it did.
  for (std::size_t size = 0; size < 3; ++size) {
    Kept& kept = kept_[3 * type + size];
    if (kept.generation + 1 == generation_) kept.generation = generation_, total_ += std::size_t(kept.bands);
    if (kept.packed_generation + 1 == generation_) kept.packed_generation = generation_;
  }
  return &kept_type.reduction;
}

void SearchCache::keep_type(std::size_t type, TypeReduction reduction, const AreaParams& params) {
  types_[type] = {generation_, std::move(reduction), params};
}

const std::vector<Area>* SearchCache::grown(std::size_t type, const std::vector<Area>& before, const AreaParams& params) {
  Grown& g = grown_[type];
  if (all_changed_ || g.generation + 1 != generation_ || !(params == g.params) ||
      before.size() != g.record.before.size() || any_changed(changed_rows_[type]) ||
      !std::equal(before.begin(), before.end(), g.record.before.begin(), [](const Area& a, const Area& b) { return same_bits(a, b); }))
    return nullptr;
  g.generation = generation_;
  return &g.record.after;
}

GrowthReplay SearchCache::growth_replay(std::size_t type, const AreaParams& params) const {
  const Grown& g = grown_[type];
  if (all_changed_ || g.generation + 1 != generation_ || !(params == g.params)) return {};
  return {&g.record, &spec_, changed_rows_[type]};
}

void SearchCache::keep_grown(std::size_t type, GrowthRecord record, const AreaParams& params) {
  grown_[type] = {generation_, std::move(record), params};
}

RowBands SearchCache::plan(Kept& kept, std::size_t type, int layers, const SizeRange& range, float fill,
                           double dominant_deg, int reach, int columns_before, int columns_after) {
  const int bands = std::max(1, (spec_.nz + kBandRows - 1) / kBandRows);
  RowBands out{kBandRows, std::vector<std::uint8_t>(std::size_t(bands), 1),
               std::vector<glm::ivec2>(std::size_t(bands), glm::ivec2(0, spec_.nx - 1))};
  const bool same = kept.generation + 1 == generation_ && !all_changed_ && kept.min_d == range.min_d && kept.max_d == range.max_d &&
                    kept.height_ratio == range.height_ratio && kept.fill == fill &&
                    kept.dominant_deg == dominant_deg && kept.layers == layers && kept.bands == bands;
  if (!same) {
    drop(kept);
    kept.min_d = range.min_d, kept.max_d = range.max_d, kept.height_ratio = range.height_ratio;
    kept.dominant_deg = dominant_deg, kept.fill = fill, kept.layers = layers, kept.bands = bands;
    kept.pieces.resize(std::size_t(std::max(layers, 0)) * std::size_t(bands));
    kept.states.resize(kept.pieces.size());
    kept.ranks.resize(kept.pieces.size());
  } else {
    // A band's columns: those within reach of a column changed in a row within reach.
    const std::vector<glm::ivec2>& changed = changed_rows_[type];
    for (int b = 0; b < bands; ++b) {
      const int lo = std::max(0, b * kBandRows - reach), hi = std::min(spec_.nz, (b + 1) * kBandRows + reach);
      glm::ivec2 columns(spec_.nx, -1);
      for (int z = lo; z < hi; ++z)
        columns = glm::ivec2(std::min(columns.x, changed[std::size_t(z)].x), std::max(columns.y, changed[std::size_t(z)].y));
      out.searched[std::size_t(b)] = columns.x <= columns.y;
      out.columns[std::size_t(b)] =
          glm::ivec2(std::max(0, columns.x - columns_before), std::min(spec_.nx - 1, columns.y + columns_after));
    }
  }
  total_ += std::size_t(bands);
  searched_ += std::size_t(std::count(out.searched.begin(), out.searched.end(), std::uint8_t{1}));
  return out;
}

void SearchCache::drop(Kept& kept) {
  for (const auto& piece : kept.pieces) kept_bytes_ -= piece.size() * kBytesEach;
  kept = {};
}

namespace {

// The centres of a wall list whose corners 1 come row by row (z1 never falls), as search_walls's bits: twice the
// centre, (2 x1 + dx, 2 y1 - h, 2 z1 + dz), a bit each, in rows of 2 z1 + dz. A later wall's centre lies within
// `reach` rows of 2 z1 (|dz| <= reach), so rows from before that are used again: a large floor's list marks a
// window of rows (what a hash of every centre took, with a cache miss a wall), not the grid's volume.
class WallCentres {
 public:
  WallCentres(const GridSpec& spec, std::span<const Candidates::Shape> shapes) {
    int reach = 0;
    for (const Candidates::Shape& s : shapes) reach = std::max(reach, std::abs(s.dz)), h_max_ = std::max(h_max_, s.side);
    const std::size_t x_span = 2 * std::size_t(std::max(spec.nx, 1));
    y_span_ = std::size_t(2 * std::max(spec.ny - 1, 0) + h_max_ + 1);
    rows_ = 2 * std::size_t(reach) + 3;
    row_words_ = (x_span * y_span_ + 63) / 64;
    bits_.assign(rows_ * row_words_, 0);
    tags_.assign(rows_, std::numeric_limits<int>::min());
  }
  // Marks the wall's centre; false where a wall before it had that centre.
  bool insert(const PackedCandidate& wall) {
    const glm::ivec3 c = wall.corner(0), sum = wall.corner_sum() / 2;  // (2 x1 + dx, 2 y1 - h, 2 z1 + dz)
    if (c.z < z1_) throw std::logic_error("a wall list out of search order");
    // The row of 2 z1 + dz modulo rows_, from that of 2 z1, found once a z1 (|dz| <= reach): a division a wall
    // was a fifth of the lists' assembly.
    if (c.z != z1_) z1_ = c.z, row_2z1_ = (2 * c.z) % int(rows_);  // corners lie in the grid: z1 >= 0
    int wrapped = row_2z1_ + sum.z - 2 * c.z;
    wrapped += wrapped < 0 ? int(rows_) : wrapped >= int(rows_) ? -int(rows_) : 0;
    const auto row = std::size_t(wrapped);
    if (tags_[row] != sum.z) {
      std::fill_n(bits_.begin() + std::ptrdiff_t(row * row_words_), row_words_, std::uint64_t{0});
      tags_[row] = sum.z;
    }
    const std::size_t bit = std::size_t(sum.x) * y_span_ + std::size_t(sum.y + h_max_);
    std::uint64_t& word = bits_[row * row_words_ + bit / 64];
    const std::uint64_t mask = std::uint64_t{1} << (bit % 64);
    if (word & mask) return false;
    word |= mask;
    return true;
  }

 private:
  int h_max_ = 0, z1_ = std::numeric_limits<int>::min(), row_2z1_ = 0;
  std::size_t y_span_ = 0, rows_ = 0, row_words_ = 0;
  std::vector<std::uint64_t> bits_;
  std::vector<int> tags_;  // per row: the 2 z1 + dz its bits hold
};

}  // namespace

std::vector<SearchCache::Replaced> SearchCache::replace(Kept& kept, std::size_t type, const RowBands& bands,
                                                        const Candidates& found, const std::vector<Piece>& pieces) {
  const bool walls = type == 0;
  const std::size_t band_count = bands.searched.size();
  // The columns whose features the type's searches read that changed, made when first asked for.
  std::optional<ChangedRegion> changed_region;
  const auto features_changed = [&]() -> const ChangedRegion& {
    if (!changed_region) changed_region = changed_columns(type);
    return *changed_region;
  };
  // Each searched slot's new rectangles, [begin, end) of `found`.
  std::vector<std::pair<std::size_t, std::size_t>> fresh(kept.pieces.size(), {0, 0});
  std::size_t begin = 0;
  for (const Piece& p : pieces) {
    fresh[std::size_t(p.layer) * band_count + std::size_t(p.band)] = {begin, p.end};
    begin = p.end;
  }
  // A rectangle's place in search order (x, z), and the column that decides whether its band's search found it
  // anew: a square's centre on the half-voxel lattice (its cell's column x / 2), a wall's corner 1 (the wall
  // search goes corner by corner).
  const auto place_of = [&](const Candidates::Item& item) {
    const PackedCandidate p = found.decode(item);
    if (walls) return glm::ivec2(p.corner(0).x, p.corner(0).z);
    const glm::ivec3 sum = p.corner_sum();
    return glm::ivec2(sum.x / 2, sum.z / 2);
  };
  const auto column_of = [&](const glm::ivec2& place) { return walls ? place.x : place.x / 2; };
  const auto before = [](const glm::ivec2& a, const glm::ivec2& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; };
  std::vector<Replaced> old;
  // A slot's scratch, kept from slot to slot (furniture has a slot per level and band: lists per slot were a
  // quarter of an update's allocations).
  std::vector<glm::ivec2> places;
  std::vector<std::uint8_t> in_columns;  // searched(places[k])
  Replaced gone{0, {}, {}};
  std::vector<std::uint32_t> gone_ranks;
  std::vector<glm::ivec2> gone_places;
  std::vector<std::uint8_t> found_again;
  for (std::size_t b = 0; b < band_count; ++b) {
    if (!bands.searched[b]) continue;
    const glm::ivec2 columns = bands.columns[b];
    for (int layer = 0; layer < kept.layers; ++layer) {
      const std::size_t slot = std::size_t(layer) * band_count + b;
      Replaced r{slot, std::exchange(kept.pieces[slot], {}), std::exchange(kept.states[slot], {})};
      const std::vector<std::uint32_t> old_ranks = std::exchange(kept.ranks[slot], {});
      kept_bytes_ -= r.items.size() * kBytesEach;
      std::vector<Candidates::Item>& items = kept.pieces[slot];
      std::vector<std::int8_t>& states = kept.states[slot];
      std::vector<std::uint32_t>& ranks = kept.ranks[slot];
      const auto [first, end] = fresh[slot];
      // The slot's rectangles outside the columns searched are as they were, with their packing and rank
      // (which read no changed column either); the search found the others anew. Both in search order.
      const auto searched = [&](const glm::ivec2& place) {
        return column_of(place) >= columns.x && column_of(place) <= columns.y;
      };
      const std::size_t n = r.items.size();
      places.resize(n), in_columns.resize(n);
      gone.items.clear(), gone.states.clear(), gone_ranks.clear(), gone_places.clear();
      for (std::size_t k = 0; k < n; ++k) {
        places[k] = place_of(r.items[k]);
        in_columns[k] = searched(places[k]);
        if (in_columns[k]) {
          gone.items.push_back(r.items[k]), gone.states.push_back(r.states[k]), gone_ranks.push_back(old_ranks[k]);
          gone_places.push_back(places[k]);
        }
      }
      const std::size_t kept_as_were = n - gone.items.size();
      items.reserve(kept_as_were + (end - first)), states.reserve(items.capacity()), ranks.reserve(items.capacity());
      // Squares: one found again keeps its packing and rank where its contact reads no changed column (its
      // packing reads other squares alone, which the replay watches): none changed near it, or none near its
      // edges (a small object set down inside a large square). Both lists are in search order, a centre's
      // squares (one a level) together. Walls are matched so when the list is assembled (their packing reads
      // other walls alone).
      found_again.assign(gone.items.size(), 0);
      std::size_t g = 0;  // the first gone square not before the fresh one
      const auto add_fresh = [&](std::size_t i, const glm::ivec2& place) {
        const Candidates::Item& item = found.item(i);
        if (!walls) {
          while (g < gone.items.size() && before(gone_places[g], place)) ++g;
          const auto changed = [&] {
            const Candidate c = found.decode(item).unpack();
            const ChangedRegion& columns = features_changed();
            return columns.touches(ChangedRegion::around(c)) && contact_may_read(c, columns.added());
          };
          for (std::size_t k = g; k < gone.items.size() && gone_places[k] == place; ++k)
            if (gone.items[k] == item && !found_again[k] && !changed()) {
              found_again[k] = 1;
              items.push_back(item), states.push_back(gone.states[k]), ranks.push_back(gone_ranks[k]);
              return;
            }
        }
        items.push_back(item), states.push_back(PackReplay::kUnknown), ranks.push_back(PackReplay::kUnknownRank);
      };
      // The two merged in search order; the rectangles kept as they were go a run at a time, up to the next one
      // found anew.
      std::size_t i = first;
      for (std::size_t k = 0; k < n;) {
        if (in_columns[k]) {
          ++k;
          continue;
        }
        for (glm::ivec2 at; i < end && before(at = place_of(found.item(i)), places[k]); ++i) add_fresh(i, at);
        const std::optional<glm::ivec2> next_fresh = i < end ? std::optional(place_of(found.item(i))) : std::nullopt;
        std::size_t run_end = k + 1;
        while (run_end < n && !in_columns[run_end] && !(next_fresh && before(*next_fresh, places[run_end]))) ++run_end;
        const auto from = std::ptrdiff_t(k), to = std::ptrdiff_t(run_end);
        items.insert(items.end(), r.items.begin() + from, r.items.begin() + to);
        states.insert(states.end(), r.states.begin() + from, r.states.begin() + to);
        ranks.insert(ranks.end(), old_ranks.begin() + from, old_ranks.begin() + to);
        k = run_end;
      }
      for (; i < end; ++i) add_fresh(i, place_of(found.item(i)));
      // Gone: those not found again.
      r = {slot, {}, {}};
      const auto not_found = std::size_t(std::count(found_again.begin(), found_again.end(), std::uint8_t{0}));
      r.items.reserve(not_found), r.states.reserve(not_found);
      for (std::size_t k = 0; k < gone.items.size(); ++k)
        if (!found_again[k]) r.items.push_back(gone.items[k]), r.states.push_back(gone.states[k]);
      kept_bytes_ += items.size() * kBytesEach;
      old.push_back(std::move(r));
    }
  }
  kept.generation = generation_;
  return old;
}

Candidates SearchCache::assemble(Kept& kept, const Candidates& found, std::vector<Replaced> replaced, bool walls) {
  // The previous analysis's packing of each rectangle, where known: of a replaced slot's rectangles by identity.
  const bool known = kept.packed_generation + 1 == generation_;
  kept.source.clear();
  kept.replay = {};
  Candidates out = found.empty_like();
  std::size_t count = 0;
  for (const auto& piece : kept.pieces) count += piece.size();
  kept.slot_begin.clear();
  kept.replay.previous.reserve(count);
  if (!walls) {
    // Squares: layer by layer, band by band, each slot's whole. A square replaced and not found again as it was
    // (replace()) counts as gone, one found anew as new.
    for (const Replaced& r : replaced)
      for (std::size_t k = 0; known && k < r.items.size(); ++k)
        if (r.states[k] == PackReplay::kPacked) kept.replay.gone.push_back(found.decode(r.items[k]).unpack());
    kept.replay.ranks.reserve(count);
    kept.slot_begin.reserve(kept.pieces.size() + 1);
    for (std::size_t slot = 0; slot < kept.pieces.size(); ++slot) {
      const std::vector<Candidates::Item>& items = kept.pieces[slot];
      kept.slot_begin.push_back(out.size());
      out.push_items(items);
      std::vector<std::int8_t>& previous = kept.replay.previous;
      std::vector<std::uint32_t>& ranks = kept.replay.ranks;
      if (known) {
        previous.insert(previous.end(), kept.states[slot].begin(), kept.states[slot].end());
        ranks.insert(ranks.end(), kept.ranks[slot].begin(), kept.ranks[slot].end());
      } else {
        previous.insert(previous.end(), items.size(), PackReplay::kUnknown);
        ranks.insert(ranks.end(), items.size(), PackReplay::kUnknownRank);
      }
    }
    kept.slot_begin.push_back(out.size());
  } else {
    kept.source.reserve(count);
    // Walls: a replaced slot's rectangles found again keep their packing (a wall's order is the search's, which
    // keeps it among the others); the bands in order, each rectangle unless an earlier one has its centre (as
    // the whole search skips it: an earlier band's, or in a band searched in part, one kept outside its columns).
    // A replaced slot's rectangles and those it replaced (replace()) are both in search order: corner 1's z1, x1
    // and y1, then the ring's order (search_walls's loops). So the two lists are matched in one pass, side by side.
    std::vector<const Replaced*> replaced_of(kept.pieces.size(), nullptr);
    std::vector<std::vector<std::uint8_t>> matched(kept.pieces.size());
    for (const Replaced& r : replaced) {
      if (!known) continue;
      replaced_of[r.slot] = &r;
      matched[r.slot].assign(r.items.size(), 0);
    }
    const auto search_order = [&](const Candidates::Item& item) {
      return wall_search_order(found.decode(item).corner(0), item.shape);
    };
    std::size_t next = 0;  // the slot's first replaced rectangle not before the current one
    const auto previous_state = [&](std::size_t slot, std::size_t k) -> std::int8_t {
      if (!known) return PackReplay::kUnknown;
      // A rectangle kept outside the columns searched has its own; one found anew, that of its match.
      const Replaced* r = replaced_of[slot];
      if (r == nullptr || kept.states[slot][k] != PackReplay::kUnknown) return kept.states[slot][k];
      const Candidates::Item& item = kept.pieces[slot][k];
      const auto at = search_order(item);
      while (next < r->items.size() && search_order(r->items[next]) < at) ++next;
      if (next >= r->items.size() || !(r->items[next] == item)) return PackReplay::kUnknown;
      matched[slot][next] = 1;
      return r->states[next];
    };
    WallCentres centres(spec_, found.shapes());
    for (std::size_t slot = 0; slot < kept.pieces.size(); ++slot) {
      next = 0;
      for (std::size_t k = 0; k < kept.pieces[slot].size(); ++k) {
        const Candidates::Item& item = kept.pieces[slot][k];
        const std::int8_t state = previous_state(slot, k);
        const PackedCandidate p = found.decode(item);
        if (!centres.insert(p)) {
          if (state == PackReplay::kPacked) kept.replay.gone.push_back(p.unpack());
          continue;
        }
        out.push_item(item);
        kept.source.push_back({std::uint32_t(slot), std::uint32_t(k)});
        kept.replay.previous.push_back(state);
      }
    }
    // Packed before, not found again.
    for (const Replaced& r : replaced)
      for (std::size_t k = 0; known && k < r.items.size(); ++k)
        if (!matched[r.slot][k] && r.states[k] == PackReplay::kPacked)
          kept.replay.gone.push_back(found.decode(r.items[k]).unpack());
  }
  kept.replay_known = known;
  // The kept rectangles stay within twice the grid's bytes and 16 MB; past that a search keeps nothing.
  if (kept_bytes_ > 2 * spec_.voxel_count() + (std::size_t{16} << 20)) drop(kept);
  return out;
}

ChangedRegion SearchCache::changed_columns(std::size_t type) const {
  ChangedRegion changed({glm::ivec2(0), glm::ivec2(spec_.nx - 1, spec_.nz - 1)});
  for (std::size_t z = 0; z < changed_rows_[type].size(); ++z)
    if (const glm::ivec2 span = changed_rows_[type][z]; span.x <= span.y)
      changed.add({glm::ivec2(span.x, int(z)), glm::ivec2(span.y, int(z))});
  return changed;
}

template <class Reach>
const std::vector<Reach>& SearchCache::place_for_reach(Placed<Reach>& kept, const std::vector<Sized>& for_reach,
                                                       bool walls, const std::function<Reach(const Sized&)>& place) {
  const bool known = !all_changed_ && kept.generation + 1 == generation_;
  const auto same = [](const Sized& a, const Sized& b) { return a.packed == b.packed && a.size == b.size; };
  // A wall's place reads the features within two columns of its corners (ChangedRegion::around).
  std::optional<ChangedRegion> changed;
  if (known && walls && any_changed(changed_rows_[0])) changed = changed_columns(0);
  // The same list, each rectangle's place reading nothing changed (an update away from the walls): the areas as
  // they were, neither placed nor copied again.
  if (known && !changed &&
      std::equal(for_reach.begin(), for_reach.end(), kept.rectangles.begin(), kept.rectangles.end(), same)) {
    kept.generation = generation_;
    return kept.areas;
  }
  // Each rectangle's place in the previous list, where it was there (the lists keep their order: list_match.h).
  const std::vector<std::uint32_t> before =
      known ? match_in_order(std::span<const Sized>(kept.rectangles), std::span<const Sized>(for_reach), same,
                             [](const Sized& s) { return s.packed.hash() ^ std::uint64_t(s.size); })
            : std::vector<std::uint32_t>(for_reach.size(), FirstIndex::kAbsent);
  std::vector<Reach> out;
  out.reserve(for_reach.size());
  for (std::size_t k = 0; k < for_reach.size(); ++k) {
    const Sized& s = for_reach[k];
    const std::uint32_t j = before[k];
    const bool reuse = j != FirstIndex::kAbsent && (!changed || !changed->touches(ChangedRegion::around(s.c())));
    out.push_back(reuse ? kept.areas[j] : place(s));
  }
  kept = {generation_, for_reach, std::move(out)};
  return kept.areas;
}

const std::vector<ReachFloor>& SearchCache::reach_floors(const std::vector<Sized>& for_reach,
                                                         const std::function<ReachFloor(const Sized&)>& place) {
  return place_for_reach(floors_for_reach_, for_reach, false, place);
}

const std::vector<ReachWall>& SearchCache::reach_walls(const std::vector<Sized>& for_reach,
                                                       const std::function<ReachWall(const Sized&)>& place) {
  return place_for_reach(walls_for_reach_, for_reach, true, place);
}

const PackReplay* SearchCache::replay(std::size_t type, std::size_t size) const {
  const Kept& kept = kept_[3 * type + size];
  return kept.replay_known && kept.generation == generation_ ? &kept.replay : nullptr;
}

void SearchCache::record_packing(std::size_t type, std::size_t size, std::span<const std::size_t> packed,
                                 std::span<const std::uint32_t> ranks) {
  Kept& kept = kept_[3 * type + size];
  if (kept.generation != generation_) return;  // dropped, or not searched in this analysis
  if (type == 0) {
    for (std::vector<std::int8_t>& states : kept.states) std::fill(states.begin(), states.end(), PackReplay::kUnknown);
    for (const auto& [slot, k] : kept.source) kept.states[slot][k] = PackReplay::kRefused;
    for (const std::size_t i : packed) kept.states[kept.source[i].first][kept.source[i].second] = PackReplay::kPacked;
  } else {  // every square of the list, slot by slot (assemble)
    for (std::size_t slot = 0; slot < kept.states.size(); ++slot) {
      std::fill(kept.states[slot].begin(), kept.states[slot].end(), PackReplay::kRefused);
      if (!ranks.empty())
        std::copy(ranks.begin() + std::ptrdiff_t(kept.slot_begin[slot]), ranks.begin() + std::ptrdiff_t(kept.slot_begin[slot + 1]),
                  kept.ranks[slot].begin());
    }
    for (const std::size_t i : packed) {
      const std::size_t slot =
          std::size_t(std::upper_bound(kept.slot_begin.begin(), kept.slot_begin.end(), i) - kept.slot_begin.begin()) - 1;
      kept.states[slot][i - kept.slot_begin[slot]] = PackReplay::kPacked;
    }
  }
  kept.packed_generation = generation_;
  kept.source = {};
  kept.slot_begin = {};
  kept.replay = {};
}

BandedSearch SearchCache::from_previous(const Kept& kept, std::size_t type, const RowBands& bands,
                                        std::vector<Piece>& pieces) const {
  BandedSearch banded{&bands, &pieces, &kept.ring};
  // The kept pieces are the previous search's where plan() kept them (the same search over the same levels).
  if (all_changed_ || kept.generation + 1 != generation_) return banded;
  banded.previous = &kept.pieces, banded.change = tile_change_[type];
  if (type == 3) banded.levels_changed = &furniture_levels_changed_;
  banded.changed_lo = glm::ivec2(spec_.nx, spec_.nz), banded.changed_hi = glm::ivec2(-1);
  for (std::size_t z = 0; z < changed_rows_[type].size(); ++z)
    if (const glm::ivec2 span = changed_rows_[type][z]; span.x <= span.y) {
      banded.changed_lo = glm::min(banded.changed_lo, glm::ivec2(span.x, int(z)));
      banded.changed_hi = glm::max(banded.changed_hi, glm::ivec2(span.y, int(z)));
    }
  return banded;
}

Candidates SearchCache::walls(std::size_t size, const GridSpec& spec, const RoomFeatures& features,
                              const NormalCounts& normals, const SizeRange& range, float fill,
                              const std::stop_token& stop) {
  Kept& kept = kept_[size];
  // A wall's rectangle reads the columns from its corner 1 to `reach` after it, and the rectangles of one centre
  // have their corners 1 within `reach` / 2 of each other: with the band's columns searched from 2 `reach`
  // before to `reach` after those that changed, a centre whose rectangles lie on both sides of those columns'
  // ends has none that read a changed column, and keeps the one it had.
  const int reach = wall_search_reach(range);
  const RowBands bands = plan(kept, 0, 1, range, fill, 0.0, reach, 2 * reach, reach);
  std::vector<Piece> pieces;
  if (kept.ring.empty()) kept.ring = ring_offsets(range, Shape::WallTop);
  const Candidates found = search_walls(spec, features, normals, range, fill, stop, from_previous(kept, 0, bands, pieces));
  return assemble(kept, found, replace(kept, 0, bands, found, pieces), true);
}

Candidates SearchCache::squares(std::size_t type, std::size_t size, const GridSpec& spec, const RoomFeatures& features,
                                const SizeRange& range, float fill, double dominant_deg, const std::stop_token& stop) {
  Kept& kept = kept_[3 * type + size];
  const Surface surface = type == 1 ? Surface::Floor : type == 2 ? Surface::Ceiling : Surface::Furniture;
  const int layers = square_layers(features, surface);
  const int reach = square_search_reach(range);
  const RowBands bands = plan(kept, type, layers, range, fill, dominant_deg, reach, reach, reach);
  std::vector<Piece> pieces;
  if (kept.ring.empty()) kept.ring = ring_offsets(range, Shape::Square);
  const Candidates found =
      search_squares(spec, features, surface, range, fill, dominant_deg, stop, from_previous(kept, type, bands, pieces));
  return assemble(kept, found, replace(kept, type, bands, found, pieces), false);
}

}  // namespace roomsense::detail
