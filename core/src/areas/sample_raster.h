// The half-voxel sample cells packing marks (reduce.cpp), as bits: a row of bits per (a, b) cell of a box, so
// that a rectangle's run of samples along a row is tested and marked a 64-bit word at a time. The rows of one a
// exist from the first mark there: memory follows the marked surface, not the box, which may be the grid's.
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace roomsense::detail {

class SampleRaster {
 public:
  // Rows for a in [a_lo, a_hi] and b in [b_lo, b_hi], each with bits c in [c_lo, c_hi] (inclusive bounds).
  SampleRaster(long a_lo, long a_hi, long b_lo, long b_hi, long c_lo, long c_hi)
      : a_lo_(a_lo), b_lo_(b_lo), c_lo_(c_lo),
        na_(std::max(0L, a_hi - a_lo + 1)), nb_(std::max(0L, b_hi - b_lo + 1)),
        words_per_row_(std::max(1L, (c_hi - c_lo + 64) / 64)), nc_(64 * words_per_row_),
        slabs_(std::size_t(na_)) {}

  // Whether any bit c in [c0, c1] of row (a, b) is set; outside the box nothing is.
  bool any(long a, long b, long c0, long c1) const {
    c0 = std::max(c0, c_lo_);
    c1 = std::min(c1, c_lo_ + nc_ - 1);
    if (!inside(a, b) || c0 > c1) return false;
    const std::vector<std::uint64_t>& slab = slabs_[std::size_t(a - a_lo_)];
    if (slab.empty()) return false;
    const std::uint64_t* row = &slab[row_index(b)];
    const std::size_t i0 = std::size_t(c0 - c_lo_), i1 = std::size_t(c1 - c_lo_);
    const std::uint64_t from = ~std::uint64_t{0} << (i0 % 64), to = ~std::uint64_t{0} >> (63 - i1 % 64);
    std::size_t w = i0 / 64;
    const std::size_t last = i1 / 64;
    if (w == last) return (row[w] & from & to) != 0;  // most runs lie in one word
    if (row[w] & from) return true;
    while (++w < last)
      if (row[w] != 0) return true;
    return (row[last] & to) != 0;
  }

  // Whether bit c of row (a, b) is set; outside the box none is.
  bool test(long a, long b, long c) const {
    if (!inside(a, b) || std::size_t(c - c_lo_) >= std::size_t(nc_)) return false;
    const std::vector<std::uint64_t>& slab = slabs_[std::size_t(a - a_lo_)];
    if (slab.empty()) return false;
    const std::size_t i = std::size_t(c - c_lo_);
    return (slab[row_index(b) + i / 64] >> (i % 64)) & 1;
  }

  // Sets bits c in [c0, c1] of row (a, b). The box covers every sample of the candidates it was made for;
  // a sample outside it is a bug in that bound, not something to drop silently.
  void set(long a, long b, long c0, long c1) {
    if (c0 > c1) return;
    if (!inside(a, b) || c0 < c_lo_ || c1 >= c_lo_ + nc_) throw std::logic_error("packing sample outside its raster");
    std::vector<std::uint64_t>& slab = slabs_[std::size_t(a - a_lo_)];
    if (slab.empty()) slab.assign(std::size_t(nb_) * std::size_t(words_per_row_), 0);
    std::uint64_t* row = &slab[row_index(b)];
    for_words(c0 - c_lo_, c1 - c_lo_, [&](std::size_t w, std::uint64_t mask) { row[w] |= mask; });
  }

 private:
  // Row (a, b) in the box: each coordinate's offset from the box's start below its extent, as unsigned (one
  // comparison each, a coordinate below the start wrapping past it).
  bool inside(long a, long b) const {
    return std::size_t(a - a_lo_) < std::size_t(na_) && std::size_t(b - b_lo_) < std::size_t(nb_);
  }
  std::size_t row_index(long b) const { return std::size_t(b - b_lo_) * std::size_t(words_per_row_); }
  // Calls f(word, mask) for the words holding bits [i0, i1] of a row (0 <= i0 <= i1).
  template <class F>
  static void for_words(long i0, long i1, F f) {
    for (long w = i0 / 64; w <= i1 / 64; ++w) {
      const long lo = std::max(i0, 64 * w) - 64 * w, hi = std::min(i1, 64 * w + 63) - 64 * w;
      const std::uint64_t mask = (hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (hi + 1)) - 1) &
                                 ~((std::uint64_t{1} << lo) - 1);
      f(std::size_t(w), mask);
    }
  }

  long a_lo_, b_lo_, c_lo_, na_, nb_, words_per_row_, nc_;  // nc_: bits a row holds
  std::vector<std::vector<std::uint64_t>> slabs_;  // per a: its rows, or empty before its first mark
};

}  // namespace roomsense::detail
