// The bounds volume I (Eq. 3.60-3.62) and the hole filling of §3.6.
#include "roomsense/bounds.h"
#include "roomsense/cancel.h"

#include "column_levels.h"
#include "../grid/changed_columns.h"
#include "mesh_memo.h"
#include "parallel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

namespace roomsense {
namespace {

using detail::eight_levels;
using detail::highest_solid;
using detail::lowest_solid;

// The bits of levels [lo, hi] in word k of a column's levels [first, first + 64 * words), level `first` in
// bit 0 of word 0.
std::uint64_t level_bits(int first, std::size_t k, int lo, int hi) {
  const int from = std::max(lo - first - 64 * int(k), 0), to = std::min(hi - first - 64 * int(k), 63);
  if (from > to) return 0;
  return (~std::uint64_t{0} >> (63 - to)) & (~std::uint64_t{0} << from);
}
// Whether at least three of four bits are set, bit by bit.
std::uint64_t three_of_four(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d) {
  return (a & b & (c | d)) | (c & d & (a | b));
}

// §3.6's last step: an inactive voxel becomes active when, in any of the X-Z, X-Y and Y-Z planes, at least
// three of its four neighbours are active. Neighbours are read from the volume before this pass, I (Eq. 3.62)
// of `g` and `h`: a column holds levels [floor, g] and [h, ceiling], so it is read from those two numbers, 64
// levels at a time. A column's fills are a function of its own and its four neighbours' G and H.
class PlaneHoles {
 public:
  PlaneHoles(const GridSpec& s, const FloorCeiling& levels, const std::vector<int>& g, const std::vector<int>& h)
      : s_(s), y_lo_(levels.floor), y_hi_(levels.ceiling), first_(y_lo_ - 1),
        words_((std::size_t(y_hi_ - y_lo_ + 3) + 63) / 64), width_(std::size_t(s.nx) + 2),
        // With a border of empty columns around the grid, so that a neighbour is read unchecked.
        column_runs_(width_ * (std::size_t(s.nz) + 2), std::uint64_t(std::uint32_t(y_lo_ - 1)) << 32 | std::uint32_t(y_hi_ + 1)) {
    // Each column's levels in [y_lo, y_hi] as one number: [y_lo, top] and [bottom, y_hi] with the empty and the
    // full ranges written one way each, so that two columns alike there have the same number.
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const std::size_t col = s.column(x, z);
        int top = std::max(g[col], y_lo_ - 1), bottom = std::min(h[col], y_hi_ + 1);
        if (top + 1 >= bottom) top = y_hi_, bottom = y_hi_ + 1;
        column_runs_[std::size_t(z + 1) * width_ + std::size_t(x + 1)] = std::uint64_t(std::uint32_t(top)) << 32 | std::uint32_t(bottom);
      }
  }
  // The voxels of column (x, z) to fill (GridSpec::index), appended to `fill`.
  void fills(int x, int z, std::vector<std::size_t>& fill) const {
    const std::uint64_t* at = column_runs_.data() + std::size_t(z + 1) * width_ + std::size_t(x + 1);
    const std::uint64_t here = *at, around[4] = {at[-1], at[1], *(at - width_), at[width_]};
    // Where the four neighbours equal the column, an empty voxel has no active neighbour in the X-Z plane
    // and at most two (below, above) in the others: nothing to fill.
    if (around[0] == here && around[1] == here && around[2] == here && around[3] == here) return;
    const auto word = [&](std::uint64_t r, std::size_t k) {
      const int top = int(std::int32_t(r >> 32)), bottom = int(std::int32_t(r & 0xFFFFFFFFu));
      return level_bits(first_, k, y_lo_, top) | level_bits(first_, k, bottom, y_hi_);
    };
    for (std::size_t k = 0; k < words_; ++k) {
      const std::uint64_t c = word(here, k), l = word(around[0], k), r = word(around[1], k), b = word(around[2], k),
                          f = word(around[3], k);
      // The levels below and above (the grid's levels -1 and ny read as empty: no run reaches them).
      const std::uint64_t down = c << 1 | (k > 0 ? word(here, k - 1) >> 63 : 0),
                          up = c >> 1 | (k + 1 < words_ ? word(here, k + 1) << 63 : 0);
      const std::uint64_t three = three_of_four(l, r, b, f) | three_of_four(l, r, down, up) | three_of_four(down, up, b, f);
      std::uint64_t to_fill = ~c & level_bits(first_, k, y_lo_, y_hi_) & three;
      for (; to_fill != 0; to_fill &= to_fill - 1)
        fill.push_back(s_.index(x, first_ + 64 * int(k) + std::countr_zero(to_fill), z));
    }
  }

