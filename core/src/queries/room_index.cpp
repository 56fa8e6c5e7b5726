// Building a RoomQueries: the analysis's grid and features read once into the rasters of room_index.h.
#include "room_index.h"

#include "areas/classify.h"
#include "distance_transform.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <cmath>
#include <numbers>

namespace roomsense {
namespace {

static_assert(std::endian::native == std::endian::little);  // a word's lowest byte is the lowest level read

// The first occupied level in [from, to), or `to`. Eight levels a word: most columns are free for metres.
int first_occupied_up(const std::uint8_t* column, int from, int to) {
  int y = std::max(from, 0);
  for (; y + 8 <= to; y += 8) {
    std::uint64_t word;
    std::memcpy(&word, column + y, sizeof word);
    if (word != 0) return y + std::countr_zero(word) / 8;
  }
  for (; y < to; ++y)
    if (column[y]) return y;
  return to;
}

// The highest occupied level in (to, from], or `to`.
int first_occupied_down(const std::uint8_t* column, int from, int to) {
  int y = from;
  for (; y - 8 >= to; y -= 8) {
    std::uint64_t word;
    std::memcpy(&word, column + y - 7, sizeof word);
    if (word != 0) return y - std::countl_zero(word) / 8;
  }
  for (; y > to; --y)
    if (column[y]) return y;
  return to;
}

// Connected furniture tops: 4-neighbours whose C (Eq. 3.13) differs by at most one level (y_Actual, Eq. 3.41).
std::vector<std::int32_t> label_tops(const GridSpec& s, const std::vector<int>& furniture) {
  std::vector<std::int32_t> region(s.column_count(), -1);
  std::vector<std::size_t> stack;
  std::int32_t next = 0;
  for (std::size_t seed = 0; seed < region.size(); ++seed) {
    if (furniture[seed] == kNoFurniture || region[seed] >= 0) continue;
    region[seed] = next;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      const int x = int(c % std::size_t(s.nx)), z = int(c / std::size_t(s.nx));
      const int neighbours[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
      for (const auto& n : neighbours) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= s.nx || n[1] >= s.nz) continue;
        const std::size_t m = s.column(n[0], n[1]);
        if (region[m] >= 0 || furniture[m] == kNoFurniture || std::abs(furniture[m] - furniture[c]) > 1) continue;
        region[m] = next;
        stack.push_back(m);
      }
    }
    ++next;
  }
  return region;
}

// The wall normals F that face `normal` (within 70°: a wall at 30° to the grid is a staircase whose front voxels
// face either axis).
std::uint8_t facing_bits(const glm::vec3& normal) {
  std::uint8_t bits = 0;
  for (std::uint8_t b : {kNormalLeft, kNormalRight, kNormalForward, kNormalBackward})
    if (glm::dot(detail::normal_bits_direction(b), normal) > 0.34f) bits |= b;
  return bits;
}

// The occupied voxels of the wall faces' rows, levels [level0, level0 + rows), a bit per level and a few words per
// column, made at a column's first ask: a face's clear space is marched for all its rows at once, a word at a
// time, where a march per row read a byte per sample.
class LevelBits {
 public:
  LevelBits(const GridSpec& spec, const std::vector<std::uint8_t>& cells, int level0, int rows)
      : spec_(spec), cells_(cells), level0_(level0), rows_(std::max(rows, 0)),
        words_per_column_((std::size_t(rows_) + 63) / 64), made_(spec.column_count(), 0),
        bits_(spec.column_count() * words_per_column_, 0) {}
  std::size_t words() const { return words_per_column_; }
  const std::uint64_t* of(std::size_t column) {
    std::uint64_t* out = bits_.data() + column * words_per_column_;
    if (made_[column]) return out;
    made_[column] = 1;
    const std::uint8_t* levels = cells_.data() + column * std::size_t(spec_.ny) + std::size_t(level0_);
    for (int r = 0; r < rows_; r += 8) {
      std::uint64_t eight = 0;  // byte i: level r + i
      if (r + 8 <= rows_)
        std::memcpy(&eight, levels + r, sizeof eight);
      else
        for (int i = 0; r + i < rows_; ++i) eight |= std::uint64_t(levels[r + i]) << (8 * i);
      // Each byte to one bit: its bits or-ed into its lowest, then gathered into the top byte (byte i to bit i).
      eight |= eight >> 4, eight |= eight >> 2, eight |= eight >> 1;
      eight &= 0x0101010101010101ull;
      const std::uint64_t byte = (eight * 0x0102040810204080ull) >> 56;
      out[std::size_t(r / 64)] |= byte << (r % 64);
    }
    return out;
  }

