// The active query, step by step:
// 1. The plane tracking capability and the components the runtime offers for it (BOUNDED_2D, POLYGON_2D,
//    MESH_2D, PLANE_SEMANTIC_LABEL of them).
// 2. A spatial context with those components, then a discovery snapshot in the base space at the query's time:
//    each through a future, polled (xrPollFutureEXT) for 10 s at most and cancelled when the query is stopped.
// 3. The snapshot's component data (two-call idiom), each plane's mesh, polygon or rectangle read and moved
//    into the base space. The snapshot and the context are destroyed on every path.
// Passive capture: the application's discovery snapshots (their base space located in the session's capture
// space at the snapshot's time), the planes its component data queries return, and the plane buffers it reads;
// each plane whose geometry it read in full is triangulated as the active query does and kept.
#include "ext_spatial_plane_tracking.h"

#include "source_support.h"

#include "../capture.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"
#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <chrono>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <unordered_map>

namespace roomsense::layer {
namespace {

using xr::check;

#define EXT_FUTURE_FUNCTIONS(_) _(xrPollFutureEXT) _(xrCancelFutureEXT)
#define EXT_SPATIAL_FUNCTIONS(_)                                                                               \
  _(xrEnumerateSpatialCapabilitiesEXT) _(xrEnumerateSpatialCapabilityComponentTypesEXT)                        \
  _(xrEnumerateSpatialCapabilityFeaturesEXT) _(xrCreateSpatialContextAsyncEXT) _(xrCreateSpatialContextCompleteEXT) \
  _(xrDestroySpatialContextEXT) _(xrCreateSpatialDiscoverySnapshotAsyncEXT)                                    \
  _(xrCreateSpatialDiscoverySnapshotCompleteEXT) _(xrQuerySpatialComponentDataEXT) _(xrDestroySpatialSnapshotEXT) \
  _(xrCreateSpatialEntityFromIdEXT) _(xrDestroySpatialEntityEXT) _(xrCreateSpatialUpdateSnapshotEXT)           \
  _(xrGetSpatialBufferStringEXT) _(xrGetSpatialBufferUint8EXT) _(xrGetSpatialBufferUint16EXT)                  \
  _(xrGetSpatialBufferUint32EXT) _(xrGetSpatialBufferFloatEXT) _(xrGetSpatialBufferVector2fEXT)                \
  _(xrGetSpatialBufferVector3fEXT)

constexpr std::size_t kMaxEntities = 1u << 16;
constexpr std::size_t kMaxBufferElements = 1u << 24;  // per buffer: far beyond any plane

const XrSpatialComponentTypeEXT kWanted[] = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT};

SurfaceLabel surface_label(XrSpatialPlaneSemanticLabelEXT label) {
  switch (label) {
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT: return SurfaceLabel::Floor;
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT: return SurfaceLabel::Ceiling;
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT: return SurfaceLabel::Wall;
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT: return SurfaceLabel::Table;
    default: return SurfaceLabel::Unknown;  // UNCATEGORIZED: the runtime does not know either
  }
}

class ExtPlaneSource final : public MeshSource {
 public:
#define EXT_MEMBER(name) PFN_##name name = nullptr;
  EXT_FUTURE_FUNCTIONS(EXT_MEMBER)
  EXT_SPATIAL_FUNCTIONS(EXT_MEMBER)
#undef EXT_MEMBER

  std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) override;
  void forget_session(XrSession session) override;

  // Waits for a future to be ready; false when stopped (the future is cancelled then, and on a timeout).
  bool wait(XrInstance instance, XrFutureEXT future, const char* what, std::stop_token stop) const {
    return wait_for_future(xrPollFutureEXT, xrCancelFutureEXT, instance, future, what, stop);
  }
};

// Destroys what the query created, whatever happens.
struct QueryHandles {
  const ExtPlaneSource& next;
  XrSpatialContextEXT context = XR_NULL_HANDLE;
  XrSpatialSnapshotEXT snapshot = XR_NULL_HANDLE;
  ~QueryHandles() {
    if (snapshot != XR_NULL_HANDLE) next.xrDestroySpatialSnapshotEXT(snapshot);
    if (context != XR_NULL_HANDLE) next.xrDestroySpatialContextEXT(context);
  }
};

