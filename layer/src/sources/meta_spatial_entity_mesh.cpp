// The active query, step by step:
// 1. xrQuerySpacesFB for the spaces with XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META (a Quest has one, labelled
//    GLOBAL_MESH).
// 2. Completion without xrPollEvent, which is the application's: the spec has xrRetrieveSpaceQueryResultsFB
//    answer XR_ERROR_VALIDATION_FAILURE while a request is not complete, so the layer calls it until it
//    succeeds (10 s at most, or until stopped). The runtime still posts the query's events to the
//    application's queue; an application matches them against its own request ids, so it skips them.
// 3. Per space: the locatable and triangle-mesh components enabled where they are not (and, likewise, the
//    status polled rather than the completion event awaited), the space located in the base space with
//    xrLocateSpace, the mesh read with the two-call idiom and moved into the base space.
// The spaces are left as they are (not destroyed, components left enabled): a runtime may hand the layer the
// very handles the application holds for the same anchors.
// Passive capture: the spaces (and their uuids) the application's queries return are remembered per session
// (xrRetrieveSpaceQueryResultsFB); a triangle mesh it reads in full of one of them is located in the session's
// capture space and kept, with the active query's chunk id.
#include "meta_spatial_entity_mesh.h"

#include "source_support.h"

#include "../capture.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <mutex>
#include <thread>
#include <unordered_map>

namespace roomsense::layer {
namespace {

using xr::check;

#define META_FUNCTIONS(_)                                                                                      \
  _(xrQuerySpacesFB) _(xrRetrieveSpaceQueryResultsFB) _(xrEnumerateSpaceSupportedComponentsFB)                 \
  _(xrGetSpaceComponentStatusFB) _(xrSetSpaceComponentStatusFB) _(xrGetSpaceTriangleMeshMETA) _(xrLocateSpace)

constexpr std::uint32_t kMaxResults = 4096;

std::string chunk_id(const XrUuidEXT& id) { return uuid_chunk_id("meta", id.data); }

class MetaSource final : public MeshSource {
 public:
#define META_MEMBER(name) PFN_##name name = nullptr;
  META_FUNCTIONS(META_MEMBER)
#undef META_MEMBER

  std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) override;
  void forget_session(XrSession session) override;

 private:
  std::vector<XrSpaceQueryResultFB> find_mesh_spaces(XrSession session, std::stop_token stop) const;
  bool enable(XrSpace space, XrSpaceComponentTypeFB component, std::stop_token stop) const;
  // The runtime's arrays of the mesh read last, kept from one query to the next (under read_mutex_: a session's
  // analyzers query from their own threads). The global mesh has no version, so every query reads it whole;
  // fresh buffers of its size (2.6 MB for thesis-room1) took a page fault per 4 KiB whenever the allocator had
  // given such blocks back to the system, some 10 ms of an unchanged room's compute on this project's VM
  // (bench/README.md, stop 94).
  struct ReadBuffers {
    std::vector<XrVector3f> vertices;
    std::vector<std::uint32_t> indices;
    std::size_t vertex_count = 0, index_count = 0;  // of the last read; the vectors only grow
  };
  // Reads the space's triangle mesh into `into`.
  void read_mesh(XrSpace space, ReadBuffers& into) const;
  std::mutex read_mutex_;
  ReadBuffers read_;
};

// Calls `step` until it returns true (PollPause between calls), for at most runtime_timeout(); false when stopped.
template <typename Step>
bool poll(const char* what, std::stop_token stop, Step&& step) {
  const auto deadline = std::chrono::steady_clock::now() + runtime_timeout();
  PollPause pause;
  while (!step()) {
    if (stop.stop_requested()) return false;
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error(std::string(what) + " did not complete within " + std::to_string(runtime_timeout().count()) + " ms");
    pause.wait();
  }
  return true;
}

std::vector<XrSpaceQueryResultFB> MetaSource::find_mesh_spaces(XrSession session, std::stop_token stop) const {
  auto filter = xr_struct<XrSpaceComponentFilterInfoFB>(XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB);
  filter.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  auto info = xr_struct<XrSpaceQueryInfoFB>(XR_TYPE_SPACE_QUERY_INFO_FB);
  info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
  info.maxResultCount = kMaxResults;
  info.timeout = 0;  // the runtime's own
  info.filter = reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&filter);
  XrAsyncRequestIdFB request = 0;
  check(xrQuerySpacesFB(session, reinterpret_cast<const XrSpaceQueryInfoBaseHeaderFB*>(&info), &request), "xrQuerySpacesFB");

