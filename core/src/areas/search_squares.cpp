// Alg. 3: squares on free floor and ceiling tiles (Eq. 3.28-3.39), and on furniture tops (§3.3.4,
// Eq. 3.40/3.41), at any rotation.
#include "../floor_int.h"
#include "cell_cover.h"
#include "ring_offsets.h"
#include "search.h"
#include "roomsense/cancel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

namespace roomsense::detail {
namespace {

// A box of cells, inclusive.
struct CellBox {
  glm::ivec2 lo{0}, hi{-1};
  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
};

// Counts over axis-aligned boxes of cells in O(1) (a summed-area table), over a region of the grid: boxes
// inside it only. `Count` is int for one count, or std::uint64_t for two packed in one (see BadCells).
template <class Count>
class BoxCounts {
 public:
  // The table is written by fill() alone (a search by bands fills a few rows of a large grid).
  BoxCounts(const GridSpec& spec)
      : nx_(spec.nx), nz_(spec.nz),
        sums_(std::make_unique_for_overwrite<Count[]>(std::size_t(nx_ + 1) * std::size_t(nz_ + 1))) {}
  // value(x, z): the column's own count (a bool for 0 or 1).
  template <class Value>
  void fill(const CellBox& region, Value value) {
    const glm::ivec2 lo = region.lo, hi = region.hi;
    for (int x = lo.x; x <= hi.x + 1; ++x) at(x, lo.y) = 0;
    for (int z = lo.y; z <= hi.y; ++z) {
      at(lo.x, z + 1) = 0;
      for (int x = lo.x; x <= hi.x; ++x) at(x + 1, z + 1) = at(x, z + 1) + at(x + 1, z) - at(x, z) + Count(value(x, z));
    }
  }
  // Inlined everywhere: the search calls it from a loop GCC otherwise leaves it outside of (a call per box).
  [[gnu::always_inline]] Count sum(glm::ivec2 lo, glm::ivec2 hi) const {  // inclusive; lo and hi inside the region filled
    return at(hi.x + 1, hi.y + 1) - at(lo.x, hi.y + 1) - at(hi.x + 1, lo.y) + at(lo.x, lo.y);
  }

 private:
  Count& at(int x, int z) { return sums_[std::size_t(z) * std::size_t(nx_ + 1) + std::size_t(x)]; }
  Count at(int x, int z) const { return sums_[std::size_t(z) * std::size_t(nx_ + 1) + std::size_t(x)]; }
  int nx_, nz_;
  std::unique_ptr<Count[]> sums_;
};

// Counts over runs of cells along z in one column in O(1), over a region of the grid: a prefix sum per column,
// its cells one after another. A rotated square's cells are runs of its columns (RingOffset::runs), and a run's
// count reads two entries of one column here where BoxCounts reads four from two rows apart.
template <class Count>
class ColumnCounts {
 public:
  template <class Value>
  void fill(const CellBox& region, Value value) {
    lo_ = region.lo, height_ = std::size_t(region.hi.y - region.lo.y) + 2;
    sums_.resize(std::size_t(region.hi.x - region.lo.x + 1) * height_);
    for (int x = region.lo.x; x <= region.hi.x; ++x) {
      Count* column = sums_.data() + std::size_t(x - lo_.x) * height_;
      Count sum = column[0] = 0;
      for (int z = region.lo.y; z <= region.hi.y; ++z) column[z - region.lo.y + 1] = sum += Count(value(x, z));
    }
  }
  // Cells (x, z_lo) to (x, z_hi), inclusive, inside the region filled.
  Count sum(int x, int z_lo, int z_hi) const {
    const Count* column = sums_.data() + std::size_t(x - lo_.x) * height_;
    return column[z_hi - lo_.y + 1] - column[z_lo - lo_.y];
  }

 private:
  glm::ivec2 lo_{0};
  std::size_t height_ = 0;
  std::vector<Count> sums_;
};

// Eq. 3.30-3.38 read a box's wall cells and unsuitable cells together: both counts in one table, walls in the
// high 32 bits and unsuitable cells in the low. The table's sums are exact modulo 2^64 and a box's counts are
// each below 2^31 (cells of a grid), so a box's sum is exactly walls * 2^32 + unsuitable: one sum for both.
struct BadCells {
  static std::uint64_t of(bool wall, bool unsuitable) { return (wall ? std::uint64_t{1} << 32 : 0) | (unsuitable ? 1 : 0); }
  static int walls(std::uint64_t sum) { return int(sum >> 32); }
  static int unsuitable(std::uint64_t sum) { return int(sum & 0xffffffffu); }
  // Cells that fail every square holding them: a wall, or more unsuitable ones than it may miss.
  static bool fail(std::uint64_t sum, double may_miss) { return walls(sum) > 0 || double(unsuitable(sum)) > may_miss; }
  // For may_miss >= 0, the largest sum that does not fail: sum > most(may_miss) is fail(sum, may_miss) in one integer
  // comparison (a wall puts a sum past 2^32, and the unsuitable count is an integer).
  static std::uint64_t most(double may_miss) { return std::uint64_t(may_miss); }
};

// A bit per cell of the padded tile grid, rows along x, with a spare word after each row: word(x, z) is the
// 64 cells from (x, z) on, for any x in the row, without a bounds check.
class PaddedBits {
 public:
  struct Size {
    int nx, nz;
  };
  explicit PaddedBits(Size size)
      : row_words_(std::size_t(size.nx + 63) / 64 + 1), words_(row_words_ * std::size_t(size.nz), 0) {}
  // Rows [z_lo, z_hi] cleared: those set() wrote since (a layer's region, not the grid).
  void clear(int z_lo, int z_hi) {
    if (z_lo <= z_hi)
      std::fill(words_.begin() + std::ptrdiff_t(std::size_t(z_lo) * row_words_),
                words_.begin() + std::ptrdiff_t(std::size_t(z_hi + 1) * row_words_), std::uint64_t{0});
  }
  void set(int x, int z) { words_[std::size_t(z) * row_words_ + std::size_t(x / 64)] |= std::uint64_t{1} << (x % 64); }
  std::uint64_t word(int x, int z) const {  // x, z >= 0
    const std::uint64_t* w = words_.data() + std::size_t(z) * row_words_ + std::size_t(unsigned(x) / 64);
    // The two words as one of 128 bits, shifted: one double-word shift (x86's shrd), without a branch on the shift
    // (which varies from corner to corner).
    __extension__ typedef unsigned __int128 TwoWords;
    const TwoWords both = TwoWords{w[1]} << 64 | w[0];
    return std::uint64_t(both >> (unsigned(x) % 64));
  }