// Ear clipping of a simple outline (either winding); a fan when it is not simple enough to clip.
std::vector<std::uint32_t> triangulate(const std::vector<XrVector2f>& outline) {
  const std::size_t n = outline.size();
  std::vector<std::uint32_t> out;
  if (n < 3) return out;
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const XrVector2f& a = outline[i];
    const XrVector2f& b = outline[(i + 1) % n];
    area2 += double(a.x) * b.y - double(b.x) * a.y;
  }
  std::vector<std::uint32_t> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = static_cast<std::uint32_t>(area2 >= 0 ? i : n - 1 - i);  // counter-clockwise
  auto cross = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const XrVector2f &p = outline[a], &q = outline[b], &r = outline[c];
    return (double(q.x) - p.x) * (double(r.y) - p.y) - (double(q.y) - p.y) * (double(r.x) - p.x);
  };
  std::size_t guard = 0;
  while (ring.size() > 3 && guard++ < n * n) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::uint32_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
      if (cross(a, b, c) <= 0) continue;  // reflex or flat
      bool inside = false;
      for (std::uint32_t p : ring)
        if (p != a && p != b && p != c && cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0) {
          inside = true;
          break;
        }
      if (inside) continue;
      out.insert(out.end(), {a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
      break;
    }
    if (!clipped) break;
  }
  if (ring.size() == 3) {
    out.insert(out.end(), {ring[0], ring[1], ring[2]});
  } else {  // not simple: a fan over what is left
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) out.insert(out.end(), {ring[0], ring[i], ring[i + 1]});
  }
  return out;
}

// 2D points of a plane's frame, moved into the base space by the frame's pose.
MeshPiece place(const XrPosef& origin, const std::vector<XrVector2f>& points, std::vector<std::uint32_t> indices) {
  std::vector<XrVector3f> flat;
  flat.reserve(points.size());
  for (const XrVector2f& p : points) flat.push_back({p.x, p.y, 0.0f});
  MeshPiece piece;
  piece.vertices = transformed(flat.data(), flat.size(), to_rigid(origin));
  piece.indices = std::move(indices);  // broken triangles: checked_chunks (active), keep_capture (passive)
  return piece;
}

// A plane's triangles in the base space, from its 2D mesh, its polygon or its bounds (the active query and the
// passive capture alike).
MeshPiece mesh_plane(const XrPosef& origin, const std::vector<XrVector2f>& points, std::vector<std::uint32_t> indices) {
  return place(origin, points, std::move(indices));
}

MeshPiece polygon_plane(const XrPosef& origin, const std::vector<XrVector2f>& outline) {
  return place(origin, outline, triangulate(outline));
}

MeshPiece bounds_plane(const XrSpatialBounded2DDataEXT& bounds) {
  const float w = bounds.extents.width * 0.5f, h = bounds.extents.height * 0.5f;
  return place(bounds.center, {{-w, -h}, {w, -h}, {w, h}, {-w, h}}, {0, 1, 2, 0, 2, 3});
}

// One plane as a chunk: its id, its label on every triangle, and a change marker of both.
SourceChunk plane_chunk(XrSpatialEntityIdEXT id, MeshPiece mesh, XrSpatialPlaneSemanticLabelEXT runtime_label) {
  SourceChunk chunk;
  chunk.id = "ext:" + std::to_string(static_cast<std::uint64_t>(id));
  chunk.mesh = std::move(mesh);
  const SurfaceLabel label = surface_label(runtime_label);
  chunk.labels.assign(chunk.mesh.indices.size() / 3, label);
  chunk.change = content_hash(chunk.mesh) ^ (static_cast<std::uint64_t>(label) * 0x9E3779B97F4A7C15ull);
  return chunk;
}

