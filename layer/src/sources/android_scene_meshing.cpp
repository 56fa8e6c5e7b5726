#include "android_scene_meshing.h"

#include "../guard.h"
#include "../log.h"
#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"

#include <algorithm>
#include <cstdio>

namespace roomsense::layer {
namespace {

using xr::check;

#define ANDROID_FUNCTIONS(_)                                                                            \
  _(xrEnumerateSupportedSemanticLabelSetsANDROID) _(xrCreateSceneMeshingTrackerANDROID)                 \
  _(xrDestroySceneMeshingTrackerANDROID) _(xrCreateSceneMeshSnapshotANDROID)                            \
  _(xrDestroySceneMeshSnapshotANDROID) _(xrGetAllSubmeshStatesANDROID) _(xrGetSubmeshDataANDROID)

constexpr float kQueryExtent = 200.0f;              // metres, a box about the base space's origin: any room
constexpr std::size_t kMaxSubmeshes = 1u << 20;
constexpr std::uint32_t kMaxElements = 1u << 26;    // per submesh: far beyond any room

std::string chunk_id(const XrUuid& id) {
  std::string s = "android:";
  char hex[3];
  for (std::uint8_t b : id.data) {
    std::snprintf(hex, sizeof hex, "%02x", b);
    s += hex;
  }
  return s;
}

SurfaceLabel surface_label(std::uint8_t label) {
  switch (label) {
    case XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID: return SurfaceLabel::Other;
    case XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID: return SurfaceLabel::Floor;
    case XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID: return SurfaceLabel::Ceiling;
    case XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID: return SurfaceLabel::Wall;
    case XR_SCENE_MESH_SEMANTIC_LABEL_TABLE_ANDROID: return SurfaceLabel::Table;
    default: return SurfaceLabel::Unknown;  // a label of a newer revision
  }
}

// The label most of a triangle's three vertices have; with three different ones, the first vertex's.
std::uint8_t majority(std::uint8_t a, std::uint8_t b, std::uint8_t c) { return (b == c && a != b) ? b : a; }

class AndroidSource final : public MeshSource {
 public:
#define ANDROID_MEMBER(name) PFN_##name name = nullptr;
  ANDROID_FUNCTIONS(ANDROID_MEMBER)
#undef ANDROID_MEMBER

  std::vector<SourceChunk> query(const QueryContext& context, std::stop_token stop) override;
};

// Destroys what the query created, whatever happens.
struct QueryHandles {
  const AndroidSource& next;
  XrSceneMeshingTrackerANDROID tracker = XR_NULL_HANDLE;
  XrSceneMeshSnapshotANDROID snapshot = XR_NULL_HANDLE;
  ~QueryHandles() {
    if (snapshot != XR_NULL_HANDLE) next.xrDestroySceneMeshSnapshotANDROID(snapshot);
    if (tracker != XR_NULL_HANDLE) next.xrDestroySceneMeshingTrackerANDROID(tracker);
  }
};

std::vector<SourceChunk> AndroidSource::query(const QueryContext& context, std::stop_token stop) {
  const auto sets = xr::read_two_call<XrSceneMeshSemanticLabelSetANDROID>(
      "xrEnumerateSupportedSemanticLabelSetsANDROID",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSceneMeshSemanticLabelSetANDROID* out) {
        return xrEnumerateSupportedSemanticLabelSetsANDROID(context.instance, context.system, capacity, count, out);
      },
      64);
  const bool labelled = std::find(sets.begin(), sets.end(), XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID) != sets.end();

  QueryHandles handles{*this};
  auto tracker_info = xr_struct<XrSceneMeshingTrackerCreateInfoANDROID>(XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID);
  tracker_info.semanticLabelSet = labelled ? XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID : XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID;
  tracker_info.enableNormals = XR_FALSE;
  check(xrCreateSceneMeshingTrackerANDROID(context.session, &tracker_info, &handles.tracker), "xrCreateSceneMeshingTrackerANDROID");

