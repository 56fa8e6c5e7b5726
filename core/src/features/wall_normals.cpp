// Wall normals F (Alg. 1).
#include "column_steps.h"
#include "roomsense/features.h"

#include <algorithm>
#include <bit>
#include <memory>
#include <span>

namespace roomsense {
namespace {

// The levels I_Floor..I_Ceiling of the columns a wall's runs step through, as bits (`words` 64-bit words per
// column): Alg. 1 tests each level of a run on its own, step by step; one pass over a column's levels serves every
// run through it, and the runs of a wall column's levels step together.
class FreeLevels {
 public:
  FreeLevels(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling,
             const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room,
             const std::vector<int>& furniture)
      : in_{grid, levels, ceiling, walls, room}, furniture_(furniture),
        count_(levels.ceiling - levels.floor + 1),
        words_(std::size_t(count_ + 63) / 64),
        masks_(std::make_unique_for_overwrite<std::uint64_t[]>(grid.spec.column_count() * words_)),
        known_(grid.spec.column_count(), 0) {}

  int count() const { return count_; }  // levels
  std::size_t words() const { return words_; }
  // Bit j of column `col` is set where level I_Floor + j is free: no wall, no voxel, in the room, and above the
  // furniture top; beyond the thesis, below the column's own ceiling (a wall ends at a roof's slope or a soffit's
  // underside).
  const std::uint64_t* at(std::size_t col) {
    std::uint64_t* mask = masks_.get() + col * words_;
    if (known_[col]) return mask;
    known_[col] = 1;
    std::fill(mask, mask + words_, std::uint64_t{0});
    const auto& [grid, levels, ceiling, walls, room] = in_;
    if (walls[col] || !room[col]) return mask;
    const int from = std::max(levels.floor, furniture_[col] + 1);
    const int to = ceiling[col] >= levels.ceiling ? levels.ceiling : std::min(levels.ceiling, ceiling[col] - 1);
    const std::uint8_t* cells = grid.cells.data() + col * std::size_t(grid.spec.ny);
    for (int y = from; y <= to; ++y) {
      const auto j = std::size_t(y - levels.floor);
      mask[j / 64] |= std::uint64_t{cells[y] == 0} << (j % 64);
    }
    return mask;
  }

 private:
  detail::StoreyColumns in_;
  const std::vector<int>& furniture_;
  int count_;
  std::size_t words_;
  std::unique_ptr<std::uint64_t[]> masks_;  // a column's words are written when it is first asked for
  std::vector<std::uint8_t> known_;
};

// Alg. 1's runs from wall columns, each writing the normal bits it finds into the column next to its wall.
class NormalRuns {
 public:
  NormalRuns(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling, int reach,
             const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room,
             const std::vector<int>& furniture)
      : s_(grid.spec), levels_(levels), walls_(walls), room_(room), reach_(reach),
        free_(grid, levels, ceiling, walls, room, furniture), running_(free_.words()), clear_(free_.words()) {}

  struct Direction {
    int dx, dz;
    std::uint8_t bit;
  };
  static constexpr Direction kDirections[] = {
      {-1, 0, kNormalLeft}, {1, 0, kNormalRight}, {0, -1, kNormalBackward}, {0, 1, kNormalForward}};

  // The run from wall column (x, z) in direction d: sets d's bit at the levels of column (x + dx, z + dz) where it
  // is clear. That column must lie in the grid.
  void run(int x, int z, const Direction& d, std::vector<std::uint8_t>& normals) {
    // A step (x, z) is free at level y when it is inside the grid and its FreeLevels bit is set. Alg. 1 lets the
    // Left/Backward scans silently skip indices below 0; we treat leaving the grid as blocked on every side, since
    // outside the grid is outside the room (b = 0) anyway.
    const std::size_t words = free_.words();
    const int count = free_.count();
    // Per level: whether its run is still free (`running`), and whether it ended clear (`clear`).
    for (std::size_t w = 0; w < words; ++w)
      running_[w] = w + 1 < words || count % 64 == 0 ? ~std::uint64_t{0} : (std::uint64_t{1} << (count % 64)) - 1;
    std::fill(clear_.begin(), clear_.end(), std::uint64_t{0});
    bool any = true;
    for (int i = 1; i <= reach_ && any; ++i) {
      const int xi = x + i * d.dx, zi = z + i * d.dz;
      // Beyond the thesis: a run of half the reach that ends at a wall, or where the room ends, is clear too: an
      // alcove or a corridor narrower than the reach still has walls to hang things on. A run that ends at a
      // voxel (furniture, clutter) is not.
      const bool half_run = 2 * (i - 1) >= reach_;
      if (!s_.contains(xi, 0, zi)) {
        if (half_run)
          for (std::size_t w = 0; w < words; ++w) clear_[w] |= running_[w];
        std::fill(running_.begin(), running_.end(), std::uint64_t{0});
        break;
      }
      const std::size_t col = s_.column(xi, zi);
      const std::uint64_t* step = free_.at(col);
      const bool ends = half_run && (walls_[col] || !room_[col]);
      any = false;
      for (std::size_t w = 0; w < words; ++w) {
        if (ends) clear_[w] |= running_[w] & ~step[w];
        running_[w] &= step[w];
        any = any || running_[w] != 0;
      }
    }
    std::uint8_t* column = normals.data() + s_.index(x + d.dx, levels_.floor, z + d.dz);
    for (std::size_t w = 0; w < words; ++w)
      for (std::uint64_t bits = clear_[w] | running_[w]; bits != 0; bits &= bits - 1)
        column[w * 64 + std::size_t(std::countr_zero(bits))] |= d.bit;
  }

 private:
  const GridSpec& s_;
  const FloorCeiling& levels_;
  const std::vector<std::uint8_t>& walls_;
  const std::vector<std::uint8_t>& room_;
  int reach_;
  FreeLevels free_;
  std::vector<std::uint64_t> running_, clear_;
};

}  // namespace

std::vector<std::uint8_t> detect_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels,
                                              const std::vector<int>& ceiling, int reach,
                                              const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room,
                                              const std::vector<int>& furniture) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> normals(s.voxel_count(), 0);
  if (levels.ceiling < levels.floor) return normals;
  NormalRuns runs(grid, levels, ceiling, reach, walls, room, furniture);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      if (!walls[s.column(x, z)]) continue;
      for (const NormalRuns::Direction& d : NormalRuns::kDirections)
        if (s.contains(x + d.dx, 0, z + d.dz)) runs.run(x, z, d, normals);  // else never clear
    }
  return normals;
}

void detail::update_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling,
                                 int reach, const std::vector<std::uint8_t>& walls,
                                 const std::vector<std::uint8_t>& room, const std::vector<int>& furniture,
                                 std::span<const std::uint32_t> changed, std::vector<std::uint8_t>& normals) {
  const GridSpec& s = grid.spec;
  if (levels.ceiling < levels.floor || changed.empty()) return;
  // The bits of column t in direction d come from the run of the wall at t - d through t, t + d, ...,
  // t + (reach - 1) d: a changed column c reaches the columns from c - reach to c + reach along each axis.
  NormalRuns runs(grid, levels, ceiling, reach, walls, room, furniture);
  redo_along_axes(s, changed, reach, normals, [&](int x, int z) {
    for (const NormalRuns::Direction& d : NormalRuns::kDirections) {
      const int wx = x - d.dx, wz = z - d.dz;
      if (s.contains(wx, 0, wz) && walls[s.column(wx, wz)]) runs.run(wx, wz, d, normals);
    }
  });
}

}  // namespace roomsense