std::vector<SourceChunk> ExtPlaneSource::run_query(const QueryContext& context, std::stop_token stop) {
  // 1. The capability and its components.
  const auto capabilities = xr::read_two_call<XrSpatialCapabilityEXT>(
      "xrEnumerateSpatialCapabilitiesEXT",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSpatialCapabilityEXT* out) {
        return xrEnumerateSpatialCapabilitiesEXT(context.instance, context.system, capacity, count, out);
      },
      256);
  if (std::find(capabilities.begin(), capabilities.end(), XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT) == capabilities.end())
    throw std::runtime_error("the runtime offers no plane tracking capability");
  auto types = xr_struct<XrSpatialCapabilityComponentTypesEXT>(XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT);
  const auto offered = xr::read_two_call<XrSpatialComponentTypeEXT>(
      "xrEnumerateSpatialCapabilityComponentTypesEXT",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSpatialComponentTypeEXT* out) {
        types.componentTypeCapacityInput = capacity;
        types.componentTypes = out;
        const XrResult r = xrEnumerateSpatialCapabilityComponentTypesEXT(context.instance, context.system,
                                                                          XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &types);
        *count = types.componentTypeCountOutput;
        return r;
      },
      256);
  std::vector<XrSpatialComponentTypeEXT> enabled;
  for (XrSpatialComponentTypeEXT c : kWanted)
    if (std::find(offered.begin(), offered.end(), c) != offered.end()) enabled.push_back(c);
  auto has = [&](XrSpatialComponentTypeEXT c) { return std::find(enabled.begin(), enabled.end(), c) != enabled.end(); };
  if (!has(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT) && !has(XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT) &&
      !has(XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT))
    throw std::runtime_error("the runtime's plane tracking offers no plane geometry");

  // 2. Context, then discovery snapshot, each through a future.
  QueryHandles handles{*this};
  auto config = xr_struct<XrSpatialCapabilityConfigurationPlaneTrackingEXT>(XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT);
  config.capability = XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT;
  config.enabledComponentCount = static_cast<uint32_t>(enabled.size());
  config.enabledComponents = enabled.data();
  const auto* config_header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
  auto create = xr_struct<XrSpatialContextCreateInfoEXT>(XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT);
  create.capabilityConfigCount = 1;
  create.capabilityConfigs = &config_header;
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  check(xrCreateSpatialContextAsyncEXT(context.session, &create, &future), "xrCreateSpatialContextAsyncEXT");
  if (!wait(context.instance, future, "xrCreateSpatialContextAsyncEXT", stop)) return {};
  auto created = xr_struct<XrCreateSpatialContextCompletionEXT>(XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT);
  check(xrCreateSpatialContextCompleteEXT(context.session, future, &created), "xrCreateSpatialContextCompleteEXT");
  check(created.futureResult, "xrCreateSpatialContextCompleteEXT (future result)");
  handles.context = created.spatialContext;

  auto discover = xr_struct<XrSpatialDiscoverySnapshotCreateInfoEXT>(XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT);
  discover.componentTypeCount = static_cast<uint32_t>(enabled.size());
  discover.componentTypes = enabled.data();
  check(xrCreateSpatialDiscoverySnapshotAsyncEXT(handles.context, &discover, &future), "xrCreateSpatialDiscoverySnapshotAsyncEXT");
  if (!wait(context.instance, future, "xrCreateSpatialDiscoverySnapshotAsyncEXT", stop)) return {};
  auto completion_info = xr_struct<XrCreateSpatialDiscoverySnapshotCompletionInfoEXT>(XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT);
  completion_info.baseSpace = context.base;
  completion_info.time = context.time;
  completion_info.future = future;
  auto snapshot = xr_struct<XrCreateSpatialDiscoverySnapshotCompletionEXT>(XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT);
  check(xrCreateSpatialDiscoverySnapshotCompleteEXT(handles.context, &completion_info, &snapshot),
        "xrCreateSpatialDiscoverySnapshotCompleteEXT");
  check(snapshot.futureResult, "xrCreateSpatialDiscoverySnapshotCompleteEXT (future result)");
  handles.snapshot = snapshot.snapshot;
  if (stop.stop_requested()) return {};

  // 3. The component data: counts first, then every list at once.
  auto condition = xr_struct<XrSpatialComponentDataQueryConditionEXT>(XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT);
  condition.componentTypeCount = static_cast<uint32_t>(enabled.size());
  condition.componentTypes = enabled.data();
  auto result = xr_struct<XrSpatialComponentDataQueryResultEXT>(XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT);
  check(xrQuerySpatialComponentDataEXT(handles.snapshot, &condition, &result), "xrQuerySpatialComponentDataEXT");
  const std::size_t n = result.entityIdCountOutput;
  if (n > kMaxEntities) throw std::runtime_error("the runtime reported an absurd number of planes");
  if (n == 0) return {};
  std::vector<XrSpatialEntityIdEXT> ids(n);
  std::vector<XrSpatialEntityTrackingStateEXT> states(n);
  std::vector<XrSpatialBounded2DDataEXT> bounds(n);
  std::vector<XrSpatialPolygon2DDataEXT> polygons(n);
  std::vector<XrSpatialMeshDataEXT> meshes(n);
  std::vector<XrSpatialPlaneSemanticLabelEXT> labels(n, XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT);
  auto bound_list = xr_struct<XrSpatialComponentBounded2DListEXT>(XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT);
  auto polygon_list = xr_struct<XrSpatialComponentPolygon2DListEXT>(XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT);
  auto mesh_list = xr_struct<XrSpatialComponentMesh2DListEXT>(XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT);
  auto label_list = xr_struct<XrSpatialComponentPlaneSemanticLabelListEXT>(XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT);
  const auto count = static_cast<uint32_t>(n);
  void* chain = nullptr;
  if (has(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT)) bound_list = {bound_list.type, chain, count, bounds.data()}, chain = &bound_list;
  if (has(XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT)) polygon_list = {polygon_list.type, chain, count, polygons.data()}, chain = &polygon_list;
  if (has(XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT)) mesh_list = {mesh_list.type, chain, count, meshes.data()}, chain = &mesh_list;
  if (has(XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT)) label_list = {label_list.type, chain, count, labels.data()}, chain = &label_list;
  result.next = chain;
  result.entityIdCapacityInput = count;
  result.entityIds = ids.data();
  result.entityStateCapacityInput = count;
  result.entityStates = states.data();
  check(xrQuerySpatialComponentDataEXT(handles.snapshot, &condition, &result), "xrQuerySpatialComponentDataEXT");
  const std::size_t got = std::min<std::size_t>(n, result.entityIdCountOutput);

  auto buffer_get = [&](XrSpatialBufferIdEXT id) {
    auto info = xr_struct<XrSpatialBufferGetInfoEXT>(XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT);
    info.bufferId = id;
    return info;
  };
  auto read_points = [&](const XrSpatialBufferEXT& buffer) {
    if (buffer.bufferType != XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT)
      throw std::runtime_error("the runtime served plane vertices of buffer type " + std::to_string(buffer.bufferType));
    const auto info = buffer_get(buffer.bufferId);
    return xr::read_two_call<XrVector2f>(
        "xrGetSpatialBufferVector2fEXT",
        [&](std::uint32_t capacity, std::uint32_t* c, XrVector2f* out) {
          return xrGetSpatialBufferVector2fEXT(handles.snapshot, &info, capacity, c, out);
        },
        kMaxBufferElements);
  };
  auto read_indices = [&](const XrSpatialBufferEXT& buffer) -> std::vector<std::uint32_t> {
    const auto info = buffer_get(buffer.bufferId);
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT32_EXT)
      return xr::read_two_call<std::uint32_t>(
          "xrGetSpatialBufferUint32EXT",
          [&](std::uint32_t capacity, std::uint32_t* c, std::uint32_t* out) {
            return xrGetSpatialBufferUint32EXT(handles.snapshot, &info, capacity, c, out);
          },
          kMaxBufferElements);
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) {
      const auto small = xr::read_two_call<std::uint16_t>(
          "xrGetSpatialBufferUint16EXT",
          [&](std::uint32_t capacity, std::uint32_t* c, std::uint16_t* out) {
            return xrGetSpatialBufferUint16EXT(handles.snapshot, &info, capacity, c, out);
          },
          kMaxBufferElements);
      return {small.begin(), small.end()};
    }
    throw std::runtime_error("the runtime served plane indices of buffer type " + std::to_string(buffer.bufferType));
  };

  std::vector<SourceChunk> out;
  out.reserve(got);
  for (std::size_t i = 0; i < got; ++i) {
    if (stop.stop_requested()) return {};
    if (states[i] != XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT) continue;
    MeshPiece mesh;
    if (has(XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT) && meshes[i].vertexBuffer.bufferId != XR_NULL_SPATIAL_BUFFER_ID_EXT) {
      mesh = mesh_plane(meshes[i].origin, read_points(meshes[i].vertexBuffer), read_indices(meshes[i].indexBuffer));
    } else if (has(XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT) && polygons[i].vertexBuffer.bufferId != XR_NULL_SPATIAL_BUFFER_ID_EXT) {
      mesh = polygon_plane(polygons[i].origin, read_points(polygons[i].vertexBuffer));
    } else if (has(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT)) {
      mesh = bounds_plane(bounds[i]);
    }
    SourceChunk chunk = plane_chunk(ids[i], std::move(mesh), labels[i]);  // in the base space already
    if (std::optional<SourceChunk> kept = served_before(context, chunk.id, chunk.change, chunk.placed)) chunk = std::move(*kept);
    out.push_back(std::move(chunk));  // an empty one is dropped by checked_chunks
  }
  return out;
}

