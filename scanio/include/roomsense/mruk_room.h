// Meta MR Utility Kit (MRUK) room JSON: the format of MRUK.SaveSceneToJsonString / LoadSceneFromJsonString and
// of MRUK's bundled test rooms. Read into the same QuestCapture as the Quest scene captures (quest_capture.h),
// so plane_rect() and volume_top_rect() and everything downstream work on both.
//
// The file: {"CoordinateSystem": "Unity" | "Unreal", "Rooms": [{"UUID", "RoomLayout", "Anchors": [{"UUID",
// "SemanticClassifications": ["TABLE", ...], "Transform": {"Translation", "Rotation", "Scale"},
// "PlaneBounds": {"Min", "Max"}, "PlaneBoundary2D": [[x, y], ...], "VolumeBounds": {"Min", "Max"},
// "GlobalMesh": {"Positions": [[x, y, z], ...], "Indices": [...]}}]}]}. Vectors are JSON arrays; a missing
// CoordinateSystem reads as "Unity" (the enum's default), the only value MRUK's own rooms use.
//
// What the reader makes of it (see mruk_room.cpp for the sources and the conversion):
// - Every room is read and merged: planes, volumes and meshes.
// - An anchor with plane bounds (PlaneBounds, or only PlaneBoundary2D) becomes a QuestPlane; one with
//   VolumeBounds a QuestVolume; an anchor with both (tables, couches, beds, storage) becomes both, as in a
//   Quest capture. The label is the first of SemanticClassifications ("" when there is none), i.e. the same
//   names as a capture's semanticLabel_META (WALL_FACE, FLOOR, CEILING, TABLE, ...).
// - Poses are in our frame (right-handed, +Y up, metres): a plane's pose has +Y into the surface and the
//   rectangle in its X/Z plane, a volume's pose is the anchor's native OpenXR frame (+Z the top for furniture)
//   with the box [offset, offset + extent], exactly the conventions of a Quest capture.
// - The mesh: a room's GlobalMesh anchor(s) when it has any. A room without one (MRUK's test rooms mostly have
//   none) gets a mesh built from its anchors so the analysis can run: each plane's boundary polygon
//   (PlaneBoundary2D, else the PlaneBounds rectangle) triangulated with its front face into the room, and each
//   volume as a closed box of 12 outward triangles (an anchor with a volume gets only the box, which already
//   holds its plane). Front faces are counter-clockwise.
// - skipped_entities counts anchors with no geometry at all (no plane, volume or mesh).
#pragma once
#include "roomsense/quest_capture.h"

#include <string>
#include <string_view>

namespace roomsense::scanio {

// Throws Error(ErrorCode::Io) with one line naming the file and what is wrong: bad JSON, a wrong type, a
// missing field, a number that is not finite or lies beyond 1 km, Min above Max, an index out of range, an
// unknown CoordinateSystem, no rooms or no usable geometry.
QuestCapture parse_mruk_room(std::string_view json_text, const std::string& source_name);
QuestCapture load_mruk_room(const std::string& path);

// A scene capture file (.json) of either kind, told apart by its content: an MRUK room or a Quest capture.
QuestCapture load_scene_capture(const std::string& path);

// A cheap sniff: true when the text is a JSON object with a top-level "Rooms" key (an MRUK room), false for a
// Quest capture (top-level "spatialEntities") and anything else. Reads tokens only until it can tell, and at
// most the first MiB, so a prefix of a file is enough.
bool is_mruk_room_json(std::string_view json_text);

}  // namespace roomsense::scanio