 private:
  const GridSpec& s_;
  int y_lo_, y_hi_, first_;  // first_: the level of bit 0, the one below those checked
  std::size_t words_, width_;
  std::vector<std::uint64_t> column_runs_;
};

// PlaneHoles's fills of every column, collected first (per worker, over its own z layers) and set afterwards.
void fill_plane_holes(const GridSpec& s, const FloorCeiling& levels, const std::vector<int>& g,
                      const std::vector<int>& h, std::vector<std::uint8_t>& volume, unsigned threads) {
  const PlaneHoles holes(s, levels, g, h);
  std::vector<std::vector<std::size_t>> fills(detail::parallel_slices(std::size_t(s.nz), threads, 8));
  detail::parallel_for(std::size_t(s.nz), threads, 8, [&](std::size_t z_begin, std::size_t z_end, std::size_t slice) {
    std::vector<std::size_t> found;  // moved in after: the slices' vectors share cache lines
    for (int z = int(z_begin); z < int(z_end); ++z)
      for (int x = 0; x < s.nx; ++x) holes.fills(x, z, found);
    fills[slice] = std::move(found);
  });
  for (const auto& fill : fills)
    for (const std::size_t i : fill) volume[i] = 1;
}

// Ours: a plateau of G or H (columns of one height, 4-connected, inside the room) smaller than `min_cells`
// takes the height its border shares most with its neighbours. Scans carry surfaces jittering by a voxel
// and specks of noise; each such plateau costs the bounds mesh a ring of corners. Repeated until no small
// plateau is left, at most a few passes, as merging one can leave its neighbour small.
//
// A pass visits the plateaus as they were when it began, in the order of their first column, and flattens each
// small one with a border, reading its border's heights as the pass left them so far. A plateau a pass did not
// flatten and whose columns and neighbours it left as they were is not flattened by the next pass either (it
// is as large, and had the same border), so a pass after the first looks only at the plateaus with a column
// the last one changed or next to one. A plateau is followed only as far as min_cells columns.
void flatten_small_plateaus(const GridSpec& s, const std::vector<std::uint8_t>& room, int min_cells,
                            std::vector<int>& height) {
  if (min_cells <= 1) return;
  const std::size_t nx = std::size_t(s.nx);
  const auto for_neighbours = [&](std::size_t c, auto&& f) {
    const std::size_t x = c % nx, z = c / nx;
    if (x > 0) f(c - 1);
    if (x + 1 < nx) f(c + 1);
    if (z > 0) f(c - nx);
    if (z + 1 < std::size_t(s.nz)) f(c + nx);
  };
  // The columns to look from after the first pass: those the last pass changed and their neighbours.
  std::vector<std::size_t> from;
  std::vector<int> owner(height.size(), -1);  // the search that reached a column in this pass
  std::vector<std::size_t> reached, cells, stack, changed;
  struct Small {
    std::size_t first, begin, end;  // its first column; its columns in `small_cells`
  };
  std::vector<Small> smalls;
  std::vector<std::size_t> small_cells;
  std::vector<std::pair<int, int>> border;  // (neighbour height, shared edges)
  // A column with min_cells - 1 neighbours of its height lies in a large plateau: no search starts from it (one
  // from a small plateau's column never reaches it, so the small plateaus found are the same).
  const auto surely_large = [&](std::size_t c) {
    int same = 0;
    for_neighbours(c, [&](std::size_t n) { same += room[n] && height[n] == height[c]; });
    return same + 1 >= min_cells;
  };
  // The first pass looks from every room column, in order. Their heights with a border, a column outside the
  // room holding none (no room column's height), so that its neighbours of its height are counted unchecked.
  constexpr int kNoHeight = std::numeric_limits<int>::min();
  const std::ptrdiff_t width = std::ptrdiff_t(nx) + 2;
  std::vector<int> bordered(std::size_t(width) * (std::size_t(s.nz) + 2), kNoHeight);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      if (room[s.column(x, z)]) bordered[std::size_t((z + 1) * width + x + 1)] = height[s.column(x, z)];
  for (int pass = 0; pass < 8 && (pass == 0 || !from.empty()); ++pass) {
    // The small plateaus reached from the columns looked from, as they are at the start of the pass.
    smalls.clear();
    small_cells.clear();
    int searches = 0;
    const auto look_from = [&](std::size_t start) {
      const int id = searches++, h = height[start];
      bool is_large = false;
      cells.clear();
      stack.assign(1, start);
      owner[start] = id;
      reached.push_back(start);
      while (!stack.empty() && !is_large) {
        const std::size_t c = stack.back();
        stack.pop_back();
        cells.push_back(c);
        is_large = int(cells.size()) >= min_cells;
        for_neighbours(c, [&](std::size_t n) {
          if (!room[n] || height[n] != h) return;
          if (owner[n] < 0) {
            owner[n] = id;
            reached.push_back(n);
            stack.push_back(n);
          } else if (owner[n] != id) {
            is_large = true;  // a search of the same plateau stopped at min_cells columns
          }
        });
      }
      if (is_large) return;
      smalls.push_back({*std::min_element(cells.begin(), cells.end()), small_cells.size(), small_cells.size() + cells.size()});
      small_cells.insert(small_cells.end(), cells.begin(), cells.end());
    };
    if (pass == 0) {
      for (int z = 0; z < s.nz; ++z)
        for (int x = 0; x < s.nx; ++x) {
          const std::size_t c = s.column(x, z);
          if (!room[c] || owner[c] >= 0) continue;
          const int* b = bordered.data() + (z + 1) * width + x + 1;
          const int same = int(b[-1] == *b) + int(b[1] == *b) + int(b[-width] == *b) + int(b[width] == *b);
          if (same + 1 < min_cells) look_from(c);  // else surely large
        }
    } else {
      for (const std::size_t start : from)
        if (owner[start] < 0 && !surely_large(start)) look_from(start);
    }
    for (const std::size_t c : reached) owner[c] = -1;
    reached.clear();
    std::sort(smalls.begin(), smalls.end(), [](const Small& a, const Small& b) { return a.first < b.first; });
    changed.clear();
    for (const Small& p : smalls) {
      const int h = height[small_cells[p.begin]];
      border.clear();
      for (std::size_t k = p.begin; k < p.end; ++k)
        for_neighbours(small_cells[k], [&](std::size_t n) {
          if (!room[n] || height[n] == h) return;
          const auto it = std::find_if(border.begin(), border.end(), [&](const auto& e) { return e.first == height[n]; });
          if (it == border.end()) border.push_back({height[n], 1});
          else ++it->second;
        });
      if (border.empty()) continue;
      // The most shared border; on a tie the nearer height, then the lower.
      const auto best = std::min_element(border.begin(), border.end(), [&](const auto& a, const auto& b) {
        if (a.second != b.second) return a.second > b.second;
        if (std::abs(a.first - h) != std::abs(b.first - h)) return std::abs(a.first - h) < std::abs(b.first - h);
        return a.first < b.first;
      });
      for (std::size_t k = p.begin; k < p.end; ++k) height[small_cells[k]] = best->first;
      changed.insert(changed.end(), small_cells.begin() + std::ptrdiff_t(p.begin), small_cells.begin() + std::ptrdiff_t(p.end));
    }
    from.clear();
    for (const std::size_t c : changed) {
      from.push_back(c);
      for_neighbours(c, [&](std::size_t n) {
        if (room[n]) from.push_back(n);
      });
    }
  }
}

// The volume of one storey over `room`'s columns (the storey's B, or a room's part of it). With a memo of the
// storey's previous volume (StoreyVolumeMemo) and the columns whose cells changed since (`changed`, per column),
// where the storey read the same levels and parameters (its room and ceilings may have changed too): that volume
// written again only where it changed; kept in the memo.
std::vector<std::uint8_t> storey_volume(const VoxelGrid& grid, const BoundsStorey& storey,
                                        const std::vector<std::uint8_t>& room, const BoundsParams& params,
                                        unsigned threads, const std::stop_token& stop,
                                        detail::StoreyVolumeMemo* memo = nullptr,
                                        const std::vector<std::uint8_t>* changed = nullptr) {
  const GridSpec& s = grid.spec;
  const FloorCeiling& levels = storey.levels;
  const int y_end = std::clamp(storey.y_end, levels.floor + 1, levels.ceiling - 1);
  const std::uint32_t min_plateau_bits = std::bit_cast<std::uint32_t>(params.min_plateau_area);
  const std::vector<int> no_ceiling;
  const std::vector<int>& ceilings = storey.ceiling != nullptr ? *storey.ceiling : no_ceiling;
  const bool replay = memo != nullptr && changed != nullptr && memo->spec == s && memo->levels == levels &&
                      memo->y_end == storey.y_end && memo->min_plateau_area_bits == min_plateau_bits &&
                      memo->room.size() == room.size() && memo->ceiling.size() == ceilings.size();
  // Beyond the thesis: under a ceiling lower than I_Ceiling (a roof's slope, a soffit) the column's free space
  // ends at it; G looks no higher, and H is at most it.
  const auto ceiling_of = [&](std::size_t col) {
    return storey.ceiling != nullptr ? std::min((*storey.ceiling)[col], levels.ceiling) : levels.ceiling;
  };
  std::vector<int> g, h;
  const auto find_g_h = [&](std::size_t col) {
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    // G (Eq. 3.60): the highest active level in (I_Floor, I_yEnd]; else I_Floor inside the room; else -1.
    const int ceiling = ceiling_of(col);
    const int top = highest_solid(v, levels.floor, std::min(y_end, ceiling - 1));
    g[col] = top > levels.floor ? top : room[col] ? levels.floor : -1;
    // H (Eq. 3.61): the lowest active level in [I_yEnd, I_Ceiling); else I_Ceiling inside the room; else
    // I_Ceiling + 1.
    const int bottom = lowest_solid(v, y_end, levels.ceiling);
    h[col] = bottom < levels.ceiling ? bottom : room[col] ? levels.ceiling : levels.ceiling + 1;
    if (room[col] && ceiling < levels.ceiling) h[col] = std::min(h[col], std::max(ceiling, levels.floor + 1));
  };
  if (replay) {
    // A column's G and H read its cells, whether it is the room's and its ceiling: found again where one changed.
    g = memo->g_found, h = memo->h_found;
    for (std::size_t col = 0; col < s.column_count(); ++col)
      if ((*changed)[col] || memo->room[col] != room[col] || (!ceilings.empty() && memo->ceiling[col] != ceilings[col]))
        find_g_h(col);
  } else {
    g.resize(s.column_count()), h.resize(s.column_count());
    // Slices of kColumnGrain: at 4096 columns a slice, a room of thesis-room1's 4,331 columns was one slice, G and H
    // and the volume's columns each found on one thread (the bounds stage alone 0.765 -> 0.726 ms with these).
    detail::parallel_for(s.column_count(), threads, detail::kColumnGrain, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t col = begin; col < end; ++col) find_g_h(col);
    });
  }
  std::vector<int> g_found = memo ? g : std::vector<int>(), h_found = memo ? h : std::vector<int>();
  stop_point(stop);
  // In cells, rounding 0.04 m² at 0.1 m to 4, not 5; NaN or <= 0 turns the step off.
  const double cells = params.min_plateau_area > 0.0f
                           ? std::ceil(double(params.min_plateau_area) / (double(s.voxel_size) * s.voxel_size) - 1e-4)
                           : 0.0;
  const int min_cells = int(std::min(cells, double(s.column_count())));
  // Flattening reads the room and the heights as found alone: where a replay found the previous ones, its result is
  // the previous one (a change that reached G alone, or H, or neither: the other storeys of a home).
  const bool same_room = replay && memo->room == room;
  const bool same[2] = {same_room && g == memo->g_found, same_room && h == memo->h_found};
  detail::parallel_tasks(2, threads, [&](std::size_t i) {
    std::vector<int>& heights = i == 0 ? g : h;
    if (same[i]) heights = i == 0 ? memo->g : memo->h;
    else flatten_small_plateaus(s, room, min_cells, heights);
  });
  stop_point(stop);
  // I (Eq. 3.62) of a column from G and H, into levels [floor, ceiling] that hold nothing.
  const auto write_column = [&](std::vector<std::uint8_t>& volume, std::size_t col) {
    std::uint8_t* out = volume.data() + col * std::size_t(s.ny);
    for (int y = levels.floor; y <= g[col]; ++y) out[y] = 1;
    for (int y = h[col]; y <= levels.ceiling; ++y) out[y] = 1;
  };
  // Into the storage of the volume the memo gave out last, where it has one (StoreyVolumeMemo::spare).
  std::vector<std::uint8_t> volume = memo ? std::exchange(memo->spare, {}) : std::vector<std::uint8_t>();
  if (replay) {
    // The columns whose G or H changed, and their neighbours, written again with their holes, into the memo's
    // volume (a stop before the end leaves the memo without cells: bounds_volume).
    std::vector<std::uint8_t>& kept = memo->volume;
    std::vector<std::uint8_t> again(s.column_count(), 0);
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const std::size_t col = s.column(x, z);
        if (g[col] == memo->g[col] && h[col] == memo->h[col]) continue;
        again[col] = 1;
        if (x > 0) again[col - 1] = 1;
        if (x + 1 < s.nx) again[col + 1] = 1;
        if (z > 0) again[col - std::size_t(s.nx)] = 1;
        if (z + 1 < s.nz) again[col + std::size_t(s.nx)] = 1;
      }
    const PlaneHoles holes(s, levels, g, h);
    std::vector<std::size_t> fill;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x)
        if (const std::size_t col = s.column(x, z); again[col]) {
          std::fill(kept.begin() + std::ptrdiff_t(col * std::size_t(s.ny) + std::size_t(levels.floor)),
                    kept.begin() + std::ptrdiff_t(col * std::size_t(s.ny) + std::size_t(levels.ceiling) + 1), std::uint8_t{0});
          write_column(kept, col);
          holes.fills(x, z, fill);
        }
    for (const std::size_t i : fill) kept[i] = 1;
    volume.assign(kept.begin(), kept.end());
  } else {
    volume.assign(s.voxel_count(), 0);
    detail::parallel_for(s.column_count(), threads, detail::kColumnGrain, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t col = begin; col < end; ++col) write_column(volume, col);
    });
    stop_point(stop);
    fill_plane_holes(s, levels, g, h, volume, threads);
  }
  if (memo) {
    if (!replay) {  // what the storey read; a replay read the same
      memo->spec = s, memo->levels = levels, memo->y_end = storey.y_end, memo->min_plateau_area_bits = min_plateau_bits;
      memo->volume = volume;
    }
    memo->room = room, memo->ceiling = ceilings;
    memo->g_found = std::move(g_found), memo->h_found = std::move(h_found);
    memo->g = std::move(g), memo->h = std::move(h);
  }
  return volume;
}

}  // namespace

