// The bounds volume I (Eq. 3.60-3.62) and the hole filling of §3.6.
#include "roomsense/bounds.h"

#include <algorithm>

namespace roomsense {
namespace {

// §3.6's last step: an inactive voxel becomes active when, in any of the X-Z, X-Y and Y-Z planes, at least
// three of its four neighbours are active. Neighbours are read from the volume before this pass: the
// cells to fill are collected first and set afterwards.
void fill_plane_holes(const GridSpec& s, const FloorCeiling& levels, std::vector<std::uint8_t>& volume) {
  const auto at = [&](int x, int y, int z) { return s.contains(x, y, z) ? int(volume[s.index(x, y, z)]) : 0; };
  std::vector<std::size_t> fill;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      for (int y = levels.floor; y <= levels.ceiling; ++y) {
        if (volume[s.index(x, y, z)]) continue;
        const int left = at(x - 1, y, z), right = at(x + 1, y, z), down = at(x, y - 1, z), up = at(x, y + 1, z);
        const int back = at(x, y, z - 1), front = at(x, y, z + 1);
        const int xz = left + right + back + front, xy = left + right + down + up, yz = down + up + back + front;
        if (xz >= 3 || xy >= 3 || yz >= 3) fill.push_back(s.index(x, y, z));
      }
  for (std::size_t i : fill) volume[i] = 1;
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
  // Only levels that hold a solid voxel (and the one above them) can form a contact.
  int y_lo = s.ny, y_hi = -1;
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    const std::uint8_t* v = volume.data() + col * std::size_t(s.ny);
    for (int y = 0; y < s.ny; ++y)
      if (v[y]) {
        y_lo = std::min(y_lo, y);
        y_hi = std::max(y_hi, y);
      }
  }
  if (y_hi < 0) return;
  const int y_end = std::min(y_hi + 1, s.ny - 1);
  // A 2x2 block around an edge holds cells p, q (one diagonal) and r, t (the other). When one diagonal is
  // solid and the other empty, the empty pair is filled. Filling only adds solid voxels, so the loop ends;
  // in practice after one or two passes.
  const auto settle = [](std::uint8_t& p, std::uint8_t& q, std::uint8_t& r, std::uint8_t& t) {
    if (p && q && !r && !t) {
      r = t = 1;
      return true;
    }
    if (r && t && !p && !q) {
      p = q = 1;
      return true;
    }
    return false;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        std::uint8_t* c = volume.data() + s.column(x, z) * std::size_t(s.ny);
        std::uint8_t* cx = x + 1 < s.nx ? volume.data() + s.column(x + 1, z) * std::size_t(s.ny) : nullptr;
        std::uint8_t* cz = z + 1 < s.nz ? volume.data() + s.column(x, z + 1) * std::size_t(s.ny) : nullptr;
        std::uint8_t* cxz = cx && cz ? volume.data() + s.column(x + 1, z + 1) * std::size_t(s.ny) : nullptr;
        for (int y = y_lo; y <= y_end; ++y) {
          if (cxz) changed |= settle(c[y], cxz[y], cx[y], cz[y]);  // edge along y
          if (y + 1 < s.ny) {
            if (cx) changed |= settle(c[y], cx[y + 1], cx[y], c[y + 1]);  // edge along z
            if (cz) changed |= settle(c[y], cz[y + 1], cz[y], c[y + 1]);  // edge along x
          }
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
