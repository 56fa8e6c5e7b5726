// What one XR_MSFT_scene_understanding compute produces, immutable once built so that scenes can share it
// with no locking.
#pragma once
#include "pose_math.h"
#include "room_source.h"

#include <openxr/openxr.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

namespace roomsense::sim {

struct ScanStep;  // scan_progress.h

// The cube of `chunk_size` a chunk covers: its place in the room, the same whatever else of the room is there (a
// room being scanned, scan_progress.h), so ids made from it stay.
struct ChunkCell {
  long x = 0, y = 0, z = 0;
  auto operator<=>(const ChunkCell&) const = default;
};
// The cell of the triangle whose first index is `first` (its centroid's), or of a point.
ChunkCell triangle_cell(const Scan& mesh, std::size_t first, double chunk_size);
ChunkCell point_cell(const glm::dvec3& p, double chunk_size);
// A key for ids: the cell's coordinates, 21 bits each.
std::uint64_t cell_key(const ChunkCell& cell);

struct MeshBuffer {
  std::vector<XrVector3f> vertices;  // in the owning component's space
  std::vector<std::uint32_t> indices;
  bool fits_uint16() const { return vertices.size() <= 65536; }
};

struct SceneComponent {
  XrSceneComponentTypeMSFT type = XR_SCENE_COMPONENT_TYPE_INVALID_MSFT;
  XrUuidMSFT id{};
  XrUuidMSFT parent{};  // all zero: no parent
  Rigid pose;           // in world (LOCAL/STAGE) space
  std::optional<XrSceneObjectTypeMSFT> object_type;  // own kind for objects, the parent's for planes
  XrScenePlaneAlignmentTypeMSFT alignment = XR_SCENE_PLANE_ALIGNMENT_TYPE_NON_ORTHOGONAL_MSFT;
  XrExtent2Df size{};
  std::uint64_t mesh_buffer_id = 0;  // 0: none
  bool uint16_ok = false;
  XrTime update_time = 0;            // its XrSceneComponentMSFT::updateTime
};

struct SceneData {
  std::vector<SceneComponent> components;
  std::unordered_map<std::uint64_t, std::shared_ptr<const MeshBuffer>> meshes;
};

// Bounds of a compute, already resolved into world space (spaces may move after the call).
struct WorldBounds {
  struct Sphere { glm::dvec3 centre; double radius; };
  struct Box { Rigid pose; glm::dvec3 half_extents; };
  std::vector<Sphere> spheres;  // frustums are approximated by the sphere of their far distance
  std::vector<Box> boxes;
  bool unbounded() const { return spheres.empty() && boxes.empty(); }
};

struct ComputeRequest {
  std::shared_ptr<const ScanStep> scanned;  // the room, in chunks, as scanned when the compute was asked for
  bool visual_mesh = false, collider_mesh = false, planes = false, plane_meshes = false;
  WorldBounds bounds;
  std::uint64_t serial = 0;  // the observer's: goes into component UUIDs, the same at each of its computes
  XrTime time = 0;  // components' updateTime: the observer's first compute, or when a chunk being scanned changed
};

std::shared_ptr<const SceneData> build_scene(const ComputeRequest& request);

// The room's mesh split into cubes of `chunk_size`: each chunk has its own pose (centre, and a yaw that
// differs per chunk) and its vertices in that pose's frame. A triangle goes to the chunk of its centroid;
// vertices shared across chunks are repeated in each. Vertices no triangle uses go to their own position's chunk.
struct Chunk {
  ChunkCell cell;
  Rigid pose;
  MeshBuffer mesh;
  glm::dvec3 world_min{0.0}, world_max{0.0};
};
std::vector<Chunk> split_into_chunks(const Scan& mesh, double chunk_size);

}  // namespace roomsense::sim
