// SearchCache (search_cache.h): what each band of a search reads lies within the search's reach of its rows
// (wall_search_reach, square_search_reach), so a band none of whose rows within that reach changed finds what
// it found before.
#include "search_cache.h"

#include "key_table.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace roomsense::detail {
namespace {

bool same_spec(const GridSpec& a, const GridSpec& b) {
  return a.origin == b.origin && a.voxel_size == b.voxel_size && a.nx == b.nx && a.ny == b.ny && a.nz == b.nz;
}

// Marks row z where a per-column (`per_column` 1) or per-voxel (ny) array differs from its previous copy.
template <class T>
void mark_changed(const std::vector<T>& now, const std::vector<T>& before, std::size_t per_column, const GridSpec& spec,
                  std::vector<std::uint8_t>& rows) {
  if (now.size() != before.size()) {  // one of them empty (wall_blocked): every row
    std::fill(rows.begin(), rows.end(), std::uint8_t{1});
    return;
  }
  if (now.empty()) return;
  const std::size_t row = std::size_t(spec.nx) * per_column;
  for (int z = 0; z < spec.nz; ++z)
    if (!rows[std::size_t(z)] &&
        std::memcmp(now.data() + std::size_t(z) * row, before.data() + std::size_t(z) * row, row * sizeof(T)) != 0)
      rows[std::size_t(z)] = 1;
}

}  // namespace

void SearchCache::begin(const GridSpec& spec, const RoomFeatures& features) {
  ++generation_;
  searched_ = 0, total_ = 0;
  std::vector<int> facet_levels;
  for (const CeilingFacet& f : features.facets) facet_levels.push_back(f.level);
  all_changed_ = !same_spec(spec, spec_) || features.levels != levels_ || features.y_end != y_end_ ||
                 facet_levels != facet_levels_;
  for (std::vector<std::uint8_t>& rows : changed_rows_) rows.assign(std::size_t(spec.nz), all_changed_ ? 1 : 0);
  if (!all_changed_) {
    const auto ny = std::size_t(spec.ny);
    std::vector<std::uint8_t> walls(std::size_t(spec.nz), 0);
    mark_changed(features.walls, walls_, 1, spec, walls);
    for (std::vector<std::uint8_t>& rows : changed_rows_) rows = walls;  // no type's rectangle covers a wall
    mark_changed(features.normals, normals_, ny, spec, changed_rows_[0]);
    mark_changed(features.wall_blocked, wall_blocked_, ny, spec, changed_rows_[0]);
    mark_changed(features.ceiling, ceiling_, 1, spec, changed_rows_[0]);  // where walls grow up to
    mark_changed(features.free_floor, free_floor_, 1, spec, changed_rows_[1]);
    mark_changed(features.free_ceiling, free_ceiling_, 1, spec, changed_rows_[2]);
    mark_changed(features.ceiling_facet, ceiling_facet_, 1, spec, changed_rows_[2]);
    mark_changed(features.furniture, furniture_, 1, spec, changed_rows_[3]);
  }
  spec_ = spec, levels_ = features.levels, y_end_ = features.y_end, facet_levels_ = std::move(facet_levels);
  walls_ = features.walls, normals_ = features.normals, wall_blocked_ = features.wall_blocked;
  free_floor_ = features.free_floor, free_ceiling_ = features.free_ceiling;
  furniture_ = features.furniture, ceiling_facet_ = features.ceiling_facet, ceiling_ = features.ceiling;
}

const SearchCache::Reduction* SearchCache::unchanged_reduction(const AreaParams& params) {
  const auto changed = [](const std::vector<std::uint8_t>& rows) { return std::find(rows.begin(), rows.end(), 1) != rows.end(); };
  if (all_changed_ || reduction_generation_ + 1 != generation_ || !(params == reduction_params_) ||
      std::any_of(changed_rows_.begin(), changed_rows_.end(), changed))
    return nullptr;
  // The searches would find what they kept: their pieces hold for this analysis's features too.
  for (Kept& kept : kept_)
    if (kept.generation + 1 == generation_) kept.generation = generation_, total_ += std::size_t(kept.bands);
  reduction_generation_ = generation_;
  return &reduction_;
}