  // The count call succeeds once the request is complete (validation failure before).
  auto results = xr_struct<XrSpaceQueryResultsFB>(XR_TYPE_SPACE_QUERY_RESULTS_FB);
  const bool done = poll("the runtime's space query", stop, [&] {
    const XrResult r = xrRetrieveSpaceQueryResultsFB(session, request, &results);
    if (r == XR_ERROR_VALIDATION_FAILURE) return false;
    check(r, "xrRetrieveSpaceQueryResultsFB");
    return true;
  });
  if (!done || results.resultCountOutput == 0) return {};
  if (results.resultCountOutput > kMaxResults) throw std::runtime_error("xrRetrieveSpaceQueryResultsFB reported an absurd result count");
  std::vector<XrSpaceQueryResultFB> found(results.resultCountOutput);
  results.resultCapacityInput = static_cast<std::uint32_t>(found.size());
  results.results = found.data();
  check(xrRetrieveSpaceQueryResultsFB(session, request, &results), "xrRetrieveSpaceQueryResultsFB");
  found.resize(std::min<std::size_t>(found.size(), results.resultCountOutput));
  return found;
}

// Makes sure a component of the space is enabled; false when it is not supported, or when stopped.
bool MetaSource::enable(XrSpace space, XrSpaceComponentTypeFB component, std::stop_token stop) const {
  const auto supported = xr::read_two_call<XrSpaceComponentTypeFB>(
      "xrEnumerateSpaceSupportedComponentsFB",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSpaceComponentTypeFB* out) {
        return xrEnumerateSpaceSupportedComponentsFB(space, capacity, count, out);
      },
      256);
  if (std::find(supported.begin(), supported.end(), component) == supported.end()) return false;
  auto status = xr_struct<XrSpaceComponentStatusFB>(XR_TYPE_SPACE_COMPONENT_STATUS_FB);
  check(xrGetSpaceComponentStatusFB(space, component, &status), "xrGetSpaceComponentStatusFB");
  if (status.enabled && !status.changePending) return true;
  if (!status.changePending) {
    auto set = xr_struct<XrSpaceComponentStatusSetInfoFB>(XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB);
    set.componentType = component;
    set.enabled = XR_TRUE;
    XrAsyncRequestIdFB request = 0;
    const XrResult r = xrSetSpaceComponentStatusFB(space, &set, &request);
    // Already set or pending: the application got there first.
    if (r != XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB && r != XR_ERROR_SPACE_COMPONENT_STATUS_PENDING_FB)
      check(r, "xrSetSpaceComponentStatusFB");
  }
  return poll("enabling a space component", stop, [&] {
    check(xrGetSpaceComponentStatusFB(space, component, &status), "xrGetSpaceComponentStatusFB");
    if (status.changePending) return false;
    if (!status.enabled) throw std::runtime_error("the runtime did not enable component " + std::to_string(component));
    return true;
  });
}

void MetaSource::read_mesh(XrSpace space, ReadBuffers& into) const {
  const auto get = xr_struct<XrSpaceTriangleMeshGetInfoMETA>(XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META);
  auto mesh = xr_struct<XrSpaceTriangleMeshMETA>(XR_TYPE_SPACE_TRIANGLE_MESH_META);
  into.vertex_count = into.index_count = 0;
  check(xrGetSpaceTriangleMeshMETA(space, &get, &mesh), "xrGetSpaceTriangleMeshMETA");
  if (mesh.vertexCountOutput > kMaxRuntimeBufferElements || mesh.indexCountOutput > kMaxRuntimeBufferElements)
    throw std::runtime_error("xrGetSpaceTriangleMeshMETA reported " + std::to_string(mesh.vertexCountOutput) + " vertices and " +
                             std::to_string(mesh.indexCountOutput) + " indices, over the limit");
  if (into.vertices.size() < mesh.vertexCountOutput) into.vertices.resize(mesh.vertexCountOutput);
  if (into.indices.size() < mesh.indexCountOutput) into.indices.resize(mesh.indexCountOutput);
  mesh.vertexCapacityInput = mesh.vertexCountOutput;
  mesh.vertices = into.vertices.data();
  mesh.indexCapacityInput = mesh.indexCountOutput;
  mesh.indices = into.indices.data();
  if (mesh.vertexCapacityInput > 0 || mesh.indexCapacityInput > 0)
    check(xrGetSpaceTriangleMeshMETA(space, &get, &mesh), "xrGetSpaceTriangleMeshMETA");
  into.vertex_count = std::min<std::size_t>(mesh.vertexCapacityInput, mesh.vertexCountOutput);
  into.index_count = std::min<std::size_t>(mesh.indexCapacityInput, mesh.indexCountOutput);
}

