// A voxel column's levels read eight at a time: one byte per level (GridSpec::index), the lowest level in the
// lowest byte of a word; and the box of a volume's solid voxels, found with them.
#pragma once
#include "roomsense/grid.h"
#include "../parallel.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

namespace roomsense::detail {

static_assert(std::endian::native == std::endian::little);
inline std::uint64_t eight_levels(const std::uint8_t* v, int y) {
  std::uint64_t w;
  std::memcpy(&w, v + y, 8);
  return w;
}
// The lowest level in [from, to) holding a voxel of column `v`; `to` where none does.
inline int lowest_solid(const std::uint8_t* v, int from, int to) {
  if (to - from < 8) {
    for (; from < to; ++from)
      if (v[from]) return from;
    return to;
  }
  // Whole words, then the last eight levels (those it shares with the words read are empty).
  for (; from + 8 <= to; from += 8)
    if (const std::uint64_t w = eight_levels(v, from)) return from + std::countr_zero(w) / 8;
  if (const std::uint64_t w = from < to ? eight_levels(v, to - 8) : 0) return to - 8 + std::countr_zero(w) / 8;
  return to;
}
// The highest level in (below, to] holding a voxel of column `v`; `below` where none does.
inline int highest_solid(const std::uint8_t* v, int below, int to) {
  if (to - below < 8) {
    for (; to > below; --to)
      if (v[to]) return to;
    return below;
  }
  // Whole words, then the first eight levels above `below` (those it shares with the words read are empty).
  for (; to - 8 >= below; to -= 8)
    if (const std::uint64_t w = eight_levels(v, to - 7)) return to - 7 + (63 - std::countl_zero(w)) / 8;
  if (const std::uint64_t w = to > below ? eight_levels(v, below + 1) : 0)
    return below + 1 + (63 - std::countl_zero(w)) / 8;
  return below;
}

// The box of a volume's solid voxels (one byte per voxel, GridSpec::index): meshing stops at its faces (outside it
// every mask entry is 0), and the edge contacts read only its levels.
struct SolidBox {
  int lo[3], hi[3];  // inclusive; hi < lo when empty
  bool operator==(const SolidBox&) const = default;
};
// Rows of columns side by side, each slice's box joined after: minima and maxima, in any order.
inline SolidBox solid_box(const GridSpec& s, const std::vector<std::uint8_t>& volume, unsigned threads) {
  const SolidBox kEmpty{{s.nx, s.ny, s.nz}, {-1, -1, -1}};
  std::vector<SolidBox> parts(parallel_slices(std::size_t(s.nz), threads, kRowGrain), kEmpty);
  parallel_for(std::size_t(s.nz), threads, kRowGrain, [&](std::size_t z_begin, std::size_t z_end, std::size_t slice) {
    // Kept in this thread's registers and stored once: the slices' boxes share cache lines, and a store per column
    // to them made the two workers pass the line back and forth (solid_box of thesis-room1's bounds: ~45 us, not ~9).
    SolidBox box = kEmpty;
    for (int z = int(z_begin); z < int(z_end); ++z)
      for (int x = 0; x < s.nx; ++x) {
        // A column's lowest and highest solid voxels: found from either end, most columns' first.
        const std::uint8_t* v = volume.data() + s.column(x, z) * std::size_t(s.ny);
        const int first = lowest_solid(v, 0, s.ny);
        if (first == s.ny) continue;
        const int lo[3] = {x, first, z}, hi[3] = {x, highest_solid(v, first, s.ny - 1), z};
        for (int k = 0; k < 3; ++k) {
          box.lo[k] = std::min(box.lo[k], lo[k]);
          box.hi[k] = std::max(box.hi[k], hi[k]);
        }
      }
    parts[slice] = box;
  });
  SolidBox box = kEmpty;
  for (const SolidBox& part : parts)
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], part.lo[k]), box.hi[k] = std::max(box.hi[k], part.hi[k]);
  return box;
}

}  // namespace roomsense::detail