 private:
  const GridSpec& spec_;
  const std::vector<std::uint8_t>& cells_;
  int level0_, rows_;
  std::size_t words_per_column_;
  std::vector<std::uint8_t> made_;
  std::vector<std::uint64_t> bits_;
};

WallFace wall_face(const RoomQueries::Index& ix, const RoomFeatures& f, const Surface& wall, LevelBits& occupied) {
  const GridSpec& s = ix.spec;
  const float voxel = s.voxel_size;
  WallFace face;
  face.storey = wall.storey;
  face.x_axis = glm::normalize(glm::vec3(wall.x_axis.x, 0.0f, wall.x_axis.z));
  face.normal = glm::normalize(glm::vec3(wall.normal.x, 0.0f, wall.normal.z));
  face.start = wall.center - face.x_axis * (0.5f * wall.extents.x);
  face.start.y = 0.0f;
  face.nu = std::max(1, int(std::lround(wall.extents.x / voxel)));
  face.level0 = ix.levels.floor + 1;
  face.nv = std::max(0, ix.levels.ceiling - face.level0);
  face.depth.assign(std::size_t(face.nu) * std::size_t(face.nv), 0.0f);
  const std::uint8_t facing = facing_bits(face.normal);
  constexpr float kMaxDepth = 4.0f;  // metres: deeper is as good as unlimited for any query
  constexpr int kSteps = 10;         // the first free voxel is looked for 0.25 to 2.5 voxels in front
  // Every sample below lies at p + normal * distance, with p on the plane at y = 0: its column depends on the cell's
  // u alone, not on its level. So each u's columns are found once, with the very same float arithmetic, and the
  // rows are marched together, a bit each (issue 19: the placement index is built at the first query after each
  // new result; thesis-room1's took 5.3-5.9 ms, now 0.9-1.0).
  struct Column {
    int x = 0, z = 0;
  };
  const auto column_at = [&](const glm::vec3& p) {
    return Column{int(std::floor((p.x - s.origin.x) / voxel)), int(std::floor((p.z - s.origin.z) / voxel))};
  };
  // The march of clear space from the first free sample at step (k + 1) / 4 of a voxel: the columns its samples,
  // half a voxel apart, fall in, up to the first that leaves the grid or the room or is a wall, whatever the level
  // (levels of a face lie strictly between I_Floor and I_Ceiling). Found at the first cell that needs it.
  struct March {
    bool found = false;
    std::vector<std::size_t> columns;  // GridSpec::column
    std::vector<float> distance;       // of each sample
  };
  std::array<March, kSteps> marches;
  const auto march_from = [&](const glm::vec3& p, int k, float t) -> const March& {
    March& m = marches[std::size_t(k)];
    if (m.found) return m;
    m.found = true;
    for (float next = t + 0.5f * voxel; next <= kMaxDepth; next += 0.5f * voxel) {
      const Column q = column_at(p + face.normal * next);
      if (q.x < 0 || q.z < 0 || q.x >= s.nx || q.z >= s.nz) break;
      const std::size_t c = s.column(q.x, q.z);
      if (!ix.inside[c] || ix.walls[c]) break;
      m.columns.push_back(c);
      m.distance.push_back(next);
    }
    return m;
  };
  std::array<Column, kSteps> ahead;
  std::array<Column, 4> behind;
  // Per first step, the rows whose march starts there, a bit each.
  const std::size_t words = occupied.words();
  std::vector<std::uint64_t> pending(kSteps * words);
  for (int u = 0; u < face.nu; ++u) {
    const glm::vec3 p = face.start + face.x_axis * ((float(u) + 0.5f) * voxel);
    for (int k = 0; k < kSteps; ++k) ahead[std::size_t(k)] = column_at(p + face.normal * ((0.25f * float(k + 1)) * voxel));
    for (int k = 0; k < 4; ++k) behind[std::size_t(k)] = column_at(p + face.normal * ((-1.0f + 0.5f * float(k)) * voxel));
    for (March& m : marches) {
      m.found = false;
      m.columns.clear();
      m.distance.clear();
    }
    std::fill(pending.begin(), pending.end(), std::uint64_t{0});
    std::uint32_t marched = 0;  // a bit per first step some row starts its march from
    for (int v = 0; v < face.nv; ++v) {
      const int level = face.level0 + v;
      // The first free voxel in front of the wall's plane (the plane is where the scanned surface is, within half
      // a voxel; the surface's voxels may be two thick) must be F facing this way, or next to one: a wall off the
      // grid's axes is a staircase, and the line along the normal may pass the F voxel of its step diagonally.
      int first = -1;
      for (int k = 0; k < kSteps; ++k) {
        const glm::ivec3 q(ahead[std::size_t(k)].x, level, ahead[std::size_t(k)].z);
        if (!s.contains(q.x, q.y, q.z)) break;
        if (ix.cells[s.index(q.x, q.y, q.z)] != 0) continue;
        const auto open_f = [&](int x, int z) {
          if (!s.contains(x, q.y, z)) return false;
          const std::size_t i = s.index(x, q.y, z);
          return (f.normals[i] & facing) != 0 && (f.wall_blocked.empty() || !f.wall_blocked[i]);
        };
        const bool blocked = !f.wall_blocked.empty() && f.wall_blocked[s.index(q.x, q.y, q.z)];
        if (!blocked && (open_f(q.x, q.z) || open_f(q.x - 1, q.z) || open_f(q.x + 1, q.z) || open_f(q.x, q.z - 1) ||
                         open_f(q.x, q.z + 1)))
          first = k;
        break;
      }
      if (first < 0) continue;
      // The wall's scanned surface is there, within a voxel of the plane and a level of the row: an F voxel of a
      // neighbouring wall column (a wall off the grid's axes) may lie before a window or a hole in this one.
      bool surface = false;
      for (const Column& b : behind)
        for (int dy = -1; dy <= 1 && !surface; ++dy)
          surface = s.contains(b.x, level + dy, b.z) && ix.cells[s.index(b.x, level + dy, b.z)] != 0;
      if (!surface) continue;
      pending[std::size_t(first) * words + std::size_t(v / 64)] |= std::uint64_t{1} << (v % 64);
      marched |= 1u << first;
    }
    // Clear space in front: the last free sample, half a voxel apart, before a voxel, a wall or the room's edge;
    // the rows that start from one step marched together.
    for (; marched != 0; marched &= marched - 1) {
      const int k = std::countr_zero(marched);
      const float t = (0.25f * float(k + 1)) * voxel;
      const March& m = march_from(p, k, t);
      std::uint64_t* rows = pending.data() + std::size_t(k) * words;
      const auto set_depth = [&](std::size_t w, std::uint64_t bits, float free_to) {
        for (; bits != 0; bits &= bits - 1) {
          const std::size_t v = 64 * w + std::size_t(std::countr_zero(bits));
          face.depth[v * std::size_t(face.nu) + std::size_t(u)] = free_to;
        }
      };
      bool open = true;
      for (std::size_t n = 0; n < m.columns.size() && open; ++n) {
        const std::uint64_t* occupied_here = occupied.of(m.columns[n]);
        const float free_to = n == 0 ? t : m.distance[n - 1];
        open = false;
        for (std::size_t w = 0; w < words; ++w) {
          set_depth(w, rows[w] & occupied_here[w], free_to);
          rows[w] &= ~occupied_here[w];
          open = open || rows[w] != 0;
        }
      }
      const float free_to = m.columns.empty() ? t : m.distance.back();
      for (std::size_t w = 0; w < words; ++w) set_depth(w, rows[w], free_to);
    }
  }
  return face;
}