std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                        const std::vector<std::uint8_t>& room, const BoundsParams& params,
                                        unsigned threads, const std::stop_token& stop) {
  const detail::StagePool pool(threads);
  return storey_volume(grid, BoundsStorey{levels, y_end, &room}, room, params, threads, stop);
}

void fill_edge_contacts(const GridSpec& s, std::vector<std::uint8_t>& volume, unsigned threads) {
  detail::fill_edge_contacts(s, volume, threads, nullptr);
}

namespace {

// The solid box (SolidBox) through `memo`: each column's lowest and highest solid levels found again only where
// `changed` (empty: everywhere), kept in the memo, and their extremes.
detail::SolidBox solid_box_of_columns(const GridSpec& s, const std::vector<std::uint8_t>& volume, unsigned threads,
                                      const std::vector<std::uint8_t>& changed, detail::EdgeContactMemo& memo) {
  const std::size_t ny = std::size_t(s.ny), columns = s.column_count();
  const auto levels_of = [&](std::size_t col) {
    const std::uint8_t* v = volume.data() + col * ny;
    const int first = lowest_solid(v, 0, s.ny);
    memo.lowest[col] = first;
    memo.highest[col] = first == s.ny ? -1 : highest_solid(v, first, s.ny - 1);
  };
  if (changed.empty()) {
    memo.lowest.resize(columns), memo.highest.resize(columns);
    detail::parallel_for(columns, threads, std::size_t(s.nx) * detail::kRowGrain,
                         [&](std::size_t begin, std::size_t end, std::size_t) {
                           for (std::size_t col = begin; col < end; ++col) levels_of(col);
                         });
  } else {
    for (std::size_t col = 0; col < columns; ++col)
      if (changed[col]) levels_of(col);
  }
  detail::SolidBox box{{s.nx, s.ny, s.nz}, {-1, -1, -1}};
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t col = s.column(x, z);
      if (memo.highest[col] < 0) continue;
      box.lo[0] = std::min(box.lo[0], x), box.hi[0] = std::max(box.hi[0], x);
      box.lo[1] = std::min(box.lo[1], int(memo.lowest[col])), box.hi[1] = std::max(box.hi[1], int(memo.highest[col]));
      box.lo[2] = std::min(box.lo[2], z), box.hi[2] = std::max(box.hi[2], z);
    }
  return box;
}

}  // namespace

