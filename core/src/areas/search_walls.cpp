// Alg. 2: wall rectangles between two voxels with compatible normals (Eq. 3.20-3.27).
#include "../key_table.h"
#include "cell_cover.h"
#include "ring_offsets.h"
#include "search.h"
#include "roomsense/cancel.h"
#include "roomsense/error.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <limits>
#include <tuple>

namespace roomsense::detail {

NormalCounts count_normals(const GridSpec& spec, const RoomFeatures& features) {
  NormalCounts n;
  n.y0 = features.levels.floor;
  // 16-bit counts at most: a room taller than 65535 voxels has no wall areas above that.
  n.levels = std::min({features.levels.ceiling - n.y0 + 1, spec.ny - n.y0,
                       int(std::numeric_limits<std::uint16_t>::max())});
  const std::size_t stride = std::size_t(n.levels + 1);
  const auto normals_of = [&](std::size_t col) { return features.normals.data() + col * std::size_t(spec.ny) + n.y0; };
  n.start.assign(spec.column_count(), NormalCounts::kNoNormal);
  // Slot 0 is kNoNormal's zeros (where there are levels to count).
  std::size_t slots = n.levels > 0 ? 1 : 0, columns_with_normal = 0;
  for (std::size_t col = 0; col < spec.column_count() && n.levels > 0; ++col) {
    const std::uint8_t* f = normals_of(col);
    if (!std::any_of(f, f + n.levels, [](std::uint8_t v) { return v != 0; })) continue;
    // Starts below 2^30 (kStartBits): counts of 2^30 voxels, past any voxel budget the pipeline takes, would not fit.
    if ((slots + 1) * stride >= NormalCounts::kStartBits)
      throw Error(ErrorCode::GridTooLarge, "the wall search counts the normals of at most 2^30 - 2 voxels");
    n.start[col] = std::uint32_t(slots++ * stride);
    ++columns_with_normal;
  }
  const auto prefix_of = [&]<class Count>(std::vector<Count>& prefix) {
    prefix.assign(std::size_t(slots) * stride, 0);
    for (std::size_t col = 0; col < spec.column_count(); ++col) {
      if (!n.has_normal(col)) continue;
      const std::uint8_t* f = normals_of(col);
      Count* p = prefix.data() + (n.start[col] & NormalCounts::kStartBits);
      for (int i = 0; i < n.levels; ++i) p[i + 1] = Count(p[i] + (f[i] != 0 ? 1 : 0));
    }
  };
  if (n.levels < 256) prefix_of(n.prefix8);
  else prefix_of(n.prefix16);
  // The bit rows take 4 * 64 bits per (level, x) for every 64 z: at most the normals' own bytes from 32 z on.
  // Shallower grids (and rooms without normals) go without them.
  n.z_words = columns_with_normal > 0 && spec.nz >= 32 ? std::size_t(spec.nz + 63) / 64 : 0;
  n.z_bits.assign(std::size_t(std::max(n.levels, 0)) * std::size_t(spec.nx) * 4 * n.z_words, 0);
  for (std::size_t col = 0; col < spec.column_count() && n.z_words > 0; ++col) {
    if (!n.has_normal(col)) continue;
    const int x = int(col % std::size_t(spec.nx)), z = int(col / std::size_t(spec.nx));
    const std::uint8_t* f = normals_of(col);
    for (int i = 0; i < n.levels; ++i)
      for (int k = 0; k < 4; ++k)
        if (f[i] & ~(1 << k) & 0xf)
          n.z_bits[((std::size_t(i) * std::size_t(spec.nx) + std::size_t(x)) * 4 + std::size_t(k)) * n.z_words +
                   std::size_t(z / 64)] |= std::uint64_t{1} << (z % 64);
  }
  if (!features.wall_blocked.empty()) {
    n.blocked_words = std::size_t(n.levels + 63) / 64;
    n.blocked_bits.assign(spec.column_count() * n.blocked_words, 0);
    for (std::size_t col = 0; col < spec.column_count(); ++col) {
      const std::uint8_t* b = features.wall_blocked.data() + col * std::size_t(spec.ny) + n.y0;
      // Most columns have no opening before them: found in one pass the compiler vectorizes.
      std::uint8_t any = 0;
      for (int i = 0; i < n.levels; ++i) any |= b[i];
      if (any == 0) continue;
      std::uint64_t* words = n.blocked_bits.data() + col * n.blocked_words;
      for (int i = 0; i < n.levels; ++i)
        if (b[i] != 0) words[i / 64] |= std::uint64_t{1} << (i % 64);
      if (std::any_of(words, words + n.blocked_words, [](std::uint64_t w) { return w != 0; }))
        n.start[col] |= NormalCounts::kHasBlocked;
    }
  }
  for (std::size_t col = 0; col < std::min(spec.column_count(), features.walls.size()); ++col)
    if (features.walls[col]) n.start[col] |= NormalCounts::kWallColumn;
  // The run sums of both orders, where their sums' bytes stay within twice the grid's voxels.
  const auto listed = [&](std::size_t col) { return n.has_normal(col) || n.flagged(col); };
  std::size_t listed_columns = 0;
  for (std::size_t col = 0; col < spec.column_count(); ++col) listed_columns += listed(col) ? 1 : 0;
  const std::size_t sums_stride = n.run_sums_stride();
  if (n.levels > 0 && 2 * 4 * (listed_columns + 1) * sums_stride <= 2 * spec.voxel_count()) {
    const auto run_sums = [&]<class Count>(const std::vector<Count>& prefix, NormalCounts::RunSums& out,
                                           bool z_fastest) {
      out.rank.resize(spec.column_count() + 1);
      out.sums = std::make_unique_for_overwrite<std::uint32_t[]>((listed_columns + 1) * sums_stride);
      std::fill_n(out.sums.get(), sums_stride, 0u);  // rank 0: no column before it
      std::uint32_t rank = 0;
      std::size_t i = 0;  // the column's index in the order
      const auto add = [&](std::size_t col) {
        out.rank[i++] = rank;
        if (!listed(col)) return;
        const std::uint32_t* before = out.sums.get() + std::size_t(rank) * sums_stride;
        std::uint32_t* after = out.sums.get() + std::size_t(++rank) * sums_stride;
        const Count* counts = prefix.data() + (n.start[col] & NormalCounts::kStartBits);
        for (std::size_t l = 0; l <= std::size_t(n.levels); ++l) after[l] = before[l] + counts[l];
        after[sums_stride - 1] = before[sums_stride - 1] + (n.flagged(col) ? 1 : 0);
      };
      if (z_fastest) {
        for (int x = 0; x < spec.nx; ++x)
          for (int z = 0; z < spec.nz; ++z) add(spec.column(x, z));
      } else {
        for (std::size_t col = 0; col < spec.column_count(); ++col) add(col);
      }
      out.rank[spec.column_count()] = rank;
    };
    for (const bool z_fastest : {false, true}) {
      NormalCounts::RunSums& out = z_fastest ? n.along_z : n.along_x;
      if (n.levels < 256) run_sums(n.prefix8, out, z_fastest);
      else run_sums(n.prefix16, out, z_fastest);
    }
  }
  return n;
}

// A rectangle's cells lie between its corners, |dz| <= max_d, and may touch one more row each way.
int wall_search_reach(const SizeRange& size) { return int(std::floor(size.max_d)) + 2; }

namespace {

// The search whole (kBanded false: the code the full analysis runs, without a test of the bands), or by bands.
template <bool kBanded>
Candidates walls_search(const GridSpec& spec, const RoomFeatures& features, const NormalCounts& normals,
                        const SizeRange& size, float fill, const std::stop_token& stop, BandedSearch banded) {
  const std::vector<RingOffset> own_ring = banded.ring ? std::vector<RingOffset>() : ring_offsets(size, Shape::WallTop);
  const std::vector<RingOffset>& ring = banded.ring ? *banded.ring : own_ring;
  const int floor = normals.y0, ceiling = normals.y0 + normals.levels - 1;
  // Alg. 2 starts the top row at I_Floor + ⌊w_min/2⌋, leaving room for the height below it.
  const int y_first = floor + int(std::floor(size.min_d * size.height_ratio));
  const auto& f = features.normals;

  // The rectangles' levels lie in [floor, ceiling]; their offsets are the ring's, each with its height.
  std::vector<Candidates::Shape> shapes;
  shapes.reserve(ring.size());
  for (const RingOffset& o : ring) shapes.push_back({o.dx, o.dz, size.wall_height(o.d)});
  // Per ring offset, the voxels with a normal a rectangle of it needs at its full height: fill of (⌊d⌋ + 1)(h + 1).
  std::vector<double> need(ring.size());
  for (std::size_t r = 0; r < ring.size(); ++r)
    need[r] = double(fill) * (std::floor(ring[r].d) + 1.0) * double(shapes[r].side + 1);
  // Per ring offset, its covered cells as runs along x, one a row, where those are fewer than its runs along z
  // (RingOffset::runs, one a column): a top nearer the x axis covers a few rows of many columns, and the test
  // below costs more a run than a cell. Which runs it reads does not change its outcome (see there).
  struct RowRun {
    int dz, dx_lo, dx_hi;
  };
  std::vector<RowRun> row_runs;
  std::vector<std::uint32_t> row_runs_end(ring.size());  // offset r's are [end of r - 1, end of r)
  for (std::size_t r = 0; r < ring.size(); ++r) {
    const RingOffset& o = ring[r];
    const std::size_t begin = row_runs.size();
    int z_lo = o.runs.front().dz_lo, z_hi = o.runs.front().dz_hi;
    for (const CellRun& run : o.runs) z_lo = std::min(z_lo, run.dz_lo), z_hi = std::max(z_hi, run.dz_hi);
    if (std::size_t(z_hi - z_lo + 1) < o.runs.size())
      for (int z = z_lo; z <= z_hi; ++z) {
        RowRun row{z, std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
        int cells = 0;
        for (const CellRun& run : o.runs)
          if (z >= run.dz_lo && z <= run.dz_hi) row.dx_lo = std::min(row.dx_lo, run.dx), row.dx_hi = std::max(row.dx_hi, run.dx), ++cells;
        if (cells == 0) continue;
        if (cells != row.dx_hi - row.dx_lo + 1) {  // a row's cells apart (not a segment's): the columns' runs
          row_runs.resize(begin);
          break;
        }
        row_runs.push_back(row);
      }
    row_runs_end[r] = std::uint32_t(row_runs.size());
  }
  // Eq. 3.25's test for one rectangle (ring offset r, top at y_top): no wall column among the cells the top
  // segment touches, and enough voxels with a normal in the rows [y1 - h, y1]. Gives up once too many voxels lack
  // one; as no cell lowers the count of those, the cells may be read in any order. Beyond the thesis: no voxel
  // before an opening (RoomFeatures::wall_blocked). `prefix`: the counts' (NormalCounts::usable).
  const std::size_t sums_stride = normals.run_sums_stride();
  constexpr int kCellsAtOnce = 3;  // shorter runs cost less cell by cell
  const auto valid_in = [&]<class Count>(const Count* prefix, int x1, int z1, std::size_t r, int y_top) {
    const RingOffset& o = ring[r];
    const int y_bottom = std::max(y_top - shapes[r].side, floor);
    const long rows = y_top - y_bottom + 1;
    const double may_miss = double(long(o.cells) * rows) - need[r];
    const NormalCounts::Levels span = normals.levels_of(y_bottom, y_top);
    long missing = 0;
    // `cells` cells from column `col` on, `step` columns apart: their voxels with a normal. A column without one
    // counts none (its counts are slot 0's zeros); the rare column a rectangle may not hold (a wall, or a blocked
    // voxel in the span) is told by its flags. False where one may not be held.
    const auto add_run = [&](std::size_t col, int cells, std::size_t step) {
      int with_normal = 0;
      for (int k = 0; k < cells; ++k, col += step) {
        const std::uint32_t word = normals.start[col];
        if (word & (NormalCounts::kWallColumn | NormalCounts::kHasBlocked)) {
          int counted = 0;
          if (!normals.usable(prefix, col, span, counted)) return false;
          with_normal += counted;
        } else {
          with_normal += normal_counts::count(prefix, word, span);
        }
      }
      missing += rows * long(cells) - with_normal;
      return true;
    };
    // add_run at once from `order`'s sums (NormalCounts::RunSums), the run's columns being [i, i + cells) there; cell
    // by cell where it holds a flagged column, is too short to gain, or there are no sums.
    const auto add_run_sums = [&](const NormalCounts::RunSums& order, std::size_t i, std::size_t col, int cells,
                                  std::size_t step) {
      if (cells < kCellsAtOnce || order.rank.empty()) return add_run(col, cells, step);
      const std::uint32_t* lo = order.sums.get() + std::size_t(order.rank[i]) * sums_stride;
      const std::uint32_t* hi = order.sums.get() + std::size_t(order.rank[i + std::size_t(cells)]) * sums_stride;
      if (hi[sums_stride - 1] != lo[sums_stride - 1]) return add_run(col, cells, step);
      // Unsigned differences: exact, as each true difference is a count below 2^32.
      missing += rows * long(cells) - long((hi[span.to] - lo[span.to]) - (hi[span.from] - lo[span.from]));
      return true;
    };
    const std::size_t rows_begin = r == 0 ? 0 : row_runs_end[r - 1], rows_end = row_runs_end[r];
    if (rows_begin < rows_end) {  // row by row; a row past the grid's edge lacks every voxel
      for (std::size_t k = rows_begin; k < rows_end; ++k) {
        const RowRun& run = row_runs[k];
        const int z = z1 + run.dz, cells = run.dx_hi - run.dx_lo + 1;
        if (z < 0 || z >= spec.nz) missing += rows * long(cells);
        else if (const std::size_t col = spec.column(x1 + run.dx_lo, z);
                 !add_run_sums(normals.along_x, col, col, cells, 1))
          return false;
        if (double(missing) > may_miss) return false;
      }
      return true;
    }
    // Column by column; most rectangles lie inside the grid along z: no run of theirs to clip.
    const bool inside = z1 + o.box_lo.y >= 0 && z1 + o.box_hi.y < spec.nz;
    for (const CellRun& run : o.runs) {
      // The run's cells in the grid; those past its edge lack every voxel.
      int in_lo = z1 + run.dz_lo, in_hi = z1 + run.dz_hi;
      if (!inside) {
        const int z_lo = in_lo, z_hi = in_hi;
        in_lo = std::max(z_lo, 0), in_hi = std::min(z_hi, spec.nz - 1);
        missing += rows * long((z_hi - z_lo + 1) - std::max(in_hi - in_lo + 1, 0));
      }
      const std::size_t along_z = std::size_t(x1 + run.dx) * std::size_t(spec.nz) + std::size_t(in_lo);
      if (in_lo <= in_hi && !add_run_sums(normals.along_z, along_z, spec.column(x1 + run.dx, in_lo), in_hi - in_lo + 1,
                                          std::size_t(spec.nx)))
        return false;
      if (double(missing) > may_miss) return false;
    }
    return true;
  };
  const auto valid = [&](int x1, int z1, std::size_t r, int y_top) {
    return normals.prefix8.empty() ? valid_in(normals.prefix16.data(), x1, z1, r, y_top)
                                   : valid_in(normals.prefix8.data(), x1, z1, r, y_top);
  };

  Candidates out(spec, spec.ny, shapes);
  // The ring in words of 64 dz (bit dz + reach) per dx, in the ring's order (dx ascending, then dz): only the
  // words that hold offsets, each with the ring index of its lowest bit. Offset bit b of a word is ring entry
  // first + rank[b], its entries before it in the word: a byte per bit, not std::popcount of the bits below b,
  // which GCC compiles to a libgcc call on the x86-64 baseline (0.75 % of the hall's time).
  int reach = 0;
  for (const RingOffset& o : ring) reach = std::max({reach, o.dx, std::abs(o.dz)});
  // One bit per possible centre of a valid rectangle found so far, indexed by 2 x centre: x1 + x2 in
  // [0, 2 nx), 2 y1 - h in [2 floor - h_max, 2 ceiling], and z1 + z2, which from first corner row z1 lies in
  // [2 z1 - reach, 2 z1 + reach]: rows of z1 + z2 in a ring of `rows`, the two that come in with each z1
  // cleared (they held rows no later first corner reaches). A large floor's whole set took megabytes, each
  // analysis fresh pages.
  const int h_max = size.wall_height(size.max_d);
  const int y_base = 2 * floor - h_max, y_span = 2 * ceiling - y_base + 1;
  const std::size_t rows = std::size_t(2 * reach + 3), row_bits = std::size_t(2 * spec.nx) * std::size_t(y_span);
  BitSet centres(rows * row_bits);
  std::size_t first_row = 0;  // the ring's row of z1 + z2 = 2 z1 - reach, for the current z1
  const auto ring_row = [&](int dz) {  // of z1 + z2 = 2 z1 + dz, |dz| <= reach
    const std::size_t row = first_row + std::size_t(dz + reach);
    return row >= rows ? row - rows : row;
  };
  const auto centre_bit = [&](int sx, int sy, int dz) {
    return ring_row(dz) * row_bits + std::size_t(sx) * std::size_t(y_span) + std::size_t(sy - y_base);
  };
  struct RingWord {
    int dx, dz_from;        // dz_from: the dz of bit 0
    std::uint64_t offsets;  // bit dz - dz_from
    std::uint32_t first;    // the ring index of the lowest bit
    std::array<std::uint8_t, 64> rank;  // per set bit: the word's ring entries before it
  };
  std::vector<RingWord> ring_words;
  for (std::size_t r = 0; r < ring.size(); ++r) {
    const int dz_from = (ring[r].dz + reach) / 64 * 64 - reach;
    if (ring_words.empty() || ring_words.back().dx != ring[r].dx || ring_words.back().dz_from != dz_from)
      ring_words.push_back({ring[r].dx, dz_from, 0, std::uint32_t(r), {}});
    RingWord& word = ring_words.back();
    const int bit = ring[r].dz - dz_from;
    word.offsets |= std::uint64_t{1} << bit;
    word.rank[std::size_t(bit)] = std::uint8_t(r - word.first);
  }
  // Whether every word starts at the same dz (a ring under 64 voxels across: one word per dx), so that a row's
  // second corners share one window (NormalCounts::z_window_at); the bit rows' words a column apart.
  const bool one_start = std::all_of(ring_words.begin(), ring_words.end(),
                                     [&](const RingWord& w) { return w.dz_from == ring_words.front().dz_from; });
  const std::size_t column_words = normals.column_words();
  // Beyond the thesis (issue 19), a band searched again after a change, from its previous rectangles
  // (BandedSearch::previous): every one of them valid, and among them the first valid one of each centre in search
  // order. A rectangle that reads no changed column is as valid as it was: valid where it is its centre's first
  // previous rectangle; not valid where its centre had none before it (were it valid, that centre's first valid
  // one, at it or before it, would be there); tested only where an earlier one had its centre (a rectangle reads
  // its offset's box, RingOffset::box_lo). The band's previous rectangles by centre.
  // (Tested as `kBanded && from_previous` in the loops: a whole search's then carry no test of it.)
  bool from_previous = false;
  glm::ivec2 changed_lo(0), changed_hi(-1);
  if constexpr (kBanded)
    if (banded.previous) from_previous = true, changed_lo = banded.changed_lo, changed_hi = banded.changed_hi;
  const auto centre_key = [&](int x1, int y1, int z1, std::size_t r) {
    return pack_key(2 * x1 + ring[r].dx, 2 * y1 - shapes[r].side, 2 * z1 + ring[r].dz);
  };
  KeyTable previous_centres;  // centre -> its first rectangle in `before`
  const std::vector<Candidates::Item>* before = nullptr;
  int previous_band = -1;
  // Only the centres a changed column may reach are searched again. Rectangle r with twice its centre at (sx, sz)
  // has 2 x1 = sx - dx and reads the columns x1 + box_lo.x to x1 + box_hi.x (z alike), so it reads the changed box
  // only where sx lies in [2 changed_lo.x + min(dx - 2 box_hi.x), 2 changed_hi.x + max(dx - 2 box_lo.x)] (over the
  // ring) and sz alike: the affected box. Every rectangle of a centre outside it is as valid as it was, so that
  // centre's first valid one is the one `before` holds: copied from there into `out` in search order, between the
  // rectangles found (take_before). The search tries the rectangles of affected centres alone.
  glm::ivec2 affected_lo(std::numeric_limits<int>::min()), affected_hi(std::numeric_limits<int>::max());
  if (from_previous) {
    glm::ivec2 below(std::numeric_limits<int>::max()), above(std::numeric_limits<int>::min());
    for (const RingOffset& o : ring) {
      const glm::ivec2 d(o.dx, o.dz);
      below = glm::min(below, d - 2 * o.box_hi), above = glm::max(above, d - 2 * o.box_lo);
    }
    affected_lo = 2 * changed_lo + below, affected_hi = 2 * changed_hi + above;
  }
  const auto affected = [&](int sx, int sz) {
    return sx >= affected_lo.x && sx <= affected_hi.x && sz >= affected_lo.y && sz <= affected_hi.y;
  };
  // The previous rectangles of the band searched whose centres are not affected, into `out` in search order up to
  // (not including) `key`: those of corners 1 in the band's columns (the others replace() keeps).
  std::size_t before_next = 0;
  glm::ivec2 band_columns(0, -1);
  const auto take_before = [&](const WallSearchOrder& key) {
    for (; before_next < before->size(); ++before_next) {
      const Candidates::Item& item = (*before)[before_next];
      const glm::ivec3 c = out.decode(item).corner(0);
      if (!(wall_search_order(c, item.shape) < key)) return;
      const RingOffset& o = ring[item.shape];
      if (c.x >= band_columns.x && c.x <= band_columns.y && !affected(2 * c.x + o.dx, 2 * c.z + o.dz)) out.push_item(item);
    }
  };
  constexpr WallSearchOrder kBandEnd{std::numeric_limits<int>::max(), 0, 0, 0};
  const auto valid_now = [&](int x1, int y1, int z1, std::size_t r) {
    const RingOffset& o = ring[r];
    if (kBanded && from_previous && (x1 + o.box_hi.x < changed_lo.x || x1 + o.box_lo.x > changed_hi.x ||
                                     z1 + o.box_hi.y < changed_lo.y || z1 + o.box_lo.y > changed_hi.y)) {
      const std::uint32_t j = previous_centres.find(centre_key(x1, y1, z1, r));
      if (j == KeyTable::kAbsent) return false;
      const Candidates::Item& item = (*before)[j];
      const glm::ivec3 c = out.decode(item).corner(0);
      if (c == glm::ivec3(x1, y1, z1) && item.shape == r) return true;
      if (wall_search_order(c, item.shape) > wall_search_order({x1, y1, z1}, std::uint32_t(r))) return false;
    }
    return valid(x1, z1, r, y1);
  };
  // Where Alg. 2 has a second corner: one with a compatible normal at a ring offset, tried in the ring's order.
  // By bands, each band's centres are its own: the bits it set are cleared when it ends.
  std::vector<std::size_t> band_bits;
  const auto try_rectangle = [&](int x1, int y1, int z1, std::size_t r) {
    const RingOffset& o = ring[r];
    const int h = shapes[r].side;
    const std::size_t bit = centre_bit(2 * x1 + o.dx, 2 * y1 - h, o.dz);
    if (centres.test(bit) || !valid_now(x1, y1, z1, r)) return;
    centres.set(bit);
    if constexpr (kBanded) band_bits.push_back(bit);
    if (kBanded && from_previous) take_before(wall_search_order({x1, y1, z1}, std::uint32_t(r)));
    out.push_back(glm::ivec3(x1, y1, z1), std::uint32_t(r));
  };
  const auto end_band = [&](int band) {
    if (from_previous) take_before(kBandEnd);
    banded.pieces->push_back({0, band, out.size()});
    for (const std::size_t bit : band_bits) centres.reset(bit);
    band_bits.clear();
  };
  for (int z1 = 0; z1 < spec.nz; ++z1, stop_point(stop)) {
    int x_first = 0, x_last = spec.nx - 1;
    if constexpr (kBanded) {
      const RowBands& b = *banded.bands;
      if (z1 > 0 && b.band(z1 - 1) != b.band(z1) && b.searches(z1 - 1)) end_band(b.band(z1 - 1));
      if (!b.searches(z1)) continue;  // a band searched starts with no centre: the last one's were cleared
      const glm::ivec2 columns = b.columns[std::size_t(b.band(z1))];
      x_first = std::max(columns.x, 0), x_last = std::min(columns.y, spec.nx - 1);
      if (from_previous && b.band(z1) != previous_band) {
        previous_band = b.band(z1);
        before = &(*banded.previous)[std::size_t(previous_band)];
        before_next = 0, band_columns = glm::ivec2(x_first, x_last);
        previous_centres = KeyTable();  // read for the rectangles the search tries: those of affected centres
        for (std::size_t j = 0; j < before->size(); ++j) {
          const Candidates::Item& item = (*before)[j];
          const glm::ivec3 c = out.decode(item).corner(0);
          if (affected(2 * c.x + ring[item.shape].dx, 2 * c.z + ring[item.shape].dz))
            previous_centres.insert(centre_key(c.x, c.y, c.z, item.shape), std::uint32_t(j));
        }
      }
    }
    first_row = std::size_t(2 * z1 + int(rows) - reach) % rows;  // 2 z1 - reach, kept non-negative
    for (const int dz : {reach - 1, reach})
      if (dz >= -reach) centres.reset(ring_row(dz) * row_bits, (ring_row(dz) + 1) * row_bits);
    // The first corners of rectangles of affected centres: 2 z1 + dz and 2 x1 + dx in the affected box, with
    // |dz| <= reach and 0 <= dx <= reach (ring_offsets); >> 1 is floor(v / 2) for either sign.
    if (from_previous) {
      if (2 * z1 < affected_lo.y - reach || 2 * z1 > affected_hi.y + reach) continue;
      x_first = std::max(x_first, (affected_lo.x - reach) >> 1);
      x_last = std::min(x_last, affected_hi.x >> 1);
    }
    // The window of second corners' z: every word's (one_start) for every first corner of the row.
    const NormalCounts::ZWindow row_window =
        normals.z_window_at(z1 + (ring_words.empty() ? 0 : ring_words.front().dz_from));
    for (int x1 = x_first; x1 <= x_last; ++x1) {
      if (!normals.has_normal(spec.column(x1, z1))) continue;  // most of an open floor
      for (int y1 = std::max(y_first, floor); y1 <= ceiling; ++y1) {
        const std::uint8_t f1 = f[spec.index(x1, y1, z1)];
        if (f1 == 0) continue;
        if (normals.z_bits.empty()) {  // a grid too shallow in z for bit rows: the second corners one by one
          const std::uint8_t compatible = compatible_normals(f1);
          for (std::size_t r = 0; r < ring.size(); ++r) {
            const int x2 = x1 + ring[r].dx, z2 = z1 + ring[r].dz;
            if (x2 < spec.nx && z2 >= 0 && z2 < spec.nz && (f[spec.index(x2, y1, z2)] & compatible) != 0 &&
                affected(x1 + x2, z1 + z2))
              try_rectangle(x1, y1, z1, r);
          }
          continue;
        }
        const NormalCounts::ZRows rows = NormalCounts::z_rows(f1);
        if (rows.count == 0) continue;  // no normal a second corner may carry
        const std::uint64_t* rows_here = normals.z_rows_at(spec.nx, x1, y1, rows);
        for (const RingWord& word : ring_words) {
          if (x1 + word.dx >= spec.nx || (kBanded && 2 * x1 + word.dx > affected_hi.x)) break;  // dx only grows
          if (kBanded && 2 * x1 + word.dx < affected_lo.x) continue;
          const std::uint64_t* rows_there = rows_here + std::size_t(word.dx) * column_words;
          const NormalCounts::ZWindow window = one_start ? row_window : normals.z_window_at(z1 + word.dz_from);
          std::uint64_t seconds = word.offsets & normals.z_window(rows_there, rows, window);
          if (kBanded && from_previous)  // dz with 2 z1 + dz in the affected box
            seconds &= bits_between(affected_lo.y - 2 * z1 - word.dz_from, affected_hi.y - 2 * z1 - word.dz_from);
          for (; seconds != 0; seconds &= seconds - 1)
            try_rectangle(x1, y1, z1, word.first + word.rank[std::size_t(std::countr_zero(seconds))]);
        }
      }
    }
  }
  if constexpr (kBanded)
    if (spec.nz > 0 && banded.bands->searches(spec.nz - 1)) end_band(banded.bands->band(spec.nz - 1));
  return out;
}

}  // namespace

Candidates search_walls(const GridSpec& spec, const RoomFeatures& features, const NormalCounts& normals,
                        const SizeRange& size, float fill, const std::stop_token& stop, BandedSearch banded) {
  return banded.bands ? walls_search<true>(spec, features, normals, size, fill, stop, banded)
                      : walls_search<false>(spec, features, normals, size, fill, stop, banded);
}

}  // namespace roomsense::detail
