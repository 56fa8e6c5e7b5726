// The room's planar surfaces, as a plane-tracking runtime reports them (XR_EXT_spatial_plane_tracking): one
// floor and one ceiling per storey, one plane per straight wall segment (split at corners and at openings),
// one per furniture top. Derived from the pipeline's features (§3.2), not from the raw mesh, so they agree
// with the placement areas: a wall segment follows the room outline where wall columns (Eq. 3.11) stand, a
// floor follows the room mask (Eq. 3.12), a furniture top follows C (Eq. 3.13).
#pragma once
#include "roomsense/analysis.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <stop_token>
#include <string_view>
#include <vector>

namespace roomsense {

enum class SurfaceKind : std::uint8_t {
  Floor,
  Ceiling,
  Wall,
  Table,      // a furniture top at table height (SurfaceParams::table_min..table_max above the floor)
  Furniture,  // any other furniture top: a seat, a bed, a low shelf
};

std::string_view surface_kind_name(SurfaceKind kind);  // "floor", "ceiling", "wall", "table", "furniture"

struct SurfaceParams {
  float min_area = 0.1f;            // m²: smaller regions are left out
  float min_wall_width = 0.3f;      // m: shorter wall segments are left out
  // m: a run this long without wall splits a wall: a door, an open side. A window does not split it: the
  // columns under and over it hold wall (a sill and a lintel), though too little for A.
  float opening_width = 0.5f;
  float outline_tolerance = 1.0f;   // voxels: how far the simplified outline may stray from the raster
  float min_top_width = 0.25f;      // m: furniture tops narrower than this (a window sill, a rim) are left out
  float table_min = 0.55f;          // m above the floor: furniture tops in [table_min, table_max] are tables
  float table_max = 1.2f;
};

struct Surface {
  SurfaceKind kind = SurfaceKind::Floor;
  std::uint32_t storey = 0;      // index into AnalysisResult::storeys
  int room = kNoRoom;            // index into AnalysisResult::rooms: the room a wall faces, a top stands in, a
                                 // floor or ceiling covers; kNoRoom where none is near (a stray top)
  glm::vec3 center{0.0f};        // centre of the bounding rectangle, on the plane
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit, into free space: +Z of the pose
  glm::vec3 x_axis{1.0f, 0.0f, 0.0f};  // unit, along the width; horizontal for walls, so +Y = normal × x is up
  glm::vec2 extents{0.0f};       // width (along x_axis) × height (along normal × x_axis) of the bounding rectangle
  // The outline in the plane's (X, Y) frame about `center`: counter-clockwise seen from +Z, simple, no
  // repeated closing vertex, at least 3 vertices. For walls, the rectangle of the segment.
  std::vector<glm::vec2> polygon;
  // The polygon as counter-clockwise triangles (indices into `polygon`): XR_EXT_spatial_plane_tracking's MESH_2D.
  std::vector<std::uint32_t> triangles;

  glm::vec3 y_axis() const { return glm::cross(normal, x_axis); }
  glm::quat orientation() const;  // rotates (X, Y, Z) onto (x_axis, y_axis, normal): the OpenXR pose
};

// Every surface of an analysis that found a room (analysis.ok()), in a stable order: floors, ceilings,
// walls, then furniture tops (tables before other furniture); within a kind by storey, then by position:
// walls go round their storey's outline counter-clockwise seen from above, from its lowest corner in z
// (then x), and tops by centre z, then x. Empty for a result that is not ok.
// - Each storey's floor and ceiling follow the largest region of its B with its holes filled, its walls its
//   A; furniture tops come from each storey's C. A storey of several rooms (RoomFeatures::rooms) has one
//   floor and one ceiling per room instead, over the room's part of that region (room_mask); its walls
//   still follow the storey's outline, each saying the room it faces.
// - Horizontal surfaces take x_axis along the side of their least-area bounding rectangle nearest +X (so
//   +X for a room on the grid axes); then y_axis is -Z-ish for a floor or a top, +Z-ish for a ceiling.
// - Walls lie on the line through their wall columns, where the scanned surface is (within half a voxel).
// A stop request throws Error(Cancelled).
std::vector<Surface> extract_surfaces(const AnalysisResult& analysis, const SurfaceParams& params = {},
                                      const std::stop_token& stop = {});

}  // namespace roomsense
