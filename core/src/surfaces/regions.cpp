// See regions.h.
#include "regions.h"

#include <algorithm>

namespace roomsense::detail {

std::size_t ColumnMask::count() const {
  return std::size_t(std::count_if(cells.begin(), cells.end(), [](std::uint8_t c) { return c != 0; }));
}

ColumnMask component_mask(const Components& components, int nx, int label) {
  const std::array<int, 4>& box = components.boxes[std::size_t(label)];
  ColumnMask mask(box[2] - box[0] + 3, box[3] - box[1] + 3, box[0] - 1, box[1] - 1);
  for (int z = box[1]; z <= box[3]; ++z)
    for (int x = box[0]; x <= box[2]; ++x)
      if (components.label[std::size_t(z) * std::size_t(nx) + std::size_t(x)] == label)
        mask.cells[mask.column(x - mask.x0, z - mask.z0)] = 1;
  return mask;
}

int largest_component(const Components& components) {
  int best = -1;
  for (std::size_t i = 0; i < components.sizes.size(); ++i)
    if (best < 0 || components.sizes[i] > components.sizes[std::size_t(best)]) best = int(i);
  return best;
}

ColumnMask fill_holes(const ColumnMask& region) {
  const int nx = region.nx, nz = region.nz;
  std::vector<std::uint8_t> outside(region.cells.size(), 0);
  std::vector<std::size_t> queue;
  const auto reach = [&](int x, int z) {
    if (x < 0 || z < 0 || x >= nx || z >= nz) return;
    const std::size_t c = region.column(x, z);
    if (region.cells[c] || outside[c]) return;
    outside[c] = 1;
    queue.push_back(c);
  };
  for (int x = 0; x < nx; ++x) {
    reach(x, 0);
    reach(x, nz - 1);
  }
  for (int z = 0; z < nz; ++z) {
    reach(0, z);
    reach(nx - 1, z);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int x = int(queue[head] % std::size_t(nx)), z = int(queue[head] / std::size_t(nx));
    reach(x - 1, z);
    reach(x + 1, z);
    reach(x, z - 1);
    reach(x, z + 1);
  }
  ColumnMask filled = region;
  for (std::size_t c = 0; c < filled.cells.size(); ++c) filled.cells[c] = outside[c] ? 0 : 1;
  return filled;
}

}  // namespace roomsense::detail
