// Wall normals F (Alg. 1).
#include "roomsense/features.h"

namespace roomsense {

std::vector<std::uint8_t> detect_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels,
                                              const std::vector<int>& ceiling, int reach,
                                              const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room,
                                              const std::vector<int>& furniture) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> normals(s.voxel_count(), 0);
  // A step (x, z) is free at level y when it is inside the grid, no wall, no voxel, in the room, and not at
  // or below a furniture top; beyond the thesis, below the column's own ceiling (a wall ends at a roof's slope
  // or a soffit's underside). Alg. 1 lets the Left/Backward scans silently skip indices below 0; we treat
  // leaving the grid as blocked on every side, since outside the grid is outside the room (b = 0) anyway.
  const auto free_at = [&](int x, int y, int z) {
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz) return false;
    const std::size_t col = s.column(x, z);
    return !walls[col] && !grid.at(x, y, z) && room[col] && furniture[col] < y &&
           (ceiling[col] >= levels.ceiling || y < ceiling[col]);
  };
  // Beyond the thesis: a run of half the reach that ends at a wall, or where the room ends, is clear too: an
  // alcove or a corridor narrower than the reach still has walls to hang things on. A run that ends at a voxel
  // (furniture, clutter) is not.
  const auto ends_room = [&](int x, int z) {
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz) return true;
    const std::size_t col = s.column(x, z);
    return walls[col] || !room[col];
  };
  const auto clear_run = [&](int x, int y, int z, int dx, int dz) {
    for (int i = 1; i <= reach; ++i)
      if (!free_at(x + i * dx, y, z + i * dz)) return 2 * (i - 1) >= reach && ends_room(x + i * dx, z + i * dz);
    return true;
  };
  struct Direction {
    int dx, dz;
    std::uint8_t bit;
  };
  constexpr Direction kDirections[] = {
      {-1, 0, kNormalLeft}, {1, 0, kNormalRight}, {0, -1, kNormalBackward}, {0, 1, kNormalForward}};
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      if (!walls[s.column(x, z)]) continue;
      for (int y = levels.floor; y <= levels.ceiling; ++y)
        for (const Direction& d : kDirections)
          if (clear_run(x, y, z, d.dx, d.dz)) normals[s.index(x + d.dx, y, z + d.dz)] |= d.bit;
    }
  return normals;
}

}  // namespace roomsense
