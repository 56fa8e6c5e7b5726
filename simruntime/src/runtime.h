// The runtime's state: every handle is an opaque id mapped to its object, all behind one mutex. One lock is
// plenty for a simulator and makes every entry point trivially thread-safe; the only long work (a scene
// compute) runs on its own thread with its own lock (ComputeJob).
#pragma once
#include "actions.h"
#include "config.h"
#include "room_source.h"
#include "scan_progress.h"
#include "scene_data.h"

#include <openxr/openxr.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace roomsense::sim {

inline constexpr XrSystemId kSystemId = 1;
inline constexpr const char* kRuntimeName = "roomsense simulated runtime";
inline constexpr const char* kSystemName = "roomsense simulated headset (headless)";
inline constexpr uint32_t kMaxLayerCount = 16;            // XrSystemGraphicsProperties: the spec's minimum
inline constexpr uint32_t kMaxSwapchainImageSize = 4096;  // ... and at least the views' maximum image rectangles

// A view configuration type valid here: the core ones (no extension that adds one is ever enabled). Others are
// XR_ERROR_VALIDATION_FAILURE; valid ones other than stereo are XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED.
inline bool is_view_configuration_type(XrViewConfigurationType type) {
  return type == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO || type == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
}

XrTime now_time();  // CLOCK_MONOTONIC in nanoseconds, as XR_KHR_convert_timespec_time says

template <typename H>
std::uint64_t id_of(H handle) {
  if constexpr (std::is_pointer_v<H>) return reinterpret_cast<std::uint64_t>(handle);
  else return static_cast<std::uint64_t>(handle);
}
template <typename H>
H handle_of(std::uint64_t id) {
  if constexpr (std::is_pointer_v<H>) return reinterpret_cast<H>(id);
  else return static_cast<H>(id);
}

struct SessionEvent {
  std::uint64_t session;
  XrSessionState state;
  XrTime time;
};

struct InstanceState {
  std::set<std::string> extensions;  // enabled ones
  Config config;
  std::shared_ptr<const Room> room;  // null when ROOMSENSE_SIM_SCENE is unset
  std::shared_ptr<ScanProgress> scan;  // with ROOMSENSE_SIM_SCAN_SECONDS > 0
  mutable std::shared_ptr<const ScanStep> whole;  // without: the room, never changing (split at the first ask)
  std::deque<SessionEvent> events;
  std::deque<XrEventDataBuffer> extension_events;  // scene extensions' events, after the session events
  std::vector<std::string> paths;  // XrPath n names paths[n - 1]
  std::unordered_map<std::string, XrPath> path_ids;
  bool has(const char* extension) const { return extensions.count(extension) != 0; }
  // The room as the live-meshing extensions serve it at `now` (scan_progress.h); null without a room. Call under
  // the runtime's lock.
  std::shared_ptr<const ScanStep> room_at(XrTime now) const {
    if (scan) return scan->at(now);
    if (!whole && room) whole = whole_room(room, config.chunk_size);
    return whole;
  }
};

struct SessionState {
  std::uint64_t instance = 0;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  bool running = false;
  bool exit_requested = false;
  int frames_waited = 0;  // xrWaitFrame calls not yet matched by xrBeginFrame
  bool frame_begun = false;
  XrTime next_display_time = 0;
};

struct SpaceState {
  std::uint64_t session = 0;
  XrReferenceSpaceType type = XR_REFERENCE_SPACE_TYPE_LOCAL;
  XrPosef pose_in_reference{{0, 0, 0, 1}, {0, 0, 0}};  // or in the action's pose, for an action space
  std::uint64_t action = 0;  // an action space's pose action (actions.h); 0 for a reference space
};

// Shared between an observer and its compute thread.
struct ComputeJob {
  std::mutex mutex;
  // The compute's pause ends on `ending`, not on a stop token: a wait on one registers a std::stop_callback,
  // whose removal can hang in MinGW-w64's GCC 12 libstdc++ (tests/windows/check_no_atomic_waits.cmake says why).
  std::condition_variable wake;
  bool ending = false;  // set when the observer goes
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_NONE_MSFT;
  std::shared_ptr<const SceneData> result;  // of the last successful compute
};

struct ObserverState {
  std::uint64_t session = 0;
  XrTime first_compute = 0;  // what its components' updateTime says: the room has not changed since
  std::shared_ptr<ComputeJob> job = std::make_shared<ComputeJob>();
  std::jthread worker;  // joined when the observer goes away

  ObserverState() = default;
  ObserverState(const ObserverState&) = delete;
  ObserverState& operator=(const ObserverState&) = delete;
  ~ObserverState() { end_compute(); }  // then the worker is joined
  // Ends a compute's pause (its delay, or a fault's UPDATING for ever); the compute then ends at once.
  void end_compute() {
    {
      std::lock_guard lock(job->mutex);
      job->ending = true;
    }
    job->wake.notify_all();
  }
};

struct SceneState {
  std::uint64_t observer = 0;
  std::uint64_t session = 0;
  std::shared_ptr<const SceneData> data;
};

struct Runtime {
  std::mutex mutex;
  std::unordered_map<std::uint64_t, std::unique_ptr<InstanceState>> instances;
  std::unordered_map<std::uint64_t, std::unique_ptr<SessionState>> sessions;
  std::unordered_map<std::uint64_t, std::unique_ptr<SpaceState>> spaces;
  std::unordered_map<std::uint64_t, std::unique_ptr<ObserverState>> observers;
  std::unordered_map<std::uint64_t, std::unique_ptr<SceneState>> scenes;
  ActionSystem input;  // action sets and actions
  std::uint64_t next_id = 0x52530001;  // one counter for every type: a handle of the wrong type is never found

  std::uint64_t new_id() { return next_id++; }

  template <typename Map>
  static auto* find(Map& map, std::uint64_t id) {
    auto it = map.find(id);
    return it == map.end() ? nullptr : it->second.get();
  }
  InstanceState* instance(XrInstance h) { return find(instances, id_of(h)); }
  SessionState* session(XrSession h) { return find(sessions, id_of(h)); }
  SpaceState* space(XrSpace h) { return find(spaces, id_of(h)); }
  ObserverState* observer(XrSceneObserverMSFT h) { return find(observers, id_of(h)); }
  SceneState* scene(XrSceneMSFT h) { return find(scenes, id_of(h)); }

  // Destruction unlinks objects under the lock and hands back what must be destroyed after it is released
  // (observers join their compute threads).
  struct Graveyard {
    std::vector<std::unique_ptr<ObserverState>> observers;  // their compute threads are joined here
    std::vector<std::uint64_t> sessions, instances;         // each served extension forgets their objects
    Graveyard() = default;
    Graveyard(const Graveyard&) = delete;
    Graveyard& operator=(const Graveyard&) = delete;
    ~Graveyard();
  };
  void destroy_session(std::uint64_t id, Graveyard& graveyard);
  void destroy_observer(std::uint64_t id, Graveyard& graveyard);
  void destroy_instance(std::uint64_t id, Graveyard& graveyard);

  void push_state(SessionState& session, std::uint64_t session_id, XrSessionState state);
};

Runtime& runtime();

}  // namespace roomsense::sim