std::shared_ptr<const RoomQueries::Index> build_index(const AnalysisResult& analysis,
                                                      const std::vector<Surface>& surfaces) {
  if (!analysis.ok() || !analysis.features) return nullptr;
  const RoomFeatures& f = *analysis.features;
  // The placement index reads C, D and F, which a run without the areas' features skipped.
  if (f.furniture.size() != analysis.voxels.grid.spec.column_count()) return nullptr;
  auto ix = std::make_shared<RoomQueries::Index>();
  const GridSpec& s = analysis.voxels.grid.spec;
  ix->spec = s;
  ix->cells = analysis.voxels.grid.cells;
  ix->levels = f.levels;
  ix->floor_y = analysis.floor_y;
  ix->ceiling_y = analysis.ceiling_y;
  const AreaParams area_defaults;
  ix->close_distance = area_defaults.close_distance;
  ix->close_height = area_defaults.close_height;
  ix->inside = room_inside(s, f.room, f.enclosed);
  ix->walls = f.walls;
  ix->top_level = f.furniture;
  ix->top_region = label_tops(s, f.furniture);

  const int rough = voxels_for(FeatureParams{}.floor_roughness, s.voxel_size);
  const std::size_t columns = s.column_count();
  ix->floor_clear.assign(columns, -1.0f);
  ix->top_clear.assign(columns, -1.0f);
  ix->ceiling_clear.assign(columns, -1.0f);
  std::vector<std::uint8_t> not_floor(columns, 1);
  for (std::size_t c = 0; c < columns; ++c) {
    const std::uint8_t* column = ix->cells.data() + c * std::size_t(s.ny);
    if (!ix->inside[c] || ix->walls[c]) continue;
    ix->inside_cells.push_back(std::uint32_t(c));
    if (f.free_floor[c]) {
      const int o = first_occupied_up(column, f.levels.floor + rough + 1, f.levels.ceiling);
      ix->floor_clear[c] = (o >= f.levels.ceiling ? ix->ceiling_y : ix->top_y(o)) - ix->floor_y;
      not_floor[c] = 0;
      ix->floor_cells.push_back(std::uint32_t(c));
    }
    if (f.free_ceiling[c]) {
      const int o = first_occupied_down(column, f.levels.ceiling - 1, f.levels.floor);
      ix->ceiling_clear[c] = ix->ceiling_y - (o <= f.levels.floor ? ix->floor_y : ix->top_y(o + 1));
      ix->ceiling_cells.push_back(std::uint32_t(c));
    }
    if (f.furniture[c] != kNoFurniture) {
      const int o = first_occupied_up(column, f.furniture[c], f.levels.ceiling);
      ix->top_clear[c] = (o >= f.levels.ceiling ? ix->ceiling_y : ix->top_y(o)) - ix->top_y(f.furniture[c]);
      ix->top_cells.push_back(std::uint32_t(c));
    }
  }
  ix->stand_distance = detail::distance_to_unmasked(s.nx, s.nz, not_floor);
  for (float& d : ix->stand_distance) d *= s.voxel_size;

  float longest = 0.0f;
  LevelBits occupied(s, ix->cells, f.levels.floor + 1, f.levels.ceiling - f.levels.floor - 1);
  for (const Surface& wall : surfaces) {
    if (wall.kind != SurfaceKind::Wall || wall.storey != 0) continue;
    ix->faces.push_back(wall_face(*ix, f, wall, occupied));
    if (wall.extents.x > longest) {
      longest = wall.extents.x;
      const double deg = std::atan2(-double(wall.x_axis.z), double(wall.x_axis.x)) * 180.0 / std::numbers::pi;
      ix->dominant_deg = std::fmod(std::fmod(deg, 90.0) + 90.0, 90.0);
    }
  }
  for (std::uint32_t i = 0; i < ix->faces.size(); ++i)
    for (std::uint32_t c = 0; c < ix->faces[i].depth.size(); ++c)
      if (ix->faces[i].depth[c] > 0.0f) ix->wall_cells.emplace_back(i, c);
  return ix;
}

}  // namespace

