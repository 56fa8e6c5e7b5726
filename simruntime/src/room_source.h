// The room a simulated runtime serves: a world-space mesh plus, when the file has labels, objects with a plane
// each. World space is the runtime's LOCAL and STAGE space.
#pragma once
#include "roomsense/scan.h"

#include <openxr/openxr.h>

#include <memory>
#include <string>
#include <vector>

namespace roomsense::sim {

struct RoomObject {
  std::string label;                   // the file's label, e.g. "TABLE"
  XrSceneObjectTypeMSFT kind = XR_SCENE_OBJECT_TYPE_UNCATEGORIZED_MSFT;
  XrPosef plane_pose{};                // MSFT convention: centre, +Z normal into free space
  XrExtent2Df plane_size{};
};

struct Room {
  std::string source;                  // the file it came from
  Scan mesh;                           // world space
  std::vector<RoomObject> objects;     // empty for plain mesh files
};

// Loads a mesh file (OBJ/PLY/glTF/GLB via scanio) or a Quest capture (.json). Loaded rooms are cached by
// path and modification time, since tests create many instances on the same room.
// Throws roomsense::Error (or std::exception) with one clear line when the file is missing or malformed.
std::shared_ptr<const Room> load_room(const std::string& path);

// Quest semantic label -> MSFT object kind (FLOOR->floor, CEILING->ceiling, WALL_FACE->wall, furniture->platform).
XrSceneObjectTypeMSFT object_kind_for_label(const std::string& label);

}  // namespace roomsense::sim
