// Where a wall is open (RoomFeatures::wall_blocked): beyond the thesis, whose Eq. 3.25 lets a fifth of a wall
// rectangle lack wall voxels, so a rectangle may hang half over a window or a door. A person accepts no wall
// area over an opening, so the voxels before one block wall areas outright:
// - before a wall column whose surface is missing at that height, or lies deeper than a recess (a window, a
//   hole in the wall);
// - before a gap in a line of wall columns that is open down to the floor (a door), up to max_opening wide;
// - with the runtime's labels: before a surface labelled a window or door frame or a screen (wall art), and,
//   when the runtime labels walls, before any surface not labelled a wall.
#include "column_steps.h"
#include "roomsense/features.h"

#include <algorithm>
#include <cstring>
#include <optional>

namespace roomsense {
namespace {

struct Step {
  int dx, dz;
};
constexpr Step kSteps[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// The openings of one storey's walls, column by column: the doors of every column first (they read whole lines
// of columns), then any column's blocked voxels from the columns around it.
class Openings {
 public:
  // The lines whose doors are found: along x the rows [z_from, z_to], along z the columns [x_from, x_to].
  struct Lines {
    int z_from, z_to, x_from, x_to;
  };
  // How far a column's blocked voxels reach from a wall (the face's recess), for a recess of `recess_voxels`.
  static int depth(int recess_voxels) { return 1 + std::max(0, recess_voxels); }

  // The doors of `lines` (all, where not given): block() reads those of the columns beside the one it does.
  Openings(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& walls,
           const std::vector<std::uint8_t>& room, int recess_voxels, int max_opening_voxels, const LabelGrid& labels,
           std::optional<Lines> lines = std::nullopt)
      : grid_(grid), s_(grid.spec), walls_(walls), room_(room), labels_(labels),
        // The wall's face may lie one voxel further back than its column (a wall a little off vertical or off the
        // axes crosses voxel boundaries), plus the recess.
        depth_(depth(recess_voxels)),
        labelled_walls_(labels.has_any(label_bit(SurfaceLabel::Wall))),
        labelled_openings_(labels.has_any(kWallOpeningLabels)),
        y_from_(std::max(levels.floor + 1, 0)), y_to_(std::min(levels.ceiling - 1, s_.ny - 1)),
        door_(s_.column_count(), 0) {
    find_doors(levels, max_opening_voxels, lines.value_or(Lines{0, s_.nz - 1, 0, s_.nx - 1}));
  }

  // Sets the blocked voxels of column (x, z); whether it has any. Inlined: a call per column cost the hall 0.6 M
  // instructions.
  [[gnu::always_inline]] bool block(int x, int z, std::vector<std::uint8_t>& blocked) const {
    const std::size_t c = s_.column(x, z);
    if (walls_[c] || !room_[c]) return false;
    bool any = false;
    for (const Step& d : kSteps) {
      // The wall, if any, lies behind (x, z) at (x, z) - d; its face runs along `along`.
      const int bx = x - d.dx, bz = z - d.dz;
      if (!inside(bx, bz)) continue;
      const Step along{d.dz, d.dx};
      if (is_wall(bx, bz)) {
        for (int y = y_from_; y <= y_to_; ++y) {
          bool open = true;
          for (int k = 1; k <= depth_ && open; ++k)
            open = !(inside(x - k * d.dx, z - k * d.dz) && grid_.at(x - k * d.dx, y, z - k * d.dz));
          if (!open && !labels_.empty()) {
            // Across the face, the labels' planes lie off the scan by a few centimetres: look from the
            // voxel back to the recess. Openings need no margin on the face: voxelized, they already
            // overstate themselves by up to a voxel. Wall labels get one, so that a wall is not refused at
            // its labelled rectangle's edge.
            LabelMask near = 0, on = 0;
            for (int k = 0; k <= depth_ + 1; ++k) {
              near = LabelMask(near | labels_near(x - k * d.dx, y, z - k * d.dz, along, 1));
              on = LabelMask(on | labels_near(x - k * d.dx, y, z - k * d.dz, along, 0));
            }
            open = (labelled_openings_ && (on & kWallOpeningLabels)) ||
                   (labelled_walls_ && !(near & label_bit(SurfaceLabel::Wall)));
          }
          if (open) blocked[s_.index(x, y, z)] = 1, any = true;
        }
      } else if (door_[s_.column(bx, bz)] & (along.dx != 0 ? 1 : 2)) {
        for (int y = y_from_; y <= y_to_; ++y) blocked[s_.index(x, y, z)] = 1;
        any = true;
      }
    }
    return any;
  }

  // A column whose voxels or entries changed reaches the blocked voxels of the columns up to the depth after it
  // along each axis (their face's recess) and of the next ones (its door).
  int reach() const { return depth_; }

 private:
  bool inside(int x, int z) const { return x >= 0 && z >= 0 && x < s_.nx && z < s_.nz; }
  bool is_wall(int x, int z) const { return inside(x, z) && walls_[s_.column(x, z)] != 0; }
  // Labels of (x, y, z) and, with `reach` 1, of the voxels next to it on the wall's face.
  LabelMask labels_near(int x, int y, int z, Step along, int reach) const {
    LabelMask m = 0;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int i = -reach; i <= reach; ++i) m = LabelMask(m | labels_.at(s_, x + i * along.dx, y + dy, z + i * along.dz));
    return m;
  }

  // A door: column (x, z) lies in a gap of at most max_opening between wall columns along a grid axis, and is
  // open down to the floor (no voxel in the lower half of the room). Found for every column at once, from the
  // nearest wall column before and after it along each axis: bit 0 along x, bit 1 along z.
  void find_doors(const FloorCeiling& levels, int max_opening_voxels, const Lines& lines) {
    const int low_top = std::min(y_to_, levels.floor + std::max(1, (levels.ceiling - levels.floor) / 2));
    // The lower half's levels [low_from, low_end) within the column, empty for levels of no height.
    const int low_from = std::min(y_from_, s_.ny), low_end = std::max(low_from, std::min(low_top + 1, s_.ny));
    const auto along = [&](int first_line, int last_line, int length, auto column_at, std::uint8_t bit) {
      std::vector<int> previous(std::size_t(length), -1);
      for (int line = std::max(first_line, 0); line <= last_line; ++line) {
        for (int i = 0, wall = -1; i < length; ++i) {
          if (walls_[column_at(line, i)]) wall = i;
          previous[std::size_t(i)] = wall;
        }
        for (int i = length - 1, next = -1; i >= 0; --i) {
          const std::size_t col = column_at(line, i);
          if (walls_[col]) {
            next = i;
            continue;
          }
          if (next < 0 || previous[std::size_t(i)] < 0 || next - previous[std::size_t(i)] - 1 > max_opening_voxels)
            continue;
          const std::uint8_t* v = grid_.cells.data() + col * std::size_t(s_.ny);
          if (std::none_of(v + low_from, v + low_end, [](std::uint8_t c) { return c != 0; })) door_[col] |= bit;
        }
      }
    };
    along(lines.z_from, std::min(lines.z_to, s_.nz - 1), s_.nx, [&](int z, int x) { return s_.column(x, z); }, 1);
    along(lines.x_from, std::min(lines.x_to, s_.nx - 1), s_.nz, [&](int x, int z) { return s_.column(x, z); }, 2);
  }

  const VoxelGrid& grid_;
  const GridSpec& s_;
  const std::vector<std::uint8_t>& walls_;
  const std::vector<std::uint8_t>& room_;
  const LabelGrid& labels_;
  int depth_;
  bool labelled_walls_, labelled_openings_;
  int y_from_, y_to_;
  std::vector<std::uint8_t> door_;
};

}  // namespace

std::vector<std::uint8_t> detect_wall_openings(const VoxelGrid& grid, const FloorCeiling& levels,
                                               const std::vector<std::uint8_t>& walls,
                                               const std::vector<std::uint8_t>& room, int recess_voxels,
                                               int max_opening_voxels, const LabelGrid& labels) {
  const GridSpec& s = grid.spec;
  const Openings openings(grid, levels, walls, room, recess_voxels, max_opening_voxels, labels);
  std::vector<std::uint8_t> blocked(s.voxel_count(), 0);
  bool any = false;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) any = openings.block(x, z, blocked) || any;
  if (!any) blocked.clear();
  return blocked;
}

