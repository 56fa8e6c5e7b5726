// Alg. 3: squares on free floor and ceiling tiles (Eq. 3.28-3.39), and on furniture tops (§3.3.4,
// Eq. 3.40/3.41), at any rotation.
#include "cell_cover.h"
#include "ring_offsets.h"
#include "search.h"

#include <algorithm>

namespace roomsense::detail {
namespace {

// Prefix sums along z for each x: cells (x, z_lo..z_hi) are summed in O(1) per column of a square.
class ColumnPrefix {
 public:
  ColumnPrefix(const GridSpec& spec) : nz_(spec.nz), sums_(std::size_t(spec.nx) * std::size_t(spec.nz + 1), 0) {}
  template <class Pred>
  void fill(const GridSpec& spec, Pred pred) {
    for (int x = 0; x < spec.nx; ++x) {
      int* s = sums_.data() + std::size_t(x) * std::size_t(nz_ + 1);
      for (int z = 0; z < nz_; ++z) s[z + 1] = s[z] + (pred(spec.column(x, z)) ? 1 : 0);
    }
  }
  int sum(int x, int z_lo, int z_hi) const {
    const int* s = sums_.data() + std::size_t(x) * std::size_t(nz_ + 1);
    return s[z_hi + 1] - s[z_lo];
  }

 private:
  int nz_;
  std::vector<int> sums_;
};

// One bit per possible centre (4 x the centre, Eq. 3.42) of one level.
class CentreSet {
 public:
  CentreSet(const GridSpec& spec) : width_(4 * std::size_t(spec.nx)), bits_((width_ * 4 * spec.nz + 63) / 64, 0) {}
  bool contains(glm::ivec3 sum) const {
    const std::size_t i = bit(sum);
    return (bits_[i / 64] >> (i % 64)) & 1u;
  }
  void insert(glm::ivec3 sum) {
    const std::size_t i = bit(sum);
    bits_[i / 64] |= std::uint64_t{1} << (i % 64);
  }

 private:
  std::size_t bit(glm::ivec3 sum) const { return std::size_t(sum.z) * width_ + std::size_t(sum.x); }
  std::size_t width_;
  std::vector<std::uint64_t> bits_;
};

}  // namespace

Candidates search_squares(const GridSpec& spec, const RoomFeatures& features, Surface surface,
                          const SizeRange& size, float fill) {
  const std::vector<RingOffset> ring = ring_offsets(size, Shape::Square);
  const FloorCeiling& levels = features.levels;
  // The levels searched: one for floors (I_Floor + 1) and ceilings (I_Ceiling - 1), (I_Floor, I_yEnd] for
  // furniture (Eq. 3.40), whose tops C holds as the level above the top voxel (Eq. 3.13).
  int y_from = levels.floor + 1, y_to = levels.floor + 1;
  if (surface == Surface::Ceiling) y_from = y_to = levels.ceiling - 1;
  if (surface == Surface::Furniture) y_to = features.y_end;

  Candidates out;
  ColumnPrefix suitable(spec), walls(spec), raised(spec);
  walls.fill(spec, [&](std::size_t col) { return features.walls[col] != 0; });
  // Centres found so far, per level of the squares' corners (y_actual for furniture, Eq. 3.41).
  std::vector<CentreSet> centres(std::size_t(y_to - y_from + 2), CentreSet(spec));
  for (int y1 = y_from; y1 <= y_to; ++y1) {
    // Corner 1 must be a tile of this level; the other cells may also be one level higher (§3.3.4).
    std::vector<std::uint8_t> tile(spec.column_count(), 0), first(spec.column_count(), 0);
    for (std::size_t col = 0; col < tile.size(); ++col) {
      if (surface == Surface::Floor) tile[col] = first[col] = features.free_floor[col];
      if (surface == Surface::Ceiling) tile[col] = first[col] = features.free_ceiling[col];
      if (surface == Surface::Furniture) {
        first[col] = features.furniture[col] == y1;
        tile[col] = first[col] || features.furniture[col] == y1 + 1;
      }
    }
    if (std::none_of(first.begin(), first.end(), [](std::uint8_t t) { return t != 0; })) continue;
    suitable.fill(spec, [&](std::size_t col) { return tile[col] != 0; });
    if (surface == Surface::Furniture) raised.fill(spec, [&](std::size_t col) { return features.furniture[col] == y1 + 1; });
    CentreSet& here = centres[std::size_t(y1 - y_from)];
    CentreSet& above = centres[std::size_t(y1 - y_from + 1)];
    const auto is_tile = [&](int x, int z) {
      return x >= 0 && z >= 0 && x < spec.nx && z < spec.nz && tile[spec.column(x, z)] != 0;
    };

    for (int z1 = 0; z1 < spec.nz; ++z1)
      for (int x1 = 0; x1 < spec.nx; ++x1) {
        if (!first[spec.column(x1, z1)]) continue;
        for (const RingOffset& o : ring) {
          const int x2 = x1 + o.dx, z2 = z1 + o.dz;
          const int x3 = x2 - o.dz, z3 = z2 + o.dx;  // Eq. 3.28
          const int x4 = x1 - o.dz, z4 = z1 + o.dx;
          if (!is_tile(x2, z2) || !is_tile(x3, z3) || !is_tile(x4, z4)) continue;
          const glm::ivec3 sum(x1 + x2 + x3 + x4, 0, z1 + z2 + z3 + z4);
          // A square whose centre an earlier valid square of this search holds is dropped by Eq. 3.44 anyway.
          const bool may_rise = surface == Surface::Furniture;
          if (here.contains(sum) && (!may_rise || above.contains(sum))) continue;

          // Eq. 3.30-3.38: every cell the square reaches into; none a wall, 95 % of (d + 1)² suitable. Gives up
          // once more cells are unsuitable than that allows.
          const double may_miss = double(o.cells) - double(fill) * (o.d + 1.0) * (o.d + 1.0);
          int missing = 0;
          bool fails = may_miss < 0.0, rises = false;
          for (std::size_t r = 0; r < o.runs.size() && !fails; ++r) {
            const CellRun& run = o.runs[r];
            const int x = x1 + run.dx, lo = z1 + run.dz_lo, hi = z1 + run.dz_hi;  // inside: the corners are
            const int cells = hi - lo + 1;
            missing += cells - suitable.sum(x, lo, hi);
            fails = double(missing) > may_miss || walls.sum(x, lo, hi) > 0;
            if (may_rise && !rises) rises = raised.sum(x, lo, hi) > 0;
          }
          if (fails) continue;
          const int y = rises ? y1 + 1 : y1;  // y_Actual, Eq. 3.41
          CentreSet& level = rises ? above : here;
          if (level.contains(sum)) continue;
          level.insert(sum);
          out.push_back({{glm::ivec3(x1, y, z1), glm::ivec3(x2, y, z2), glm::ivec3(x3, y, z3), glm::ivec3(x4, y, z4)}});
        }
      }
  }
  return out;
}

}  // namespace roomsense::detail
