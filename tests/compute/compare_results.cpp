#include "vulkan_test_env.h"

#include <sstream>

namespace roomsense::test {
namespace {

// Every test that may create a Vulkan instance needs the drivers pinned first (see vulkan_test_env.h).
[[maybe_unused]] const bool drivers_pinned = (pin_vulkan_drivers_for_leak_reports(), true);

template <class T>
::testing::AssertionResult same_vector(const char* what, const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << what << ": sizes differ, cpu " << a.size() << " vulkan " << b.size();
  std::size_t diffs = 0, first = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i] && diffs++ == 0) first = i;
  if (diffs == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << diffs << " of " << a.size() << " differ, first at " << first
                                       << " (cpu " << +a[first] << ", vulkan " << +b[first] << ")";
}

std::string describe(const std::optional<FloorCeiling>& l) {
  if (!l) return "none";
  std::ostringstream s;
  s << "floor " << l->floor << " ceiling " << l->ceiling << " peaks " << l->floor_peak << "/" << l->ceiling_peak;
  return s.str();
}

}  // namespace

void expect_identical(const VoxelStageResult& cpu, const VoxelStageResult& gpu) {
  const GridSpec& s = cpu.grid.spec;
  EXPECT_EQ(s.nx, gpu.grid.spec.nx);
  EXPECT_EQ(s.ny, gpu.grid.spec.ny);
  EXPECT_EQ(s.nz, gpu.grid.spec.nz);
  const auto grid = same_vector("grid V", cpu.grid.cells, gpu.grid.cells);
  if (!grid && cpu.grid.cells.size() == gpu.grid.cells.size()) {
    for (std::size_t i = 0; i < cpu.grid.cells.size(); ++i)
      if (cpu.grid.cells[i] != gpu.grid.cells[i]) {
        const std::size_t col = i / std::size_t(s.ny);
        ADD_FAILURE() << "first differing voxel: x " << col % std::size_t(s.nx) << " y " << i % std::size_t(s.ny) << " z "
                      << col / std::size_t(s.nx);
        break;
      }
  }
  EXPECT_TRUE(grid);
  EXPECT_TRUE(same_vector("level counts |V_y|", cpu.level_counts, gpu.level_counts));
  EXPECT_EQ(describe(cpu.levels), describe(gpu.levels));
  EXPECT_TRUE(same_vector("column counts |V_xz|", cpu.column_counts, gpu.column_counts));
  EXPECT_TRUE(same_vector("column any", cpu.column_any, gpu.column_any));
}

}  // namespace roomsense::test
