// The planar surfaces of an analysis (surfaces.h): per storey its room region, outlined and fitted to its
// walls, gives the floor, the ceiling and the wall segments; the runs of C give the furniture tops.
#include "roomsense/surfaces.h"

#include "roomsense/cancel.h"
#include "bounds/polygon_triangulation.h"
#include "outline.h"
#include "polygon.h"
#include "regions.h"
#include "wall_segments.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace roomsense {
namespace {

using detail::ColumnMask;
using detail::Polygon2;

// What one storey's surfaces are read from, all on the grid's column raster.
struct StoreyRaster {
  int floor_level = 0, ceiling_level = 0;  // I_Floor, I_Ceiling of the storey
  float floor_y = 0.0f, ceiling_y = 0.0f;
  ColumnMask floor_region;                 // the room region: B (Eq. 3.12); the ceiling has its outline
  ColumnMask walls;                        // A (Eq. 3.11)
  const RoomFeatures* features = nullptr;  // the ceiling per column and its facets (issue 15)
  const std::vector<glm::vec3>* planes = nullptr;  // Storey::ceiling_planes
  // The height of the ceiling over the point (x, z) of column `col` of a stepped storey: the plane of the
  // facet it lies under (a roof's slope, a soffit); elsewhere, where the column's ceiling level lies lower,
  // the sloping plane nearest the middle of that level within two voxels of it (the eaves, too low for free
  // ceiling tiles), or that middle; else I_Ceiling's surface or the lowest sloping plane that comes within a
  // level of it there (the ridge between two slopes).
  float ceiling_over(const GridSpec& s, std::size_t col, double x, double z) const {
    const auto at = [&](const glm::vec3& p) { return float(double(p.x) * x + double(p.y) * z + double(p.z)); };
    const auto sloping = [](const glm::vec3& p) { return p.x * p.x + p.y * p.y > 0.01f; };
    const int facet = features->ceiling_facet[col], c = features->ceiling[col];
    if (facet > 0 && std::size_t(facet) <= planes->size()) return std::min(ceiling_y, at((*planes)[std::size_t(facet - 1)]));
    if (c < ceiling_level - 1) {
      const float middle = s.origin.y + (float(c) + 0.5f) * s.voxel_size;
      float best = middle, off = 2.0f * s.voxel_size;
      for (const glm::vec3& p : *planes)
        if (sloping(p) && std::fabs(at(p) - middle) <= off) best = at(p), off = std::fabs(at(p) - middle);
      return best;
    }
    float y = ceiling_y;
    const float near = s.origin.y + float(ceiling_level - 2) * s.voxel_size;
    for (const glm::vec3& p : *planes)
      if (sloping(p) && at(p) >= near) y = std::min(y, at(p));
    return y;
  }
  bool stepped() const { return features->facets.size() > 1; }  // a ceiling of several facets
};

ColumnMask mask_of(const GridSpec& s, const std::vector<std::uint8_t>& cells) {
  ColumnMask m(s.nx, s.nz);
  m.cells = cells;
  return m;
}

// Each storey has its features (analysis.h): its floor and ceiling follow its B, its walls its A.
StoreyRaster storey_raster(const AnalysisResult& analysis, std::size_t index) {
  const GridSpec& s = analysis.voxels.grid.spec;
  const RoomFeatures& f = analysis.storey_features(index);
  const Storey& storey = analysis.storeys[index];
  return {f.levels.floor,     f.levels.ceiling, storey.floor_y, storey.ceiling_y, mask_of(s, f.room), mask_of(s, f.walls),
          &f, &storey.ceiling_planes};
}

// A column holding wall both in the lower and in the upper half of the storey: under a window, a sill, over
// it a lintel. Not so a door (nothing below the lintel but floor) or an open side, which end a wall segment.
bool bridges(const VoxelGrid& grid, int x, int z, const StoreyRaster& r) {
  const GridSpec& s = grid.spec;
  const int lo = std::max(r.floor_level + 1, 0), hi = std::min(r.ceiling_level - 1, s.ny - 1);
  const int mid = (lo + hi) / 2;
  if (lo >= hi) return false;
  const std::uint8_t* v = grid.column_data(x, z);
  const auto any = [](const std::uint8_t* b, const std::uint8_t* e) { return std::find(b, e, std::uint8_t{1}) != e; };
  return any(v + lo, v + mid + 1) && any(v + mid + 1, v + hi + 1);
}

// The filled largest region of a mask (B's other components lie outside the walls: seen through a window or
// a door, not floor of this room), or an empty mask.
ColumnMask main_region(const ColumnMask& mask) {
  const detail::Components parts = detail::label_components(
      mask.nx, mask.nz, [&](std::size_t c) { return mask.cells[c] != 0; }, [](std::size_t, std::size_t) { return true; });
  const int largest = detail::largest_component(parts);
  if (largest < 0) return {};
  return detail::fill_holes(detail::component_mask(parts, mask.nx, largest));
}

glm::dvec2 to_world(const GridSpec& s, const glm::dvec2& lattice) {
  return glm::dvec2(s.origin.x, s.origin.z) + lattice * double(s.voxel_size);
}

// A horizontal surface at height y over a lattice polygon. Its x_axis runs along a side of the least-area
// rectangle around the polygon, the side nearest +X: extents are tight for a room or a table turned off the
// axes, and x_axis = +X for one on them.
Surface horizontal(SurfaceKind kind, std::uint32_t storey, const GridSpec& s, const Polygon2& lattice, float y,
                   bool up) {
  Polygon2 world;
  for (const glm::dvec2& p : lattice) world.push_back(to_world(s, p));
  const glm::dvec2 dir = detail::least_area_rectangle_direction(world);
  const glm::dvec3 normal(0.0, up ? 1.0 : -1.0, 0.0), x_axis(dir.x, 0.0, dir.y);
  const glm::dvec3 y_axis = glm::cross(normal, x_axis);
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  Polygon2 plane;
  for (const glm::dvec2& p : world) {
    const glm::dvec3 q(p.x, 0.0, p.y);
    plane.emplace_back(glm::dot(q, x_axis), glm::dot(q, y_axis));
    lo = glm::min(lo, plane.back());
    hi = glm::max(hi, plane.back());
  }
  const glm::dvec2 mid = 0.5 * (lo + hi);
  // Counter-clockwise seen from +Z: the outline as seen from above flips for a ceiling, seen from below.
  if (detail::signed_area(plane) < 0.0) std::reverse(plane.begin(), plane.end());
  Surface out;
  out.kind = kind;
  out.storey = storey;
  glm::dvec3 centre = x_axis * mid.x + y_axis * mid.y;
  centre.y = y;
  out.center = glm::vec3(centre);
  out.normal = glm::vec3(normal);
  out.x_axis = glm::vec3(x_axis);
  out.extents = glm::vec2(hi - lo);
  for (const glm::dvec2& p : plane) out.polygon.emplace_back(p - mid);
  return out;
}

// Beyond the thesis (issue 15): a ceiling facet that slopes or steps, on its plane y = p.x x + p.y z + p.z
// over a lattice polygon, facing down. Its x_axis runs level along the slope (+X on a level facet).
Surface sloped_ceiling(std::uint32_t storey, const GridSpec& s, const Polygon2& lattice, const glm::vec3& p) {
  const glm::dvec3 normal = glm::normalize(glm::dvec3(p.x, -1.0, p.y));
  const glm::dvec2 level(p.y, -p.x);
  const glm::dvec3 x_axis = glm::length(level) > 1e-6 ? glm::normalize(glm::dvec3(level.x, 0.0, level.y)) : glm::dvec3(1, 0, 0);
  const glm::dvec3 y_axis = glm::cross(normal, x_axis);
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  Polygon2 plane;
  double offset = 0.0;
  for (const glm::dvec2& l : lattice) {
    const glm::dvec2 w = to_world(s, l);
    const glm::dvec3 q(w.x, double(p.x) * w.x + double(p.y) * w.y + double(p.z), w.y);
    plane.emplace_back(glm::dot(q, x_axis), glm::dot(q, y_axis));
    offset = glm::dot(q, normal);
    lo = glm::min(lo, plane.back());
    hi = glm::max(hi, plane.back());
  }
  const glm::dvec2 mid = 0.5 * (lo + hi);
  if (detail::signed_area(plane) < 0.0) std::reverse(plane.begin(), plane.end());
  Surface out;
  out.kind = SurfaceKind::Ceiling;
  out.storey = storey;
  out.center = glm::vec3(x_axis * mid.x + y_axis * mid.y + normal * offset);
  out.normal = glm::vec3(normal);
  out.x_axis = glm::vec3(x_axis);
  out.extents = glm::vec2(hi - lo);
  for (const glm::dvec2& q : plane) out.polygon.emplace_back(q - mid);
  return out;
}

// Douglas-Peucker on an open polyline: the points that keep every dropped one within `tolerance` of it.
std::vector<glm::vec2> simplify_polyline(const std::vector<glm::vec2>& points, float tolerance) {
  if (points.size() <= 2) return points;
  std::vector<std::uint8_t> keep(points.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> spans{{0, points.size() - 1}};
  while (!spans.empty()) {
    const auto [i, j] = spans.back();
    spans.pop_back();
    const glm::vec2 d = points[j] - points[i];
    const float length = glm::length(d);
    float worst = 0.0f;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const glm::vec2 e = points[k] - points[i];
      const float off = length > 0.0f ? std::fabs(d.x * e.y - d.y * e.x) / length : glm::length(e);
      if (off > worst) worst = off, at = k;
    }
    if (worst <= tolerance) continue;
    keep[at] = 1;
    spans.push_back({i, at});
    spans.push_back({at, j});
  }
  std::vector<glm::vec2> out;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (keep[k]) out.push_back(points[k]);
  return out;
}

// A wall plane over a segment from the storey's floor to its ceiling: a rectangle, or beyond the thesis
// (issue 15) a polygon whose top follows the ceiling in front of the wall (a gable under a pitched roof, a wall
// under a soffit), simplified to within 5 cm.
Surface wall(std::uint32_t storey, const GridSpec& s, const detail::WallSegment& segment, const StoreyRaster& r) {
  const glm::dvec2 a = to_world(s, segment.a), b = to_world(s, segment.b);
  const glm::dvec2 n = detail::inward_normal(glm::normalize(b - a)), mid = 0.5 * (a + b);
  const float width = float(glm::distance(a, b));
  Surface out;
  out.kind = SurfaceKind::Wall;
  out.storey = storey;
  out.normal = glm::vec3(float(n.x), 0.0f, float(n.y));
  out.x_axis = glm::vec3(float(n.y), 0.0f, float(-n.x));  // up × normal, so that normal × x_axis is up
  const float w = 0.5f * width;
  // The ceiling over the first column in front of the wall that is no wall (within 3 voxels), every half voxel
  // along it, right to left; the ends take the nearest sample's height.
  std::vector<glm::vec2> top;
  const double step = 0.5 * double(s.voxel_size);
  for (double t = double(width); r.stepped() && t >= -1e-9; t -= step)
    for (int d = 1; d <= 3; ++d) {
      const glm::dvec2 q = a + glm::normalize(b - a) * std::max(t, 0.0) + n * (double(d) * double(s.voxel_size));
      const double fx = std::floor((q.x - double(s.origin.x)) / double(s.voxel_size));
      const double fz = std::floor((q.y - double(s.origin.z)) / double(s.voxel_size));
      if (!(fx >= 0.0 && fz >= 0.0 && fx < double(s.nx) && fz < double(s.nz))) break;
      const std::size_t col = s.column(int(fx), int(fz));
      if (r.walls.cells[col]) continue;
      top.emplace_back(float(std::max(t, 0.0)) - w, std::max(r.ceiling_over(s, col, q.x, q.y), r.floor_y + s.voxel_size));
      break;
    }
  const bool level = std::all_of(top.begin(), top.end(), [&](const glm::vec2& p) { return p.y == r.ceiling_y; });
  if (!level) {
    top.front().x = w, top.back().x = -w;
    top = simplify_polyline(top, 0.05f);
  }
  float high = level ? r.ceiling_y : r.floor_y;
  for (const glm::vec2& p : top) high = std::max(high, p.y);
  const float height = high - r.floor_y, centre_y = 0.5f * (r.floor_y + high), h = 0.5f * height;
  out.center = glm::vec3(float(mid.x), centre_y, float(mid.y));
  out.extents = {width, height};
  if (level) {
    out.polygon = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
    return out;
  }
  out.polygon = {{-w, -h}, {w, -h}};
  for (const glm::vec2& p : top) out.polygon.emplace_back(p.x, p.y - centre_y);
  return out;
}

// Floor, ceiling and walls of one storey, appended to the three lists.
void storey_surfaces(const AnalysisResult& analysis, std::uint32_t index, const StoreyRaster& r,
                     const SurfaceParams& params, const std::stop_token& stop, std::vector<Surface>& floors,
                     std::vector<Surface>& ceilings, std::vector<Surface>& walls) {
  const VoxelGrid& grid = analysis.voxels.grid;
  const GridSpec& s = grid.spec;
  const double voxel = s.voxel_size, min_cells = params.min_area / (voxel * voxel);
  const ColumnMask region = main_region(r.floor_region);
  if (region.count() == 0 || double(region.count()) < min_cells) return;
  detail::WallSearch search;
  search.walls = &r.walls;
  search.bridges = [&](int x, int z) { return bridges(grid, x, z, r); };
  search.opening = params.opening_width / voxel;
  search.min_width = params.min_wall_width / voxel;
  // The floor, the ceiling and the walls around one region, all of room `room`.
  const auto outline_surfaces = [&](const ColumnMask& part, int room) {
    stop_point(stop);
    const Polygon2 outline = detail::simplify_outline(detail::trace_outline(part), params.outline_tolerance);
    stop_point(stop);
    const detail::StoreyOutline fitted = detail::fit_walls(outline, search);
    floors.push_back(horizontal(SurfaceKind::Floor, index, s, fitted.polygon, r.floor_y, true));
    floors.back().room = room;
    if (!r.stepped()) {
      ceilings.push_back(horizontal(SurfaceKind::Ceiling, index, s, fitted.polygon, r.ceiling_y, false));
      ceilings.back().room = room;
    } else {
      // Beyond the thesis (issue 15): where the ceiling slopes or steps, the level ceiling covers the part's
      // columns under I_Ceiling (within a level), and each facet below it is a plane of its own.
      ColumnMask high(s.nx, s.nz);
      for (int z = 0; z < s.nz; ++z)
        for (int x = 0; x < s.nx; ++x) {
          const std::size_t col = s.column(x, z);
          high.cells[col] = part.at(x - part.x0, z - part.z0) && r.features->ceiling[col] >= r.ceiling_level - 1;
        }
      // Not a strip along a ridge, as furniture tops leave out sills.
      const ColumnMask level = main_region(high);
      if (double(level.count()) >= min_cells) {
        const Polygon2 under = detail::simplify_outline(detail::trace_outline(level), params.outline_tolerance);
        Surface ceiling = horizontal(SurfaceKind::Ceiling, index, s, under, r.ceiling_y, false);
        ceiling.room = room;
        if (std::min(ceiling.extents.x, ceiling.extents.y) >= 2.0f * params.min_top_width) ceilings.push_back(std::move(ceiling));
      }
    }
    for (const detail::WallSegment& segment : fitted.walls) {
      walls.push_back(wall(index, s, segment, r));
      walls.back().room = room;
    }
  };
  // Beyond the thesis (issue 15): each facet of the ceiling that slopes or steps, on its plane.
  const std::vector<glm::vec3>& planes = analysis.storeys[index].ceiling_planes;
  for (std::size_t k = 1; k < r.features->facets.size() && k <= planes.size(); ++k) {
    ColumnMask tiles(s.nx, s.nz);
    for (std::size_t col = 0; col < tiles.cells.size(); ++col) tiles.cells[col] = r.features->ceiling_facet[col] == int(k);
    const ColumnMask facet = main_region(tiles);
    if (double(facet.count()) < min_cells) continue;
    const Polygon2 outline = detail::simplify_outline(detail::trace_outline(facet), params.outline_tolerance);
    ceilings.push_back(sloped_ceiling(index, s, outline, planes[k - 1]));
    ceilings.back().room = room_at_point(analysis, index, ceilings.back().center);
  }
  const RoomSplit& split = analysis.storey_features(index).rooms;
  const int first = first_room_of(analysis, index);
  if (split.count <= 1) {
    outline_surfaces(region, split.count == 1 ? first : kNoRoom);
    return;
  }
  // Several rooms: each room's part of the region (its free columns and the walls nearest it) has its own
  // floor, ceiling and walls; a wall between two rooms is a plane on each side, a doorway ends them.
  std::vector<std::uint8_t> cells(s.column_count(), 0);  // the region on the whole grid (it is cropped)
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) cells[s.column(x, z)] = region.at(x - region.x0, z - region.z0) ? 1 : 0;
  const std::vector<int> rooms_of = rooms_of_mask(s, cells, split, room_reach_columns(s));
  for (int k = 0; k < split.count; ++k) {
    const ColumnMask part = main_region(mask_of(s, room_mask(rooms_of, k)));
    if (double(part.count()) >= min_cells) outline_surfaces(part, first + k);
  }
}

