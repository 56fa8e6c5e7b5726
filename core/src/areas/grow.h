// Growth, beyond the thesis (issue 14): packed areas stretch into the free surface around them.
#pragma once
#include "roomsense/areas.h"
#include "roomsense/features.h"

#include <cstdint>
#include <functional>
#include <span>
#include <stop_token>
#include <vector>

namespace roomsense::detail {

// What a point of the surface is for an area growing over it.
enum class SurfaceCell : std::uint8_t {
  Usable,     // a tile, or a voxel with a wall normal
  Unusable,   // a gap the search's fill tolerates (Eq. 3.25, 3.38)
  Forbidden,  // a wall column, or before an opening: never under an area
};

struct GrowthRule {
  float step = 0.05f;  // metres an edge moves at a time: half a voxel
  float max_length = 1e3f;  // metres: no side grows past this (the grid's diagonal), whatever cell_at says
  float fill = 0.95f;        // the share of the grown area's samples that must be Usable (the search's fill)
  float strip_fill = 0.95f;  // the share of each new strip's samples
  // How far beyond each new sample the surface must go on. A voxelized top overstates its surface by up to a
  // voxel at its edge, so tops keep their areas' edges on the centres of their outermost cells, as the search
  // does (Eq. 3.54): half a voxel. Free floor and ceiling end at what stands on them, and walls at the next
  // wall or opening (Forbidden), which overstate themselves instead: 0.
  float lookahead = 0.0f;
  // Distances along an area's normal at which its samples also conflict with other areas' samples: walls a
  // voxel either side of their plane (as packing, reduce.h), furniture tops the levels Eq. 3.49 treats as one.
  std::vector<float> conflict_depths{0.0f};
  std::function<SurfaceCell(const glm::vec3& world, const Area& area)> cell_at;  // a point of the area's plane
  // Where a point's cell is its voxel's, optionally: the voxel (each coordinate from the point's same coordinate
  // alone, as floor((p + offset - origin) / voxel) is) and the voxel's cell, cell_at being the two in turn. An
  // area along the grid's axes then has its samples' voxels as a product of its rows' and its columns', and
  // growth counts its cells by runs of samples in one voxel rather than sample by sample.
  std::function<glm::ivec3(const glm::vec3& world, const Area& area)> voxel_at;
  std::function<SurfaceCell(const glm::ivec3& voxel, const Area& area)> cell_of;
  // Whether cell_at reads a point's height or the area's. Where it reads neither (floor, ceiling), a flat area
  // grows alike at any height at which its samples lie in the same layers of sample cells: a replay takes its
  // growth across a floor or ceiling height that a re-sent chunk refined.
  bool cells_read_height = true;
};

// One growth, for the next analysis's (issue 19): its areas before and after, and the edges each one moved, in
// order.
struct GrowthRecord {
  std::vector<Area> before, after;
  std::vector<std::uint8_t> moves;       // edges (0 bottom, 1 right, 2 top, 3 left), area by area
  std::vector<std::uint32_t> moves_end;  // per area: where its moves end
};

// What a growth may take from the previous analysis's (same rule and parameters): its record, and per grid row z
// the span of columns (x to y; none where x > y) whose features the rule reads changed since.
struct GrowthReplay {
  const GrowthRecord* previous = nullptr;  // none: every area grows
  const GridSpec* spec = nullptr;
  std::span<const glm::ivec2> changed_rows;
};

// Packing places whole squares of three fixed sizes, so strips narrower than the smallest size, and the
// margins between sizes, stay empty. Each area, in order (largest first), moves its four edges outward one
// step at a time, in turn, while the new strip is surface the search would accept (`strip_fill` of it Usable,
// `fill` of the whole area, nothing Forbidden) and no other area's. The area stays a rectangle on its own axes; its size class becomes the
// largest whose width (and height, for walls) it now holds, so an app asking for a class gets at least that.
// An area that `replay`'s previous growth grew too (the same bits, or as above the same but for its height, in
// the same order among those) moves its edges as it did there where nothing it read there changed: no feature
// column, and no other area's samples (another area new, gone or grown otherwise). `record`, where given,
// receives this growth's record.
void grow_areas(std::span<Area> areas, const GrowthRule& rule, const AreaParams& params,
                const std::stop_token& stop = {}, const GrowthReplay& replay = {}, GrowthRecord* record = nullptr);

// Bit for bit, every field (so that a -0 is not taken for a 0).
bool same_bits(const Area& a, const Area& b);

}  // namespace roomsense::detail