detail::FilledVolume detail::fill_edge_contacts(const GridSpec& s, std::vector<std::uint8_t>& volume, unsigned threads,
                                                EdgeContactMemo* memo) {
  // Only levels that hold a solid voxel (and the one above them) can form a contact: the solid box's.
  const detail::StagePool pool(threads);
  const std::size_t ny = std::size_t(s.ny);
  using detail::kRowGrain;
  // With a memo of this grid's last volume: the columns that changed since (nothing else is found again).
  const bool from_memo = memo != nullptr && memo->spec == s && memo->volume.size() == volume.size() &&
                         memo->may_fill.size() == s.column_count() && memo->lowest.size() == s.column_count() &&
                         memo->filled.size() == s.column_count();
  const std::vector<std::uint8_t> changed =
      from_memo ? detail::changed_columns(ny, memo->volume, volume) : std::vector<std::uint8_t>();
  if (memo) memo->spec = GridSpec{};  // valid again once it holds this volume's all
  // The box is the filled volume's too: a fill puts voxels in a block whose other diagonal is solid, at its
  // levels (an edge along y) or between them (along x or z), so within the box of that diagonal.
  FilledVolume out;
  out.box = memo ? solid_box_of_columns(s, volume, threads, changed, *memo) : detail::solid_box(s, volume, threads);
  const int y_lo = out.box.lo[1], y_hi = out.box.hi[1];
  if (y_hi < 0) return out;
  const int y_end = std::min(y_hi + 1, s.ny - 1);
  // A 2x2 block around an edge holds cells p, q (one diagonal) and r, t (the other). When one diagonal is
  // solid and the other empty, the empty pair is filled. Filling only adds solid voxels, so the loop ends;
  // in practice after one or two passes.
  const auto fillable = [](bool p, bool q, bool r, bool t) { return (p && q && !r && !t) || (r && t && !p && !q); };
  const auto settle = [&](std::uint8_t& p, std::uint8_t& q, std::uint8_t& r, std::uint8_t& t) {
    if (!fillable(p, q, r, t)) return false;
    if (p) r = t = 1;
    else p = q = 1;
    return true;
  };
  // The levels the checks read, [y_lo, y_end + 1] within the grid.
  const std::size_t read_from = std::size_t(y_lo), read_count = std::size_t(std::min(y_end + 1, s.ny - 1) - y_lo + 1);
  const auto same = [&](const std::uint8_t* a, const std::uint8_t* b) {
    return std::equal(a + read_from, a + read_from + read_count, b + read_from);
  };
  // The block of columns (x, z), (x + 1, z), (x, z + 1), (x + 1, z + 1) (c, cx, cz, cxz; null past the grid's
  // side), and which of its edges can fill: along y, z and x.
  struct Block {
    std::uint8_t *c, *cx, *cz, *cxz;
    bool check_y, check_z, check_x;
  };
  // The block's four columns (col for those past the grid's side).
  const auto columns_at = [&](int x, int z) {
    const std::size_t col = s.column(x, z);
    return std::array<std::size_t, 4>{col, x + 1 < s.nx ? s.column(x + 1, z) : col, z + 1 < s.nz ? s.column(x, z + 1) : col,
                                      x + 1 < s.nx && z + 1 < s.nz ? s.column(x + 1, z + 1) : col};
  };
  // The block at (x, z), of columns_at(x, z).
  const auto block_at = [&](int x, int z, const std::array<std::size_t, 4>& cols) {
    Block b;
    b.c = volume.data() + cols[0] * ny;
    b.cx = x + 1 < s.nx ? volume.data() + cols[1] * ny : nullptr;
    b.cz = z + 1 < s.nz ? volume.data() + cols[2] * ny : nullptr;
    b.cxz = b.cx && b.cz ? volume.data() + cols[3] * ny : nullptr;
    // A contact needs a solid and an empty voxel side by side in each pair of columns the edge lies between:
    // where two of them are equal over the levels read, that edge can fill nothing, as long as nothing in this
    // block is filled (after a fill every check runs).
    b.check_y = b.cxz && !same(b.c, b.cx) && !same(b.c, b.cz) && !same(b.cxz, b.cx) && !same(b.cxz, b.cz);
    b.check_z = b.cx && !same(b.c, b.cx), b.check_x = b.cz && !same(b.c, b.cz);
    return b;
  };
  // Whether an edge of a block can fill as the block stands, eight levels at a time (`fillable` on each byte's
  // lowest bit): a block none of whose edges can fill fills nothing, as only a fill changes it. A voxel reads
  // as 1 where it is not 0.
  const auto can_fill = [&](const Block& b) {
    if (!b.check_y && !b.check_z && !b.check_x) return false;
    constexpr std::uint64_t kOnes = 0x0101010101010101ull, kLow7 = 0x7F7F7F7F7F7F7F7Full;
    const auto solid = [&](const std::uint8_t* v, int y) {
      const std::uint64_t w = eight_levels(v, y);
      return ((((w & kLow7) + kLow7) | w) >> 7) & kOnes;
    };
    int y = y_lo;
    for (; y + 8 <= y_end + 1 && y + 9 <= s.ny; y += 8) {
      const std::uint64_t C = solid(b.c, y), C_up = solid(b.c, y + 1);
      std::uint64_t edges = 0;
      if (b.check_y) {
        const std::uint64_t X = solid(b.cx, y), Z = solid(b.cz, y), XZ = solid(b.cxz, y);
        edges |= (C & XZ & ~X & ~Z) | (X & Z & ~C & ~XZ);
      }
      if (b.check_z) {
        const std::uint64_t X = solid(b.cx, y), X_up = solid(b.cx, y + 1);
        edges |= (C & X_up & ~X & ~C_up) | (X & C_up & ~C & ~X_up);
      }
      if (b.check_x) {
        const std::uint64_t Z = solid(b.cz, y), Z_up = solid(b.cz, y + 1);
        edges |= (C & Z_up & ~Z & ~C_up) | (Z & C_up & ~C & ~Z_up);
      }
      if (edges & kOnes) return true;
    }
    for (; y <= y_end; ++y) {
      if (b.check_y && fillable(b.c[y], b.cxz[y], b.cx[y], b.cz[y])) return true;
      if (y + 1 < s.ny && ((b.check_z && fillable(b.c[y], b.cx[y + 1], b.cx[y], b.c[y + 1])) ||
                           (b.check_x && fillable(b.c[y], b.cz[y + 1], b.cz[y], b.c[y + 1]))))
        return true;
    }
    return false;
  };
  // The blocks that can fill in the volume as given, found side by side: the first pass, in order, visits only
  // those and the blocks with a column it filled earlier. Any other block still holds what it held when it was
  // found unable to fill, so skipping it changes nothing.
  // With the memo's, over the same levels: those of the blocks with a column that changed found again.
  std::vector<std::uint8_t> may_fill;
  if (from_memo && memo->y_lo == y_lo && memo->y_hi == y_hi) {
    may_fill = memo->may_fill;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const std::array<std::size_t, 4> cols = columns_at(x, z);
        if (changed[cols[0]] | changed[cols[1]] | changed[cols[2]] | changed[cols[3]])
          may_fill[cols[0]] = can_fill(block_at(x, z, cols)) ? 1 : 0;
      }
  } else {
    may_fill.assign(s.column_count(), 0);
    detail::parallel_for(std::size_t(s.nz), threads, kRowGrain, [&](std::size_t z_begin, std::size_t z_end, std::size_t) {
      for (int z = int(z_begin); z < int(z_end); ++z)
        for (int x = 0; x < s.nx; ++x) may_fill[s.column(x, z)] = can_fill(block_at(x, z, columns_at(x, z))) ? 1 : 0;
    });
  }
  if (memo) {  // the volume as given, before the passes below fill it
    if (from_memo) {
      detail::copy_columns(ny, volume, memo->volume, changed);
    } else {
      memo->volume = volume;
    }
    memo->may_fill = may_fill, memo->y_lo = y_lo, memo->y_hi = y_hi;
  }
  std::vector<std::uint8_t> filled_any(memo ? s.column_count() : 0, 0);  // the columns of the blocks that filled
  // Which columns a pass filled in: a later pass visits only the blocks with such a column (earlier in this
  // pass or anywhere in the last), by the same reasoning: the passes fill exactly what full passes would.
  std::vector<std::uint8_t> filled_last = std::move(may_fill), filled_now(s.column_count(), 0);
  for (bool changed = true, first_pass = true; changed; first_pass = false) {
    changed = false;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const std::array<std::size_t, 4> cols = columns_at(x, z);
        const auto [col, col_x, col_z, col_xz] = cols;
        const bool last = first_pass ? filled_last[col] != 0
                                     : (filled_last[col] | filled_last[col_x] | filled_last[col_z] | filled_last[col_xz]) != 0;
        if (!last && !(filled_now[col] | filled_now[col_x] | filled_now[col_z] | filled_now[col_xz])) continue;
        Block b = block_at(x, z, cols);
        if (!can_fill(b)) continue;
        bool filled = false;
        const auto fill = [&](std::uint8_t& p, std::uint8_t& q, std::uint8_t& r, std::uint8_t& t) {
          if (!settle(p, q, r, t)) return;
          filled = true;
          b.check_y = b.cxz != nullptr, b.check_z = b.cx != nullptr, b.check_x = b.cz != nullptr;
        };
        for (int y = y_lo; y <= y_end; ++y) {
          if (b.check_y) fill(b.c[y], b.cxz[y], b.cx[y], b.cz[y]);  // edge along y
          if (y + 1 < s.ny) {
            if (b.check_z) fill(b.c[y], b.cx[y + 1], b.cx[y], b.c[y + 1]);  // edge along z
            if (b.check_x) fill(b.c[y], b.cz[y + 1], b.cz[y], b.c[y + 1]);  // edge along x
          }
        }
        if (filled) {
          changed = true;
          filled_now[col] = filled_now[col_x] = filled_now[col_z] = filled_now[col_xz] = 1;
          if (memo) filled_any[col] = filled_any[col_x] = filled_any[col_z] = filled_any[col_xz] = 1;
        }
      }
    filled_last.swap(filled_now);
    std::fill(filled_now.begin(), filled_now.end(), std::uint8_t{0});
  }
  if (memo) {
    if (from_memo) {  // where this filled volume may differ from the last one
      out.may_differ = changed;
      for (std::size_t col = 0; col < out.may_differ.size(); ++col) out.may_differ[col] |= memo->filled[col] | filled_any[col];
    }
    memo->filled = std::move(filled_any);
    memo->spec = s;
  }
  return out;
}