// ---- passive capture: the application's contexts and discovery snapshots, the planes its queries return and
// the plane buffers it reads

constexpr std::size_t kMaxRecords = 4096;  // contexts and snapshots per process, planes per snapshot: oldest first out

struct PlaneRecord {
  XrSpatialPlaneSemanticLabelEXT label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  std::optional<XrSpatialMeshDataEXT> mesh;
  std::optional<XrSpatialPolygon2DDataEXT> polygon;
  int kept = 0;  // 1 bounds, 2 polygon, 3 mesh: a coarser geometry read later does not replace a finer one
};

struct SnapshotRecord {
  std::shared_ptr<SessionState> session;
  xr::Rigid base_in_capture;  // the snapshot's base space in the capture space, at the snapshot's time
  std::mutex mutex;           // the application may read buffers from several threads
  std::unordered_map<XrSpatialEntityIdEXT, PlaneRecord> planes;
  std::deque<XrSpatialEntityIdEXT> plane_order;
  std::unordered_map<XrSpatialBufferIdEXT, XrSpatialEntityIdEXT> owners;  // buffer -> plane
  std::unordered_map<XrSpatialBufferIdEXT, std::vector<XrVector2f>> points;
  std::unordered_map<XrSpatialBufferIdEXT, std::vector<std::uint32_t>> indices;
};

