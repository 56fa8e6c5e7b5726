// Voxelization on the CPU: the reference for every backend (thesis Eq. 3.6/3.7, plus triangle mode).
// This file is compiled with -ffp-contract=off: a fused multiply-add would round differently from the
// Vulkan shaders, which mark their arithmetic `precise`.
#include "../parallel.h"
#include "roomsense/voxelize.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace roomsense {
namespace {

float dot3(const glm::vec3& a, const glm::vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float abs_sum(const glm::vec3& a) { return std::fabs(a.x) + std::fabs(a.y) + std::fabs(a.z); }

// True when the projections p0..p2 of the triangle on an axis lie outside [-r, r].
bool separated(float p0, float p1, float p2, float r) {
  const float lo = std::min(std::min(p0, p1), p2);
  const float hi = std::max(std::max(p0, p1), p2);
  return lo > r || hi < -r;
}

int clamp_index(float v, int n) {
  const float f = std::floor(v);
  if (!(f >= 0.0f)) return 0;
  if (f >= float(n - 1)) return n - 1;
  return int(f);
}

void mark(std::uint8_t& cell) { std::atomic_ref<std::uint8_t>(cell).store(1, std::memory_order_relaxed); }
bool marked(std::uint8_t& cell) { return std::atomic_ref<std::uint8_t>(cell).load(std::memory_order_relaxed) != 0; }

}  // namespace

std::vector<glm::vec3> to_grid_units(std::span<const glm::vec3> world, const GridSpec& spec) {
  std::vector<glm::vec3> out(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) out[i] = (world[i] - spec.origin) / spec.voxel_size;
  return out;
}

int box_index(float v, int n) { return clamp_index(v + kVoxelTestEpsilon, n); }

bool triangle_overlaps_voxel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int x, int y, int z) {
  constexpr float h = 0.5f;                         // half extent of [i - eps, i + 1 - eps]
  constexpr float offset = 0.5f - kVoxelTestEpsilon;  // centre - i, exact in binary
  const glm::vec3 centre(float(x) + offset, float(y) + offset, float(z) + offset);
  const glm::vec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // The box's own axes.
  if (separated(v0.x, v1.x, v2.x, h) || separated(v0.y, v1.y, v2.y, h) || separated(v0.z, v1.z, v2.z, h))
    return false;
  // The nine cross products of box axes and triangle edges.
  const glm::vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  for (const glm::vec3& e : edges) {
    const glm::vec3 axes[3] = {glm::vec3(0.0f, -e.z, e.y), glm::vec3(e.z, 0.0f, -e.x), glm::vec3(-e.y, e.x, 0.0f)};
    for (const glm::vec3& axis : axes)
      if (separated(dot3(axis, v0), dot3(axis, v1), dot3(axis, v2), h * abs_sum(axis))) return false;
  }
  // The triangle's plane.
  const glm::vec3& e0 = edges[0];
  const glm::vec3& e1 = edges[1];
  const glm::vec3 n(e0.y * e1.z - e0.z * e1.y, e0.z * e1.x - e0.x * e1.z, e0.x * e1.y - e0.y * e1.x);
  const float d = dot3(n, v0);
  const float r = h * abs_sum(n);
  return !(d > r || d < -r);
}