BoundsMesh build_bounds(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                        const std::vector<std::uint8_t>& room, const BoundsParams& params, unsigned threads,
                        std::stop_token stop) {
  const BoundsStorey storey{levels, y_end, &room};
  return build_bounds(grid, std::span(&storey, 1), params, threads, std::move(stop));
}

std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, std::span<const BoundsStorey> storeys,
                                        const BoundsParams& params, unsigned threads, const std::stop_token& stop) {
  const detail::StagePool pool(threads);
  return detail::bounds_volume(grid, storeys, params, threads, stop, nullptr);
}

std::vector<std::uint8_t> detail::bounds_volume(const VoxelGrid& grid, std::span<const BoundsStorey> storeys,
                                                const BoundsParams& params, unsigned threads,
                                                const std::stop_token& stop, MeshMemo* memo) {
  // With a memo of this grid's previous cells: the columns whose cells changed since (a byte each). The memo
  // holds no cells until every storey's volume is kept again: a stop on the way leaves the next volume whole.
  std::optional<std::vector<std::uint8_t>> changed;
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> previous_cells;
  if (memo) previous_cells = std::exchange(memo->volume_cells, {});
  if (memo && memo->volume_spec == s && previous_cells.size() == grid.cells.size())
    changed = detail::changed_columns(std::size_t(s.ny), previous_cells, grid.cells);
  if (memo) memo->storey_volumes.resize(storeys.size());
  // The first storey's volume, the others' or-ed into it.
  std::vector<std::uint8_t> volume;
  for (std::size_t k = 0; k < storeys.size(); ++k) {
    const BoundsStorey& storey = storeys[k];
    std::vector<std::uint8_t> part = storey_volume(grid, storey, *storey.room, params, threads, stop,
                                                   memo ? &memo->storey_volumes[k] : nullptr, changed ? &*changed : nullptr);
    // By iterators: a loop over volume[i] reloads the vector's size and data after each byte it stores (a byte
    // may alias them), and is not vectorized.
    if (volume.empty()) {
      volume = std::move(part);
    } else {
      std::transform(volume.begin(), volume.end(), part.begin(), volume.begin(), std::bit_or<>());
      if (memo) memo->storey_volumes[k].give_back(std::move(part));
    }
    stop_point(stop);
  }
  if (volume.empty()) volume.assign(grid.spec.voxel_count(), 0);
  if (memo) {
    memo->volume_spec = s;
    previous_cells.assign(grid.cells.begin(), grid.cells.end());  // its storage, not a new allocation
    memo->volume_cells = std::move(previous_cells);
  }
  return volume;
}

