// Regions on the column raster (x, z) of a grid: 4-connected components and hole filling. The floor of a
// storey is one such region (the room mask B, Eq. 3.12), a furniture top another (a run of C, Eq. 3.13).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
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

// The 4-connected components of the columns where `member(column)` holds, two neighbours joined where
// `joins(column, neighbour)` holds (e.g. furniture levels at most one apart). A template, so that `member` and `joins`
// inline: called through std::function, they took most of the time a room's split spent labelling its cores.
template <class Member, class Joins>
Components label_components(int nx, int nz, const Member& member, const Joins& joins) {
  Components out;
  out.label.assign(std::size_t(nx) * std::size_t(nz), -1);
  // A breadth-first walk from each column no component holds yet, in scan order; each queued column with its x
  // and z (no division to find them again).
  struct Queued {
    std::size_t column;
    int x, z;
  };
  std::vector<Queued> queue;
  for (int seed_z = 0; seed_z < nz; ++seed_z)
    for (int seed_x = 0; seed_x < nx; ++seed_x) {
      const std::size_t seed = std::size_t(seed_z) * std::size_t(nx) + std::size_t(seed_x);
      if (out.label[seed] >= 0 || !member(seed)) continue;
      const int id = int(out.sizes.size());
      out.label[seed] = id;
      queue.assign(1, {seed, seed_x, seed_z});
      std::array<int, 4> box{seed_x, seed_z, seed_x, seed_z};
      for (std::size_t head = 0; head < queue.size(); ++head) {
        // Named copies, not structured bindings: clang before 16 lets no lambda capture those.
        const std::size_t col = queue[head].column;
        const int x = queue[head].x, z = queue[head].z;
        box = {std::min(box[0], x), std::min(box[1], z), std::max(box[2], x), std::max(box[3], z)};
        const auto visit = [&](bool inside, std::size_t next, int xn, int zn) {
          if (!inside || out.label[next] >= 0 || !member(next) || !joins(col, next)) return;
          out.label[next] = id;
          queue.push_back({next, xn, zn});
        };
        visit(x > 0, col - 1, x - 1, z);
        visit(x + 1 < nx, col + 1, x + 1, z);
        visit(z > 0, col - std::size_t(nx), x, z - 1);
        visit(z + 1 < nz, col + std::size_t(nx), x, z + 1);
      }
      out.sizes.push_back(queue.size());
      out.boxes.push_back(box);
    }
  return out;
}

// The columns of one component, in its box widened by one column all round (so that outside reaches round it).
ColumnMask component_mask(const Components& components, int nx, int label);

// The largest component (the first in scan order among equals), or -1 when there is none.
int largest_component(const Components& components);

// Fills every hole: the outside is what a 4-connected walk from beyond the raster's border reaches. The
// outline of a filled 4-connected region is then one simple lattice loop (no two parts touch at a corner
// only, since the pocket such a touch would close off is a hole).
ColumnMask fill_holes(const ColumnMask& region);

}  // namespace roomsense::detail
