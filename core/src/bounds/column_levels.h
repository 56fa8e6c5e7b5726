// A voxel column's levels read eight at a time: one byte per level (GridSpec::index), the lowest level in the
// lowest byte of a word.
#pragma once
#include <bit>
#include <cstdint>
#include <cstring>

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

}  // namespace roomsense::detail