void SearchCache::keep_reduction(Reduction reduction, const AreaParams& params) {
  reduction_ = std::move(reduction);
  reduction_params_ = params;
  reduction_generation_ = generation_;
}

namespace {

// Bit for bit, so that a -0 is not taken for a 0.
bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(const glm::vec3& a, const glm::vec3& b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }
bool same_bits(const Area& a, const Area& b) {
  // Every field: a field added to Area changes its size and must be compared here.
  static_assert(sizeof(Area) == 4 + 4 * 12 + 2 * 12 + 4 * 4 + 3 * 4);
  for (std::size_t i = 0; i < 4; ++i)
    if (!same_bits(a.corners[i], b.corners[i])) return false;
  return a.type == b.type && a.size == b.size && a.reach == b.reach && same_bits(a.center, b.center) &&
         same_bits(a.normal, b.normal) && same_bits(a.half_width, b.half_width) &&
         same_bits(a.half_height, b.half_height) && same_bits(a.rotation_deg, b.rotation_deg) &&
         same_bits(a.volume_height, b.volume_height) && a.flags == b.flags && a.storey == b.storey && a.room == b.room;
}

}  // namespace

const std::vector<Area>* SearchCache::grown(std::size_t type, const std::vector<Area>& before, const AreaParams& params) {
  Grown& g = grown_[type];
  const std::vector<std::uint8_t>& rows = changed_rows_[type];
  if (all_changed_ || g.generation + 1 != generation_ || !(params == g.params) || before.size() != g.before.size() ||
      std::find(rows.begin(), rows.end(), 1) != rows.end() ||
      !std::equal(before.begin(), before.end(), g.before.begin(), [](const Area& a, const Area& b) { return same_bits(a, b); }))
    return nullptr;
  g.generation = generation_;
  return &g.after;
}

void SearchCache::keep_grown(std::size_t type, std::vector<Area> before, std::vector<Area> after, const AreaParams& params) {
  grown_[type] = {generation_, std::move(before), std::move(after), params};
}

RowBands SearchCache::plan(Kept& kept, std::size_t type, int layers, const SizeRange& range, float fill,
                           double dominant_deg, int reach) {
  const int bands = std::max(1, (spec_.nz + kBandRows - 1) / kBandRows);
  RowBands out{kBandRows, std::vector<std::uint8_t>(std::size_t(bands), 1)};
  const bool same = kept.generation + 1 == generation_ && !all_changed_ && kept.min_d == range.min_d && kept.max_d == range.max_d &&
                    kept.height_ratio == range.height_ratio && kept.fill == fill &&
                    kept.dominant_deg == dominant_deg && kept.layers == layers && kept.bands == bands;
  if (!same) {
    drop(kept);
    kept = {0, range.min_d, range.max_d, range.height_ratio, dominant_deg, fill, layers, bands, {}};
    kept.pieces.resize(std::size_t(std::max(layers, 0)) * std::size_t(bands));
  } else {
    const std::vector<std::uint8_t>& changed = changed_rows_[type];
    for (int b = 0; b < bands; ++b) {
      const int lo = std::max(0, b * kBandRows - reach), hi = std::min(spec_.nz, (b + 1) * kBandRows + reach);
      out.searched[std::size_t(b)] = std::any_of(changed.begin() + lo, changed.begin() + hi, [](std::uint8_t c) { return c != 0; });
    }
  }
  total_ += std::size_t(bands);
  searched_ += std::size_t(std::count(out.searched.begin(), out.searched.end(), std::uint8_t{1}));
  return out;
}

void SearchCache::drop(Kept& kept) {
  for (const auto& piece : kept.pieces) kept_bytes_ -= piece.size() * sizeof(Candidates::Item);
  kept = {};
}

