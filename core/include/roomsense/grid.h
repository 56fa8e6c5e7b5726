// The voxel grid V of thesis §3.1 (Eq. 3.4-3.7) and the budget that keeps it bounded.
#pragma once
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomsense {

// Default and limits. The budget caps the voxel count of one grid: the pipeline holds about three arrays
// of one byte per voxel (V, the wall normals F, the bounds volume I), so 2^25 voxels is at most ~100 MiB.
inline constexpr float kDefaultVoxelSize = 0.10f;
inline constexpr float kMinVoxelSize = 0.01f;
inline constexpr float kMaxVoxelSize = 1.0f;
inline constexpr std::size_t kDefaultVoxelBudget = std::size_t{1} << 25;

// dims: x = L_Grid, y = H_Grid, z = W_Grid. Voxel (x,y,z) covers [origin + (x,y,z)*s, origin + (x+1,y+1,z+1)*s).
struct GridSpec {
  glm::vec3 origin{0.0f};
  float voxel_size = kDefaultVoxelSize;
  int nx = 0, ny = 0, nz = 0;

  std::size_t voxel_count() const { return std::size_t(nx) * std::size_t(ny) * std::size_t(nz); }
  std::size_t column_count() const { return std::size_t(nx) * std::size_t(nz); }
  // Columns are contiguous in y: every per-column scan of §3.2 walks memory in order.
  std::size_t column(int x, int z) const { return std::size_t(z) * std::size_t(nx) + std::size_t(x); }
  std::size_t index(int x, int y, int z) const { return column(x, z) * std::size_t(ny) + std::size_t(y); }
  bool contains(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz; }
  // The world position of lattice point (x,y,z): the minimum corner of voxel (x,y,z).
  glm::vec3 lattice_to_world(float x, float y, float z) const { return origin + glm::vec3(x, y, z) * voxel_size; }
  bool operator==(const GridSpec&) const = default;
};

// Eq. 3.4/3.5: the grid spanning [lo, hi]. Throws Error(GridTooLarge) past `voxel_budget` voxels, and
// Error(BadParameter) for a voxel size outside [kMinVoxelSize, kMaxVoxelSize].
GridSpec make_grid_spec(const glm::vec3& lo, const glm::vec3& hi, float voxel_size,
                        std::size_t voxel_budget = kDefaultVoxelBudget);

// V (Eq. 3.7): one byte per voxel, 0 or 1, laid out by GridSpec::index.
struct VoxelGrid {
  GridSpec spec;
  std::vector<std::uint8_t> cells;

  VoxelGrid() = default;
  explicit VoxelGrid(const GridSpec& s) : spec(s), cells(s.voxel_count(), 0) {}
  std::uint8_t at(int x, int y, int z) const { return cells[spec.index(x, y, z)]; }
  // 0 outside the grid, as Eq. 3.63 asks for out-of-range reads.
  std::uint8_t at_or_zero(int x, int y, int z) const { return spec.contains(x, y, z) ? at(x, y, z) : 0; }
  void set(int x, int y, int z) { cells[spec.index(x, y, z)] = 1; }
  const std::uint8_t* column_data(int x, int z) const { return cells.data() + spec.column(x, z) * spec.ny; }
};

}  // namespace roomsense