// Furniture tops of one storey: 4-connected runs of C (Eq. 3.13) whose levels differ by at most one
// (a top straddling a level boundary), each at the level most of it has. C holds the level above the top
// voxel, and the top surface is that level's lower face, where find_areas places furniture areas.
std::vector<Surface> furniture_tops(const AnalysisResult& analysis, std::uint32_t storey, const SurfaceParams& params,
                                    const std::stop_token& stop) {
  const GridSpec& s = analysis.voxels.grid.spec;
  const std::vector<int>& c = analysis.storey_features(storey).furniture;
  if (c.size() != s.column_count()) return {};  // C not derived (AnalysisOptions::area_features)
  const double voxel = s.voxel_size, min_cells = params.min_area / (voxel * voxel);
  const detail::Components parts = detail::label_components(
      s.nx, s.nz, [&](std::size_t col) { return c[col] != kNoFurniture; },
      [&](std::size_t a, std::size_t b) { return std::abs(c[a] - c[b]) <= 1; });
  std::vector<std::map<int, std::size_t>> levels(parts.sizes.size());
  for (std::size_t col = 0; col < c.size(); ++col)
    if (parts.label[col] >= 0) ++levels[std::size_t(parts.label[col])][c[col]];
  std::vector<Surface> out;
  for (std::size_t id = 0; id < parts.sizes.size(); ++id) {
    if (double(parts.sizes[id]) < min_cells) continue;
    stop_point(stop);
    int level = 0;
    std::size_t most = 0;
    for (const auto& [l, count] : levels[id])  // ascending: ties go to the higher level
      if (count >= most) {
        most = count;
        level = l;
      }
    const ColumnMask region = detail::fill_holes(detail::component_mask(parts, s.nx, int(id)));
    // Half a voxel in: the top's edge lies somewhere inside its boundary columns, on average at their centres.
    const Polygon2 outline = detail::inset_polygon(
        detail::simplify_outline(detail::trace_outline(region), params.outline_tolerance), 0.5);
    const float y = s.origin.y + float(level) * s.voxel_size, above = y - analysis.storeys[storey].floor_y;
    const bool table = above >= params.table_min && above <= params.table_max;
    Surface top = horizontal(table ? SurfaceKind::Table : SurfaceKind::Furniture, storey, s, outline, y, true);
    top.room = room_at_point(analysis, storey, top.center);
    // A window's sill is C too (wall below, 1 m clear above), but a strip a wall thick is no place to put
    // things; the least-area rectangle measures the narrow side whatever the strip's direction.
    if (std::min(top.extents.x, top.extents.y) >= params.min_top_width) out.push_back(std::move(top));
  }
  std::sort(out.begin(), out.end(), [](const Surface& a, const Surface& b) {
    return std::tie(a.kind, a.center.z, a.center.x, a.center.y) < std::tie(b.kind, b.center.z, b.center.x, b.center.y);
  });
  return out;
}

}  // namespace

