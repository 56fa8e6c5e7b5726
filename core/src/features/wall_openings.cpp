// Where a wall is open (RoomFeatures::wall_blocked): beyond the thesis, whose Eq. 3.25 lets a fifth of a wall
// rectangle lack wall voxels, so a rectangle may hang half over a window or a door. A person accepts no wall
// area over an opening, so the voxels before one block wall areas outright:
// - before a wall column whose surface is missing at that height, or lies deeper than a recess (a window, a
//   hole in the wall);
// - before a gap in a line of wall columns that is open down to the floor (a door), up to max_opening wide;
// - with the runtime's labels: before a surface labelled a window or door frame or a screen (wall art), and,
//   when the runtime labels walls, before any surface not labelled a wall.
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {
namespace {

struct Step {
  int dx, dz;
};
constexpr Step kSteps[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

}  // namespace

std::vector<std::uint8_t> detect_wall_openings(const VoxelGrid& grid, const FloorCeiling& levels,
                                               const std::vector<std::uint8_t>& walls,
                                               const std::vector<std::uint8_t>& room, int recess_voxels,
                                               int max_opening_voxels, const LabelGrid& labels) {
  const GridSpec& s = grid.spec;
  // The wall's face may lie one voxel further back than its column (a wall a little off vertical or off the
  // axes crosses voxel boundaries), plus the recess.
  const int depth = 1 + std::max(0, recess_voxels);
  const bool labelled_walls = labels.has_any(label_bit(SurfaceLabel::Wall));
  const bool labelled_openings = labels.has_any(kWallOpeningLabels);
  const int y_from = std::max(levels.floor + 1, 0), y_to = std::min(levels.ceiling - 1, s.ny - 1);
  const auto inside = [&](int x, int z) { return x >= 0 && z >= 0 && x < s.nx && z < s.nz; };
  const auto is_wall = [&](int x, int z) { return inside(x, z) && walls[s.column(x, z)] != 0; };
  // Labels of (x, y, z) and, with `reach` 1, of the voxels next to it on the wall's face.
  const auto labels_near = [&](int x, int y, int z, Step along, int reach) {
    LabelMask m = 0;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int i = -reach; i <= reach; ++i) m = LabelMask(m | labels.at(s, x + i * along.dx, y + dy, z + i * along.dz));
    return m;
  };
  // A door: column (x, z) lies in a gap of at most max_opening between wall columns along a grid axis, and is
  // open down to the floor (no voxel in the lower half of the room). Found for every column at once, from the
  // nearest wall column before and after it along each axis: bit 0 along x, bit 1 along z.
  const int low_top = std::min(y_to, levels.floor + std::max(1, (levels.ceiling - levels.floor) / 2));
  // The lower half's levels [low_from, low_end) within the column, empty for levels of no height.
  const int low_from = std::min(y_from, s.ny), low_end = std::max(low_from, std::min(low_top + 1, s.ny));
  std::vector<std::uint8_t> door(s.column_count(), 0);
  const auto find_doors = [&](int lines, int length, auto column_at, std::uint8_t bit) {
    std::vector<int> previous(std::size_t(length), -1);
    for (int line = 0; line < lines; ++line) {
      for (int i = 0, wall = -1; i < length; ++i) {
        if (walls[column_at(line, i)]) wall = i;
        previous[std::size_t(i)] = wall;
      }
      for (int i = length - 1, next = -1; i >= 0; --i) {
        const std::size_t col = column_at(line, i);
        if (walls[col]) {
          next = i;
          continue;
        }
        if (next < 0 || previous[std::size_t(i)] < 0 || next - previous[std::size_t(i)] - 1 > max_opening_voxels) continue;
        const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
        if (std::none_of(v + low_from, v + low_end, [](std::uint8_t c) { return c != 0; })) door[col] |= bit;
      }
    }
  };
  find_doors(s.nz, s.nx, [&](int z, int x) { return s.column(x, z); }, 1);
  find_doors(s.nx, s.nz, [&](int x, int z) { return s.column(x, z); }, 2);

  std::vector<std::uint8_t> blocked(s.voxel_count(), 0);
  bool any = false;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t c = s.column(x, z);
      if (walls[c] || !room[c]) continue;
      for (const Step& d : kSteps) {
        // The wall, if any, lies behind (x, z) at (x, z) - d; its face runs along `along`.
        const int bx = x - d.dx, bz = z - d.dz;
        if (!inside(bx, bz)) continue;
        const Step along{d.dz, d.dx};
        if (is_wall(bx, bz)) {
          for (int y = y_from; y <= y_to; ++y) {
            bool open = true;
            for (int k = 1; k <= depth && open; ++k)
              open = !(inside(x - k * d.dx, z - k * d.dz) && grid.at(x - k * d.dx, y, z - k * d.dz));
            if (!open && !labels.empty()) {
              // Across the face, the labels' planes lie off the scan by a few centimetres: look from the
              // voxel back to the recess. Openings need no margin on the face: voxelized, they already
              // overstate themselves by up to a voxel. Wall labels get one, so that a wall is not refused at
              // its labelled rectangle's edge.
              LabelMask near = 0, on = 0;
              for (int k = 0; k <= depth + 1; ++k) {
                near = LabelMask(near | labels_near(x - k * d.dx, y, z - k * d.dz, along, 1));
                on = LabelMask(on | labels_near(x - k * d.dx, y, z - k * d.dz, along, 0));
              }
              open = (labelled_openings && (on & kWallOpeningLabels)) ||
                     (labelled_walls && !(near & label_bit(SurfaceLabel::Wall)));
            }
            if (open) blocked[s.index(x, y, z)] = 1, any = true;
          }
        } else if (door[s.column(bx, bz)] & (along.dx != 0 ? 1 : 2)) {
          for (int y = y_from; y <= y_to; ++y) blocked[s.index(x, y, z)] = 1;
          any = true;
        }
      }
    }
  if (!any) blocked.clear();
  return blocked;
}

}  // namespace roomsense