void SearchCache::keep(Kept& kept, const RowBands& bands, const Candidates& found, const std::vector<Piece>& pieces) {
  const std::size_t band_count = bands.searched.size();
  for (std::size_t b = 0; b < band_count; ++b) {
    if (!bands.searched[b]) continue;
    for (int layer = 0; layer < kept.layers; ++layer) {
      std::vector<Candidates::Item>& piece = kept.pieces[std::size_t(layer) * band_count + b];
      kept_bytes_ -= piece.size() * sizeof(Candidates::Item);
      piece = {};
    }
  }
  std::size_t begin = 0;
  for (const Piece& p : pieces) {
    std::vector<Candidates::Item>& piece = kept.pieces[std::size_t(p.layer) * band_count + std::size_t(p.band)];
    for (std::size_t i = begin; i < p.end; ++i) piece.push_back(found.item(i));
    kept_bytes_ += (p.end - begin) * sizeof(Candidates::Item);
    begin = p.end;
  }
  kept.generation = generation_;
  // The kept rectangles stay within twice the grid's bytes and 16 MB; past that a search keeps nothing.
  if (kept_bytes_ > 2 * spec_.voxel_count() + (std::size_t{16} << 20)) drop(kept);
}

Candidates SearchCache::walls(std::size_t size, const GridSpec& spec, const RoomFeatures& features,
                              const NormalCounts& normals, const SizeRange& range, float fill,
                              const std::stop_token& stop) {
  Kept& kept = kept_[size];
  const RowBands bands = plan(kept, 0, 1, range, fill, 0.0, wall_search_reach(range));
  std::vector<Piece> pieces;
  const Candidates found = search_walls(spec, features, normals, range, fill, stop, {&bands, &pieces});
  // The bands in order, each rectangle unless an earlier band found its centre (as the whole search skips it).
  Candidates out = found.empty_like();
  KeyTable centres;
  std::size_t count = found.size();
  for (std::size_t b = 0; b < bands.searched.size(); ++b) count += bands.searched[b] ? 0 : kept.pieces[b].size();
  centres.reserve(count);
  const auto add = [&](const Candidates::Item& item) {
    const glm::ivec3 sum = corner_sum(found.decode(item).unpack());
    if (centres.insert(pack_key(sum.x, sum.y, sum.z))) out.push_item(item);
  };
  std::size_t begin = 0;
  auto piece = pieces.begin();
  for (int b = 0; b < int(bands.searched.size()); ++b) {
    if (bands.searched[std::size_t(b)]) {
      for (std::size_t i = begin; i < piece->end; ++i) add(found.item(i));
      begin = piece->end, ++piece;
      continue;
    }
    for (const Candidates::Item& item : kept.pieces[std::size_t(b)]) add(item);
  }
  keep(kept, bands, found, pieces);
  return out;
}

Candidates SearchCache::squares(std::size_t type, std::size_t size, const GridSpec& spec, const RoomFeatures& features,
                                const SizeRange& range, float fill, double dominant_deg, const std::stop_token& stop) {
  Kept& kept = kept_[3 * type + size];
  const Surface surface = type == 1 ? Surface::Floor : type == 2 ? Surface::Ceiling : Surface::Furniture;
  const int layers = square_layers(features, surface);
  const RowBands bands = plan(kept, type, layers, range, fill, dominant_deg, square_search_reach(range));
  std::vector<Piece> pieces;
  const Candidates found = search_squares(spec, features, surface, range, fill, dominant_deg, stop, {&bands, &pieces});
  // Layer by layer, band by band: the searched bands from found, the others as kept.
  std::vector<std::pair<std::size_t, std::size_t>> found_range(std::size_t(std::max(layers, 0)) * bands.searched.size(), {0, 0});
  std::size_t begin = 0;
  for (const Piece& p : pieces) {
    found_range[std::size_t(p.layer) * bands.searched.size() + std::size_t(p.band)] = {begin, p.end};
    begin = p.end;
  }
  Candidates out = found.empty_like();
  for (std::size_t i = 0; i < found_range.size(); ++i) {
    if (bands.searched[i % bands.searched.size()]) {
      for (std::size_t k = found_range[i].first; k < found_range[i].second; ++k) out.push_item(found.item(k));
      continue;
    }
    for (const Candidates::Item& item : kept.pieces[i]) out.push_item(item);
  }
  keep(kept, bands, found, pieces);
  return out;
}

}  // namespace roomsense::detail
