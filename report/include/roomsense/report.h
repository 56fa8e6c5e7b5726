// Pictures of an analysis for people: a top-down plan (plan.svg) and a 3D scene (scene.glb) that open in a
// browser or any glTF viewer. The input is what both callers have: the CLI holds a whole AnalysisResult and
// its Scan; an OpenXR app holds what the layer returns (areas, the bounds mesh, floor and ceiling heights)
// and the meshes it submitted, but no voxel features. Without features the plan draws the footprint from
// the bounds mesh and leaves out wall columns, wall normals and furniture tops.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/export.h"
#include "roomsense/queries.h"

#include <glm/gtc/quaternion.hpp>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace roomsense {

// The voxel features behind the plan's footprint, wall columns and furniture tops (CLI only).
struct ReportFeatures {
  const GridSpec* grid = nullptr;          // the grid the features index (VoxelGrid::spec)
  const RoomFeatures* features = nullptr;  // A, B, C and F of the main storey
  std::span<const RoomFeatures> other_storeys;  // optional: those of storeys[1..], in that order
};

// Everything a report draws. Non-owning: the referenced data must outlive the call.
struct ReportInput {
  std::string title;                 // shown in the plan's heading, e.g. the scan's file name
  float floor_y = 0.0f;              // metres: the main storey's scanned floor and ceiling surfaces
  float ceiling_y = 0.0f;
  std::span<const Storey> storeys;   // optional: the plan draws one drawing per storey (main first)
  std::span<const Room> rooms;       // optional: outlined in the plan and coloured in the scene (with features)
  std::span<const Area> areas;       // classified areas, one plan element and one scene node each
                                     // (areas with a type, size or reach outside its enum are left out)
  const BoundsMesh* bounds = nullptr;  // optional: the room-bounds mesh
  std::span<const Scan> scan;        // the input meshes (several when an app submitted several)
  ReportFeatures voxels;             // optional (both pointers or neither)
  std::span<const Placement> placements;  // optional: answers of a placement query, drawn above everything
};

// The CLI's input: a finished analysis of `scan`. Holds references into both.
ReportInput report_input(const AnalysisResult& result, const Scan& scan, std::string title);

// An area from an OpenXR-style pose, as an app reads it from XR_EXTX_room_understanding: the centre,
// the orientation taking (X, Y, Z) to (width axis, height axis, normal), and the full width and height.
// Fills the corners (counter-clockwise from the front), normal, half extents and the category flags.
Area area_from_pose(AreaType type, AreaSize size, Reach reach, const glm::vec3& center,
                    const glm::quat& orientation, float width, float height);

// The thesis's reach colours (Fig. 3.17): red for close, green for distance, blue for none; sRGB, "#rrggbb".
std::string_view reach_colour(Reach reach);
// A room's colour (index into AnalysisResult::rooms), from a palette of eight that avoids the reach colours.
std::string_view room_colour(std::size_t room);

// plan.svg: a top view, looking down -Y. +X points right and +Z points down the page, so the view is the
// right-handed frame seen from above (+Y towards the viewer). Layers, bottom to top: the room footprint,
// furniture tops, wall columns with their normals as ticks, the bounds outline at 1.6 m above the floor,
// then ceiling, floor, furniture and wall areas, room borders, then placements (one <polygon class="placement"> each, with
// data-index and data-surface; walls as a strip before the wall). Every area is one <polygon class="area"> with data-index,
// data-type, data-size, data-reach and a <title>; horizontal areas are their rectangle, wall areas (which
// project to a line) a strip on the room side of their wall. Beside the drawing: a legend, a metre scale
// bar, the floor and ceiling heights. One drawing per storey, main storey first, each with its own heading
// line, its storey's features, its areas (Area::storey) and the bounds cut 1.6 m above its floor; ids of the
// main storey's elements are as above, those of storey N (from 2) end in "-storeyN". With features, each
// room is one <path class="room-outline" data-room="K"> (its border with walls and other rooms) in its room
// colour and labelled with its index and floor area.
std::string plan_svg(const ReportInput& input);

// scene.glb: nodes "scan" (grey), "bounds" (translucent) and one per area, "area N TYPE SIZE REACH" with N
// the area's index in input.areas, each a thin quad 1 cm in front of its surface, coloured by reach; then one
// per placement, "placement N SURFACE", the object's box (its footprint extruded along the normal by its height)
// in magenta; then with features, one per room, "room K", its free floor 1 cm above the storey's floor in the
// room's colour. A node whose mesh would be empty (no scan, no bounds) is left out.
GlbScene scene_glb(const ReportInput& input);

// The file names write_report uses inside its folder.
inline constexpr std::string_view kPlanSvgName = "plan.svg";
inline constexpr std::string_view kSceneGlbName = "scene.glb";

// Creates `dir` (and its parents) when needed and writes plan.svg and scene.glb into it.
// Throws Error(Io) with one line naming the path when the folder or a file cannot be written.
void write_report(const ReportInput& input, const std::string& dir);

}  // namespace roomsense
