// Voxelization (thesis §3.1, Eq. 3.6/3.7) and the column statistics of §3.2 that both backends compute:
// level counts |V_y| (Eq. 3.8), floor/ceiling choice (Eq. 3.9/3.10), column counts |V_xz| (Eq. 3.11) and the
// any-voxel-in-column mask behind B_Room (Eq. 3.12). The Vulkan backend (compute/) implements the same
// VoxelStage interface and must give bit-identical results.
#pragma once
#include "roomsense/grid.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

namespace roomsense {

enum class VoxelMode {
  Vertices,   // the thesis: a voxel is active when a vertex lies in it
  Triangles,  // ours: every voxel a triangle passes through
};

// Vertex positions in grid units: (v - origin) / voxel_size, computed once on the CPU so that every backend
// starts from the same floats. Voxel (x,y,z) is the cube [x, x+1) x [y, y+1) x [z, z+1) in these units.
// Each vertex alone: the same on any number of `threads`.
std::vector<glm::vec3> to_grid_units(std::span<const glm::vec3> world, const GridSpec& spec, unsigned threads = 1);

// The triangle/voxel test used by triangle mode (separating axis theorem, Akenine-Möller 2001). Voxel i is
// tested as the closed cube [i - eps, i + 1 - eps] (per axis, eps = kVoxelTestEpsilon): neighbours touch,
// so no face can slip between them, and a face lying exactly on a voxel boundary lands in the upper voxel,
// as a vertex does under Eq. 3.6. A triangle's voxel range per axis is box_index(min) .. box_index(max).
// Triangle mode marks a triangle's corners' cells (box_index per axis) without the test, as a corner lies in
// its cell's cube, and tests the other voxels of its range.
// Only +, -, * and comparisons, in a fixed order: IEEE single precision gives every backend the same answer.
inline constexpr float kVoxelTestEpsilon = 1.0f / 1024.0f;
// floor(v) clamped to [0, n - 1], for any v (NaN gives 0): Eq. 3.6 per axis. Without std::floor, a libm
// call on x86-64's baseline: below 0 and from n - 1 (an integer) on the clamp decides, and in between
// truncation is the floor. Inline: the GPU stage's work list calls it six times per triangle.
inline int clamp_index(float v, int n) {
  if (!(v >= 0.0f)) return 0;
  if (v >= float(n - 1)) return n - 1;
  return int(v);
}
// The voxel whose test cube holds coordinate v (grid units), clamped to [0, n).
inline int box_index(float v, int n) { return clamp_index(v + kVoxelTestEpsilon, n); }
bool triangle_overlaps_voxel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int x, int y, int z);

struct FloorCeiling {
  int floor = 0;         // I_Floor: the top of the floor's band of levels
  int ceiling = 0;       // I_Ceiling: the bottom of the ceiling's band
  int floor_peak = 0;    // the fullest floor level, floor_peak <= floor
  int ceiling_peak = 0;  // the fullest ceiling level, ceiling_peak >= ceiling
  bool operator==(const FloorCeiling&) const = default;
};

// Eq. 3.9/3.10: the two fullest levels at least `min_separation` levels apart. Ties go to the lower level.
// Nothing when no two non-empty levels are that far apart.
// Beyond the thesis: a real floor is seldom flat to the voxel. When it straddles a level boundary, the level
// above the floor's peak holds a large share of it too, and the thesis would read those voxels as furniture
// (Eq. 3.13) and deny the free floor (Eq. 3.14) wherever they are. So when the level above the floor's peak
// holds at least 1/kSurfaceBandDivisor of the peak's count, I_Floor is that level; likewise below the ceiling.
inline constexpr std::uint64_t kSurfaceBandDivisor = 4;
std::optional<FloorCeiling> select_floor_ceiling(std::span<const std::uint32_t> level_counts, int min_separation);

// The work budget of triangle mode, in triangle-voxel tests. A real scan needs few: our recorded rooms
// need 3e4-4e5 at 10 cm voxels and at most 4e6 at 2 cm. Room-sized triangles at a fine voxel need 1e5
// each, so a few thousand of them would run for minutes. Past the budget a backend throws
// Error(TooMuchWork) with too_much_work_message(); on a 2-core machine the budget is 2-3 s of work.
inline constexpr std::uint64_t kDefaultVoxelTestBudget = std::uint64_t{1} << 27;
std::string too_much_work_message(std::uint64_t budget);

struct VoxelizeRequest {
  GridSpec spec;
  std::span<const glm::vec3> grid_vertices;  // from to_grid_units
  std::span<const std::uint32_t> indices;    // validated: every index < grid_vertices.size()
  VoxelMode mode = VoxelMode::Triangles;
  int min_separation_levels = 15;            // 1.5 m at 0.1 m voxels
  std::uint64_t test_budget = kDefaultVoxelTestBudget;
  std::stop_token stop;                      // a stop request makes run() throw Error(Cancelled)
};

struct VoxelStageResult {
  VoxelGrid grid;                            // V
  std::vector<std::uint32_t> level_counts;   // |V_y| for y in [0, ny)
  std::optional<FloorCeiling> levels;        // Eq. 3.9/3.10 on level_counts
  std::vector<std::uint32_t> column_counts;  // |V_xz| for y in [floor, ceiling], per GridSpec::column; all 0 without levels
  std::vector<std::uint8_t> column_any;      // 1 where any voxel lies in y in [floor, ceiling]; all 0 without levels
  std::uint64_t voxel_tests = 0;             // triangle-voxel tests done, the work VoxelizeRequest::test_budget bounds
};

// A backend for the voxel stage. Implementations are not required to be thread-safe.
class VoxelStage {
 public:
  virtual ~VoxelStage() = default;
  virtual std::string name() const = 0;
  virtual VoxelStageResult run(const VoxelizeRequest& request) = 0;
};

// The reference implementation, on the CPU.
class CpuVoxelStage final : public VoxelStage {
 public:
  explicit CpuVoxelStage(unsigned threads = 0) : threads_(threads) {}
  std::string name() const override { return "cpu"; }
  VoxelStageResult run(const VoxelizeRequest& request) override;

 private:
  unsigned threads_;
};

// The pieces of CpuVoxelStage, for tests and for backends that do part of the work on the CPU.
// `tests`, when given, receives the triangle-voxel tests done (the work the budget counts).
VoxelGrid voxelize_cpu(const VoxelizeRequest& request, unsigned threads = 0, std::uint64_t* tests = nullptr);
// The same marks set in `grid` (of request.spec), which may hold marks already: a caller voxelizing one chunk at a
// time reuses one grid, clearing only the chunk's box.
void voxelize_cpu_into(const VoxelizeRequest& request, VoxelGrid& grid, unsigned threads = 0,
                       std::uint64_t* tests = nullptr);
// |V_y| per level, and per column its voxels between the levels: the same on any number of threads (0: one per
// core; by default one, as before the parameter existed).
std::vector<std::uint32_t> count_levels(const VoxelGrid& grid, unsigned threads = 1);
void count_columns(const VoxelGrid& grid, const std::optional<FloorCeiling>& levels,
                   std::vector<std::uint32_t>& column_counts, std::vector<std::uint8_t>& column_any,
                   unsigned threads = 1);
// count_columns's count of one column: its voxels in [levels.floor, levels.ceiling].
std::uint32_t count_column(const VoxelGrid& grid, std::size_t column, const FloorCeiling& levels);

}  // namespace roomsense