std::vector<std::uint8_t> room_bounds_volume(const VoxelGrid& grid, const BoundsStorey& storey,
                                             const std::vector<std::uint8_t>& room_columns, const BoundsParams& params,
                                             unsigned threads, const std::stop_token& stop) {
  const detail::StagePool pool(threads);
  return detail::room_bounds_volume(grid, storey, room_columns, params, threads, stop, nullptr, nullptr);
}

std::vector<std::uint8_t> detail::room_bounds_volume(const VoxelGrid& grid, const BoundsStorey& storey,
                                                     const std::vector<std::uint8_t>& room_columns,
                                                     const BoundsParams& params, unsigned threads,
                                                     const std::stop_token& stop, StoreyVolumeMemo* memo,
                                                     const std::vector<std::uint8_t>* changed) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> volume = storey_volume(grid, storey, room_columns, params, threads, stop, memo, changed);
  const int lo = std::max(storey.levels.floor, 0), hi = std::min(storey.levels.ceiling, s.ny - 1);
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    if (!(*storey.room)[col] || room_columns[col]) continue;
    std::uint8_t* out = volume.data() + col * std::size_t(s.ny);
    for (int y = lo; y <= hi; ++y) out[y] = 1;
  }
  return volume;
}

BoundsMesh build_room_bounds(const VoxelGrid& grid, const BoundsStorey& storey,
                             const std::vector<std::uint8_t>& room_columns, const BoundsParams& params,
                             unsigned threads, std::stop_token stop) {
  const detail::StagePool pool(threads);
  return detail::build_room_bounds(grid, storey, room_columns, params, threads, std::move(stop), nullptr);
}

