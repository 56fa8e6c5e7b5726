// Per-instance and per-session state, in maps keyed by handle behind one mutex. Nothing of a call chain
// lives in a global: every hook finds the functions it calls next through the handle it was given, so the
// layer works with several instances, and an instance destroyed and re-created starts afresh.
#pragma once
#include "config.h"
#include "functions.h"
#include "mesh.h"

#include <openxr/openxr.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>
#include <unordered_map>
#include <vector>

namespace roomsense::layer {

class Analyzer;

inline constexpr const char* kLayerName = "XR_APILAYER_ROOMSENSE_room_understanding";

struct InstanceState {
  XrInstance handle = XR_NULL_HANDLE;
  NextDispatch next;
  bool extx = false;      // the application enabled XR_EXTX_room_understanding
  bool app_msft = false;  // the application enabled XR_MSFT_scene_understanding
  bool msft = false;      // XR_MSFT_scene_understanding is enabled below us (by the application or by the layer)
  bool capture = false;   // sessions are tracked and the scene meshes the application reads are captured
  Config config;
};

// A scene mesh the application read, in its session's capture space.
struct CapturedMesh {
  MeshPiece mesh;
  XrUuidMSFT component{};
  std::uint64_t hash = 0;       // content_hash of the buffers as served
  std::uint64_t observer = 0;   // serial of the observer ...
  std::uint64_t scene = 0;      // ... and of the scene it came from (later scenes replace earlier ones)
};

struct SessionState {
  XrSession handle = XR_NULL_HANDLE;
  std::shared_ptr<InstanceState> instance;
  XrSystemId system = XR_NULL_SYSTEM_ID;

  std::mutex mutex;  // guards everything below
  XrSpace capture_space = XR_NULL_HANDLE;  // a LOCAL space of the layer's, created at the first capture
  bool capture_space_failed = false;
  std::vector<std::shared_ptr<const CapturedMesh>> captured;
  std::uint64_t capture_generation = 0;   // bumped by every capture
  std::uint64_t exported_generation = 0;  // what the last export-only analysis saw
  // Export-only analyses (ROOMSENSE_EXPORT_DIR for an application without the extension) run here.
  std::condition_variable_any export_wake;
  bool export_pending = false;
  std::jthread export_worker;
};

struct ReferenceSpaceInfo {
  XrSession session = XR_NULL_HANDLE;
  XrReferenceSpaceType type = XR_REFERENCE_SPACE_TYPE_LOCAL;
  XrPosef pose{{0, 0, 0, 1}, {0, 0, 0}};
};

// What the layer knows of one of the application's scenes, for passive capture.
struct SceneRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t observer = 0, serial = 0;
  struct Component {
    XrUuidMSFT id{};
    XrTime update_time = 0;
  };
  std::mutex mutex;  // the application may read buffers from several threads
  std::unordered_map<std::uint64_t, Component> mesh_components;  // mesh buffer id -> component
  struct Partial {
    std::vector<XrVector3f> vertices;
    std::vector<std::uint32_t> indices;
    bool have_vertices = false, have_indices = false, done = false;
  };
  std::unordered_map<std::uint64_t, Partial> buffers;  // mesh buffer id -> what was read so far
};

struct ObserverRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t serial = 0;
};

// The handle maps. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Registry {
  std::mutex mutex;
  std::unordered_map<XrInstance, std::shared_ptr<InstanceState>> instances;
  std::unordered_map<XrSession, std::shared_ptr<SessionState>> sessions;
  std::map<XrSpace, ReferenceSpaceInfo> spaces;  // reference spaces of sessions of instances with the extension
  std::deque<XrSpace> space_order;               // creation order, to bound `spaces` (see entry.cpp)
  std::unordered_map<XrSceneObserverMSFT, ObserverRecord> observers;
  std::unordered_map<XrSceneMSFT, std::shared_ptr<SceneRecord>> scenes;
  std::unordered_map<XrRoomAnalyzerEXTX, std::shared_ptr<Analyzer>> analyzers;
  std::uint64_t serial = 0;

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
