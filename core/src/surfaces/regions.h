// Regions on the column raster (x, z) of a grid: 4-connected components and hole filling. The floor of a
// storey is one such region (the room mask B, Eq. 3.12), a furniture top another (a run of C, Eq. 3.13).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace roomsense::detail {

// One byte per column, laid out like GridSpec::column (z * nx + x), for the columns from (x0, z0) of the grid
// on: the whole grid, or the box around one region.
struct ColumnMask {
  int nx = 0, nz = 0;
  int x0 = 0, z0 = 0;
  std::vector<std::uint8_t> cells;

  ColumnMask() = default;
  ColumnMask(int x_count, int z_count, int x_first = 0, int z_first = 0)
      : nx(x_count), nz(z_count), x0(x_first), z0(z_first), cells(std::size_t(x_count) * std::size_t(z_count), 0) {}
  std::size_t column(int x, int z) const { return std::size_t(z) * std::size_t(nx) + std::size_t(x); }
  bool at(int x, int z) const { return x >= 0 && z >= 0 && x < nx && z < nz && cells[column(x, z)] != 0; }  // local x, z
  std::size_t count() const;
};

struct Components {
  std::vector<int> label;          // per column: the component, or -1 outside every one
  std::vector<std::size_t> sizes;  // columns per component; components are numbered in scan order of their first column
  std::vector<std::array<int, 4>> boxes;  // per component: lowest x, z and highest x, z
};

// The 4-connected components of the columns where `member` holds, two neighbours joined where `joins` holds
// (e.g. furniture levels at most one apart).
Components label_components(int nx, int nz, const std::function<bool(std::size_t)>& member,
                            const std::function<bool(std::size_t, std::size_t)>& joins);

// The columns of one component, in its box widened by one column all round (so that outside reaches round it).
ColumnMask component_mask(const Components& components, int nx, int label);

// The largest component (the first in scan order among equals), or -1 when there is none.
int largest_component(const Components& components);

// Fills every hole: the outside is what a 4-connected walk from beyond the raster's border reaches. The
// outline of a filled 4-connected region is then one simple lattice loop (no two parts touch at a corner
// only, since the pocket such a touch would close off is a hole).
ColumnMask fill_holes(const ColumnMask& region);

}  // namespace roomsense::detail
