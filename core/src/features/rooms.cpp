// Beyond the thesis (issue 15): a storey's free space split into rooms at doorways and narrow passages.
#include "roomsense/features.h"

#include "queries/distance_transform.h"
#include "surfaces/regions.h"

#include <algorithm>

namespace roomsense {

RoomSplit split_rooms(const GridSpec& spec, const std::vector<std::uint8_t>& inside,
                      const std::vector<std::uint8_t>& walls, float min_passage, float min_room_area) {
  const std::size_t columns = spec.column_count();
  std::vector<std::uint8_t> free(columns, 0);
  for (std::size_t c = 0; c < columns; ++c) free[c] = inside[c] && !walls[c] ? 1 : 0;
  // A core cell has more than half the passage to the nearest blocked cell, centre to centre: a corridor of
  // w cells has cores only when w > min_passage / voxel.
  const float core_cells = 0.5f * min_passage / spec.voxel_size;
  const std::vector<std::uint8_t> core = detail::farther_than(spec.nx, spec.nz, free, core_cells + 1e-3f);
  const detail::Components cores = detail::label_components(
      spec.nx, spec.nz, [&](std::size_t c) { return free[c] && core[c]; }, [](std::size_t, std::size_t) { return true; });

  // Every free column joins the core it reaches first through free columns (a breadth-first search from all
  // cores at once, 4-connected, in column order on ties): a doorway is split where the two fronts meet.
  std::vector<int> label(columns, kNoRoom);
  // First in, first out: the columns queued and not yet spread from start at `head`; each with its x and z.
  struct Queued {
    std::size_t column;
    int x, z;
  };
  std::vector<Queued> queue;
  std::size_t head = 0;
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x)
      if (const std::size_t c = spec.column(x, z); cores.label[c] >= 0) {
        label[c] = cores.label[c];
        queue.push_back({c, x, z});
      }
  int next = int(cores.sizes.size());
  // Breadth-first from the queued columns over free unlabelled ones, each taking its parent's label.
  const auto spread = [&] {
    for (; head < queue.size(); ++head) {
      const std::size_t c = queue[head].column;  // named copies: `visit` captures them (clang before 16
      // lets no lambda capture a structured binding)
      const int x = queue[head].x, z = queue[head].z;
      const auto visit = [&](bool inside, std::size_t nc, int xn, int zn) {
        if (!inside || !free[nc] || label[nc] != kNoRoom) return;
        label[nc] = label[c];
        queue.push_back({nc, xn, zn});
      };
      visit(x > 0, c - 1, x - 1, z);
      visit(x + 1 < spec.nx, c + 1, x + 1, z);
      visit(z > 0, c - std::size_t(spec.nx), x, z - 1);
      visit(z + 1 < spec.nz, c + std::size_t(spec.nx), x, z + 1);
    }
  };
  spread();
  // Free space no core reaches (a closet narrower than the passage) is a room of its own.
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x) {
      const std::size_t c = spec.column(x, z);
      if (!free[c] || label[c] != kNoRoom) continue;
      label[c] = next++;
      queue.push_back({c, x, z});
      spread();
    }

  // A room below min_room_area (a wide spot of a corridor, a core squeezed between two others) joins the room
  // it shares the longest border with, the smallest first; one with no neighbour belongs to no room.
  const double min_cells = double(min_room_area) / (double(spec.voxel_size) * double(spec.voxel_size));
  std::vector<std::size_t> size(std::size_t(next), 0);
  for (const int l : label)
    if (l != kNoRoom) ++size[std::size_t(l)];
  for (;;) {
    int small = -1;
    for (int l = 0; l < next; ++l)
      if (size[std::size_t(l)] > 0 && double(size[std::size_t(l)]) < min_cells &&
          (small < 0 || size[std::size_t(l)] < size[std::size_t(small)]))
        small = l;
    if (small < 0) break;
    std::vector<std::size_t> border(std::size_t(next), 0);
    for (int z = 0; z < spec.nz; ++z)
      for (int x = 0; x < spec.nx; ++x) {
        if (label[spec.column(x, z)] != small) continue;
        const int nbr[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
        for (const auto& n : nbr)
          if (n[0] >= 0 && n[1] >= 0 && n[0] < spec.nx && n[1] < spec.nz) {
            const int other = label[spec.column(n[0], n[1])];
            if (other != kNoRoom && other != small) ++border[std::size_t(other)];
          }
      }
    const auto most = std::max_element(border.begin(), border.end());
    const int into = *most > 0 ? int(most - border.begin()) : kNoRoom;
    for (int& l : label)
      if (l == small) l = into;
    if (into != kNoRoom) size[std::size_t(into)] += size[std::size_t(small)];
    size[std::size_t(small)] = 0;
  }

  // Rooms numbered by size, largest first (then by their first column), so that room 0 is the main room.
  std::vector<std::size_t> first(std::size_t(next), columns);
  for (std::size_t c = 0; c < columns; ++c)
    if (label[c] != kNoRoom) first[std::size_t(label[c])] = std::min(first[std::size_t(label[c])], c);
  std::vector<int> order;
  for (int l = 0; l < next; ++l)
    if (size[std::size_t(l)] > 0) order.push_back(l);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (size[std::size_t(a)] != size[std::size_t(b)]) return size[std::size_t(a)] > size[std::size_t(b)];
    return first[std::size_t(a)] < first[std::size_t(b)];
  });
  std::vector<int> rank(static_cast<std::size_t>(next), kNoRoom);
  for (std::size_t i = 0; i < order.size(); ++i) rank[std::size_t(order[i])] = int(i);
  RoomSplit out;
  out.count = int(order.size());
  out.room = std::move(label);
  for (int& r : out.room)
    if (r != kNoRoom) r = rank[std::size_t(r)];
  return out;
}

int room_at(const GridSpec& spec, const RoomSplit& rooms, int x, int z, int reach) {
  // The nearest labelled column by Chebyshev rings, then by scan order within a ring.
  for (int d = 0; d <= reach; ++d)
    for (int dz = -d; dz <= d; ++dz)
      for (int dx = -d; dx <= d; ++dx) {
        if (std::max(std::abs(dx), std::abs(dz)) != d) continue;
        const int cx = x + dx, cz = z + dz;
        if (cx < 0 || cz < 0 || cx >= spec.nx || cz >= spec.nz) continue;
        const int r = rooms.room[spec.column(cx, cz)];
        if (r != kNoRoom) return r;
      }
  return kNoRoom;
}

std::vector<int> rooms_of_mask(const GridSpec& spec, const std::vector<std::uint8_t>& mask, const RoomSplit& rooms,
                               int reach) {
  std::vector<int> out(spec.column_count(), kNoRoom);
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x)
      if (const std::size_t c = spec.column(x, z); mask[c]) out[c] = room_at(spec, rooms, x, z, reach);
  return out;
}

std::vector<std::uint8_t> room_mask(const std::vector<int>& rooms_of, int room) {
  std::vector<std::uint8_t> out(rooms_of.size(), 0);
  for (std::size_t c = 0; c < rooms_of.size(); ++c) out[c] = rooms_of[c] == room ? 1 : 0;
  return out;
}

std::vector<std::uint8_t> room_mask(const GridSpec& spec, const std::vector<std::uint8_t>& mask, const RoomSplit& rooms,
                                    int room, int reach) {
  return room_mask(rooms_of_mask(spec, mask, rooms, reach), room);
}

}  // namespace roomsense
