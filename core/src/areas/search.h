// The searches of §3.3: wall rectangles (Alg. 2) and horizontal squares (Alg. 3) for one size class.
#pragma once
#include "candidate.h"
#include "roomsense/features.h"

#include <bit>
#include <memory>
#include <stop_token>
#include <tuple>

namespace roomsense::detail {

// Per-column prefix counts over y of "has a wall normal" (F != 0) in [floor, ceiling]: shared by the three
// wall searches so each rectangle row costs O(1) per column. Only columns with a normal have counts (walls
// and what stands near them, not the open floor); a byte a count where the room is under 256 levels high
// (every room at the usual voxel sizes), else two; the blocked voxels a bit each.
struct NormalCounts {
  // Per column, one word for Eq. 3.25's test of a cell: where its counts start in prefix8/prefix16 (kNoNormal:
  // it has no normal), and flags: a wall column (no rectangle's cell may lie there) and one with a blocked
  // voxel at some level. The counts' first slot is all zeros, kNoNormal's: a column without a normal counts
  // none without a test (the wall search reads tens of thousands of cells).
  static constexpr std::uint32_t kWallColumn = 1u << 31, kHasBlocked = 1u << 30, kStartBits = kHasBlocked - 1;
  static constexpr std::uint32_t kNoNormal = 0;
  int y0 = 0, levels = 0;               // covers y in [y0, y0 + levels)
  std::vector<std::uint32_t> start;     // per column: where its counts start (kStartBits), and flags
  std::vector<std::uint8_t> prefix8;    // start + (y - y0 + 1): the column's voxels with a normal in [y0, y], when levels < 256
  std::vector<std::uint16_t> prefix16;  // the same, otherwise
  std::size_t blocked_words = 0;        // per column
  std::vector<std::uint64_t> blocked_bits;  // RoomFeatures::wall_blocked, bit y - y0; empty when none is
  // Per level, x and normal bit k (kNormalLeft ... kNormalBackward), a bit per z: the voxels with a normal
  // other than k. Alg. 2 pairs a first corner with every normal but the one opposite a lone normal of its own,
  // so where a second corner may lie is one row, or two for a first corner of two normals, read 64 z at a
  // time (the searches' most frequent read). Empty (z_words 0) for grids under 32 voxels in z, where the rows
  // would outweigh the normals themselves, and rooms without normals.
  std::size_t z_words = 0;
  std::vector<std::uint64_t> z_bits;  // ((y - y0) * nx + x) * 4 + k, then z / 64
  // A rectangle's cells as runs of consecutive columns, counted a run at a time rather than a cell at a time (a
  // wall's top covers some ten cells in one or two runs). Per order of the columns (`along_x`: the columns'
  // own order, x fastest; `along_z`: z fastest, index x * nz + z), the listed columns (those with a normal, and
  // the flagged ones: a wall column, or one with a blocked voxel) ranked in that order, and per rank the counts of
  // the listed columns before it summed level by level, one more slot counting the flagged ones among them. The
  // voxels with a normal of the columns [i, j) of an order in a span are then two ranks and four sums apart; a
  // run holding a flagged column is read cell by cell (usable()). Empty where the two orders' sums would take more
  // bytes than twice the grid's voxels (a room whose every column has a normal): the runs are then read cell by cell.
  struct RunSums {
    std::vector<std::uint32_t> rank;  // per column in the order, and one past the last: listed columns before it
    std::unique_ptr<std::uint32_t[]> sums;  // rank * (levels + 2) + level offset (Levels), then + levels + 1: flagged
  };
  RunSums along_x, along_z;
  std::size_t run_sums_stride() const { return std::size_t(levels) + 2; }  // a rank's sums: levels 0..levels, flagged
  bool has_normal(std::size_t column) const { return (start[column] & kStartBits) != kNoNormal; }
  bool flagged(std::size_t column) const { return (start[column] & ~kStartBits) != 0; }  // a wall column, or blocked
  int count(std::size_t column, int y_from, int y_to) const;  // voxels with a normal in [y_from, y_to]
  // A span of levels [y_from, y_to], found once per rectangle.
  struct Levels {
    std::size_t from, to;  // offsets of the counts below y_from and through y_to
  };
  Levels levels_of(int y_from, int y_to) const { return {std::size_t(y_from - y0), std::size_t(y_to - y0 + 1)}; }
  // Eq. 3.25's test of one cell over a span of levels: false where no rectangle may hold the cell (a wall column,
  // or a blocked voxel in the span), else the voxels with a normal in it in `with_normal`. `prefix`: prefix8's or
  // prefix16's data, whichever the counts are in (the wall search chooses once a rectangle, not once a cell).
  template <class Count>
  bool usable(const Count* prefix, std::size_t column, Levels span, int& with_normal) const;
  // The bit rows a first corner of normals `first` reads (compatible_normals): row k alone (all four normals but
  // k), rows 0 and 1 together (all four), or none. Found once per first corner, not per window.
  struct ZRows {
    int count = 0;  // 0, 1 or 2
    std::size_t k = 0;
  };
  static ZRows z_rows(std::uint8_t first);
  // The bit rows `rows` (z_rows) of the voxels at (x, y); those at (x + dx, y) lie dx * column_words() further
  // (a first corner's second corners are found column by column).
  const std::uint64_t* z_rows_at(int nx, int x, int y, ZRows rows) const {
    return z_bits.data() + ((std::size_t(y - y0) * std::size_t(nx) + std::size_t(x)) * 4 + rows.k) * z_words;
  }
  std::size_t column_words() const { return 4 * z_words; }
  // Where bits z in [z_from, z_from + 64) lie in a bit row: found once for every second corner of a row of first
  // corners where the ring's words start at one dz (a ring under 64 voxels across), not once per word.
  struct ZWindow {
    enum class Kind : std::uint8_t { None, Below, OneWord, TwoWords } kind = Kind::None;  // None: outside the grid
    std::size_t word = 0;
    unsigned shift = 0;
  };
  ZWindow z_window_at(int z_from) const;
  // The window's bits of the voxels whose rows start at `first_row` (z_rows_at) and whose normal Alg. 2 pairs
  // with a first corner whose rows are `rows` (one or two of them).
  std::uint64_t z_window(const std::uint64_t* first_row, ZRows rows, const ZWindow& at) const;
};
NormalCounts count_normals(const GridSpec& spec, const RoomFeatures& features);
// Normals the second corner of a wall rectangle may carry (Alg. 2) when the first carries `first`: the first
// corner's, or one at a right angle to them, so that only corners facing opposite ways are refused.
inline std::uint8_t compatible_normals(std::uint8_t first) {
  std::uint8_t out = first & (kNormalLeft | kNormalRight | kNormalForward | kNormalBackward);
  if (first & (kNormalLeft | kNormalRight)) out |= kNormalForward | kNormalBackward;
  if (first & (kNormalForward | kNormalBackward)) out |= kNormalLeft | kNormalRight;
  return std::uint8_t(out);
}

namespace normal_counts {
// The counts in [span.from, span.to) of a column whose counts start at `start` (kNoNormal: none), in `prefix`.
template <class Count>
int count(const Count* prefix, std::uint32_t start, NormalCounts::Levels span) {
  return int(prefix[start + span.to]) - int(prefix[start + span.from]);
}
inline int count(const NormalCounts& n, std::uint32_t start, NormalCounts::Levels span) {
  return n.prefix8.empty() ? count(n.prefix16.data(), start, span) : count(n.prefix8.data(), start, span);
}
// Any blocked voxel in the span, of a column that has one.
inline bool blocked(const NormalCounts& n, std::size_t column, NormalCounts::Levels span) {
  const std::uint64_t* words = n.blocked_bits.data() + column * n.blocked_words;
  // Bits y - y0, unsigned so that / and % are shifts.
  const std::size_t first = span.from, last = span.to - 1;
  // Bits [first % 64, 63] of the first word, [0, last % 64] of the last, whole words between.
  const std::uint64_t head = ~std::uint64_t{0} << (first % 64), tail = ~std::uint64_t{0} >> (63 - last % 64);
  if (first / 64 == last / 64) return (words[first / 64] & head & tail) != 0;
  if (words[first / 64] & head || words[last / 64] & tail) return true;
  for (std::size_t w = first / 64 + 1; w < last / 64; ++w)
    if (words[w] != 0) return true;
  return false;
}
}  // namespace normal_counts

inline int NormalCounts::count(std::size_t column, int y_from, int y_to) const {
  return normal_counts::count(*this, start[column] & kStartBits, levels_of(y_from, y_to));
}

template <class Count>
bool NormalCounts::usable(const Count* prefix, std::size_t column, Levels span, int& with_normal) const {
  const std::uint32_t word = start[column];
  if ((word & kWallColumn) || ((word & kHasBlocked) && normal_counts::blocked(*this, column, span))) return false;
  with_normal = normal_counts::count(prefix, word & kStartBits, span);
  return true;
}

inline NormalCounts::ZRows NormalCounts::z_rows(std::uint8_t first) {
  constexpr std::uint8_t kAll = kNormalLeft | kNormalRight | kNormalForward | kNormalBackward;
  const std::uint8_t compatible = compatible_normals(first);
  if (compatible == 0) return {};
  // All four normals but k: row k; all four: rows 0 and 1 (a normal other than left, or other than right).
  if (compatible == kAll) return {2, 0};
  return {1, std::size_t(std::countr_zero(unsigned(kAll & ~compatible)))};
}

inline NormalCounts::ZWindow NormalCounts::z_window_at(int z_from) const {
  if (z_from >= int(64 * z_words) || z_from <= -64) return {};
  if (z_from < 0) return {ZWindow::Kind::Below, 0, unsigned(-z_from)};
  const std::size_t w = std::size_t(z_from / 64);
  const unsigned shift = unsigned(z_from % 64);
  return {shift != 0 && w + 1 < z_words ? ZWindow::Kind::TwoWords : ZWindow::Kind::OneWord, w, shift};
}

inline std::uint64_t NormalCounts::z_window(const std::uint64_t* first_row, ZRows rows, const ZWindow& at) const {
  const auto window = [&](const std::uint64_t* row) -> std::uint64_t {
    switch (at.kind) {
      case ZWindow::Kind::None: return 0;
      case ZWindow::Kind::Below: return row[0] << at.shift;
      case ZWindow::Kind::OneWord: return row[at.word] >> at.shift;
      case ZWindow::Kind::TwoWords: return (row[at.word] >> at.shift) | (row[at.word + 1] << (64 - at.shift));
    }
    return 0;
  };
  return rows.count == 2 ? window(first_row) | window(first_row + z_words) : window(first_row);
}

// A search over bands of grid rows (z), for SearchCache (search_cache.h): band b holds rows [b * rows,
// (b + 1) * rows) of a wall search's first corners or a square search's centres (their cell's z), and only
// the bands marked are searched. Each band's rectangles are those it finds searched alone: a square's centre
// lies in one band, but a wall rectangle's centre may be found again by a later band, which the whole
// search would skip (SearchCache drops it). The output says where each band's rectangles end (`pieces`):
// per band for walls, per layer and band (layer-major, as the output) for squares.
// A square search also searches only the centres of a band whose cell's column lies in the band's `columns`
// (the others' squares are as they were); a wall search reads only `searched`.
struct RowBands {
  int rows = 0;
  std::vector<std::uint8_t> searched;  // per band of the grid: 1 to search it
  std::vector<glm::ivec2> columns;     // per band: the columns searched (squares' centres, walls' corners 1), inclusive
  int band(int z) const { return z / rows; }
  bool searches(int z) const { return searched[std::size_t(z / rows)] != 0; }
};
struct Piece {
  int layer = 0, band = 0;
  std::size_t end = 0;  // one past its last rectangle in the output
};
struct RingOffset;
// How the features a floor's or a ceiling's square search reads changed since its previous search: tiles
// (first corners) only lost and walls only added (`Lost`, an object set down), the reverse (`Gained`, one taken
// away), or neither (`Mixed`).
enum class TileChange : std::uint8_t { Mixed, Lost, Gained };
struct BandedSearch {
  const RowBands* bands = nullptr;    // nullptr: the whole grid at once, no pieces
  std::vector<Piece>* pieces = nullptr;
  const std::vector<RingOffset>* ring = nullptr;  // the size's ring_offsets, where the caller keeps them
  // The previous search's rectangles per slot (layer * bands + band), in search order, over the same grid,
  // levels, offsets and shapes; the box of every column whose features the search reads that changed since; and,
  // for squares, how the tiles changed. A wall search then takes a rectangle that reads no changed column from
  // them (search_walls), and a floor's or a ceiling's square search (one square a centre) each centre's previous
  // square where it can (search_squares).
  const std::vector<std::vector<Candidates::Item>>* previous = nullptr;
  glm::ivec2 changed_lo{0}, changed_hi{-1};
  TileChange change = TileChange::Mixed;
  // Furniture's: per level y, whether any column's class at y changed (a first corner there, a tile one level up,
  // or neither; walls: every level), so that a layer whose tiles are as they were finds its previous squares.
  const std::vector<std::uint8_t>* levels_changed = nullptr;
};

// Bits [from, to] of a word, those of them in [0, 63]: the searches' masks of a row's centres or a ring's offsets.
inline std::uint64_t bits_between(int from, int to) {
  from = from < 0 ? 0 : from, to = to > 63 ? 63 : to;
  if (from > to) return 0;
  return (~std::uint64_t{0} >> (63 - to)) & (~std::uint64_t{0} << from);
}

// A wall rectangle's place in search_walls's order: corner 1's z, x and y, then its ring offset (its shape).
using WallSearchOrder = std::tuple<int, int, int, std::uint32_t>;
inline WallSearchOrder wall_search_order(const glm::ivec3& corner1, std::uint32_t shape) {
  return {corner1.z, corner1.x, corner1.y, shape};
}

// Alg. 2 (Eq. 3.20-3.27). Returns the first valid rectangle for each distinct centre, in search order: a
// later rectangle with the same centre would always be dropped by Eq. 3.44, so this changes nothing.
Candidates search_walls(const GridSpec& spec, const RoomFeatures& features, const NormalCounts& normals,
                        const SizeRange& size, float fill, const std::stop_token& stop = {}, BandedSearch banded = {});
// How far a wall search's rectangles reach in z from their first corner, and a square search's cells from
// their centre's cell: the rows around a band whose features its rectangles read.
int wall_search_reach(const SizeRange& size);
int square_search_reach(const SizeRange& size);

enum class Surface { Floor, Ceiling, Furniture };

// Alg. 3 (Eq. 3.28-3.39) on free floor D (Surface::Floor) or free ceiling E (Surface::Ceiling), and its
// furniture variant (§3.3.4, Eq. 3.40/3.41) on every level of C. Same first-per-centre rule as above, trying
// the orientations nearest the room's main direction (`dominant_deg`, see reduce.h) first.
Candidates search_squares(const GridSpec& spec, const RoomFeatures& features, Surface surface,
                          const SizeRange& size, float fill, double dominant_deg = 0.0,
                          const std::stop_token& stop = {}, BandedSearch banded = {});
// The layers a square search works through (furniture levels, or ceiling facets), in its order.
int square_layers(const RoomFeatures& features, Surface surface);

}  // namespace roomsense::detail