BoundsMesh detail::build_room_bounds(const VoxelGrid& grid, const BoundsStorey& storey,
                                     const std::vector<std::uint8_t>& room_columns, const BoundsParams& params,
                                     unsigned threads, std::stop_token stop, MeshMemo* memo) {
  // On the room's columns and a margin only: a room of a large home costs what its own size does. The margin
  // holds the solid around the room (its walls, the next rooms' columns); where the room's free space runs on
  // past it (a window, an unscanned gap), the shell closes at the margin instead of the grid's edge.
  constexpr int kMargin = 2;
  const GridSpec& s = grid.spec;
  int x0 = s.nx, z0 = s.nz, x1 = -1, z1 = -1;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      if (room_columns[s.column(x, z)]) {
        x0 = std::min(x0, x), x1 = std::max(x1, x);
        z0 = std::min(z0, z), z1 = std::max(z1, z);
      }
  if (x1 < 0) return {};
  x0 = std::max(x0 - kMargin, 0), z0 = std::max(z0 - kMargin, 0);
  x1 = std::min(x1 + kMargin, s.nx - 1), z1 = std::min(z1 + kMargin, s.nz - 1);
  GridSpec crop = s;
  crop.nx = x1 - x0 + 1;
  crop.nz = z1 - z0 + 1;
  crop.origin = s.lattice_to_world(float(x0), 0.0f, float(z0));
  // The room's inputs: the grid's and the masks' crops (a row of the crop's columns is one run of the grid's bytes).
  MeshMemo::RoomInputs in{crop,
                          {},  // the cells, row after row below: not zeroed first (every room, every update)
                          std::vector<std::uint8_t>(crop.column_count()),
                          std::vector<std::uint8_t>(crop.column_count()),
                          std::vector<int>(crop.column_count(), storey.levels.ceiling),
                          storey.levels,
                          storey.y_end,
                          std::bit_cast<std::uint32_t>(params.min_plateau_area)};
  if (memo) in.cells = std::exchange(memo->spare_cells, {});  // its storage: a room's crop is a megabyte
  in.cells.clear();
  in.cells.reserve(crop.voxel_count());
  for (int z = 0; z < crop.nz; ++z) {
    const std::uint8_t* row = grid.column_data(x0, z + z0);
    in.cells.insert(in.cells.end(), row, row + std::size_t(crop.nx) * std::size_t(s.ny));
    for (int x = 0; x < crop.nx; ++x) {
      const std::size_t from = s.column(x + x0, z + z0), to = crop.column(x, z);
      in.room[to] = room_columns[from];
      in.storey[to] = (*storey.room)[from];
      if (storey.ceiling != nullptr) in.ceiling[to] = (*storey.ceiling)[from];
    }
  }
  // The room's inputs as they were: its mesh as it was. Else, where the crop is the same, the columns whose
  // cells changed: the room's volume is derived again there alone (StoreyVolumeMemo).
  std::optional<std::vector<std::uint8_t>> changed;
  if (memo) {
    if (memo->room == in) {
      memo->spare_cells = std::move(in.cells);
      return memo->room_mesh;
    }
    if (memo->room && memo->room->crop == crop) changed = detail::changed_columns(std::size_t(s.ny), memo->room->cells, in.cells);
    if (memo->room) memo->spare_cells = std::move(memo->room->cells);
    memo->room.reset();  // kept again below, once the mesh is built
  }
  VoxelGrid part;
  part.spec = crop;
  part.cells = std::move(in.cells);
  BoundsStorey cropped = storey;
  cropped.room = &in.storey;
  cropped.ceiling = &in.ceiling;
  std::vector<std::uint8_t> volume = detail::room_bounds_volume(part, cropped, in.room, params, threads, stop,
                                                                memo ? &memo->room_volume : nullptr,
                                                                changed ? &*changed : nullptr);
  in.cells = std::move(part.cells);
  const detail::FilledVolume filled = detail::fill_edge_contacts(crop, volume, threads, memo ? &memo->contacts : nullptr);
  BoundsMesh mesh = detail::mesh_volume(crop, volume, threads, std::move(stop), memo, &filled);
  if (memo) {
    memo->room_volume.give_back(std::move(volume));
    memo->room = std::move(in), memo->room_mesh = mesh;
  }
  return mesh;
}

BoundsMesh build_bounds(const VoxelGrid& grid, std::span<const BoundsStorey> storeys, const BoundsParams& params,
                        unsigned threads, std::stop_token stop) {
  const detail::StagePool pool(threads);
  return detail::build_bounds(grid, storeys, params, threads, std::move(stop), nullptr);
}

BoundsMesh detail::build_bounds(const VoxelGrid& grid, std::span<const BoundsStorey> storeys,
                                const BoundsParams& params, unsigned threads, std::stop_token stop, MeshMemo* memo) {
  std::vector<std::uint8_t> volume = detail::bounds_volume(grid, storeys, params, threads, stop, memo);
  const detail::FilledVolume filled = detail::fill_edge_contacts(grid.spec, volume, threads, memo ? &memo->contacts : nullptr);
  BoundsMesh mesh = detail::mesh_volume(grid.spec, volume, threads, std::move(stop), memo, &filled);
  if (memo && !memo->storey_volumes.empty()) memo->storey_volumes.front().give_back(std::move(volume));
  return mesh;
}

}  // namespace roomsense
