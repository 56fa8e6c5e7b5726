// The room's inside (RoomFeatures::enclosed): beyond the thesis, a real scan holds what the headset saw through
// doors and windows (a corridor, the next room), and areas there are not in the room the user stands in.
#include "roomsense/features.h"

#include <algorithm>
#include <deque>

namespace roomsense {
namespace {

// Columns within `r` (Chebyshev distance) of a marked column: a separable running maximum.
std::vector<std::uint8_t> dilate(const GridSpec& s, const std::vector<std::uint8_t>& mask, int r) {
  std::vector<std::uint8_t> along_x(mask.size(), 0), out(mask.size(), 0);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      if (mask[s.column(x, z)])
        for (int i = std::max(0, x - r); i <= std::min(s.nx - 1, x + r); ++i) along_x[s.column(i, z)] = 1;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      if (along_x[s.column(x, z)])
        for (int j = std::max(0, z - r); j <= std::min(s.nz - 1, z + r); ++j) out[s.column(x, j)] = 1;
  return out;
}

// Columns outside B with B columns on all four sides along the axes: a patch the scan missed inside the room,
// not the space between the room and the grid's edge.
std::vector<std::uint8_t> enclosed_holes(const GridSpec& s, const std::vector<std::uint8_t>& room) {
  std::vector<std::uint8_t> sides(room.size(), 0);  // bit per side with a B column on it
  for (int z = 0; z < s.nz; ++z) {
    bool seen = false;
    for (int x = 0; x < s.nx; ++x) sides[s.column(x, z)] |= seen ? 1 : 0, seen = seen || room[s.column(x, z)];
    seen = false;
    for (int x = s.nx - 1; x >= 0; --x) sides[s.column(x, z)] |= seen ? 2 : 0, seen = seen || room[s.column(x, z)];
  }
  for (int x = 0; x < s.nx; ++x) {
    bool seen = false;
    for (int z = 0; z < s.nz; ++z) sides[s.column(x, z)] |= seen ? 4 : 0, seen = seen || room[s.column(x, z)];
    seen = false;
    for (int z = s.nz - 1; z >= 0; --z) sides[s.column(x, z)] |= seen ? 8 : 0, seen = seen || room[s.column(x, z)];
  }
  for (std::size_t c = 0; c < sides.size(); ++c) sides[c] = !room[c] && sides[c] == 15;
  return sides;
}
}  // namespace

std::vector<std::uint8_t> detect_enclosed(const GridSpec& s, const std::vector<std::uint8_t>& walls,
                                          const std::vector<std::uint8_t>& room, int max_opening_voxels) {
  const std::vector<std::uint8_t> all(s.column_count(), 1);
  const int r = (max_opening_voxels + 1) / 2;  // walls grown by r on both sides close a gap of 2r
  if (r <= 0) return all;
  const std::vector<std::uint8_t> closed = dilate(s, walls, r);
  // Outside: reachable from the grid's edge, 4-connected (a diagonal step between two wall columns is no way
  // through), first around the closed walls, then up to r further around the walls themselves: back out to the
  // openings, and r into them.
  std::vector<int> steps(s.column_count(), -1);
  std::deque<std::pair<int, int>> queue;
  const auto reach = [&](int x, int z, bool seed) {
    const std::size_t c = s.column(x, z);
    if (steps[c] >= 0 || walls[c] || (!seed && closed[c])) return;
    steps[c] = 0;
    queue.emplace_back(x, z);
  };
  // Every column on the grid's edge but walls is outside, closed or not: a pocket between a slanted wall and
  // the edge is outside too.
  for (int x = 0; x < s.nx; ++x) reach(x, 0, true), reach(x, s.nz - 1, true);
  for (int z = 0; z < s.nz; ++z) reach(0, z, true), reach(s.nx - 1, z, true);
  for (int pass = 0; pass < 2; ++pass) {
    // Pass 0 floods the outside of the closed walls; pass 1 grows it by r steps past them.
    if (pass == 1)
      for (int z = 0; z < s.nz; ++z)
        for (int x = 0; x < s.nx; ++x)
          if (steps[s.column(x, z)] == 0) queue.emplace_back(x, z);
    while (!queue.empty()) {
      const auto [x, z] = queue.front();
      queue.pop_front();
      const int step = steps[s.column(x, z)];
      if (pass == 1 && step >= r) continue;
      const int next = step + 1;
      if (pass == 0) {
        for (const auto& [dx, dz] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
          if (x + dx >= 0 && z + dz >= 0 && x + dx < s.nx && z + dz < s.nz) reach(x + dx, z + dz, false);
      } else {
        for (const auto& [dx, dz] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = x + dx, nz = z + dz;
          if (nx < 0 || nz < 0 || nx >= s.nx || nz >= s.nz) continue;
          const std::size_t c = s.column(nx, nz);
          if (steps[c] >= 0 || walls[c]) continue;
          steps[c] = next;
          queue.emplace_back(nx, nz);
        }
      }
    }
  }
  std::vector<std::uint8_t> enclosed(s.column_count(), 0);
  std::size_t room_columns = 0, inside = 0;
  for (std::size_t c = 0; c < enclosed.size(); ++c) {
    enclosed[c] = steps[c] < 0 ? 1 : 0;
    room_columns += room[c] && !walls[c];
    inside += room[c] && !walls[c] && enclosed[c];
  }
  // Walls that do not close (a scan with a wall missing) leave little inside: then nothing is outside.
  return 2 * inside < room_columns ? all : enclosed;
}

void cut_at_labelled_walls(const GridSpec& s, const FloorCeiling& levels, int y_end, const LabelGrid& labels,
                           const std::vector<std::uint8_t>& room, std::vector<std::uint8_t>& enclosed) {
  constexpr LabelMask kBoundary = label_bits({SurfaceLabel::Wall, SurfaceLabel::DoorFrame, SurfaceLabel::WindowFrame});
  if (!labels.has_any(kBoundary)) return;
  // A boundary column holds the labels both low in the room and above furniture height (I_yEnd): the side of a
  // cabinet or couch labelled wall closes nothing.
  const int y_from = std::max(levels.floor + 1, 0), y_to = std::min(levels.ceiling - 1, s.ny - 1);
  const int low_top = (levels.floor + levels.ceiling) / 2, high_from = std::min(y_end, y_to);
  std::vector<std::uint8_t> boundary(s.column_count(), 0);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      bool low = false, high = false;
      for (int y = y_from; y <= y_to; ++y)
        if (labels.at(s, x, y, z) & kBoundary) {
          low = low || y <= low_top;
          high = high || y >= high_from;
        }
      boundary[s.column(x, z)] = low && high;
    }
  // 4-connected components of the enclosed columns off the labelled boundary, with their room columns and
  // whether they reach the grid's edge.
  std::vector<int> component(s.column_count(), -1);
  struct Part {
    std::size_t room = 0;
    bool edge = false;
  };
  std::vector<Part> parts;
  for (int z0 = 0; z0 < s.nz; ++z0)
    for (int x0 = 0; x0 < s.nx; ++x0) {
      const std::size_t c0 = s.column(x0, z0);
      if (component[c0] >= 0 || !enclosed[c0] || boundary[c0]) continue;
      const int id = int(parts.size());
      parts.push_back({});
      std::deque<std::pair<int, int>> queue{{x0, z0}};
      component[c0] = id;
      while (!queue.empty()) {
        const auto [x, z] = queue.front();
        queue.pop_front();
        Part& part = parts[std::size_t(id)];
        part.room += room[s.column(x, z)];
        part.edge = part.edge || x == 0 || z == 0 || x == s.nx - 1 || z == s.nz - 1;
        for (const auto& [dx, dz] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = x + dx, nz = z + dz;
          if (nx < 0 || nz < 0 || nx >= s.nx || nz >= s.nz) continue;
          const std::size_t c = s.column(nx, nz);
          if (component[c] >= 0 || !enclosed[c] || boundary[c]) continue;
          component[c] = id;
          queue.emplace_back(nx, nz);
        }
      }
    }
  // The room is the largest part the labelled walls close off from the grid's edge; parts as large as half of
  // it are rooms too (the runtime labels each).
  std::size_t largest = 0, room_total = 0;
  for (const Part& p : parts) {
    if (!p.edge) largest = std::max(largest, p.room);
    room_total += p.room;
  }
  // Labels that leave less than half the room in one closed part (walls the runtime did not label, the sides
  // of furniture labelled wall) close nothing.
  if (2 * largest < room_total) return;
  for (std::size_t c = 0; c < enclosed.size(); ++c) {
    const int id = component[c];
    if (id >= 0 && (parts[std::size_t(id)].edge || 2 * parts[std::size_t(id)].room < largest)) enclosed[c] = 0;
  }
}

std::vector<std::uint8_t> room_inside(const GridSpec& s, const std::vector<std::uint8_t>& room,
                                      const std::vector<std::uint8_t>& enclosed) {
  if (std::find(enclosed.begin(), enclosed.end(), 0) == enclosed.end()) return room;  // the walls do not close
  const std::vector<std::uint8_t> holes = enclosed_holes(s, room);
  std::vector<std::uint8_t> inside(room.size(), 0);
  for (std::size_t c = 0; c < inside.size(); ++c) inside[c] = (room[c] || holes[c]) && enclosed[c];
  return inside;
}

}  // namespace roomsense
