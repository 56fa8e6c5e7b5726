// Builds one scene from a room and a compute request: mesh chunks as visual/collider meshes, labelled objects
// with their planes, all filtered by the requested bounds.
#include "scene_data.h"
#include "scan_progress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

namespace roomsense::sim {
namespace {

XrUuidMSFT make_uuid(std::uint64_t serial, std::uint64_t index) {
  XrUuidMSFT id{};
  std::memcpy(id.bytes, &serial, 8);
  std::memcpy(id.bytes + 8, &index, 8);
  return id;
}

std::uint64_t next_mesh_buffer_id() {
  static std::atomic<std::uint64_t> next{1};  // unique across scenes, so a stale id is reported as invalid
  return next++;
}

bool box_intersects(const WorldBounds& bounds, const glm::dvec3& lo, const glm::dvec3& hi) {
  if (bounds.unbounded()) return true;
  for (const auto& s : bounds.spheres) {
    const glm::dvec3 closest = glm::clamp(s.centre, lo, hi);
    if (glm::length(closest - s.centre) <= s.radius) return true;
  }
  for (const auto& b : bounds.boxes) {
    // Conservative: the world box's corners, in the bound's frame, as an axis-aligned box there.
    const Rigid to_box = b.pose.inverse();
    glm::dvec3 bmin(1e300), bmax(-1e300);
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
      const glm::dvec3 p = to_box.apply(corner);
      bmin = glm::min(bmin, p);
      bmax = glm::max(bmax, p);
    }
    if (glm::all(glm::lessThanEqual(bmin, b.half_extents)) && glm::all(glm::greaterThanEqual(bmax, -b.half_extents)))
      return true;
  }
  return false;
}

XrScenePlaneAlignmentTypeMSFT alignment_of(const Rigid& pose) {
  const double up = std::fabs((pose.rotation * glm::dvec3(0, 0, 1)).y);  // |normal . up|
  if (up > std::cos(glm::radians(15.0))) return XR_SCENE_PLANE_ALIGNMENT_TYPE_HORIZONTAL_MSFT;
  if (up < std::sin(glm::radians(15.0))) return XR_SCENE_PLANE_ALIGNMENT_TYPE_VERTICAL_MSFT;
  return XR_SCENE_PLANE_ALIGNMENT_TYPE_NON_ORTHOGONAL_MSFT;
}

std::shared_ptr<const MeshBuffer> quad_mesh(const XrExtent2Df& size) {
  auto mesh = std::make_shared<MeshBuffer>();
  const float w = size.width * 0.5f, h = size.height * 0.5f;
  mesh->vertices = {{-w, -h, 0}, {w, -h, 0}, {w, h, 0}, {-w, h, 0}};
  mesh->indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +Z, the front
  return mesh;
}

}  // namespace

std::shared_ptr<const SceneData> build_scene(const ComputeRequest& request) {
  auto scene = std::make_shared<SceneData>();
  const ScanStep& scanned = *request.scanned;
  const Room& room = *scanned.room;
  // Each component's UUID is the observer's serial and the component's place in the room (its chunk's cell, its
  // object), not its place in this scene: the observer's computes correlate it, whatever the bounds leave out and
  // whatever else of the room is scanned. The low three bits tell the kinds apart.
  const std::vector<SharedChunk>& chunks = scanned.chunks;

  if (request.visual_mesh || request.collider_mesh) {
    for (std::size_t n = 0; n < chunks.size(); ++n) {
      const Chunk& chunk = *chunks[n];
      if (!box_intersects(request.bounds, chunk.world_min, chunk.world_max)) continue;
      const std::shared_ptr<const MeshBuffer> mesh(chunks[n], &chunk.mesh);  // shared by every scene that serves it
      for (XrSceneComponentTypeMSFT type : {XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT, XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT}) {
        if ((type == XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT && !request.visual_mesh) ||
            (type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT && !request.collider_mesh))
          continue;
        SceneComponent c;
        c.type = type;
        c.id = make_uuid(request.serial, cell_key(chunk.cell) << 3 | (type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT ? 2 : 1));
        c.pose = chunk.pose;
        c.update_time = scanned.update_time(chunk.cell, request.time);
        c.mesh_buffer_id = next_mesh_buffer_id();
        c.uint16_ok = mesh->fits_uint16();
        scene->meshes.emplace(c.mesh_buffer_id, mesh);  // both kinds share one buffer, under distinct ids
        scene->components.push_back(c);
      }
    }
  }

  if (request.planes || request.plane_meshes) {
    for (std::size_t n = 0; n < room.objects.size(); ++n) {
      const RoomObject& object = room.objects[n];
      const Rigid pose = to_rigid(object.plane_pose);
      if (!box_intersects(request.bounds, pose.translation, pose.translation)) continue;
      SceneComponent obj;
      obj.type = XR_SCENE_COMPONENT_TYPE_OBJECT_MSFT;
      obj.id = make_uuid(request.serial, std::uint64_t(n) << 3 | 3);
      obj.update_time = request.time;
      obj.pose = pose;
      obj.object_type = object.kind;
      scene->components.push_back(obj);

      SceneComponent plane;
      plane.type = XR_SCENE_COMPONENT_TYPE_PLANE_MSFT;
      plane.id = make_uuid(request.serial, std::uint64_t(n) << 3 | 4);
      plane.update_time = request.time;
      plane.parent = obj.id;
      plane.pose = pose;
      plane.object_type = object.kind;
      plane.alignment = alignment_of(pose);
      plane.size = object.plane_size;
      if (request.plane_meshes) {
        plane.mesh_buffer_id = next_mesh_buffer_id();
        plane.uint16_ok = true;
        scene->meshes.emplace(plane.mesh_buffer_id, quad_mesh(object.plane_size));
      }
      scene->components.push_back(plane);
    }
  }
  return scene;
}

}  // namespace roomsense::sim
