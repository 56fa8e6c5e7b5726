// Per-instance and per-session state, in maps keyed by handle behind one mutex. Nothing of a call chain
// lives in a global: every hook finds the functions it calls next through the handle it was given, so the
// layer works with several instances, and an instance destroyed and re-created starts afresh.
#pragma once
#include "config.h"
#include "functions.h"
#include "mesh.h"
#include "sources/mesh_source.h"

#include <openxr/openxr.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace roomsense::layer {

class Analyzer;
class SpatialService;
struct SpatialInstance;

inline constexpr const char* kLayerName = "XR_APILAYER_ROOMSENSE_room_understanding";

// A mesh source enabled below the layer for one instance (sources/mesh_source.h).
struct EnabledSource {
  const SourceInfo* info = nullptr;
  std::unique_ptr<MeshSource> source;
  bool app_enabled = false;  // the application enabled its extensions too: its calls are watched
};

struct InstanceState {
  XrInstance handle = XR_NULL_HANDLE;
  NextDispatch next;
  bool extx = false;      // the application enabled XR_EXTX_room_understanding
  bool capture = false;   // sessions are tracked and the scene meshes the application reads are captured
  std::vector<EnabledSource> sources;  // best first (mesh_sources() order)
  std::vector<std::string> layer_enabled_extensions;  // enabled below us by the layer, not the application
  std::vector<XrStructureType> hidden_events;          // their events, kept from the application
  Config config;
  // The standard spatial-entity API the layer serves (spatial/); null when the application enabled none of it.
  std::shared_ptr<const SpatialInstance> spatial;

  // The instance's source of this kind, or null when it is not enabled.
  template <typename T>
  T* source(const SourceInfo& info) const {
    for (const EnabledSource& s : sources)
      if (s.info == &info) return static_cast<T*>(s.source.get());
    return nullptr;
  }
};

// A scene mesh the application read, in its session's capture space.
struct CapturedMesh {
  const SourceInfo* source = nullptr;
  SourceChunk chunk;
  std::uint64_t hash = 0;   // content_hash of the chunk as captured
  std::uint64_t group = 0;  // e.g. the scene observer it came from (0: none) ...
  std::uint64_t epoch = 0;  // ... and its scene: a later epoch of a group replaces the earlier one's meshes
};

struct SessionState {
  SessionState() = default;
  SessionState(const SessionState&) = delete;
  SessionState& operator=(const SessionState&) = delete;
  ~SessionState();  // ends an export worker that shut_down_session did not

  // Sets export_ending and wakes the export worker; returns it to join (its destructor requests stop and joins).
  std::jthread end_export();

  XrSession handle = XR_NULL_HANDLE;
  std::shared_ptr<InstanceState> instance;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  // A call of the layer's in it came back XR_ERROR_SESSION_LOST: queries and computes stop calling the runtime.
  std::atomic<bool> lost{false};
  // The latest predictedDisplayTime of xrWaitFrame: the clock of the layer's own analyses (spatial/) where the
  // runtime has no XR_KHR_convert_timespec_time.
  std::atomic<XrTime> frame_time{0};

  std::mutex mutex;  // guards everything below
  XrSpace capture_space = XR_NULL_HANDLE;  // a LOCAL space of the layer's, created at the first capture
  bool capture_space_failed = false;
  std::vector<std::shared_ptr<const CapturedMesh>> captured;
  std::uint64_t capture_generation = 0;   // bumped by every capture
  std::uint64_t exported_generation = 0;  // what the last export-only analysis saw
  // Export-only analyses (ROOMSENSE_EXPORT_DIR for an application without the extension) run here.
  // The worker waits for export_pending or export_ending, not on its stop token (why: Analyzer's mutex_).
  std::condition_variable export_wake;
  bool export_pending = false;
  bool export_ending = false;  // set when the session shuts down: the worker ends
  std::jthread export_worker;
  std::shared_ptr<SpatialService> spatial;  // created with the layer's first spatial context
};

struct ReferenceSpaceInfo {
  XrSession session = XR_NULL_HANDLE;
  XrReferenceSpaceType type = XR_REFERENCE_SPACE_TYPE_LOCAL;
  XrPosef pose{{0, 0, 0, 1}, {0, 0, 0}};
};

// The handle maps. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Registry {
  std::mutex mutex;
  std::unordered_map<XrInstance, std::shared_ptr<InstanceState>> instances;
  std::unordered_map<XrSession, std::shared_ptr<SessionState>> sessions;
  std::map<XrSpace, ReferenceSpaceInfo> spaces;  // reference spaces of sessions of instances with the extension
  std::deque<XrSpace> space_order;               // creation order, to bound `spaces` (see entry.cpp)
  std::unordered_map<XrRoomAnalyzerEXTX, std::shared_ptr<Analyzer>> analyzers;
  std::uint64_t serial = 0;  // analyzer handles

  Registry() = default;
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;
  ~Registry();  // ends the threads of the sessions an application left open (state.cpp)

  std::shared_ptr<InstanceState> instance(XrInstance handle);
  std::shared_ptr<SessionState> session(XrSession handle);
};

Registry& registry();

// Stops and joins everything of a session that runs in the background and releases the layer's own
// handles in it. Call without the registry lock, before the session is destroyed down the chain.
void shut_down_session(SessionState& session, const std::vector<std::shared_ptr<Analyzer>>& analyzers);

// Removes a session and everything of it from the maps (under the registry lock); returns its analyzers.
std::vector<std::shared_ptr<Analyzer>> forget_session_locked(Registry& r, XrSession session);

}  // namespace roomsense::layer