VoxelGrid voxelize_cpu(const VoxelizeRequest& request, unsigned threads) {
  VoxelGrid grid(request.spec);
  const GridSpec& s = request.spec;
  const auto& p = request.grid_vertices;
  const auto voxel_of = [&](const glm::vec3& v) -> std::uint8_t& {
    return grid.cells[s.index(clamp_index(v.x, s.nx), clamp_index(v.y, s.ny), clamp_index(v.z, s.nz))];
  };
  if (request.mode == VoxelMode::Vertices) {  // Eq. 3.6
    detail::parallel_for(p.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t i = begin; i < end; ++i) mark(voxel_of(p[i]));
    });
    return grid;
  }
  // Triangle mode marks the voxels whose test cubes the triangles touch, and nothing else: a vertex no
  // triangle uses adds nothing, as it has no surface.
  const std::size_t triangles = request.indices.size() / 3;
  detail::parallel_for(triangles, threads, 1 << 12, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t t = begin; t < end; ++t) {
      const glm::vec3& a = p[request.indices[3 * t]];
      const glm::vec3& b = p[request.indices[3 * t + 1]];
      const glm::vec3& c = p[request.indices[3 * t + 2]];
      const glm::vec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
      const int x0 = box_index(lo.x, s.nx), x1 = box_index(hi.x, s.nx);
      const int y0 = box_index(lo.y, s.ny), y1 = box_index(hi.y, s.ny);
      const int z0 = box_index(lo.z, s.nz), z1 = box_index(hi.z, s.nz);
      if (x0 == x1 && y0 == y1 && z0 == z1) {  // inside one test cube: no test needed
        mark(grid.cells[s.index(x0, y0, z0)]);
        continue;
      }
      for (int z = z0; z <= z1; ++z)
        for (int x = x0; x <= x1; ++x)
          for (int y = y0; y <= y1; ++y) {
            std::uint8_t& cell = grid.cells[s.index(x, y, z)];
            if (!marked(cell) && triangle_overlaps_voxel(a, b, c, x, y, z)) mark(cell);
          }
    }
  });
  return grid;
}

std::vector<std::uint32_t> count_levels(const VoxelGrid& grid) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint32_t> counts(std::size_t(s.ny), 0);
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    const std::uint8_t* cells = grid.cells.data() + col * std::size_t(s.ny);
    for (int y = 0; y < s.ny; ++y) counts[std::size_t(y)] += cells[y];
  }
  return counts;
}

std::optional<FloorCeiling> select_floor_ceiling(std::span<const std::uint32_t> counts, int min_separation) {
  min_separation = std::max(1, min_separation);  // a floor is never its own ceiling
  const auto argmax = [&](auto&& allowed) {
    int best = -1;
    for (int y = 0; y < int(counts.size()); ++y)
      if (counts[std::size_t(y)] > 0 && allowed(y) && (best < 0 || counts[std::size_t(y)] > counts[std::size_t(best)]))
        best = y;
    return best;
  };
  const int first = argmax([](int) { return true; });
  if (first < 0) return std::nullopt;
  const int second = argmax([&](int y) { return std::abs(y - first) >= min_separation; });
  if (second < 0) return std::nullopt;
  FloorCeiling fc;
  fc.floor_peak = fc.floor = std::min(first, second);
  fc.ceiling_peak = fc.ceiling = std::max(first, second);
  const auto in_band = [&](int y, int peak) {
    return kSurfaceBandDivisor * counts[std::size_t(y)] >= counts[std::size_t(peak)];
  };
  // A band never reaches the other surface: I_Floor < I_Ceiling stays true.
  if (fc.floor + 1 < fc.ceiling && in_band(fc.floor + 1, fc.floor_peak)) ++fc.floor;
  if (fc.ceiling - 1 > fc.floor && in_band(fc.ceiling - 1, fc.ceiling_peak)) --fc.ceiling;
  return fc;
}

void count_columns(const VoxelGrid& grid, const std::optional<FloorCeiling>& levels,
                   std::vector<std::uint32_t>& column_counts, std::vector<std::uint8_t>& column_any) {
  const GridSpec& s = grid.spec;
  column_counts.assign(s.column_count(), 0);
  column_any.assign(s.column_count(), 0);
  if (!levels) return;
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    const std::uint8_t* cells = grid.cells.data() + col * std::size_t(s.ny);
    std::uint32_t n = 0;
    for (int y = levels->floor; y <= levels->ceiling; ++y) n += cells[y];
    column_counts[col] = n;
    column_any[col] = n > 0 ? 1 : 0;
  }
}

VoxelStageResult CpuVoxelStage::run(const VoxelizeRequest& request) {
  VoxelStageResult r;
  r.grid = voxelize_cpu(request, threads_);
  r.level_counts = count_levels(r.grid);
  r.levels = select_floor_ceiling(r.level_counts, request.min_separation_levels);
  count_columns(r.grid, r.levels, r.column_counts, r.column_any);
  return r;
}

}  // namespace roomsense