// A handle map bounded to kMaxRecords, the oldest dropped first.
template <typename Key, typename Value>
struct Bounded {
  std::unordered_map<Key, Value> map;
  std::deque<Key> order;
  void put(Key key, Value value) {
    if (map.insert_or_assign(key, std::move(value)).second) order.push_back(key);
    while (order.size() > kMaxRecords) {
      map.erase(order.front());
      order.pop_front();
    }
  }
  void erase(Key key) {
    if (map.erase(key) > 0) std::erase(order, key);
  }
  template <typename Pred>
  void erase_if(Pred pred) {
    std::erase_if(map, pred);
    std::erase_if(order, [&](const Key& k) { return !map.contains(k); });
  }
};

// The application's handles. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Records {
  std::mutex mutex;
  Bounded<XrSpatialContextEXT, std::shared_ptr<SessionState>> contexts;
  Bounded<XrSpatialSnapshotEXT, std::shared_ptr<SnapshotRecord>> snapshots;
};

Records& records() {
  static Records r;
  return r;
}

void ExtPlaneSource::forget_session(XrSession session) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  r.contexts.erase_if([&](const auto& entry) { return entry.second->handle == session; });
  r.snapshots.erase_if([&](const auto& entry) { return entry.second->session->handle == session; });
}

ExtPlaneSource* source_of(const InstanceState& instance) {
  return instance.source<ExtPlaneSource>(ext_spatial_plane_tracking_source());
}

// The source for a handle of a session; for a handle not recorded (a snapshot of xrCreateSpatialUpdateSnapshotEXT,
// say), the first instance whose application enabled the extensions (the next function is the same for every
// instance of the process).
ExtPlaneSource* source_for(const SessionState* session) {
  if (session != nullptr) return source_of(*session->instance);
  Registry& reg = registry();
  std::lock_guard lock(reg.mutex);
  for (const auto& [handle, instance] : reg.instances)
    for (const EnabledSource& s : instance->sources)
      if (s.info == &ext_spatial_plane_tracking_source() && s.app_enabled) return static_cast<ExtPlaneSource*>(s.source.get());
  return nullptr;
}

std::shared_ptr<SnapshotRecord> snapshot_record(XrSpatialSnapshotEXT snapshot) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  const auto it = r.snapshots.map.find(snapshot);
  return it == r.snapshots.map.end() ? nullptr : it->second;
}