void detail::update_wall_openings(const VoxelGrid& grid, const FloorCeiling& levels,
                                  const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room,
                                  int recess_voxels, int max_opening_voxels, const LabelGrid& labels,
                                  std::span<const std::uint32_t> changed, std::vector<std::uint8_t>& blocked) {
  if (changed.empty()) return;
  const GridSpec& s = grid.spec;
  // The columns done again lie within the depth (at least 1) of a changed one along an axis; block() reads the
  // doors of the columns beside them: those of the lines a column further out.
  const int reach = Openings::depth(recess_voxels) + 1;
  Openings::Lines lines{s.nz, -1, s.nx, -1};
  for (const std::uint32_t c : changed) {
    const int x = int(c % std::uint32_t(s.nx)), z = int(c / std::uint32_t(s.nx));
    lines = {std::min(lines.z_from, z - reach), std::max(lines.z_to, z + reach), std::min(lines.x_from, x - reach),
             std::max(lines.x_to, x + reach)};
  }
  const Openings openings(grid, levels, walls, room, recess_voxels, max_opening_voxels, labels, lines);
  const bool none_before = blocked.empty();
  if (none_before) blocked.assign(s.voxel_count(), 0);
  bool any = false;
  detail::redo_along_axes(s, changed, openings.reach(), blocked,
                          [&](int x, int z) { any = openings.block(x, z, blocked) || any; });
  // Whether any voxel is blocked now: where none was, only in the columns done again; else memchr over them all
  // (std::find reads a byte at a time: 28 us of an update of thesis-room1, whose grid is 0.12 MB).
  if (none_before ? !any : std::memchr(blocked.data(), 1, blocked.size()) == nullptr) blocked.clear();
}

}  // namespace roomsense
