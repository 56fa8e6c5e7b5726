// The bounds volume I (Eq. 3.60-3.62) and the hole filling of §3.6.
#include "roomsense/bounds.h"

#include <algorithm>

namespace roomsense {
namespace {

// §3.6's last step: an inactive voxel becomes active when, in any of the X-Z, X-Y and Y-Z planes, at least
// three of its four neighbours are active. Neighbours are read from the volume before this pass.
void fill_plane_holes(const GridSpec& s, const FloorCeiling& levels, std::vector<std::uint8_t>& volume) {
  const std::vector<std::uint8_t> before = volume;
  const auto at = [&](int x, int y, int z) { return s.contains(x, y, z) ? int(before[s.index(x, y, z)]) : 0; };
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      for (int y = levels.floor; y <= levels.ceiling; ++y) {
        if (before[s.index(x, y, z)]) continue;
        const int xz = at(x - 1, y, z) + at(x + 1, y, z) + at(x, y, z - 1) + at(x, y, z + 1);
        const int xy = at(x - 1, y, z) + at(x + 1, y, z) + at(x, y - 1, z) + at(x, y + 1, z);
        const int yz = at(x, y - 1, z) + at(x, y + 1, z) + at(x, y, z - 1) + at(x, y, z + 1);
        if (xz >= 3 || xy >= 3 || yz >= 3) volume[s.index(x, y, z)] = 1;
      }
}


}  // namespace

std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                        const std::vector<std::uint8_t>& room) {
  const GridSpec& s = grid.spec;
  y_end = std::clamp(y_end, levels.floor + 1, levels.ceiling - 1);
  std::vector<int> g(s.column_count()), h(s.column_count());
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    // G (Eq. 3.60): the highest active level in (I_Floor, I_yEnd]; else I_Floor inside the room; else -1.
    g[col] = room[col] ? levels.floor : -1;
    for (int y = y_end; y > levels.floor; --y)
      if (v[y]) {
        g[col] = y;
        break;
      }
    // H (Eq. 3.61): the lowest active level in [I_yEnd, I_Ceiling); else I_Ceiling inside the room; else
    // I_Ceiling + 1.
    h[col] = room[col] ? levels.ceiling : levels.ceiling + 1;
    for (int y = y_end; y < levels.ceiling; ++y)
      if (v[y]) {
        h[col] = y;
        break;
      }
  }
  // I (Eq. 3.62).
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    std::uint8_t* out = volume.data() + col * std::size_t(s.ny);
    for (int y = levels.floor; y <= g[col]; ++y) out[y] = 1;
    for (int y = h[col]; y <= levels.ceiling; ++y) out[y] = 1;
  }
  fill_plane_holes(s, levels, volume);
  return volume;
}

void fill_edge_contacts(const GridSpec& s, std::vector<std::uint8_t>& volume) {
  const auto solid = [&](int x, int y, int z) { return s.contains(x, y, z) && volume[s.index(x, y, z)]; };
  // The three ways a 2x2 block can sit around an edge: the edge runs along y, x or z.
  struct Plane {
    int ux, uy, uz, vx, vy, vz;
  };
  constexpr Plane kPlanes[] = {{1, 0, 0, 0, 0, 1}, {0, 1, 0, 0, 0, 1}, {1, 0, 0, 0, 1, 0}};
  // Filling only adds solid voxels, so the loop ends; in practice one or two passes.
  for (bool changed = true; changed;) {
    changed = false;
    for (const Plane& p : kPlanes)
      for (int z = 0; z < s.nz; ++z)
        for (int x = 0; x < s.nx; ++x)
          for (int y = 0; y < s.ny; ++y) {
            const bool a = solid(x, y, z), d = solid(x + p.ux + p.vx, y + p.uy + p.vy, z + p.uz + p.vz);
            const bool b = solid(x + p.ux, y + p.uy, z + p.uz), c = solid(x + p.vx, y + p.vy, z + p.vz);
            if (a && d && !b && !c) {
              volume[s.index(x + p.ux, y + p.uy, z + p.uz)] = 1;
              volume[s.index(x + p.vx, y + p.vy, z + p.vz)] = 1;
              changed = true;
            } else if (b && c && !a && !d) {
              volume[s.index(x, y, z)] = 1;
              volume[s.index(x + p.ux + p.vx, y + p.uy + p.vy, z + p.uz + p.vz)] = 1;
              changed = true;
            }
          }
  }
}

BoundsMesh build_bounds(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                        const std::vector<std::uint8_t>& room) {
  std::vector<std::uint8_t> volume = bounds_volume(grid, levels, y_end, room);
  fill_edge_contacts(grid.spec, volume);
  return greedy_mesh(grid.spec, volume);
}

}  // namespace roomsense
