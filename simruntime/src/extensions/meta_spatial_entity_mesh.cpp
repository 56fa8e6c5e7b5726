// Quest's scene model (see the header). Every query completes at once: xrQuerySpacesFB queues
// XrEventDataSpaceQueryResultsAvailableFB (when something matched) and XrEventDataSpaceQueryCompleteFB before it
// returns, and xrSetSpaceComponentStatusFB its XrEventDataSpaceSetStatusCompleteFB; the request's results are
// retrievable from then on. Components start enabled, except the triangle mesh, which an application (or the
// layer) enables first, as on a device.
#include "meta_spatial_entity_mesh.h"
#include "../process_state.h"

#include "stable_uuid.h"

#include "../faults.h"
#include "../functions.h"
#include "../log.h"
#include "../runtime.h"
#include "../spaces.h"
#include "../validate.h"
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace roomsense::sim {
namespace {

constexpr XrSpaceComponentTypeFB kLocatable = XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB;
constexpr XrSpaceComponentTypeFB kStorable = XR_SPACE_COMPONENT_TYPE_STORABLE_FB;
constexpr XrSpaceComponentTypeFB kBounded2D = XR_SPACE_COMPONENT_TYPE_BOUNDED_2D_FB;
constexpr XrSpaceComponentTypeFB kBounded3D = XR_SPACE_COMPONENT_TYPE_BOUNDED_3D_FB;
constexpr XrSpaceComponentTypeFB kLabels = XR_SPACE_COMPONENT_TYPE_SEMANTIC_LABELS_FB;
constexpr XrSpaceComponentTypeFB kRoomLayout = XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB;
constexpr XrSpaceComponentTypeFB kContainer = XR_SPACE_COMPONENT_TYPE_SPACE_CONTAINER_FB;
constexpr XrSpaceComponentTypeFB kMesh = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
constexpr std::uint64_t kQuestSalt = 0x5155455354ull;  // "QUEST"
constexpr std::uint32_t kMaxUuidFilter = 1024;  // the most uuids one filter may name

// One anchor of the room, immutable once built.
struct Anchor {
  XrUuidEXT uuid{};
  Rigid pose;           // in world (LOCAL/STAGE) space, already rounded to what an XrPosef holds
  bool stored = true;   // found by queries (the room's anchors); an application's own new anchor is not
  std::string labels;   // comma-separated, for the semantic-labels component
  std::vector<XrSpaceComponentTypeFB> components;
  XrRect2Df box2d{};
  XrRect3DfFB box3d{};
  std::vector<XrVector2f> boundary;  // counter-clockwise in the anchor's XY plane
  std::vector<XrVector3f> vertices;  // triangle mesh, in the anchor's space
  std::vector<std::uint32_t> indices;
  XrUuidEXT floor{}, ceiling{};
  std::vector<XrUuidEXT> walls, children;
  bool has(XrSpaceComponentTypeFB c) const { return std::find(components.begin(), components.end(), c) != components.end(); }
};

struct QuestScene {
  std::vector<std::shared_ptr<const Anchor>> anchors;  // room, global mesh, then the labelled objects
};

// An anchor as one session sees it: its space handle and component states.
struct LiveAnchor {
  std::shared_ptr<const Anchor> model;
  std::uint64_t space = 0;  // 0, or a space the application may have destroyed: made again when found
  std::map<XrSpaceComponentTypeFB, bool> enabled;
};

struct SessionAnchors {
  std::uint64_t instance = 0;
  bool loaded = false;
  std::vector<LiveAnchor> anchors;    // the room's, then the application's own new anchors
  std::set<std::uint64_t> requests;   // every async request id of the session (their events go with it)
};

struct Query {
  std::uint64_t session = 0;
  std::vector<XrSpaceQueryResultFB> results;
};

// Everything here is guarded by runtime().mutex.
struct State {
  std::unordered_map<std::uint64_t, SessionAnchors> sessions;
  std::unordered_map<std::uint64_t, Query> queries;  // complete, results not yet retrieved
  std::unordered_map<std::uint64_t, std::pair<std::uint64_t, std::size_t>> spaces;  // space -> session, anchor
  std::map<const Room*, std::pair<std::shared_ptr<const Room>, std::shared_ptr<const QuestScene>>> scenes;
};

State& state() {
  return process_wide<State>();
}

// ---- the model


// Stable per room file and anchor, as a device's anchors keep their uuids; a version-4 layout.


Rigid as_stored(const Rigid& pose) { return to_rigid(to_pose(pose)); }  // what the space's XrPosef will hold

std::shared_ptr<const QuestScene> build_quest_scene(const Room& room) {
  auto scene = std::make_shared<QuestScene>();
  std::uint64_t index = 0;

  auto room_anchor = std::make_shared<Anchor>();
  room_anchor->uuid = stable_uuid(room.source, kQuestSalt, index++);
  room_anchor->components = {kLocatable, kStorable, kRoomLayout, kContainer};

  // The global mesh, in a space turned by 30 degrees about +Y around the room's floor centre.
  auto mesh = std::make_shared<Anchor>();
  mesh->uuid = stable_uuid(room.source, kQuestSalt, index++);
  mesh->labels = "GLOBAL_MESH";
  mesh->components = {kLocatable, kStorable, kLabels, kBounded3D, kMesh};
  glm::dvec3 lo(0.0), hi(0.0);
  if (!room.mesh.vertices.empty()) {
    lo = hi = glm::dvec3(room.mesh.vertices.front());
    for (const glm::vec3& v : room.mesh.vertices) lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
  }
  Rigid pose;
  pose.rotation = glm::angleAxis(glm::radians(30.0), glm::dvec3(0.0, 1.0, 0.0));
  pose.translation = {(lo.x + hi.x) * 0.5 + 0.25, lo.y, (lo.z + hi.z) * 0.5 - 0.4};
  mesh->pose = as_stored(pose);
  const Rigid to_local = mesh->pose.inverse();
  mesh->vertices.reserve(room.mesh.vertices.size());
  glm::dvec3 llo(std::numeric_limits<double>::max()), lhi(std::numeric_limits<double>::lowest());
  for (const glm::vec3& v : room.mesh.vertices) {
    const glm::dvec3 p = to_local.apply(glm::dvec3(v));
    mesh->vertices.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    llo = glm::min(llo, p), lhi = glm::max(lhi, p);
  }
  mesh->indices = room.mesh.indices;
  if (!mesh->vertices.empty())
    mesh->box3d = {{static_cast<float>(llo.x), static_cast<float>(llo.y), static_cast<float>(llo.z)},
                   {static_cast<float>(lhi.x - llo.x), static_cast<float>(lhi.y - llo.y), static_cast<float>(lhi.z - llo.z)}};
  room_anchor->children.push_back(mesh->uuid);

  std::vector<std::shared_ptr<Anchor>> objects;
  bool have_floor = false, have_ceiling = false;
  for (const RoomObject& o : room.objects) {
    auto a = std::make_shared<Anchor>();
    a->uuid = stable_uuid(room.source, kQuestSalt, index++);
    a->labels = o.label;
    a->components = {kLocatable, kStorable, kLabels, kBounded2D};
    a->pose = as_stored(to_rigid(o.plane_pose));  // +Z the normal into the room, as Meta's planes
    const float w = o.plane_size.width * 0.5f, h = o.plane_size.height * 0.5f;
    a->box2d = {{-w, -h}, {o.plane_size.width, o.plane_size.height}};
    a->boundary = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
    if (o.label == "FLOOR" && !have_floor) room_anchor->floor = a->uuid, have_floor = true;
    if (o.label == "CEILING" && !have_ceiling) room_anchor->ceiling = a->uuid, have_ceiling = true;
    if (o.label == "WALL_FACE" || o.label == "INVISIBLE_WALL_FACE") room_anchor->walls.push_back(a->uuid);
    room_anchor->children.push_back(a->uuid);
    objects.push_back(std::move(a));
  }
  scene->anchors.push_back(std::move(room_anchor));
  scene->anchors.push_back(std::move(mesh));
  for (auto& o : objects) scene->anchors.push_back(std::move(o));
  return scene;
}

// ---- per-session state (call everything below under the lock)

std::uint64_t make_space(std::uint64_t session, const Rigid& world_pose) {
  auto s = std::make_unique<SpaceState>();
  s->session = session;
  s->type = XR_REFERENCE_SPACE_TYPE_LOCAL;  // LOCAL is the world: the pose is the anchor's world pose
  s->pose_in_reference = to_pose(world_pose);
  const std::uint64_t id = runtime().new_id();
  runtime().spaces.emplace(id, std::move(s));
  return id;
}

LiveAnchor live(std::shared_ptr<const Anchor> model) {
  LiveAnchor a;
  for (XrSpaceComponentTypeFB c : model->components) a.enabled[c] = c != kMesh && c != kStorable;
  a.enabled[kStorable] = model->stored && model->has(kStorable);
  a.model = std::move(model);
  return a;
}

// The session's anchors, loading the room's on first use.
SessionAnchors& session_anchors(std::uint64_t session_id, const SessionState& session) {
  SessionAnchors& sa = state().sessions[session_id];
  sa.instance = session.instance;
  if (sa.loaded) return sa;
  sa.loaded = true;
  const InstanceState* instance = Runtime::find(runtime().instances, session.instance);
  if (instance == nullptr || !instance->room) return sa;  // no room: queries find nothing
  auto& cached = state().scenes[instance->room.get()];
  if (!cached.second) cached = {instance->room, build_quest_scene(*instance->room)};
  for (const auto& model : cached.second->anchors) sa.anchors.push_back(live(model));
  return sa;
}

// The anchor's space, made again when the application destroyed it.
std::uint64_t anchor_space(std::uint64_t session_id, SessionAnchors& sa, std::size_t index) {
  LiveAnchor& a = sa.anchors[index];
  if (a.space != 0 && runtime().spaces.count(a.space) != 0) return a.space;
  if (a.space != 0) state().spaces.erase(a.space);
  a.space = make_space(session_id, a.model->pose);
  state().spaces[a.space] = {session_id, index};
  return a.space;
}

template <typename Event>
void push_event(std::uint64_t instance, const Event& event) {
  static_assert(sizeof(Event) <= sizeof(XrEventDataBuffer));
  InstanceState* owner = Runtime::find(runtime().instances, instance);
  if (owner == nullptr) return;
  XrEventDataBuffer buffer{};
  std::memcpy(static_cast<void*>(&buffer), &event, sizeof event);
  owner->extension_events.push_back(buffer);
}

// The request id of one of our events, or 0.
std::uint64_t request_of(const XrEventDataBuffer& e) {
  XrEventDataSpaceQueryCompleteFB any{};  // every event here has type, next, requestId first
  switch (static_cast<int>(e.type)) {
    case XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB:
    case XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB:
    case XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB:
    case XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB:
      std::memcpy(&any, &e, offsetof(XrEventDataSpaceQueryCompleteFB, result));
      return static_cast<std::uint64_t>(any.requestId);
    default: return 0;
  }
}

// A space handle: its session and, for an anchor, the anchor.
struct Found {
  std::uint64_t session = 0;
  SessionAnchors* anchors = nullptr;
  LiveAnchor* anchor = nullptr;  // null for a space that is no anchor (a reference space)
};

XrResult find_space(XrSpace space, Found& out) {
  const SpaceState* s = runtime().space(space);
  if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
  out.session = s->session;
  const auto it = state().spaces.find(id_of(space));
  if (it == state().spaces.end()) return XR_SUCCESS;
  const auto sa = state().sessions.find(it->second.first);
  if (sa == state().sessions.end() || it->second.second >= sa->second.anchors.size()) return XR_SUCCESS;
  out.anchors = &sa->second;
  out.anchor = &sa->second.anchors[it->second.second];
  return XR_SUCCESS;
}

// The checks every component getter shares: the anchor has the component, and it is enabled.
XrResult component_ready(const Found& f, XrSpaceComponentTypeFB c) {
  if (f.anchor == nullptr || !f.anchor->model->has(c)) return XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB;
  return f.anchor->enabled[c] ? XR_SUCCESS : XR_ERROR_SPACE_COMPONENT_NOT_ENABLED_FB;
}

// The XR_FB_scene getters take the session and a space of it.
XrResult find_scene_space(XrSession session, XrSpace space, XrSpaceComponentTypeFB c, Found& f) {
  if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
  if (f.session != id_of(session)) return XR_ERROR_VALIDATION_FAILURE;
  return component_ready(f, c);
}

// ---- query filters

struct Filter {
  bool nothing = false;  // a storage location that holds none of the room (the cloud)
  bool by_component = false;
  XrSpaceComponentTypeFB component = kLocatable;
  std::vector<XrUuidEXT> uuids;  // empty: any
};

XrResult storage_filter(const XrSpaceStorageLocationFilterInfoFB& s, Filter& out) {
  if (s.location != XR_SPACE_STORAGE_LOCATION_LOCAL_FB && s.location != XR_SPACE_STORAGE_LOCATION_CLOUD_FB)
    return XR_ERROR_VALIDATION_FAILURE;
  out.nothing = out.nothing || s.location == XR_SPACE_STORAGE_LOCATION_CLOUD_FB;
  return XR_SUCCESS;
}

XrResult parse_filter(const XrSpaceFilterInfoBaseHeaderFB* f, Filter& out) {
  if (f == nullptr) return XR_SUCCESS;
  switch (static_cast<int>(f->type)) {
    case XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB:
      out.by_component = true;
      out.component = reinterpret_cast<const XrSpaceComponentFilterInfoFB*>(f)->componentType;
      break;
    case XR_TYPE_SPACE_UUID_FILTER_INFO_FB: {
      const auto* u = reinterpret_cast<const XrSpaceUuidFilterInfoFB*>(f);
      if (u->uuidCount == 0 || u->uuids == nullptr || u->uuidCount > kMaxUuidFilter) return XR_ERROR_VALIDATION_FAILURE;
      out.uuids.assign(u->uuids, u->uuids + u->uuidCount);
      break;
    }
    case XR_TYPE_SPACE_STORAGE_LOCATION_FILTER_INFO_FB:
      if (XrResult r = storage_filter(*reinterpret_cast<const XrSpaceStorageLocationFilterInfoFB*>(f), out); r != XR_SUCCESS)
        return r;
      break;
    default: return XR_ERROR_VALIDATION_FAILURE;
  }
  if (const auto* s = find_next<const XrSpaceStorageLocationFilterInfoFB>(f->next, XR_TYPE_SPACE_STORAGE_LOCATION_FILTER_INFO_FB))
    return storage_filter(*s, out);
  return XR_SUCCESS;
}

bool matches(const Filter& f, const Anchor& a) {
  if (f.nothing) return false;
  if (f.by_component && !a.has(f.component)) return false;
  if (!f.uuids.empty() &&
      std::none_of(f.uuids.begin(), f.uuids.end(), [&](const XrUuidEXT& u) { return same_uuid(u, a.uuid); }))
    return false;
  return true;
}

// Labels as an application that named the labels it recognises sees them: the others become OTHER.
std::string labels_for(const std::string& labels, const XrSemanticLabelsSupportInfoFB* support) {
  if (support == nullptr || support->recognizedLabels == nullptr) return labels;
  std::set<std::string> known;
  std::stringstream in(support->recognizedLabels);
  for (std::string item; std::getline(in, item, ',');) known.insert(item);
  std::string out;
  std::stringstream each(labels);
  for (std::string item; std::getline(each, item, ',');) {
    if (!out.empty()) out.push_back(',');
    out.append(known.count(item) != 0 ? item : std::string("OTHER"));
  }
  return out;
}

}  // namespace

// ---- XR_FB_spatial_entity

XrResult XRAPI_CALL xrCreateSpatialAnchorFB(XrSession session, const XrSpatialAnchorCreateInfoFB* info, XrAsyncRequestIdFB* requestId) {
  return guarded("xrCreateSpatialAnchorFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SPATIAL_ANCHOR_CREATE_INFO_FB) || requestId == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const SpaceState* base = runtime().space(info->space);
    if (base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (base->session != id_of(session)) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_valid_pose(info->poseInSpace)) return XR_ERROR_POSE_INVALID;
    if (info->time <= 0) return XR_ERROR_TIME_INVALID;
    Rigid base_world;
    if (!space_in_world(*base, base_world)) return XR_ERROR_HANDLE_INVALID;
    SessionAnchors& sa = session_anchors(id_of(session), *owner);
    auto model = std::make_shared<Anchor>();
    const std::uint64_t id = runtime().new_id();
    model->uuid = stable_uuid("spatial anchor", kQuestSalt, id);
    model->pose = as_stored(base_world * to_rigid(info->poseInSpace));
    model->stored = false;  // XR_FB_spatial_entity_storage is not served: never saved, never found by queries
    model->components = {kLocatable, kStorable};
    sa.anchors.push_back(live(std::move(model)));
    const std::uint64_t space = anchor_space(id_of(session), sa, sa.anchors.size() - 1);
    sa.requests.insert(id);
    XrEventDataSpatialAnchorCreateCompleteFB event{};
    event.type = XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB;
    event.requestId = static_cast<XrAsyncRequestIdFB>(id);
    event.result = XR_SUCCESS;
    event.space = handle_of<XrSpace>(space);
    event.uuid = sa.anchors.back().model->uuid;
    push_event(owner->instance, event);
    *requestId = static_cast<XrAsyncRequestIdFB>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSpaceUuidFB(XrSpace space, XrUuidEXT* uuid) {
  return guarded("xrGetSpaceUuidFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
    if (uuid == nullptr || f.anchor == nullptr) return XR_ERROR_VALIDATION_FAILURE;  // a reference space has no uuid
    *uuid = f.anchor->model->uuid;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEnumerateSpaceSupportedComponentsFB(XrSpace space, uint32_t capacity, uint32_t* countOutput,
                                                          XrSpaceComponentTypeFB* componentTypes) {
  return guarded("xrEnumerateSpaceSupportedComponentsFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
    static const std::vector<XrSpaceComponentTypeFB> none;
    return two_call(capacity, countOutput, componentTypes, f.anchor ? f.anchor->model->components : none);
  });
}

XrResult XRAPI_CALL xrGetSpaceComponentStatusFB(XrSpace space, XrSpaceComponentTypeFB componentType, XrSpaceComponentStatusFB* status) {
  return guarded("xrGetSpaceComponentStatusFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
    if (!has_type(status, XR_TYPE_SPACE_COMPONENT_STATUS_FB)) return XR_ERROR_VALIDATION_FAILURE;
    if (f.anchor == nullptr || !f.anchor->model->has(componentType)) return XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB;
    status->enabled = f.anchor->enabled[componentType] ? XR_TRUE : XR_FALSE;
    status->changePending = XR_FALSE;  // changes complete at once
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrSetSpaceComponentStatusFB(XrSpace space, const XrSpaceComponentStatusSetInfoFB* info, XrAsyncRequestIdFB* requestId) {
  return guarded("xrSetSpaceComponentStatusFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
    if (!has_type(info, XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB) || requestId == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (info->enabled != XR_TRUE && info->enabled != XR_FALSE) return XR_ERROR_VALIDATION_FAILURE;
    if (f.anchor == nullptr || !f.anchor->model->has(info->componentType)) return XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB;
    bool& enabled = f.anchor->enabled[info->componentType];
    if (enabled == (info->enabled == XR_TRUE)) return XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB;
    enabled = info->enabled == XR_TRUE;
    const std::uint64_t id = runtime().new_id();
    f.anchors->requests.insert(id);
    XrEventDataSpaceSetStatusCompleteFB event{};
    event.type = XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB;
    event.requestId = static_cast<XrAsyncRequestIdFB>(id);
    event.result = XR_SUCCESS;
    event.space = space;
    event.uuid = f.anchor->model->uuid;
    event.componentType = info->componentType;
    event.enabled = info->enabled;
    push_event(f.anchors->instance, event);
    *requestId = static_cast<XrAsyncRequestIdFB>(id);
    return XR_SUCCESS;
  });
}

// ---- XR_FB_spatial_entity_query

XrResult XRAPI_CALL xrQuerySpacesFB(XrSession session, const XrSpaceQueryInfoBaseHeaderFB* info, XrAsyncRequestIdFB* requestId) {
  return guarded("xrQuerySpacesFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SPACE_QUERY_INFO_FB) || requestId == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto* query = reinterpret_cast<const XrSpaceQueryInfoFB*>(info);
    if (query->queryAction != XR_SPACE_QUERY_ACTION_LOAD_FB) return XR_ERROR_VALIDATION_FAILURE;
    Filter include, exclude;
    if (XrResult r = parse_filter(query->filter, include); r != XR_SUCCESS) return r;
    if (XrResult r = parse_filter(query->excludeFilter, exclude); r != XR_SUCCESS) return r;

    const std::uint64_t session_id = id_of(session);
    SessionAnchors& sa = session_anchors(session_id, *owner);
    Query found{session_id, {}};
    for (std::size_t i = 0; i < sa.anchors.size(); ++i) {
      const Anchor& a = *sa.anchors[i].model;
      if (!a.stored || !matches(include, a) || (query->excludeFilter != nullptr && matches(exclude, a))) continue;
      if (query->maxResultCount > 0 && found.results.size() >= query->maxResultCount) break;
      found.results.push_back({handle_of<XrSpace>(anchor_space(session_id, sa, i)), a.uuid});
    }
    const std::uint64_t id = runtime().new_id();
    sa.requests.insert(id);
    *requestId = static_cast<XrAsyncRequestIdFB>(id);
    if (faults::pending(XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME)) return XR_SUCCESS;  // no events, no results: ever
    if (!found.results.empty()) {
      XrEventDataSpaceQueryResultsAvailableFB available{};
      available.type = XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB;
      available.requestId = static_cast<XrAsyncRequestIdFB>(id);
      push_event(owner->instance, available);
    }
    XrEventDataSpaceQueryCompleteFB complete{};
    complete.type = XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB;
    complete.requestId = static_cast<XrAsyncRequestIdFB>(id);
    complete.result = XR_SUCCESS;
    push_event(owner->instance, complete);
    state().queries[id] = std::move(found);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrRetrieveSpaceQueryResultsFB(XrSession session, XrAsyncRequestIdFB requestId, XrSpaceQueryResultsFB* results) {
  return guarded("xrRetrieveSpaceQueryResultsFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(results, XR_TYPE_SPACE_QUERY_RESULTS_FB)) return XR_ERROR_VALIDATION_FAILURE;
    // Unknown, of another session, or already retrieved: the spec's validation failure.
    const auto it = state().queries.find(static_cast<std::uint64_t>(requestId));
    if (it == state().queries.end() || it->second.session != id_of(session)) return XR_ERROR_VALIDATION_FAILURE;
    const XrResult r = two_call(results->resultCapacityInput, &results->resultCountOutput, results->results, it->second.results);
    // Each result is retrieved once: the results go with the call that copies them (or finds there are none).
    if (r == XR_SUCCESS && (results->resultCapacityInput > 0 || it->second.results.empty())) state().queries.erase(it);
    return r;
  });
}

// ---- XR_FB_scene

XrResult XRAPI_CALL xrGetSpaceBoundingBox2DFB(XrSession session, XrSpace space, XrRect2Df* boundingBox2DOutput) {
  return guarded("xrGetSpaceBoundingBox2DFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kBounded2D, f); r != XR_SUCCESS) return r;
    if (boundingBox2DOutput == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *boundingBox2DOutput = f.anchor->model->box2d;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSpaceBoundingBox3DFB(XrSession session, XrSpace space, XrRect3DfFB* boundingBox3DOutput) {
  return guarded("xrGetSpaceBoundingBox3DFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kBounded3D, f); r != XR_SUCCESS) return r;
    if (boundingBox3DOutput == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *boundingBox3DOutput = f.anchor->model->box3d;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSpaceSemanticLabelsFB(XrSession session, XrSpace space, XrSemanticLabelsFB* semanticLabelsOutput) {
  return guarded("xrGetSpaceSemanticLabelsFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kLabels, f); r != XR_SUCCESS) return r;
    if (!has_type(semanticLabelsOutput, XR_TYPE_SEMANTIC_LABELS_FB)) return XR_ERROR_VALIDATION_FAILURE;
    const auto* support = find_next<const XrSemanticLabelsSupportInfoFB>(semanticLabelsOutput->next, XR_TYPE_SEMANTIC_LABELS_SUPPORT_INFO_FB);
    const std::string labels = labels_for(f.anchor->model->labels, support);
    const std::vector<char> text(labels.c_str(), labels.c_str() + labels.size() + 1);  // with its terminator
    return two_call(semanticLabelsOutput->bufferCapacityInput, &semanticLabelsOutput->bufferCountOutput,
                    semanticLabelsOutput->buffer, text);
  });
}

XrResult XRAPI_CALL xrGetSpaceBoundary2DFB(XrSession session, XrSpace space, XrBoundary2DFB* boundary2DOutput) {
  return guarded("xrGetSpaceBoundary2DFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kBounded2D, f); r != XR_SUCCESS) return r;
    if (!has_type(boundary2DOutput, XR_TYPE_BOUNDARY_2D_FB)) return XR_ERROR_VALIDATION_FAILURE;
    return two_call(boundary2DOutput->vertexCapacityInput, &boundary2DOutput->vertexCountOutput, boundary2DOutput->vertices,
                    f.anchor->model->boundary);
  });
}

XrResult XRAPI_CALL xrGetSpaceRoomLayoutFB(XrSession session, XrSpace space, XrRoomLayoutFB* roomLayoutOutput) {
  return guarded("xrGetSpaceRoomLayoutFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kRoomLayout, f); r != XR_SUCCESS) return r;
    if (!has_type(roomLayoutOutput, XR_TYPE_ROOM_LAYOUT_FB)) return XR_ERROR_VALIDATION_FAILURE;
    const XrResult r = two_call(roomLayoutOutput->wallUuidCapacityInput, &roomLayoutOutput->wallUuidCountOutput,
                                roomLayoutOutput->wallUuids, f.anchor->model->walls);
    if (r == XR_SUCCESS) {
      roomLayoutOutput->floorUuid = f.anchor->model->floor;
      roomLayoutOutput->ceilingUuid = f.anchor->model->ceiling;
    }
    return r;
  });
}

// ---- XR_FB_spatial_entity_container

XrResult XRAPI_CALL xrGetSpaceContainerFB(XrSession session, XrSpace space, XrSpaceContainerFB* spaceContainerOutput) {
  return guarded("xrGetSpaceContainerFB", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_scene_space(session, space, kContainer, f); r != XR_SUCCESS) return r;
    if (!has_type(spaceContainerOutput, XR_TYPE_SPACE_CONTAINER_FB)) return XR_ERROR_VALIDATION_FAILURE;
    return two_call(spaceContainerOutput->uuidCapacityInput, &spaceContainerOutput->uuidCountOutput, spaceContainerOutput->uuids,
                    f.anchor->model->children);
  });
}

// ---- XR_META_spatial_entity_mesh

XrResult XRAPI_CALL xrGetSpaceTriangleMeshMETA(XrSpace space, const XrSpaceTriangleMeshGetInfoMETA* getInfo,
                                              XrSpaceTriangleMeshMETA* triangleMeshOutput) {
  return guarded("xrGetSpaceTriangleMeshMETA", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Found f;
    if (XrResult r = find_space(space, f); r != XR_SUCCESS) return r;
    if (!has_type(getInfo, XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META) || !has_type(triangleMeshOutput, XR_TYPE_SPACE_TRIANGLE_MESH_META))
      return XR_ERROR_VALIDATION_FAILURE;
    if (XrResult r = component_ready(f, kMesh); r != XR_SUCCESS) return r;
    XrSpaceTriangleMeshMETA& out = *triangleMeshOutput;
    if ((out.vertexCapacityInput > 0 && out.vertices == nullptr) || (out.indexCapacityInput > 0 && out.indices == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    Anchor scratch;
    const Anchor& a = faults::faulty_mesh(XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME, *f.anchor->model, scratch);
    out.vertexCountOutput = faults::vertex_count(XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME, a.vertices.size(), out.vertexCapacityInput);
    out.indexCountOutput = static_cast<uint32_t>(a.indices.size());
    // Nothing is written unless every non-zero capacity is large enough.
    if ((out.vertexCapacityInput > 0 && out.vertexCapacityInput < out.vertexCountOutput) ||
        (out.indexCapacityInput > 0 && out.indexCapacityInput < a.indices.size()))
      return XR_ERROR_SIZE_INSUFFICIENT;
    if (out.vertexCapacityInput > 0) std::copy(a.vertices.begin(), a.vertices.end(), out.vertices);
    if (out.indexCapacityInput > 0) std::copy(a.indices.begin(), a.indices.end(), out.indices);
    return XR_SUCCESS;
  });
}

namespace {

// A session's anchors, results and pending events go with it (its spaces are already gone).
void forget_session(std::uint64_t session) {
  std::lock_guard lock(runtime().mutex);
  State& s = state();
  const auto it = s.sessions.find(session);
  if (it == s.sessions.end()) return;
  const std::set<std::uint64_t>& requests = it->second.requests;
  if (InstanceState* owner = Runtime::find(runtime().instances, it->second.instance))
    std::erase_if(owner->extension_events, [&](const XrEventDataBuffer& e) { return requests.count(request_of(e)) != 0; });
  std::erase_if(s.queries, [&](const auto& q) { return q.second.session == session; });
  std::erase_if(s.spaces, [&](const auto& sp) { return sp.second.first == session; });
  s.sessions.erase(it);
}

// With no session left, the built scenes are let go (the room cache keeps the rooms themselves).
void forget_instance(std::uint64_t) {
  std::lock_guard lock(runtime().mutex);
  if (state().sessions.empty()) state().scenes.clear();
}

}  // namespace

#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&sim::name)},

// The anchors' state is shared by the five extensions; XR_FB_spatial_entity, which all the others need, forgets it.
const ServedExtension& fb_spatial_entity_extension() {
  static const ServedExtension e{XR_FB_SPATIAL_ENTITY_EXTENSION_NAME,
                                 XR_FB_spatial_entity_SPEC_VERSION,
                                 true,
                                 {SIM_SERVE(xrCreateSpatialAnchorFB) SIM_SERVE(xrGetSpaceUuidFB)
                                      SIM_SERVE(xrEnumerateSpaceSupportedComponentsFB) SIM_SERVE(xrSetSpaceComponentStatusFB)
                                          SIM_SERVE(xrGetSpaceComponentStatusFB)},
                                 &forget_session,
                                 &forget_instance};
  return e;
}

const ServedExtension& fb_spatial_entity_query_extension() {
  static const ServedExtension e{XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME,
                                 XR_FB_spatial_entity_query_SPEC_VERSION,
                                 true,
                                 {SIM_SERVE(xrQuerySpacesFB) SIM_SERVE(xrRetrieveSpaceQueryResultsFB)}};
  return e;
}

const ServedExtension& fb_scene_extension() {
  static const ServedExtension e{XR_FB_SCENE_EXTENSION_NAME,
                                 XR_FB_scene_SPEC_VERSION,
                                 true,
                                 {SIM_SERVE(xrGetSpaceBoundingBox2DFB) SIM_SERVE(xrGetSpaceBoundingBox3DFB)
                                      SIM_SERVE(xrGetSpaceSemanticLabelsFB) SIM_SERVE(xrGetSpaceBoundary2DFB)
                                          SIM_SERVE(xrGetSpaceRoomLayoutFB)}};
  return e;
}

const ServedExtension& fb_spatial_entity_container_extension() {
  static const ServedExtension e{XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME,
                                 XR_FB_spatial_entity_container_SPEC_VERSION,
                                 true,
                                 {SIM_SERVE(xrGetSpaceContainerFB)}};
  return e;
}

const ServedExtension& meta_spatial_entity_mesh_extension() {
  static const ServedExtension e{XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME,
                                 XR_META_spatial_entity_mesh_SPEC_VERSION,
                                 true,
                                 {SIM_SERVE(xrGetSpaceTriangleMeshMETA)},
                                 nullptr,
                                 nullptr,
                                 {XR_FB_SPATIAL_ENTITY_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME,
                                  XR_FB_SCENE_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME}};
  return e;
}

#undef SIM_SERVE

}  // namespace roomsense::sim