  auto snapshot_info = xr_struct<XrSceneMeshSnapshotCreateInfoANDROID>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID);
  snapshot_info.baseSpace = context.base;
  snapshot_info.time = context.time;
  snapshot_info.boundingBox.center = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
  snapshot_info.boundingBox.extents = {kQueryExtent, kQueryExtent, kQueryExtent};
  auto created = xr_struct<XrSceneMeshSnapshotCreationResultANDROID>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID);
  check(xrCreateSceneMeshSnapshotANDROID(handles.tracker, &snapshot_info, &created), "xrCreateSceneMeshSnapshotANDROID");
  handles.snapshot = created.snapshot;
  if (created.trackingState == XR_SCENE_MESH_TRACKING_STATE_ERROR_ANDROID)
    throw std::runtime_error("the runtime's scene meshing is in its error state");

  const auto states = xr::read_two_call<XrSceneSubmeshStateANDROID>(
      "xrGetAllSubmeshStatesANDROID",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSceneSubmeshStateANDROID* out) {
        return xrGetAllSubmeshStatesANDROID(handles.snapshot, capacity, count, out);
      },
      kMaxSubmeshes, xr_struct<XrSceneSubmeshStateANDROID>(XR_TYPE_SCENE_SUBMESH_STATE_ANDROID));

  std::vector<SourceChunk> out;
  out.reserve(states.size());
  std::size_t unposed = 0;
  for (const XrSceneSubmeshStateANDROID& state : states) {
    if (stop.stop_requested()) return {};
    if (!is_valid_pose(state.submeshPoseInBaseSpace)) {
      ++unposed;
      continue;
    }
    // Counts first, then the arrays (two-call idiom, one submesh at a time).
    auto data = xr_struct<XrSceneSubmeshDataANDROID>(XR_TYPE_SCENE_SUBMESH_DATA_ANDROID);
    data.submeshId = state.submeshId;
    check(xrGetSubmeshDataANDROID(handles.snapshot, 1, &data), "xrGetSubmeshDataANDROID");
    if (data.vertexCountOutput > kMaxElements || data.indexCountOutput > kMaxElements)
      throw std::runtime_error("xrGetSubmeshDataANDROID reported a submesh over the size limit");
    std::vector<XrVector3f> vertices(data.vertexCountOutput);
    std::vector<std::uint8_t> semantics(labelled ? vertices.size() : 0);
    std::vector<std::uint32_t> indices(data.indexCountOutput);
    if (!vertices.empty() || !indices.empty()) {
      data.vertexCapacityInput = static_cast<std::uint32_t>(vertices.size());
      data.vertexPositions = vertices.empty() ? nullptr : vertices.data();
      data.vertexSemantics = semantics.empty() ? nullptr : semantics.data();
      data.indexCapacityInput = static_cast<std::uint32_t>(indices.size());
      data.indices = indices.empty() ? nullptr : indices.data();
      check(xrGetSubmeshDataANDROID(handles.snapshot, 1, &data), "xrGetSubmeshDataANDROID");
      vertices.resize(std::min<std::size_t>(vertices.size(), data.vertexCountOutput));
      semantics.resize(std::min<std::size_t>(semantics.size(), vertices.size()));
      indices.resize(std::min<std::size_t>(indices.size(), data.indexCountOutput));
    }
    indices.resize(indices.size() / 3 * 3);
    if (std::any_of(indices.begin(), indices.end(), [&](std::uint32_t v) { return v >= vertices.size(); }))
      throw std::runtime_error("the runtime served a submesh with an index out of range");

    SourceChunk chunk;
    chunk.id = chunk_id(state.submeshId);
    chunk.change = static_cast<std::uint64_t>(state.lastUpdatedTime);
    chunk.mesh.vertices = transformed(vertices.data(), vertices.size(), to_rigid(state.submeshPoseInBaseSpace));
    if (labelled && !semantics.empty()) {
      chunk.labels.reserve(indices.size() / 3);
      for (std::size_t t = 0; t < indices.size(); t += 3)
        chunk.labels.push_back(surface_label(majority(semantics[indices[t]], semantics[indices[t + 1]], semantics[indices[t + 2]])));
    }
    chunk.mesh.indices = std::move(indices);
    out.push_back(std::move(chunk));
  }
  if (unposed > 0) log_warn(std::to_string(unposed) + " runtime submesh(es) had no valid pose and were left out");
  return out;
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<AndroidSource>();
#define ANDROID_LOAD(name) load_next(next, instance, #name, source->name);
  ANDROID_FUNCTIONS(ANDROID_LOAD)
#undef ANDROID_LOAD
  return source;
}

}  // namespace

const SourceInfo& android_scene_meshing_source() {
#define ANDROID_NAME(name) #name,
  static const SourceInfo source{
      XR_ANDROID_SCENE_MESHING_EXTENSION_NAME,
      "submeshes of a scene mesh snapshot, with per-vertex labels",
      {{XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, {ANDROID_FUNCTIONS(ANDROID_NAME)}}},
      {},  // no passive capture
      &create,
  };
#undef ANDROID_NAME
  return source;
}

}  // namespace roomsense::layer