// Moves planes (in the snapshot's base space) into the capture space and keeps them.
void keep_planes(SnapshotRecord& record, std::vector<SourceChunk> chunks) {
  for (SourceChunk& chunk : chunks) {
    transform_in_place(chunk.mesh.vertices, record.base_in_capture);
    keep_capture(*record.session, ext_spatial_plane_tracking_source(), std::move(chunk));
  }
}

// A plane's geometry, when the application has read all of it (mesh first, else polygon); the buffers used are
// forgotten. Call with the record's lock held.
std::optional<SourceChunk> complete_plane(SnapshotRecord& record, XrSpatialEntityIdEXT id) {
  const auto it = record.planes.find(id);
  if (it == record.planes.end()) return std::nullopt;
  PlaneRecord& plane = it->second;
  try {
    if (plane.mesh) {
      const auto points = record.points.find(plane.mesh->vertexBuffer.bufferId);
      const auto indices = record.indices.find(plane.mesh->indexBuffer.bufferId);
      if (points != record.points.end() && indices != record.indices.end()) {
        SourceChunk chunk = plane_chunk(id, mesh_plane(plane.mesh->origin, points->second, std::move(indices->second)), plane.label);
        record.points.erase(points);
        record.indices.erase(indices);
        plane.kept = 3;
        return chunk;
      }
    }
    if (plane.polygon && plane.kept <= 2) {
      const auto points = record.points.find(plane.polygon->vertexBuffer.bufferId);
      if (points != record.points.end()) {
        SourceChunk chunk = plane_chunk(id, polygon_plane(plane.polygon->origin, points->second), plane.label);
        record.points.erase(points);
        plane.kept = 2;
        return chunk;
      }
    }
  } catch (const std::exception& e) {  // a malformed plane is the application's to see, not the layer's to report
    const std::string what = e.what();
    log_debug([&] { return "a plane the application read is not captured: " + what; });
  }
  return std::nullopt;
}

