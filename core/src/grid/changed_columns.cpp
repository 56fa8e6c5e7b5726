// Which columns of a voxel grid changed between two versions of it (changed_columns.h).
#include "changed_columns.h"

#include <algorithm>
#include <cstring>

namespace roomsense::detail {

std::vector<std::uint8_t> changed_columns(std::size_t ny, std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
  if (ny == 0) return {};
  std::vector<std::uint8_t> out(a.size() / ny, 0);
  // The grid in runs of 512 voxels, each compared at once (a column of a few dozen levels is too short for
  // memcmp to pay); a run that differs marks the columns of the voxels that differ.
  const std::size_t n = a.size();
  const auto mark = [&](std::size_t from, std::size_t to) {  // voxels [from, to)
    for (std::size_t c = from / ny; c <= (to - 1) / ny; ++c)
      for (std::size_t v = std::max(from, c * ny); v < std::min(to, (c + 1) * ny); ++v)
        if (a[v] != b[v]) {
          out[c] = 1;
          break;
        }
  };
  constexpr std::size_t kRun = 512;
  for (std::size_t i = 0; i < n; i += kRun) {
    const std::size_t end = std::min(n, i + kRun);
    if (std::memcmp(a.data() + i, b.data() + i, end - i) != 0) mark(i, end);
  }
  return out;
}

std::vector<std::uint8_t> changed_columns(const VoxelGrid& a, const VoxelGrid& b) {
  return changed_columns(std::size_t(a.spec.ny), a.cells, b.cells);
}

void copy_columns(std::size_t ny, std::span<const std::uint8_t> from, std::span<std::uint8_t> to,
                  std::span<const std::uint8_t> which) {
  for (std::size_t col = 0; col < which.size(); ++col)
    if (which[col]) std::copy_n(from.begin() + std::ptrdiff_t(col * ny), ny, to.begin() + std::ptrdiff_t(col * ny));
}

}  // namespace roomsense::detail
