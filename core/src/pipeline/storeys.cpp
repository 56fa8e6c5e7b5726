#include "storeys.h"

#include "../parallel.h"

#include <algorithm>

namespace roomsense::detail {
namespace {

// select_floor_ceiling's bands around two given peaks.
FloorCeiling with_bands(std::span<const std::uint32_t> counts, int floor_peak, int ceiling_peak) {
  FloorCeiling fc{floor_peak, ceiling_peak, floor_peak, ceiling_peak};
  const auto in_band = [&](int y, int peak) {
    return kSurfaceBandDivisor * counts[std::size_t(y)] >= counts[std::size_t(peak)];
  };
  if (fc.floor + 1 < fc.ceiling && in_band(fc.floor + 1, fc.floor_peak)) ++fc.floor;
  if (fc.ceiling - 1 > fc.floor && in_band(fc.ceiling - 1, fc.ceiling_peak)) --fc.ceiling;
  return fc;
}

// The storeys between a pair's ends, bottom to top; the pair itself when no slab lies between them.
std::vector<FloorCeiling> split(std::span<const std::uint32_t> counts, std::span<const std::uint32_t> horizontal,
                                const FloorCeiling& pair, int min_separation) {
  const std::uint64_t ends = std::max(horizontal[std::size_t(pair.floor_peak)], horizontal[std::size_t(pair.ceiling_peak)]);
  std::vector<std::pair<int, int>> slabs;  // lowest and highest level
  for (int y = pair.floor_peak + min_separation; y <= pair.ceiling_peak - min_separation; ++y) {
    if (4 * std::uint64_t(horizontal[std::size_t(y)]) < ends || ends == 0) continue;
    if (!slabs.empty() && y - slabs.back().second < min_separation) slabs.back().second = y;
    else slabs.push_back({y, y});
  }
  if (slabs.empty()) return {pair};
  std::vector<FloorCeiling> out;
  int floor = pair.floor_peak;
  for (const auto& [lo, hi] : slabs) {
    out.push_back(with_bands(counts, floor, lo));
    floor = hi;
  }
  out.push_back(with_bands(counts, floor, pair.ceiling_peak));
  return out;
}

// Adds `sign` (+1 or -1, mod 2^32) to out[y] for each voxel of column `col` with an empty voxel above or below.
void count_horizontal(const VoxelGrid& grid, std::size_t col, std::uint32_t sign, std::vector<std::uint32_t>& out) {
  const int ny = grid.spec.ny;
  const std::uint8_t* v = grid.cells.data() + col * std::size_t(ny);
  for (int y = 0; y < ny; ++y)
    if (v[y] && (y == 0 || !v[y - 1] || y + 1 == ny || !v[y + 1])) out[std::size_t(y)] += sign;
}

}  // namespace

std::vector<std::uint32_t> horizontal_counts(const VoxelGrid& grid, unsigned threads) {
  // count_horizontal on every column, without its branches (they vectorize): a full analysis waits for this pass
  // (thesis-room1: 0.104 -> 0.045 ms on one thread), so columns go side by side, each slice's counts summed after
  // (integers: in any order). A grid of one level: its voxels have neither neighbour.
  const std::size_t ny = std::size_t(grid.spec.ny);
  if (ny < 2) {
    std::vector<std::uint32_t> out(ny, 0);
    for (std::size_t col = 0; col < grid.spec.column_count(); ++col) count_horizontal(grid, col, 1, out);
    return out;
  }
  return counts_by_slices(grid.spec.column_count(), threads, kColumnGrain, ny,
                          [&](std::size_t begin, std::size_t end, std::vector<std::uint32_t>& part) {
    std::uint32_t* const counts = part.data();
    for (std::size_t col = begin; col < end; ++col) {
      const std::uint8_t* v = grid.cells.data() + col * ny;
      counts[0] += v[0] != 0;
      counts[ny - 1] += v[ny - 1] != 0;
      for (std::size_t y = 1; y + 1 < ny; ++y)
        counts[y] += std::uint32_t(v[y] != 0) & ~(std::uint32_t(v[y - 1] != 0) & std::uint32_t(v[y + 1] != 0));
    }
  });
}

std::vector<std::uint32_t> horizontal_counts(const VoxelGrid& grid, const VoxelGrid& previous,
                                             std::vector<std::uint32_t> before, const std::vector<std::uint8_t>& changed) {
  for (std::size_t col = 0; col < changed.size(); ++col) {
    if (!changed[col]) continue;
    count_horizontal(previous, col, ~std::uint32_t{0}, before);
    count_horizontal(grid, col, 1, before);
  }
  return before;
}

StoreyLevels find_storeys(std::span<const std::uint32_t> counts, std::span<const std::uint32_t> horizontal,
                          const FloorCeiling& stage_pair, int min_separation) {
  StoreyLevels out;
  std::vector<FloorCeiling> parts = split(counts, horizontal, stage_pair, min_separation);
  // The storey holding the fuller of the pair's levels (the lower on a tie) stays the main one.
  const bool floor_fuller = counts[std::size_t(stage_pair.floor_peak)] >= counts[std::size_t(stage_pair.ceiling_peak)];
  const std::size_t main = floor_fuller ? 0 : parts.size() - 1;
  out.main = parts[main];
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (i != main) out.others.push_back(parts[i]);

  const std::uint32_t main_count = counts[std::size_t(stage_pair.floor_peak)];
  // The fullest pair among the levels [begin, end) holding at least a quarter of main_count.
  const auto search = [&](int begin, int end) -> std::optional<FloorCeiling> {
    if (end <= begin) return std::nullopt;
    std::vector<std::uint32_t> part(counts.begin() + begin, counts.begin() + end);
    for (std::uint32_t& c : part)
      if (4 * std::uint64_t(c) < main_count) c = 0;
    auto fc = select_floor_ceiling(part, min_separation);
    if (fc) *fc = {fc->floor + begin, fc->ceiling + begin, fc->floor_peak + begin, fc->ceiling_peak + begin};
    return fc;
  };
  const auto add = [&](const FloorCeiling& pair) {
    for (const FloorCeiling& p : split(counts, horizontal, pair, min_separation)) out.others.push_back(p);
  };
  for (int begin = stage_pair.ceiling_peak + 1; const auto pair = search(begin, int(counts.size()));) {
    add(*pair);
    begin = pair->ceiling_peak + 1;
  }
  for (int end = stage_pair.floor_peak; const auto pair = search(0, end);) {
    add(*pair);
    end = pair->floor_peak;
  }
  std::sort(out.others.begin(), out.others.end(),
            [](const FloorCeiling& a, const FloorCeiling& b) { return a.floor_peak < b.floor_peak; });
  return out;
}

}  // namespace roomsense::detail