std::vector<SourceChunk> MetaSource::run_query(const QueryContext& context, std::stop_token stop) {
  const std::vector<XrSpaceQueryResultFB> spaces = find_mesh_spaces(context.session, stop);
  std::vector<SourceChunk> out;
  std::size_t unlocated = 0;
  for (const XrSpaceQueryResultFB& found : spaces) {
    if (stop.stop_requested()) return {};
    if (!enable(found.space, XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META, stop)) continue;
    if (!enable(found.space, XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB, stop)) continue;
    if (stop.stop_requested()) return {};
    auto location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
    check(xrLocateSpace(found.space, context.base, context.time, &location), "xrLocateSpace");
    if (!located(location.locationFlags)) {
      ++unlocated;
      continue;
    }
    SourceChunk chunk;
    chunk.id = chunk_id(found.uuid);
    {
      std::lock_guard lock(read_mutex_);
      read_mesh(found.space, read_);
      // The mesh as served, in its own space: it has no version to read first.
      chunk.change = content_hash(read_.vertices.data(), read_.vertex_count, read_.indices.data(), read_.index_count);
      if (std::optional<SourceChunk> kept = served_before(context, chunk.id, chunk.change, location.pose)) {
        out.push_back(std::move(*kept));  // not moved, checked or keyed again
        continue;
      }
      // Broken triangles are dropped by checked_chunks.
      chunk.mesh.vertices.reserve(read_.vertex_count);
      for (std::size_t i = 0; i < read_.vertex_count; ++i)
        chunk.mesh.vertices.emplace_back(read_.vertices[i].x, read_.vertices[i].y, read_.vertices[i].z);
      chunk.mesh.indices.assign(read_.indices.begin(), read_.indices.begin() + std::ptrdiff_t(read_.index_count));
    }
    chunk.placed = location.pose;
    transform_in_place(chunk.mesh.vertices, to_rigid(chunk.placed));
    out.push_back(std::move(chunk));  // the global mesh has no semantic labels per triangle
  }
  if (unlocated > 0) log_warn(std::to_string(unlocated) + " runtime mesh(es) could not be located and were left out");
  return out;
}

// ---- passive capture: the spaces the application's queries returned, and the triangle meshes it reads of them

constexpr std::size_t kMaxRecordedSpaces = 4096;  // per process; the oldest is forgotten first

struct SpaceRecord {
  std::shared_ptr<SessionState> session;
  XrUuidEXT uuid{};
};

// The application's spaces. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Records {
  std::mutex mutex;
  std::unordered_map<XrSpace, SpaceRecord> spaces;
  std::deque<XrSpace> order;  // first recorded first, to bound `spaces`
};

Records& records() {
  static Records r;
  return r;
}

void MetaSource::forget_session(XrSession session) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  std::erase_if(r.spaces, [&](const auto& entry) { return entry.second.session->handle == session; });
  std::erase_if(r.order, [&](XrSpace space) { return !r.spaces.contains(space); });
}

const SourceInfo& info();

MetaSource* source_of(const InstanceState& instance) { return instance.source<MetaSource>(info()); }

// The source of the instance a space belongs to, with the space's record when the application's queries
// returned it. A space found otherwise (not through xrQuerySpacesFB) is still served, by the first instance
// whose application enabled the extension (the next function is the same for every instance of the process).
MetaSource* source_for(XrSpace space, SpaceRecord& record) {
  Registry& reg = registry();
  {
    Records& r = records();
    std::lock_guard lock(r.mutex);
    if (const auto it = r.spaces.find(space); it != r.spaces.end()) record = it->second;
  }
  if (record.session) return source_of(*record.session->instance);
  std::lock_guard lock(reg.mutex);
  for (const auto& [handle, instance] : reg.instances)
    for (const EnabledSource& s : instance->sources)
      if (s.info == &info() && s.app_enabled) return static_cast<MetaSource*>(s.source.get());
  return nullptr;
}

// A time the runtime can locate a scene anchor at. Scene anchors do not move, so any recent time serves; on
// Android (Quest) the runtime's XrTime is CLOCK_MONOTONIC in nanoseconds, which steady_clock reads there.
XrTime locate_time() {
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  return ns > 0 ? static_cast<XrTime>(ns) : 1;
}

