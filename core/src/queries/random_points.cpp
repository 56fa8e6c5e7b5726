// random_point_on_surface and random_point_in_room (queries.h): rejection sampling over the free cells, each draw
// checked exactly, with a fixed number of tries so that a room with almost no such space answers quickly.
#include "query_support.h"
#include "room_index.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense {
namespace {

constexpr int kTries = 256;

// Is every raster cell within `radius` of p (cell units) one for which ok(x, z) holds?
template <class Ok>
bool disc_on(const glm::dvec2& p, double radius, Ok&& ok) {
  const int x0 = int(std::floor(p.x - radius)), x1 = int(std::floor(p.x + radius));
  const int z0 = int(std::floor(p.y - radius)), z1 = int(std::floor(p.y + radius));
  for (int z = z0; z <= z1; ++z)
    for (int x = x0; x <= x1; ++x) {
      const double dx = std::max({double(x) - p.x, 0.0, p.x - double(x + 1)});
      const double dz = std::max({double(z) - p.y, 0.0, p.y - double(z + 1)});
      if (dx * dx + dz * dz < radius * radius && !ok(x, z)) return false;
    }
  return ok(int(std::floor(p.x)), int(std::floor(p.y)));
}

}  // namespace

std::optional<SurfacePoint> RoomQueries::random_point_on_surface(std::uint32_t surfaces, float edge_distance,
                                                                 std::uint64_t seed) const {
  detail::check_surfaces(surfaces);
  detail::check_length(edge_distance, "edge_distance");
  if (!index_) return std::nullopt;
  const Index& ix = *index_;
  const GridSpec& s = ix.spec;
  const double voxel = s.voxel_size;
  const std::size_t floors = surfaces & kOnFloor ? ix.floor_cells.size() : 0;
  const std::size_t ceilings = surfaces & kOnCeiling ? ix.ceiling_cells.size() : 0;
  const std::size_t tops = surfaces & kOnFurniture ? ix.top_cells.size() : 0;
  const std::size_t walls = surfaces & kOnWall ? ix.wall_cells.size() : 0;
  const std::size_t total = floors + ceilings + tops + walls;  // every cell is one voxel's square: uniform by area
  if (total == 0) return std::nullopt;
  detail::SeededRandom random{seed};
  const double radius = double(edge_distance) / voxel;
  const auto in_grid = [&](int x, int z) { return x >= 0 && z >= 0 && x < s.nx && z < s.nz; };
  for (int attempt = 0; attempt < kTries; ++attempt) {
    std::size_t pick = random.below(total);
    const glm::dvec2 offset(random.unit(), random.unit());
    if (pick < floors + ceilings + tops) {
      AreaType type = AreaType::Floor;
      std::uint32_t column = 0;
      if (pick < floors) {
        column = ix.floor_cells[pick];
      } else if (pick < floors + ceilings) {
        type = AreaType::Ceiling;
        column = ix.ceiling_cells[pick - floors];
      } else {
        type = AreaType::Furniture;
        column = ix.top_cells[pick - floors - ceilings];
      }
      const glm::dvec2 p(double(column % std::uint32_t(s.nx)) + offset.x, double(column / std::uint32_t(s.nx)) + offset.y);
      const auto ok = [&](int x, int z) {
        if (!in_grid(x, z)) return false;
        const std::size_t c = s.column(x, z);
        if (type == AreaType::Floor) return ix.floor_clear[c] >= 0.0f;
        if (type == AreaType::Ceiling) return ix.ceiling_clear[c] >= 0.0f;
        return ix.top_region[c] == ix.top_region[column];
      };
      if (!disc_on(p, radius, ok)) continue;
      const float y = type == AreaType::Floor     ? ix.floor_y
                      : type == AreaType::Ceiling ? ix.ceiling_y
                                                  : ix.top_y(ix.top_level[column]);
      return SurfacePoint{glm::vec3(s.origin.x + float(p.x * voxel), y, s.origin.z + float(p.y * voxel)),
                          glm::vec3(0.0f, type == AreaType::Ceiling ? -1.0f : 1.0f, 0.0f), type};
    }
    pick -= floors + ceilings + tops;
    const auto [face_index, cell] = ix.wall_cells[pick];
    const WallFace& face = ix.faces[face_index];
    const glm::dvec2 p(double(cell % std::uint32_t(face.nu)) + offset.x, double(cell / std::uint32_t(face.nu)) + offset.y);
    const auto ok = [&](int u, int v) {
      return u >= 0 && v >= 0 && u < face.nu && v < face.nv &&
             face.depth[std::size_t(v) * std::size_t(face.nu) + std::size_t(u)] > 0.0f;
    };
    if (!disc_on(p, radius, ok)) continue;
    const glm::vec3 position = face.start + face.x_axis * float(p.x * voxel) +
                               glm::vec3(0.0f, ix.top_y(face.level0) + float(p.y * voxel), 0.0f);
    return SurfacePoint{position, face.normal, AreaType::Wall};
  }
  return std::nullopt;
}

std::optional<glm::vec3> RoomQueries::random_point_in_room(float clearance, std::uint64_t seed) const {
  detail::check_length(clearance, "clearance");
  if (!index_ || index_->inside_cells.empty()) return std::nullopt;
  const Index& ix = *index_;
  const GridSpec& s = ix.spec;
  const float voxel = s.voxel_size;
  // A ball that cannot fit between floor and ceiling, or across the grid, fits nowhere: say so at once rather
  // than walk a huge cube of voxels per try. Otherwise p's height is drawn where the ball clears both.
  const float low = ix.floor_y + clearance, high = ix.ceiling_y - clearance;
  if (low > high || 2.0f * clearance > voxel * float(std::min(s.nx, s.nz))) return std::nullopt;
  detail::SeededRandom random{seed};
  for (int attempt = 0; attempt < kTries; ++attempt) {
    const std::uint32_t column = ix.inside_cells[random.below(ix.inside_cells.size())];
    const float x = s.origin.x + (float(column % std::uint32_t(s.nx)) + float(random.unit())) * voxel;
    const float z = s.origin.z + (float(column / std::uint32_t(s.nx)) + float(random.unit())) * voxel;
    const float y = low + float(random.unit()) * (high - low);
    const glm::vec3 p(x, y, z);
    // No solid voxel (scanned, or outside the room) within `clearance` of p, nor at p.
    const glm::vec3 g = (p - s.origin) / voxel;
    const float r = clearance / voxel;
    bool clear = true;
    for (int vz = int(std::floor(g.z - r)); clear && vz <= int(std::floor(g.z + r)); ++vz)
      for (int vy = int(std::floor(g.y - r)); clear && vy <= int(std::floor(g.y + r)); ++vy)
        for (int vx = int(std::floor(g.x - r)); clear && vx <= int(std::floor(g.x + r)); ++vx) {
          const glm::vec3 lo{float(vx), float(vy), float(vz)};
          const glm::vec3 d = glm::max(glm::max(lo - g, g - (lo + 1.0f)), glm::vec3(0.0f));
          if (glm::dot(d, d) <= r * r && ix.solid(vx, vy, vz)) clear = false;
        }
    if (clear) return p;
  }
  return std::nullopt;
}

}  // namespace roomsense
