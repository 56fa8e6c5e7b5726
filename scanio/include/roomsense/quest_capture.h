// Meta Quest scene captures (the .json format of @iwer/sem, see ../shared/rooms/quest-iwer): a list of spatial
// entities with XR_FB/XR_META components. Used by the simulated runtime, the CLI and tests, so the conventions
// of the file are decoded in one place.
//
// Conventions of the file, checked against its own *_global_mesh.obj exports and the labelled planes:
// - `locatable_META` is the entity's pose in the capture's world frame (right-handed, +Y up, metres).
// - `triangleMesh_META` holds base64 little-endian float32 xyz and uint32 indices in the entity's frame.
// - `bounded2D_META` is a rectangle in the entity's X/Z plane (WebXR's plane convention): x spans
//   [offset.x, offset.x + width], z spans [offset.y, offset.y + height]. The entity's +Y axis points into the
//   surface (down for floors, up for ceilings, out of the room for walls).
// - `bounded3D_META` is a box [offset, offset + (width, height, depth)] in the entity's frame.
// - Protobuf's JSON form leaves out fields that are zero, so a missing number reads as 0.
#pragma once
#include "roomsense/scan.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace roomsense::scanio {

struct QuestPose {
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // glm order: w, x, y, z; normalised by the parser
  glm::vec3 position{0.0f};
  glm::vec3 apply(const glm::vec3& p) const { return orientation * p + position; }
};

struct QuestPlane {
  std::string uuid;
  std::string label;  // semanticLabel_META as written, e.g. "FLOOR", "WALL_FACE", "TABLE"
  QuestPose pose;     // the entity's pose (file convention, see above)
  glm::vec2 offset{0.0f};
  glm::vec2 extent{0.0f};  // width, height
};

struct QuestVolume {
  std::string uuid;
  std::string label;
  QuestPose pose;
  glm::vec3 offset{0.0f};
  glm::vec3 extent{0.0f};  // width (x), height (y), depth (z)
};

struct QuestCapture {
  Scan mesh;  // every triangleMesh_META entity, merged, in world space (entity poses applied)
  std::vector<QuestPlane> planes;
  std::vector<QuestVolume> volumes;
  std::size_t skipped_entities = 0;  // entities without a pose, which cannot be placed
};

// A rectangle or box face in the OpenXR scene-extension convention (XR_MSFT_scene_understanding,
// XR_EXT_spatial_entity, our DESIGN.md): pose at the centre, +Z the normal into free space, X/Y along the
// width/height (for walls +Y is up).
struct OrientedRect {
  QuestPose pose;
  float width = 0.0f;
  float height = 0.0f;
};
OrientedRect plane_rect(const QuestPlane& plane);
// The face of the box whose outward normal points most nearly up: the surface one could put things on.
OrientedRect volume_top_rect(const QuestVolume& volume);

// A Meta semantic label (FLOOR, WALL_FACE, TABLE, WINDOW_FRAME, ...) in our enum; Unknown for labels that say
// nothing about a surface (GLOBAL_MESH, INVISIBLE_WALL_FACE) and for names of later revisions.
SurfaceLabel surface_label_of_meta(std::string_view label);
// The capture's planes (their rectangles) and volumes (their boxes) as labelled triangles, for Scan::labels.
LabelledTriangles scene_labels(const QuestCapture& capture);

// Throws Error(ErrorCode::Io) with one clear line on anything malformed: bad JSON, wrong types, truncated or
// invalid base64, sizes that are not whole vertices/triangles, indices out of range, no mesh at all.
QuestCapture parse_quest_capture(std::string_view json_text, const std::string& source_name);
QuestCapture load_quest_capture(const std::string& path);

// True when the path names a .json file (case-insensitive), the only extension the captures use.
bool is_quest_capture_path(const std::string& path);

}  // namespace roomsense::scanio