XrResult XRAPI_CALL hook_xrCreateSpatialContextCompleteEXT(XrSession session, XrFutureEXT future,
                                                           XrCreateSpatialContextCompletionEXT* completion) {
  return guarded("xrCreateSpatialContextCompleteEXT", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    ExtPlaneSource* source = source_of(*s->instance);
    if (source == nullptr) throw std::logic_error("XR_EXT_spatial_plane_tracking hook without its source");
    const XrResult result = source->xrCreateSpatialContextCompleteEXT(session, future, completion);
    if (XR_SUCCEEDED(result) && completion != nullptr && XR_SUCCEEDED(completion->futureResult) &&
        completion->spatialContext != XR_NULL_HANDLE) {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      r.contexts.put(completion->spatialContext, s);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrCreateSpatialDiscoverySnapshotCompleteEXT(XrSpatialContextEXT spatialContext,
                                                                     const XrCreateSpatialDiscoverySnapshotCompletionInfoEXT* info,
                                                                     XrCreateSpatialDiscoverySnapshotCompletionEXT* completion) {
  return guarded("xrCreateSpatialDiscoverySnapshotCompleteEXT", [&]() -> XrResult {
    std::shared_ptr<SessionState> s;
    {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      if (const auto it = r.contexts.map.find(spatialContext); it != r.contexts.map.end()) s = it->second;
    }
    ExtPlaneSource* source = source_for(s.get());
    if (source == nullptr) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source->xrCreateSpatialDiscoverySnapshotCompleteEXT(spatialContext, info, completion);
    if (!s || XR_FAILED(result) || info == nullptr || completion == nullptr || XR_FAILED(completion->futureResult) ||
        completion->snapshot == XR_NULL_HANDLE)
      return result;
    // Where the snapshot's base space is in the capture space, now that both exist.
    const std::optional<Rigid> base_in_capture = locate_in_capture_space(*s, info->baseSpace, info->time);
    if (!base_in_capture) {
      log_debug([] { return std::string("a snapshot's base space cannot be located; its planes are not captured"); });
      return result;
    }
    auto record = std::make_shared<SnapshotRecord>();
    record->session = s;
    record->base_in_capture = *base_in_capture;
    Records& r = records();
    std::lock_guard lock(r.mutex);
    r.snapshots.put(completion->snapshot, std::move(record));
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroySpatialSnapshotEXT(XrSpatialSnapshotEXT snapshot) {
  return guarded("xrDestroySpatialSnapshotEXT", [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    ExtPlaneSource* source = source_for(record ? record->session.get() : nullptr);
    if (source == nullptr) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source->xrDestroySpatialSnapshotEXT(snapshot);
    if (XR_SUCCEEDED(result) && record) {
      {
        Records& r = records();
        std::lock_guard lock(r.mutex);
        r.snapshots.erase(snapshot);
      }
      capture_read_done(record->session);  // the application is done with this snapshot
    }
    return result;
  });
}

// The component lists the application chained, when they hold `n` entries.
template <typename List>
const List* chained(const void* next, XrStructureType type, std::uint32_t List::*count, std::uint32_t n) {
  const auto* list = find_next<const List>(next, type);
  return list != nullptr && list->*count >= n ? list : nullptr;
}

XrResult XRAPI_CALL hook_xrQuerySpatialComponentDataEXT(XrSpatialSnapshotEXT snapshot,
                                                        const XrSpatialComponentDataQueryConditionEXT* queryCondition,
                                                        XrSpatialComponentDataQueryResultEXT* queryResult) {
  return guarded("xrQuerySpatialComponentDataEXT", [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    ExtPlaneSource* source = source_for(record ? record->session.get() : nullptr);
    if (source == nullptr) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source->xrQuerySpatialComponentDataEXT(snapshot, queryCondition, queryResult);
    if (result != XR_SUCCESS || !record || queryResult == nullptr || queryResult->entityIds == nullptr ||
        queryResult->entityIdCapacityInput == 0)
      return result;
    const std::uint32_t n = std::min(queryResult->entityIdCountOutput, queryResult->entityIdCapacityInput);
    const bool states = queryResult->entityStates != nullptr && queryResult->entityStateCapacityInput >= n;
    const void* next = queryResult->next;
    using Bounds = XrSpatialComponentBounded2DListEXT;
    using Polygons = XrSpatialComponentPolygon2DListEXT;
    using Meshes = XrSpatialComponentMesh2DListEXT;
    using Labels = XrSpatialComponentPlaneSemanticLabelListEXT;
    const auto* bounds = chained(next, XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, &Bounds::boundCount, n);
    const auto* polygons = chained(next, XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT, &Polygons::polygonCount, n);
    const auto* meshes = chained(next, XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, &Meshes::meshCount, n);
    const auto* labels = chained(next, XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT, &Labels::semanticLabelCount, n);
    std::vector<SourceChunk> rectangles;  // planes with bounds: kept now, replaced by their mesh or polygon once read
    {
      SnapshotRecord& rec = *record;
      std::lock_guard lock(rec.mutex);
      for (std::uint32_t i = 0; i < n; ++i) {
        if (states && queryResult->entityStates[i] != XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT) continue;
        const XrSpatialEntityIdEXT id = queryResult->entityIds[i];
        auto [it, added] = rec.planes.try_emplace(id);
        if (added) {
          rec.plane_order.push_back(id);
          while (rec.plane_order.size() > kMaxRecords) {
            rec.planes.erase(rec.plane_order.front());
            rec.plane_order.pop_front();
          }
          it = rec.planes.find(id);
          if (it == rec.planes.end()) continue;
        }
        PlaneRecord& plane = it->second;
        if (labels != nullptr && labels->semanticLabels != nullptr) plane.label = labels->semanticLabels[i];
        if (meshes != nullptr && meshes->meshes != nullptr && meshes->meshes[i].vertexBuffer.bufferId != XR_NULL_SPATIAL_BUFFER_ID_EXT) {
          plane.mesh = meshes->meshes[i];
          rec.owners[plane.mesh->vertexBuffer.bufferId] = id;
          rec.owners[plane.mesh->indexBuffer.bufferId] = id;
        }
        if (polygons != nullptr && polygons->polygons != nullptr &&
            polygons->polygons[i].vertexBuffer.bufferId != XR_NULL_SPATIAL_BUFFER_ID_EXT) {
          plane.polygon = polygons->polygons[i];
          rec.owners[plane.polygon->vertexBuffer.bufferId] = id;
        }
        if (bounds != nullptr && bounds->bounds != nullptr && plane.kept <= 1) {
          rectangles.push_back(plane_chunk(id, bounds_plane(bounds->bounds[i]), plane.label));
          plane.kept = 1;
        }
      }
    }
    keep_planes(*record, std::move(rectangles));
    return result;
  });
}

// A buffer the application read in full: remembered when a plane of the snapshot owns it, and the plane kept
// once its geometry is complete.
template <typename T>
void buffer_read(SnapshotRecord& record, XrSpatialBufferIdEXT id, const T* data, std::uint32_t count) {
  std::optional<SourceChunk> chunk;
  {
    std::lock_guard lock(record.mutex);
    const auto owner = record.owners.find(id);
    if (owner == record.owners.end()) return;
    if constexpr (std::is_same_v<T, XrVector2f>) {
      record.points[id].assign(data, data + count);
    } else {
      record.indices[id].assign(data, data + count);
    }
    chunk = complete_plane(record, owner->second);
  }
  if (chunk) {
    std::vector<SourceChunk> one;
    one.push_back(std::move(*chunk));
    keep_planes(record, std::move(one));
  }
}

template <typename T, auto Next>
XrResult read_buffer(const char* name, XrSpatialSnapshotEXT snapshot, const XrSpatialBufferGetInfoEXT* info,
                     std::uint32_t capacity, std::uint32_t* count, T* buffer) {
  return guarded(name, [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    ExtPlaneSource* source = source_for(record ? record->session.get() : nullptr);
    if (source == nullptr) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = (source->*Next)(snapshot, info, capacity, count, buffer);
    if (result == XR_SUCCESS && record && info != nullptr && count != nullptr && buffer != nullptr && capacity > 0 &&
        capacity >= *count && *count <= kMaxBufferElements)
      buffer_read(*record, info->bufferId, buffer, *count);
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetSpatialBufferVector2fEXT(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferGetInfoEXT* info,
                                                       uint32_t capacity, uint32_t* count, XrVector2f* buffer) {
  return read_buffer<XrVector2f, &ExtPlaneSource::xrGetSpatialBufferVector2fEXT>("xrGetSpatialBufferVector2fEXT", snapshot, info,
                                                                                capacity, count, buffer);
}

XrResult XRAPI_CALL hook_xrGetSpatialBufferUint16EXT(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferGetInfoEXT* info,
                                                     uint32_t capacity, uint32_t* count, uint16_t* buffer) {
  return read_buffer<uint16_t, &ExtPlaneSource::xrGetSpatialBufferUint16EXT>("xrGetSpatialBufferUint16EXT", snapshot, info,
                                                                            capacity, count, buffer);
}

XrResult XRAPI_CALL hook_xrGetSpatialBufferUint32EXT(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferGetInfoEXT* info,
                                                     uint32_t capacity, uint32_t* count, uint32_t* buffer) {
  return read_buffer<uint32_t, &ExtPlaneSource::xrGetSpatialBufferUint32EXT>("xrGetSpatialBufferUint32EXT", snapshot, info,
                                                                            capacity, count, buffer);
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<ExtPlaneSource>();
#define EXT_LOAD(name) load_next(next, instance, #name, source->name);
  EXT_FUTURE_FUNCTIONS(EXT_LOAD)
  EXT_SPATIAL_FUNCTIONS(EXT_LOAD)
#undef EXT_LOAD
  return source;
}

}  // namespace

const SourceInfo& ext_spatial_plane_tracking_source() {
#define EXT_NAME(name) #name,
#define EXT_HOOK(name) HookEntry{#name, reinterpret_cast<PFN_xrVoidFunction>(&hook_##name)},
  static const SourceInfo source{
      XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME,
      "planes of a discovery snapshot (2D meshes, polygons or bounds) with their labels",
      {{XR_EXT_FUTURE_EXTENSION_NAME, {EXT_FUTURE_FUNCTIONS(EXT_NAME)}},
       {XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME, {EXT_SPATIAL_FUNCTIONS(EXT_NAME)}, {XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT}},
       {XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, {}}},
      {EXT_HOOK(xrCreateSpatialContextCompleteEXT) EXT_HOOK(xrCreateSpatialDiscoverySnapshotCompleteEXT)
           EXT_HOOK(xrQuerySpatialComponentDataEXT) EXT_HOOK(xrDestroySpatialSnapshotEXT) EXT_HOOK(xrGetSpatialBufferVector2fEXT)
               EXT_HOOK(xrGetSpatialBufferUint16EXT) EXT_HOOK(xrGetSpatialBufferUint32EXT)},
      &create,
  };
#undef EXT_NAME
#undef EXT_HOOK
  return source;
}

}  // namespace roomsense::layer