namespace {

// The polygon as triangles of its own vertices (MESH_2D), by the bounds' ear clipper on a 0.1 mm lattice.
std::vector<std::uint32_t> triangulate(const std::vector<glm::vec2>& polygon, const std::stop_token& stop) {
  constexpr float kLattice = 1e4f;  // lattice points per metre
  detail::Loop loop;
  loop.reserve(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i)
    loop.push_back({static_cast<std::int32_t>(std::lround(polygon[i].x * kLattice)),
                    static_cast<std::int32_t>(std::lround(polygon[i].y * kLattice)), static_cast<std::uint32_t>(i)});
  detail::Triangles triangles;
  detail::triangulate_polygon(loop, {}, triangles, stop);
  std::vector<std::uint32_t> out;
  out.reserve(3 * triangles.size());
  for (const auto& t : triangles) out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace

std::string_view surface_kind_name(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Floor: return "floor";
    case SurfaceKind::Ceiling: return "ceiling";
    case SurfaceKind::Wall: return "wall";
    case SurfaceKind::Table: return "table";
    case SurfaceKind::Furniture: return "furniture";
  }
  return "unknown";
}

glm::quat Surface::orientation() const { return orientation_of(x_axis, y_axis(), normal); }

std::vector<Surface> extract_surfaces(const AnalysisResult& analysis, const SurfaceParams& params,
                                      const std::stop_token& stop) {
  stop_point(stop);
  if (!analysis.ok() || !analysis.features || analysis.storeys.empty()) return {};
  std::vector<Surface> floors, ceilings, walls;
  for (std::size_t i = 0; i < analysis.storeys.size(); ++i) {
    stop_point(stop);
    storey_surfaces(analysis, std::uint32_t(i), storey_raster(analysis, i), params, stop, floors, ceilings, walls);
  }
  std::vector<Surface> tops;
  for (std::uint32_t i = 0; i < analysis.storeys.size(); ++i) {
    stop_point(stop);
    std::vector<Surface> more = furniture_tops(analysis, i, params, stop);
    tops.insert(tops.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
  }
  // Tables before other furniture, then by storey, as the other kinds.
  std::stable_sort(tops.begin(), tops.end(), [](const Surface& a, const Surface& b) { return a.kind < b.kind; });
  std::vector<Surface> out;
  out.reserve(floors.size() + ceilings.size() + walls.size() + tops.size());
  for (std::vector<Surface>* part : {&floors, &ceilings, &walls, &tops})
    out.insert(out.end(), std::make_move_iterator(part->begin()), std::make_move_iterator(part->end()));
  for (Surface& surface : out) surface.triangles = triangulate(surface.polygon, stop);
  return out;
}

}  // namespace roomsense