 private:
  std::size_t row_words_;
  std::vector<std::uint64_t> words_;
};

// One bit per possible centre of one level, indexed by 4 x the centre (Eq. 3.42). The bits exist from the first
// insert until release(): of furniture's many levels, only those with tops and only two at a time need them.
class CentreSet {
 public:
  CentreSet(const GridSpec& spec) : width_(4 * std::size_t(spec.nx)), height_(4 * std::size_t(spec.nz)) {}
  bool contains(glm::ivec3 sum) const { return bits_ && bits_->test(bit(sum)); }
  void insert(glm::ivec3 sum) {
    if (!bits_) bits_.emplace(width_ * height_);
    bits_->set(bit(sum));
  }
  void release() { bits_.reset(); }

 private:
  std::size_t bit(glm::ivec3 sum) const { return std::size_t(sum.z) * width_ + std::size_t(sum.x); }
  std::size_t width_, height_;
  std::optional<BitSet> bits_;
};

// A centre is at most d / √2 from each corner, so corner 1 lies in this box around it (in voxels).
int corner_reach(const SizeRange& size) { return int(std::ceil(size.max_d * 0.7072)) + 1; }

}  // namespace

// The cells a square covers touch its corners' cells or their neighbours.
int square_search_reach(const SizeRange& size) { return corner_reach(size) + 1; }

// The levels searched: one for floors (I_Floor + 1), (I_Floor, I_yEnd] for furniture (Eq. 3.40), whose tops C
// holds as the level above the top voxel (Eq. 3.13). Ceilings: beyond the thesis, each facet of E
// (RoomFeatures::facets) on its own, facet 0 at I_Ceiling - 1 as Eq. 3.39.
int square_layers(const RoomFeatures& features, Surface surface) {
  if (surface == Surface::Ceiling && !features.facets.empty()) return int(features.facets.size());
  return surface == Surface::Furniture ? features.y_end - features.levels.floor : 1;
}

namespace {

// The search whole (kBanded false: the code the full analysis runs, without a test of the bands), or by bands.
template <bool kBanded>
Candidates squares_search(const GridSpec& spec, const RoomFeatures& features, Surface surface,
                          const SizeRange& size, float fill, double dominant_deg, const std::stop_token& stop,
                          BandedSearch banded) {
  // The orientations, split by the parity of dx - dz (= that of dx + dz), most nearly aligned with the room
  // first (with the grid's axes in a room without walls).
  const std::vector<RingOffset> own_ring = banded.ring ? std::vector<RingOffset>() : ring_offsets(size, Shape::Square);
  const std::vector<RingOffset>& ring = banded.ring ? *banded.ring : own_ring;
  const auto misalignment = [&](const RingOffset& o) {
    const double a = std::fmod(std::atan2(double(o.dz), double(o.dx)) * 180.0 / std::numbers::pi + 360.0, 90.0);
    const double d = std::fabs(a - dominant_deg);
    return std::min(d, 90.0 - d);
  };
  // Each offset's misalignment once, not an atan2 per comparison (rings of large squares hold thousands).
  std::vector<std::pair<double, std::size_t>> order(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) order[i] = {misalignment(ring[i]), i};
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // The lists below are sized before they are filled: a large square's ring holds thousands of offsets, and their
  // doublings were most of a search's allocations.
  std::array<std::vector<const RingOffset*>, 2> by_parity;  // into `ring`
  for (auto& parity : by_parity) parity.reserve(ring.size());
  for (const auto& [key, i] : order) by_parity[std::size_t((ring[i].dx - ring[i].dz) & 1)].push_back(&ring[i]);
  const FloorCeiling& levels = features.levels;
  // The layers (square_layers): levels from y_from, or facets.
  const bool by_facet = surface == Surface::Ceiling && !features.facets.empty();
  const int y_from = surface == Surface::Ceiling ? levels.ceiling - 1 : levels.floor + 1;
  const int y_to = surface == Surface::Furniture ? features.y_end : y_from;
  const int layers = square_layers(features, surface);

  // Corner 1 lies in the grid at y_Actual, at most one level above the highest level searched (Eq. 3.41); the
  // offsets are both parities' in turn.
  std::vector<Candidates::Shape> shapes;
  shapes.reserve(ring.size());
  for (const auto& parity : by_parity)
    for (const RingOffset* o : parity) shapes.push_back({o->dx, o->dz, PackedCandidate::kSquare});
  const std::array<std::uint32_t, 2> first_shape = {0, std::uint32_t(by_parity[0].size())};
  int top = y_to;
  if (by_facet)
    for (const auto& facet : features.facets) top = std::max(top, facet.level);
  Candidates out(spec, std::max(top, 0) + 2, std::move(shapes));
  BoxCounts<std::uint64_t> box_bad(spec);  // BadCells
  BoxCounts<int> box_raised(spec), box_first(spec);
  ColumnCounts<std::uint64_t> runs_bad;  // BadCells, as box_bad
  ColumnCounts<int> runs_raised;
  // Every orientation's square holds the disk of radius d_min / 2 around its centre, and so the cells inside
  // the box inscribed in that disk: if those alone hold a wall or too many unsuitable cells, no orientation
  // can be valid.
  const double inner_half = size.min_d / (2.0 * std::numbers::sqrt2) - 0.5;
  // That box's cells along an axis for a centre at c / 2 (half-voxel units): [ceil(c / 2 - inner_half),
  // floor(c / 2 + inner_half)] where it lies in the grid, else empty (lo > hi). Once per coordinate, not per centre
  // (a floor's search visits every centre of the grid).
  const auto inner_spans = [&](int cells) {
    std::vector<glm::ivec2> spans(inner_half >= 0.0 ? 2 * std::size_t(std::max(cells, 0)) : 0);
    for (std::size_t c = 0; c < spans.size(); ++c) {
      const glm::ivec2 span(-floor_int(inner_half - 0.5 * double(c)), floor_int(0.5 * double(c) + inner_half));
      spans[c] = span.x >= 0 && span.y < cells && span.x <= span.y ? span : glm::ivec2(1, 0);
    }
    return spans;
  };
  const std::vector<glm::ivec2> inner_x = inner_spans(spec.nx), inner_z = inner_spans(spec.nz);
  // Eq. 3.30-3.38: the cells a square of offset o may leave unsuitable and still be valid; negative where none is.
  const auto may_miss_of = [&](const RingOffset& o) { return double(o.cells) - double(fill) * (o.d + 1.0) * (o.d + 1.0); };
  double most_missing = -1.0;
  for (const auto& parity : by_parity)
    for (const RingOffset* o : parity) most_missing = std::max(most_missing, may_miss_of(*o));
  const int corner_reach = roomsense::detail::corner_reach(size);
  // Per layer, the centres that already have a square at its level: those of the layer below's squares that rise
  // into it (y_actual for furniture, Eq. 3.41). A layer's own squares at its level need no mark: each centre is
  // visited once a layer.
  std::vector<CentreSet> centres(std::size_t(layers + 1), CentreSet(spec));
  // The corner test, the loop's most frequent, reads bit copies of the tiles and of the first corners, padded by
  // corner_reach on every side, so that each orientation's four corners are constant offsets from the centre's
  // cell: no bounds checks. A centre (cx, cz) on the half-voxel lattice has cx and cz of one parity p; with
  // cx = 2 hx + p, corner 1 is at hx + (p - dx + dz) / 2, an exact division.
  const int pad = corner_reach + 1;
  const PaddedBits::Size padded_size{spec.nx + 2 * pad, spec.nz + 2 * pad};
  PaddedBits first_bits(padded_size), tile_bits(padded_size);
  // Each orientation's corners relative to the centre's cell (cx / 2, cz / 2), in padded bit coordinates; and
  // the box of every cell its square reads (RingOffset::box_lo), relative to the centre's cell.
  struct CornerCells {
    int x[4], z[4];
  };
  struct Reads {
    glm::ivec2 lo, hi;
  };
  std::array<std::vector<CornerCells>, 2> corner_cells;
  std::array<std::vector<Reads>, 2> reads;
  for (int p = 0; p < 2; ++p) {
    corner_cells[std::size_t(p)].reserve(by_parity[std::size_t(p)].size());
    reads[std::size_t(p)].reserve(by_parity[std::size_t(p)].size());
  }
  for (int p = 0; p < 2; ++p)
    for (const RingOffset* o : by_parity[std::size_t(p)]) {
      const int x1 = (p - o->dx + o->dz) / 2, z1 = (p - o->dx - o->dz) / 2;
      corner_cells[std::size_t(p)].push_back({{x1 + pad, x1 + o->dx + pad, x1 + o->dx - o->dz + pad, x1 - o->dz + pad},
                                              {z1 + pad, z1 + o->dz + pad, z1 + o->dz + o->dx + pad, z1 + o->dx + pad}});
      reads[std::size_t(p)].push_back({glm::ivec2(x1, z1) + o->box_lo, glm::ivec2(x1, z1) + o->box_hi});
    }
  // One row of centres: those still open for a square at this level (here) or one level up (above), those open
  // before its orientations were tested (a centre open then and not now found its square), and the orientation
  // each found.
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint64_t> open_here, open_above, opened_here, opened_above;
  std::vector<std::uint32_t> found_here, found_above;
  // From the previous search (BandedSearch::previous): per row, each previous square's (orientation, centre),
  // and the centres past their previous square, whose every orientation is tested.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> events;
  std::vector<std::uint64_t> had, past;
  // Each layer's first corners' box: a centre further than corner_reach from it has no square, and a square
  // around a centre within that reach lies within corner_reach of the centre. So a layer's work, a furniture
  // top's or a facet's, is its box grown by twice the reach, not the grid.
  const auto layer_of = [&](std::size_t col) {  // the layer whose first corner the column may be, or -1
    if (surface == Surface::Floor) return features.free_floor[col] != 0 ? 0 : -1;
    if (surface == Surface::Ceiling)
      return features.free_ceiling[col] == 0 ? -1 : by_facet ? features.ceiling_facet[col] : 0;
    const int f = features.furniture[col];
    return f >= y_from && f <= y_to ? f - y_from : -1;
  };
  std::vector<CellBox> first_box(std::size_t(std::max(layers, 0)),
                                 CellBox{{spec.nx, spec.nz}, {-1, -1}});
  // The first corners looked for: the grid's, or by bands those within corner_reach of a centre searched (a
  // box around the others' first corners would prune no centre searched).
  CellBox scan{{0, 0}, {spec.nx - 1, spec.nz - 1}};
  if constexpr (kBanded) {
    const RowBands& b = *banded.bands;
    CellBox searched;
    for (std::size_t band = 0; band < b.searched.size(); ++band)
      if (b.searched[band]) {
        const glm::ivec2 lo(b.columns[band].x, int(band) * b.rows), hi(b.columns[band].y, (int(band) + 1) * b.rows - 1);
        searched = searched.empty() ? CellBox{lo, hi} : CellBox{glm::min(searched.lo, lo), glm::max(searched.hi, hi)};
      }
    scan = searched.empty() ? CellBox{}
                            : CellBox{glm::max(searched.lo - corner_reach, glm::ivec2(0)),
                                      glm::min(searched.hi + corner_reach, glm::ivec2(spec.nx - 1, spec.nz - 1))};
  }
  // Where a layer of several has too few tiles for any square (no_square, below): a valid square holds all but
  // BadCells::most(may_miss) of its cells as tiles (Eq. 3.30-3.38; the tiles of a furniture square's level and the
  // level above), at least `least_tiles` for the offsets that can be valid at all, within the box of cells its offset
  // reads (RingOffset::box_lo), `square_rows` rows and `square_columns` columns at most. Those boxes lie within
  // `reads_reach` of the centre's cell.
  std::uint64_t least_tiles = std::numeric_limits<std::uint64_t>::max();
  int square_rows = 0, square_columns = 0, reads_reach = 0;
  for (int p = 0; p < 2; ++p)
    for (std::size_t i = 0; i < by_parity[std::size_t(p)].size(); ++i) {
      const Reads& r = reads[std::size_t(p)][i];
      reads_reach = std::max({reads_reach, -r.lo.x, -r.lo.y, r.hi.x, r.hi.y});
      const RingOffset& o = *by_parity[std::size_t(p)][i];
      const double may_miss = may_miss_of(o);
      if (may_miss < 0.0) continue;  // never valid (valid() below)
      least_tiles = std::min(least_tiles, std::uint64_t(o.cells) - std::min(std::uint64_t(o.cells), BadCells::most(may_miss)));
      square_rows = std::max(square_rows, r.hi.y - r.lo.y + 1);
      square_columns = std::max(square_columns, r.hi.x - r.lo.x + 1);
    }
  // The tiles are counted over the scan's box grown to hold every cell a square around a centre searched reads (by
  // bands; the grid's whole otherwise).
  const CellBox count_box = scan.empty() ? scan
                                         : CellBox{glm::max(scan.lo - std::max(reads_reach - corner_reach, 0), glm::ivec2(0)),
                                                   glm::min(scan.hi + std::max(reads_reach - corner_reach, 0),
                                                            glm::ivec2(spec.nx - 1, spec.nz - 1))};
  // Per layer of several, and past the last layer the tiles one level above it: its first corners in each row and
  // in each column of count_box, counted by the scan below.
  const bool counts_tiles = layers > 1 && !count_box.empty();
  const int count_rows = counts_tiles ? count_box.hi.y - count_box.lo.y + 1 : 0;
  const int count_columns = counts_tiles ? count_box.hi.x - count_box.lo.x + 1 : 0;
  std::vector<std::uint32_t> row_tiles(std::size_t(layers + 1) * std::size_t(count_rows), 0);
  std::vector<std::uint32_t> column_tiles(std::size_t(layers + 1) * std::size_t(count_columns), 0);
  // The most tiles of a layer (its first corners and, for furniture, the level above's) in `run` rows (or columns)
  // in a row of count_box's: `counts` and `lines` are row_tiles and count_rows, or column_tiles and count_columns.
  const auto most_in_run = [&](const std::vector<std::uint32_t>& counts, int lines, int layer, int run) {
    const std::uint32_t* own = counts.data() + std::size_t(layer) * std::size_t(lines);
    const std::uint32_t* above = surface == Surface::Furniture ? own + lines : nullptr;
    const auto at = [&](int k) { return own[k] + (above ? above[k] : 0u); };
    std::uint32_t sum = 0, most = 0;
    for (int k = 0; k < lines; ++k) {
      sum += at(k);
      if (k >= run) sum -= at(k - run);
      most = std::max(most, sum);
    }
    return most;
  };
  // Whether no centre searched can hold a square at the layer, so that the layer is not searched: where no
  // square_rows rows (or square_columns columns) in a row hold least_tiles of its tiles; or where none of
  // floor(2 inner_half) + 1 hold the tiles the inner box below needs (w x h cells, each at least floor(2 inner_half)
  // and at most one more, all but most_missing of them tiles). Most furniture tops hold no large square; and by
  // bands, a change away from every large top does not search the large squares' layers (on a HoloLens 2 home, a
  // re-sent block's large furniture search had found none, at up to a millisecond).
  const auto no_square = [&](int layer) {
    if (!counts_tiles) return false;
    const auto most = [&](int rows, int columns) {
      return std::min(most_in_run(row_tiles, count_rows, layer, rows), most_in_run(column_tiles, count_columns, layer, columns));
    };
    if (least_tiles != std::numeric_limits<std::uint64_t>::max() && most(square_rows, square_columns) < least_tiles) return true;
    if (inner_half < 0.0) return false;
    const double side = std::floor(2.0 * inner_half);
    return side * side - double(most(int(side) + 1, int(side) + 1)) > most_missing;
  };
  const auto count_tile = [&](int layer, int x, int z) {
    ++row_tiles[std::size_t(layer) * std::size_t(count_rows) + std::size_t(z - count_box.lo.y)];
    ++column_tiles[std::size_t(layer) * std::size_t(count_columns) + std::size_t(x - count_box.lo.x)];
  };
  // A floor's, a flat ceiling's first corners: each row's first and last alone.
  for (int z = scan.lo.y; z <= scan.hi.y && layers == 1; ++z) {
    int first = scan.lo.x, last = scan.hi.x;
    while (first <= last && layer_of(spec.column(first, z)) != 0) ++first;
    if (first > last) continue;
    while (layer_of(spec.column(last, z)) != 0) --last;
    CellBox& b = first_box[0];
    b.lo = glm::min(b.lo, glm::ivec2(first, z)), b.hi = glm::max(b.hi, glm::ivec2(last, z));
  }
  // Several layers' first corners within the scan's box, and their tiles within count_box (which holds it).
  const auto in_scan = [&](int x, int z) { return x >= scan.lo.x && x <= scan.hi.x && z >= scan.lo.y && z <= scan.hi.y; };
  for (int z = count_box.lo.y; z <= count_box.hi.y && layers > 1; ++z)
    for (int x = count_box.lo.x; x <= count_box.hi.x; ++x) {
      const std::size_t col = spec.column(x, z);
      const int layer = layer_of(col);
      if (surface == Surface::Furniture && features.furniture[col] == y_to + 1) count_tile(layers, x, z);
      if (layer < 0 || layer >= layers) continue;
      count_tile(layer, x, z);
      if (!in_scan(x, z)) continue;
      CellBox& b = first_box[std::size_t(layer)];
      b.lo = glm::min(b.lo, glm::ivec2(x, z)), b.hi = glm::max(b.hi, glm::ivec2(x, z));
    }
  CellBox cleared;  // the rows of the bits set since they were last cleared
  // Per column of a layer's region: a first corner, a tile (a first corner, or raised: one level up, §3.3.4), a wall.
  enum CellKind : std::uint8_t { kFirst = 1, kTile = 2, kRaised = 4, kWall = 8 };
  std::vector<std::uint8_t> kinds;
  // Beyond the thesis (issue 19), furniture's search after a change (BandedSearch::previous): a layer finds what it
  // found where its tiles are as they were (BandedSearch::levels_changed) and the layer below it found what it
  // found (whose rising squares' centres this layer's own squares skip). Each layer's previous squares in the
  // columns searched, band by band; whether the layer below found them again; where this layer's began.
  bool copies_layers = false;
  if constexpr (kBanded) copies_layers = surface == Surface::Furniture && banded.previous && banded.levels_changed;
  const auto previous_squares = [&](int layer, const auto& each) {  // each(item, band), in search order
    if constexpr (kBanded)
      for (std::size_t b = 0; b < banded.bands->searched.size(); ++b) {
        if (!banded.bands->searched[b]) continue;
        const glm::ivec2 columns = banded.bands->columns[b];
        for (const Candidates::Item& item : (*banded.previous)[std::size_t(layer) * banded.bands->searched.size() + b]) {
          const int hx = out.decode(item).corner_sum().x / 4;  // the centre's cell: cx / 2
          if (hx >= columns.x && hx <= columns.y) each(item, int(b));
        }
      }
  };
  bool below_same = true;
  std::size_t layer_begin = 0;
  for (int layer = 0; layer < layers; centres[std::size_t(layer++)].release()) {  // later layers never read it
    const int y1 = by_facet ? features.facets[std::size_t(layer)].level : y_from + layer;
    if (copies_layers) {
      if (layer > 0) {  // the layer below found its previous squares, in order, and no others
        std::size_t at = layer_begin;
        bool same = true;
        previous_squares(layer - 1, [&](const Candidates::Item& item, int) {
          same = same && at < out.size() && out.item(at) == item;
          ++at;
        });
        below_same = same && at == out.size();
      }
      layer_begin = out.size();
      const std::vector<std::uint8_t>& changed_levels = *banded.levels_changed;
      if (below_same && std::size_t(y1) < changed_levels.size() && !changed_levels[std::size_t(y1)]) {
        int band = -1;
        previous_squares(layer, [&](const Candidates::Item& item, int b) {
          if (b != band && band >= 0) banded.pieces->push_back({layer, band, out.size()});
          band = b;
          out.push_item(item);
          const PackedCandidate square = out.decode(item);
          const glm::ivec3 sum = square.corner_sum();
          if (square.corner(0).y != y1) centres[std::size_t(layer + 1)].insert({sum.x, 0, sum.z});
        });
        if (band >= 0) banded.pieces->push_back({layer, band, out.size()});
        continue;
      }
    }
    const CellBox& firsts = first_box[std::size_t(layer)];
    if (firsts.empty() || no_square(layer)) continue;
    CellBox region{glm::max(firsts.lo - 2 * corner_reach - 1, glm::ivec2(0)),
                   glm::min(firsts.hi + 2 * corner_reach + 1, glm::ivec2(spec.nx - 1, spec.nz - 1))};
    // Centres whose cell (cx / 2, cz / 2) lies within corner_reach of the first corners' box; in a row, centre
    // hx_first + i is bit i.
    const glm::ivec2 near_firsts_lo = glm::max(firsts.lo - corner_reach, glm::ivec2(0));
    const glm::ivec2 near_firsts_hi = glm::min(firsts.hi + corner_reach, glm::ivec2(spec.nx - 1, spec.nz - 1));
    // By bands: the rows of centres searched, and the cells their squares read (within corner_reach).
    if constexpr (kBanded) {
      glm::ivec2 lo(spec.nx, spec.nz), hi(-1);
      for (int z = near_firsts_lo.y; z <= near_firsts_hi.y; ++z)
        if (banded.bands->searches(z)) {
          const glm::ivec2 columns = banded.bands->columns[std::size_t(banded.bands->band(z))];
          lo = glm::min(lo, glm::ivec2(columns.x, z)), hi = glm::max(hi, glm::ivec2(columns.y, z));
        }
      if (lo.y > hi.y) continue;
      region.lo = glm::max(region.lo, lo - corner_reach - 1);
      region.hi = glm::min(region.hi, hi + corner_reach + 1);
    }
    // Corner 1 must be a tile of this level; the other cells may also be one level higher (§3.3.4). Each of the
    // region's columns told once (CellKind), then read by the bits and the three tables.
    const int region_width = region.hi.x - region.lo.x + 1;
    kinds.resize(std::size_t(region_width) * std::size_t(region.hi.y - region.lo.y + 1));
    const auto kind = [&](int x, int z) -> std::uint8_t& {
      return kinds[std::size_t(z - region.lo.y) * std::size_t(region_width) + std::size_t(x - region.lo.x)];
    };
    first_bits.clear(cleared.lo.y + pad, cleared.hi.y + pad);
    tile_bits.clear(cleared.lo.y + pad, cleared.hi.y + pad);
    cleared = region;  // what the bits hold next
    for (int z = region.lo.y; z <= region.hi.y; ++z)
      for (int x = region.lo.x; x <= region.hi.x; ++x) {
        const std::size_t col = spec.column(x, z);
        const bool first = layer_of(col) == layer;
        const bool raised = surface == Surface::Furniture && features.furniture[col] == y1 + 1;
        kind(x, z) = std::uint8_t((first ? kFirst : 0) | (first || raised ? kTile : 0) | (raised ? kRaised : 0) |
                                  (features.walls[col] != 0 ? kWall : 0));
        if (first || raised) tile_bits.set(x + pad, z + pad);
        if (first) first_bits.set(x + pad, z + pad);
      }
    const auto bad_cell = [&](int x, int z) {  // walls are never tiles
      const std::uint8_t k = kind(x, z);
      return BadCells::of((k & kWall) != 0, (k & kTile) == 0);
    };
    box_bad.fill(region, bad_cell);
    runs_bad.fill(region, bad_cell);
    box_first.fill(region, [&](int x, int z) { return (kind(x, z) & kFirst) != 0; });
    if (surface == Surface::Furniture) {
      const auto raised_cell = [&](int x, int z) { return (kind(x, z) & kRaised) != 0; };
      box_raised.fill(region, raised_cell);
      runs_raised.fill(region, raised_cell);
    }
    CentreSet& here = centres[std::size_t(layer)];
    CentreSet& above = centres[std::size_t(layer + 1)];
    const bool may_rise = surface == Surface::Furniture;
    // Beyond the thesis (issue 19), a search after a change, from the previous search's squares (one a centre:
    // not furniture's, whose centres may hold one a level). A square that reads no changed column is as valid
    // as it was: the orientations before a centre's previous square are tested only where they read a changed
    // column, and its previous square, where it reads none, is its square again. Validity (Eq. 3.30-3.38) only
    // falls as tiles are lost and walls added, and only rises the other way: where tiles were only lost, no
    // orientation before the previous square is tested, and a centre that had none has none; where they were
    // only gained, the previous square is valid still.
    bool from_previous = false;
    TileChange change = TileChange::Mixed;
    glm::ivec2 changed_lo(0), changed_hi(-1);
    if constexpr (kBanded)
      if (banded.previous && !may_rise)
        from_previous = true, change = banded.change, changed_lo = banded.changed_lo, changed_hi = banded.changed_hi;
    std::size_t cursor = 0;  // into the previous squares of the band searched

    // Eq. 3.30-3.38 for the square with first corner (x1, z1) and offset o: every cell it reaches into; none a
    // wall, 95 % of (d + 1)² suitable. Where the square's bounding box holds only tiles, all its cells are
    // suitable; otherwise count them, giving up once more cells are unsuitable than the 95 % allow. Returns
    // whether it is valid, and in `rises` whether a cell is one level higher (y_Actual, Eq. 3.41).
    const auto valid = [&](int x1, int z1, const RingOffset& o, bool& rises) {
      const double may_miss = may_miss_of(o);
      if (may_miss < 0.0) return false;
      const std::uint64_t most_bad = BadCells::most(may_miss);
      rises = false;
      const glm::ivec2 box_lo = glm::ivec2(x1, z1) + o.box_lo, box_hi = glm::ivec2(x1, z1) + o.box_hi;
      const bool box_inside = box_lo.x >= 0 && box_lo.y >= 0 && box_hi.x < spec.nx && box_hi.y < spec.nz;
      const auto rises_in_runs = [&] {
        if (may_rise && box_raised.sum(box_lo, box_hi) > 0)
          for (const CellRun& run : o.runs)
            rises = rises || runs_raised.sum(x1 + run.dx, z1 + run.dz_lo, z1 + run.dz_hi) > 0;
        return true;
      };
      const std::uint64_t bad_in_box = box_inside ? box_bad.sum(box_lo, box_hi) : 0;
      if (box_inside && bad_in_box == 0) return rises_in_runs();  // walls are unsuitable: none of either
      // The box of whole columns inside the square (RingOffset::core_lo): a wall or too many unsuitable cells
      // there fail the square at once.
      const glm::ivec2 core_lo = glm::ivec2(x1, z1) + o.core_lo, core_hi = glm::ivec2(x1, z1) + o.core_hi;
      if (core_lo.x <= core_hi.x && box_bad.sum(core_lo, core_hi) > most_bad) return false;
      // Where the bounding box holds no wall and no more unsuitable cells than allowed, neither do the cells.
      if (box_inside && bad_in_box <= most_bad) return rises_in_runs();
      std::uint64_t bad = 0;  // the runs' so far, both counts (BadCells)
      for (const CellRun& run : o.runs) {
        const int x = x1 + run.dx, lo = z1 + run.dz_lo, hi = z1 + run.dz_hi;  // inside: the corners are
        bad += runs_bad.sum(x, lo, hi);
        if (bad > most_bad) return false;
        if (may_rise && !rises) rises = runs_raised.sum(x, lo, hi) > 0;
      }
      return true;
    };

    // Eq. 3.44 keeps one square per centre, so each centre on the half-voxel lattice where square centres lie
    // takes the first valid orientation, most nearly axis-aligned first: the same centres as the thesis's loop
    // over first corners, found without trying every orientation of each. A row of centres (one cz, cx of its
    // parity) is searched at once: each orientation's corner test (corner 1 a first corner, the others tiles)
    // is four shifted words of the padded bit rows for 64 centres, and only the centres that pass it and are
    // still open are checked cell by cell. Each centre's squares are then added in orientation order, centre
    // by centre along the row, as a loop over centres would add them.
    const int cz_last = std::min(2 * near_firsts_hi.y + 1, 2 * (spec.nz - 1));
    int band = -1;  // by bands: the band of the rows searched last in this layer
    for (int cz = 2 * near_firsts_lo.y; cz <= cz_last; ++cz, stop_point(stop)) {
      if constexpr (kBanded) {
        const int b = banded.bands->band(cz / 2);
        if (!banded.bands->searches(cz / 2)) continue;
        if (b != band && band >= 0) banded.pieces->push_back({layer, band, out.size()});
        if (b != band) cursor = 0;
        band = b;
      }
      const int p = cz & 1;  // dx - dz and dx + dz share their parity: cx - cz is even
      int hx_first = near_firsts_lo.x, hx_last = std::min(near_firsts_hi.x, spec.nx - 1 - p);  // cx = 2 hx + p
      if constexpr (kBanded) {
        const glm::ivec2 columns = banded.bands->columns[std::size_t(band)];
        hx_first = std::max(hx_first, columns.x), hx_last = std::min(hx_last, columns.y);
      }
      const int centres_in_row = hx_last - hx_first + 1;
      if (centres_in_row <= 0) continue;
      const std::size_t words = (std::size_t(centres_in_row) + 63) / 64;
      const std::vector<const RingOffset*>& orientations = by_parity[std::size_t(p)];
      const std::vector<CornerCells>& cells = corner_cells[std::size_t(p)];
      const std::vector<Reads>& row_reads = reads[std::size_t(p)];
      const int hz = cz / 2;
      events.clear();
      had.assign(words, 0);
      bool row_reads_changed = false;  // whether a square of the row may read a changed column
      if constexpr (kBanded)
        if (from_previous) {
          // The row's previous squares (the slot's are in search order: by cz, then cx), each centre's one.
          const std::vector<Candidates::Item>& before =
              (*banded.previous)[std::size_t(layer) * banded.bands->searched.size() + std::size_t(band)];
          for (; cursor < before.size(); ++cursor) {
            const glm::ivec3 sum = out.decode(before[cursor]).corner_sum();  // (2 cx, ., 2 cz)
            if (sum.z / 2 > cz) break;
            const int c = sum.x / 4 - hx_first;  // cx / 2 = hx
            if (sum.z / 2 != cz || c < 0 || c >= centres_in_row) continue;
            events.push_back({before[cursor].shape - first_shape[std::size_t(p)], std::uint32_t(c)});
            had[std::size_t(c / 64)] |= std::uint64_t{1} << (c % 64);
          }
          std::sort(events.begin(), events.end());
          for (const Reads& r : row_reads)
            row_reads_changed = row_reads_changed || (hz + r.lo.y <= changed_hi.y && hz + r.hi.y >= changed_lo.y);
        }
      open_here.assign(words, 0);
      open_above.assign(words, 0);
      // The row's parts of the boxes below.
      const int near_z_lo = std::max(hz - corner_reach, 0), near_z_hi = std::min(hz + corner_reach, spec.nz - 1);
      const glm::ivec2 in_z = inner_z.empty() ? glm::ivec2(1, 0) : inner_z[std::size_t(cz)];
      for (int i = 0; i < centres_in_row; ++i) {
        const int hx = hx_first + i;
        const int cx = 2 * hx + p;
        const std::uint64_t bit = std::uint64_t{1} << (i % 64);
        // From the previous search: a centre that had a square is open, untested (its square is found again
        // cheaply); one that had none has none, unless tiles may have been gained where its row's squares read.
        if (from_previous && (had[std::size_t(i / 64)] & bit)) {
          open_here[std::size_t(i / 64)] |= bit;
          continue;
        }
        if (from_previous && (change == TileChange::Lost || !row_reads_changed)) continue;
        const glm::ivec2 near_lo(std::max(hx - corner_reach, 0), near_z_lo);
        const glm::ivec2 near_hi(std::min(hx + corner_reach, spec.nx - 1), near_z_hi);
        if (box_first.sum(near_lo, near_hi) == 0) continue;  // no first corner anywhere near: no square
        if (in_z.x <= in_z.y) {
          const glm::ivec2 in_x = inner_x[std::size_t(cx)];
          if (in_x.x <= in_x.y && BadCells::fail(box_bad.sum({in_x.x, in_z.x}, {in_x.y, in_z.y}), most_missing)) continue;
        }
        const glm::ivec3 sum(2 * cx, 0, 2 * cz);
        if (!here.contains(sum)) open_here[std::size_t(i / 64)] |= bit;
        if (may_rise && !above.contains(sum)) open_above[std::size_t(i / 64)] |= bit;
      }
      opened_here = open_here, opened_above = open_above;
      // Read only where a centre found its square: not cleared.
      if (found_here.size() < std::size_t(centres_in_row))
        found_here.resize(std::size_t(centres_in_row)), found_above.resize(std::size_t(centres_in_row));
      if (from_previous) past.assign(words, 0);
      std::size_t next = 0;  // the first event not yet taken
      for (std::size_t i = 0; i < orientations.size(); ++i) {
        const CornerCells& k = cells[i];
        // The centres hx in [reads_from, reads_to] have a square at i that reads a changed column.
        int reads_from = 1, reads_to = 0;
        if (row_reads_changed && hz + row_reads[i].lo.y <= changed_hi.y && hz + row_reads[i].hi.y >= changed_lo.y)
          reads_from = changed_lo.x - row_reads[i].hi.x, reads_to = changed_hi.x - row_reads[i].lo.x;
        for (; next < events.size() && events[next].first == i; ++next) {
          const std::uint32_t c = events[next].second;
          const std::uint64_t bit = std::uint64_t{1} << (c % 64);
          if (!(open_here[c / 64] & bit)) continue;
          const int hx = hx_first + int(c);
          if (change == TileChange::Gained || hx < reads_from || hx > reads_to) {
            open_here[c / 64] &= ~bit;
            found_here[c] = std::uint32_t(i);
          } else {
            past[c / 64] |= bit;
          }
        }
        bool any_open = false, any_past = false;
        for (std::size_t w = 0; w < words; ++w) {
          std::uint64_t open = open_here[w] | open_above[w];
          if (open == 0) continue;
          any_open = true;
          const int x = hx_first + int(64 * w);  // the word's first centre
          if (from_previous) {  // without one, every centre is tested
            any_past = any_past || past[w] != 0;
            std::uint64_t tested = past[w];
            if (change != TileChange::Lost) tested |= bits_between(reads_from - x, reads_to - x);
            open &= tested;
            if (open == 0) continue;
          }
          open &= first_bits.word(x + k.x[0], hz + k.z[0]) & tile_bits.word(x + k.x[1], hz + k.z[1]) &
                  tile_bits.word(x + k.x[2], hz + k.z[2]) & tile_bits.word(x + k.x[3], hz + k.z[3]);
          for (; open != 0; open &= open - 1) {
            const int b = std::countr_zero(open);
            const std::uint64_t bit = std::uint64_t{1} << b;
            const RingOffset& o = *orientations[i];
            const int x1 = x + b + k.x[0] - pad, z1 = hz + k.z[0] - pad;  // corner 1 from the centre's cell
            bool rises = false;
            if (!valid(x1, z1, o, rises)) continue;
            std::uint64_t& needed = rises ? open_above[w] : open_here[w];
            if (!(needed & bit)) continue;
            needed &= ~bit;
            (rises ? found_above : found_here)[64 * w + std::size_t(b)] = std::uint32_t(i);
          }
        }
        if (!any_open) break;
        // Nothing is tested before the next previous square's orientation.
        if (from_previous && !any_past && (change == TileChange::Lost || !row_reads_changed)) {
          if (next == events.size()) break;
          i = events[next].first - 1;
        }
      }
      // The centres that found a square, in order along the row (most of a row's found none).
      for (std::size_t w = 0; w < words; ++w) {
        const std::uint64_t here_found = opened_here[w] & ~open_here[w], above_found = opened_above[w] & ~open_above[w];
        for (std::uint64_t found = here_found | above_found; found != 0; found &= found - 1) {
          const int b = std::countr_zero(found);
          const int i = int(64 * w) + b;
          const std::uint32_t h = (here_found >> b) & 1 ? found_here[std::size_t(i)] : kNone;
          const std::uint32_t a = (above_found >> b) & 1 ? found_above[std::size_t(i)] : kNone;
          const int hx = hx_first + i, cx = 2 * hx + p;
          const glm::ivec3 sum(2 * cx, 0, 2 * cz);
          const auto add = [&](std::uint32_t orientation, bool rises) {
            const CornerCells& k = cells[orientation];  // corner 1 from the centre's cell, padded
            const int x1 = hx + k.x[0] - pad, z1 = hz + k.z[0] - pad;
            if (rises) above.insert(sum);
            const int y = rises ? y1 + 1 : y1;  // y_Actual, Eq. 3.41
            out.push_back(glm::ivec3(x1, y, z1), first_shape[std::size_t(p)] + orientation);
          };
          if (h != kNone && (a == kNone || h < a)) add(h, false);
          if (a != kNone) add(a, true);
          if (h != kNone && a != kNone && h > a) add(h, false);
        }
      }
    }
    if constexpr (kBanded)
      if (band >= 0) banded.pieces->push_back({layer, band, out.size()});
  }
  return out;
}

}  // namespace

Candidates search_squares(const GridSpec& spec, const RoomFeatures& features, Surface surface,
                          const SizeRange& size, float fill, double dominant_deg, const std::stop_token& stop,
                          BandedSearch banded) {
  return banded.bands ? squares_search<true>(spec, features, surface, size, fill, dominant_deg, stop, banded)
                      : squares_search<false>(spec, features, surface, size, fill, dominant_deg, stop, banded);
}

}  // namespace roomsense::detail
