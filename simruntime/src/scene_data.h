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
};

struct SceneData {
  XrTime update_time = 0;
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

// The room's mesh split for XR_MSFT_scene_understanding (split_into_chunks), made once per instance, at its first
// scene compute: the room never changes, and a split of a 78k-vertex room took about 13 ms of every compute.
class MeshChunks {
 public:
  struct Piece {
    Rigid pose;
    std::shared_ptr<const MeshBuffer> mesh;  // shared by every scene that serves it
    glm::dvec3 world_min{0.0}, world_max{0.0};
  };
  const std::vector<Piece>& of(const Scan& mesh, double chunk_size);

 private:
  std::once_flag once_;
  std::vector<Piece> pieces_;
};

struct ComputeRequest {
  std::shared_ptr<const Room> room;
  std::shared_ptr<MeshChunks> chunks;  // the instance's, of `room` at `chunk_size`
  double chunk_size = 2.0;
  bool visual_mesh = false, collider_mesh = false, planes = false, plane_meshes = false;
  WorldBounds bounds;
  std::uint64_t serial = 0;  // the observer's: goes into component UUIDs, the same at each of its computes
  XrTime time = 0;           // every component's updateTime: the observer's first compute (the room never changes)
};

std::shared_ptr<const SceneData> build_scene(const ComputeRequest& request);

// The room's mesh split into cubes of `chunk_size`: each chunk has its own pose (centre, and a yaw that
// differs per chunk) and its vertices in that pose's frame. A triangle goes to the chunk of its centroid;
// vertices shared across chunks are repeated in each. Vertices no triangle uses go to their own position's chunk.
struct Chunk {
  Rigid pose;
  MeshBuffer mesh;
  glm::dvec3 world_min{0.0}, world_max{0.0};
};
std::vector<Chunk> split_into_chunks(const Scan& mesh, double chunk_size);

}  // namespace roomsense::sim