XrResult XRAPI_CALL hook_xrRetrieveSpaceQueryResultsFB(XrSession session, XrAsyncRequestIdFB requestId, XrSpaceQueryResultsFB* results) {
  return guarded("xrRetrieveSpaceQueryResultsFB", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    MetaSource* source = source_of(*s->instance);
    if (source == nullptr) throw std::logic_error("XR_META_spatial_entity_mesh hook without its source");
    const XrResult result = source->xrRetrieveSpaceQueryResultsFB(session, requestId, results);
    if (result != XR_SUCCESS || results == nullptr || results->results == nullptr || results->resultCapacityInput == 0)
      return result;
    const std::uint32_t n = std::min(results->resultCountOutput, results->resultCapacityInput);
    Records& r = records();
    std::lock_guard lock(r.mutex);
    for (std::uint32_t i = 0; i < n; ++i) {
      const XrSpaceQueryResultFB& found = results->results[i];
      if (found.space == XR_NULL_HANDLE) continue;
      const auto [it, added] = r.spaces.insert_or_assign(found.space, SpaceRecord{s, found.uuid});
      (void)it;
      if (!added) continue;
      r.order.push_back(found.space);
      if (r.order.size() > kMaxRecordedSpaces) {
        r.spaces.erase(r.order.front());
        r.order.pop_front();
      }
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetSpaceTriangleMeshMETA(XrSpace space, const XrSpaceTriangleMeshGetInfoMETA* getInfo,
                                                    XrSpaceTriangleMeshMETA* triangleMeshOutput) {
  return guarded("xrGetSpaceTriangleMeshMETA", [&]() -> XrResult {
    SpaceRecord record;
    MetaSource* source = source_for(space, record);
    if (source == nullptr) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source->xrGetSpaceTriangleMeshMETA(space, getInfo, triangleMeshOutput);
    if (result != XR_SUCCESS || !record.session || triangleMeshOutput == nullptr) return result;
    const XrSpaceTriangleMeshMETA& mesh = *triangleMeshOutput;
    // Only a read in full: both arrays given and large enough (the count call and a short read are not).
    if (mesh.vertices == nullptr || mesh.indices == nullptr || mesh.vertexCapacityInput == 0 || mesh.indexCapacityInput == 0 ||
        mesh.vertexCapacityInput < mesh.vertexCountOutput || mesh.indexCapacityInput < mesh.indexCountOutput ||
        mesh.vertexCountOutput > kMaxRuntimeBufferElements || mesh.indexCountOutput > kMaxRuntimeBufferElements)
      return result;
    const std::size_t vertex_count = mesh.vertexCountOutput, index_count = mesh.indexCountOutput / 3 * 3;
    SessionState& session = *record.session;
    const std::optional<Rigid> in_capture = locate_in_capture_space(session, space, locate_time());
    if (!in_capture) {
      log_debug([] { return std::string("a scene mesh the application read cannot be located; not captured"); });
      return result;
    }
    SourceChunk chunk;
    chunk.id = chunk_id(record.uuid);
    chunk.change = content_hash(mesh.vertices, vertex_count, mesh.indices, index_count);  // as served, in its own space
    chunk.mesh.vertices = transformed(mesh.vertices, vertex_count, *in_capture);
    chunk.mesh.indices.assign(mesh.indices, mesh.indices + index_count);
    keep_capture(session, info(), std::move(chunk));
    capture_read_done(record.session);  // a mesh read in full is a complete read
    return result;
  });
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<MetaSource>();
#define META_LOAD(name) load_next(next, instance, #name, source->name);
  META_FUNCTIONS(META_LOAD)
#undef META_LOAD
  return source;
}

const SourceInfo& info() {
  static const SourceInfo source{
      XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME,
      "the room's global mesh, one scene space",
      {{XR_FB_SPATIAL_ENTITY_EXTENSION_NAME,
        {"xrCreateSpatialAnchorFB", "xrGetSpaceUuidFB", "xrEnumerateSpaceSupportedComponentsFB", "xrSetSpaceComponentStatusFB",
         "xrGetSpaceComponentStatusFB"},
        {XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB, XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB}},
       {XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME,
        {"xrQuerySpacesFB", "xrRetrieveSpaceQueryResultsFB"},
        {XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB, XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB}},
       {XR_FB_SCENE_EXTENSION_NAME,
        {"xrGetSpaceBoundingBox2DFB", "xrGetSpaceBoundingBox3DFB", "xrGetSpaceSemanticLabelsFB", "xrGetSpaceBoundary2DFB",
         "xrGetSpaceRoomLayoutFB"}},
       {XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME, {"xrGetSpaceTriangleMeshMETA"}}},
      {{"xrRetrieveSpaceQueryResultsFB", reinterpret_cast<PFN_xrVoidFunction>(&hook_xrRetrieveSpaceQueryResultsFB)},
       {"xrGetSpaceTriangleMeshMETA", reinterpret_cast<PFN_xrVoidFunction>(&hook_xrGetSpaceTriangleMeshMETA)}},
      &create,
  };
  return source;
}

}  // namespace

const SourceInfo& meta_spatial_entity_mesh_source() { return info(); }

}  // namespace roomsense::layer
