// Turns a room file into what the runtime serves; see room_source.h.
#include "room_source.h"
#include "process_state.h"

#include "roomsense/error.h"
#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"

#include <filesystem>
#include <map>
#include <mutex>
#include <utility>

namespace roomsense::sim {
namespace {

XrPosef to_xr(const scanio::QuestPose& p) {
  XrPosef pose{};
  pose.orientation = {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w};
  pose.position = {p.position.x, p.position.y, p.position.z};
  return pose;
}

RoomObject object_from(const std::string& label, const scanio::OrientedRect& rect) {
  return {label, object_kind_for_label(label), to_xr(rect.pose), {rect.width, rect.height}};
}

std::shared_ptr<const Room> read_room(const std::string& path) {
  auto room = std::make_shared<Room>();
  room->source = path;
  if (synth::is_builtin_source(path)) {  // the project's built-in rooms, named as the CLI names them
    room->mesh = synth::generate_builtin_source(path);
  } else if (scanio::is_quest_capture_path(path)) {
    scanio::QuestCapture capture = scanio::load_quest_capture(path);
    room->mesh = std::move(capture.mesh);
    for (const auto& plane : capture.planes) room->objects.push_back(object_from(plane.label, scanio::plane_rect(plane)));
    // MSFT has no boxes: a volume becomes an object with the plane of its top face (a table's or couch's top).
    for (const auto& volume : capture.volumes)
      room->objects.push_back(object_from(volume.label, scanio::volume_top_rect(volume)));
  } else {
    room->mesh = scanio::load_mesh_file(path);
  }
  if (room->mesh.indices.empty()) throw Error(ErrorCode::Io, "cannot serve '" + path + "': it holds no triangles");
  return room;
}

}  // namespace

XrSceneObjectTypeMSFT object_kind_for_label(const std::string& label) {
  static const std::map<std::string, XrSceneObjectTypeMSFT> kinds = {
      {"FLOOR", XR_SCENE_OBJECT_TYPE_FLOOR_MSFT},
      {"CEILING", XR_SCENE_OBJECT_TYPE_CEILING_MSFT},
      {"WALL_FACE", XR_SCENE_OBJECT_TYPE_WALL_MSFT},
      {"INNER_WALL_FACE", XR_SCENE_OBJECT_TYPE_WALL_MSFT},
      {"INVISIBLE_WALL_FACE", XR_SCENE_OBJECT_TYPE_WALL_MSFT},
      {"TABLE", XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT},
      {"COUCH", XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT},
      {"BED", XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT},
      {"STORAGE", XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT},
      {"CHAIR", XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT},
  };
  const auto it = kinds.find(label);
  return it == kinds.end() ? XR_SCENE_OBJECT_TYPE_UNCATEGORIZED_MSFT : it->second;
}

std::shared_ptr<const Room> load_room(const std::string& path) {
  struct Cache {
    std::mutex mutex;
    std::map<std::string, std::pair<std::filesystem::file_time_type, std::shared_ptr<const Room>>> rooms;
  };
  Cache& kept = process_wide<Cache>();
  auto& cache = kept.rooms;
  std::error_code ec;
  // A built-in room never changes: it gets the epoch as its stamp.
  const bool builtin = synth::is_builtin_source(path);
  const auto stamp = builtin ? std::filesystem::file_time_type{} : std::filesystem::last_write_time(path, ec);
  if (ec) throw Error(ErrorCode::Io, "cannot read '" + path + "': no such file");
  {
    std::lock_guard lock(kept.mutex);
    if (auto it = cache.find(path); it != cache.end() && it->second.first == stamp) return it->second.second;
  }
  auto room = read_room(path);  // outside the lock: loading a large scan takes a while
  std::lock_guard lock(kept.mutex);
  cache[path] = {stamp, room};
  return room;
}

}  // namespace roomsense::sim