RoomQueries::RoomQueries(const AnalysisResult& analysis)
    : RoomQueries(analysis, analysis.ok() ? extract_surfaces(analysis) : std::vector<Surface>{}) {}

RoomQueries::RoomQueries(const AnalysisResult& analysis, const std::vector<Surface>& surfaces)
    : index_(build_index(analysis, surfaces)) {}

glm::vec3 Placement::y_axis() const { return glm::cross(normal, x_axis); }

glm::quat Placement::orientation() const { return orientation_of(x_axis, y_axis(), normal); }

std::array<glm::vec3, 4> Placement::corners() const {
  const glm::vec3 x = x_axis * (0.5f * footprint.x), y = y_axis() * (0.5f * footprint.y);
  return {center - x - y, center + x - y, center + x + y, center - x + y};
}

std::string_view to_string(PlacementShortfall shortfall) {
  switch (shortfall) {
    case PlacementShortfall::None: return "none";
    case PlacementShortfall::NoSurface: return "no_surface";
    case PlacementShortfall::NoSpace: return "no_space";
    case PlacementShortfall::NoHeadroom: return "no_headroom";
    case PlacementShortfall::NoReach: return "no_reach";
    case PlacementShortfall::TooFew: return "too_few";
  }
  return "unknown";
}

}  // namespace roomsense
