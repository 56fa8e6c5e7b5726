#include "state.h"

#include "analyzer.h"
#include "capture.h"
#include "spatial/spatial_api.h"
#include "spatial/spatial_service.h"

#include "roomsense/platform.h"

namespace roomsense::layer {

Registry& registry() {
  // Destroyed when the loader unloads the layer (after the last instance is gone) or at exit; on Windows never,
  // as its sessions' and analyzers' threads may have been ended mid-way by then (platform::ProcessWide).
  static platform::ProcessWide<Registry> r;
  return r.value;
}

Registry::~Registry() {
  // An application that exits with a session open leaves it in a cycle with its spatial service (session.spatial
  // holds the service, the service its session): no destructor ends either, and the service's threads would run
  // on into the runtime's and the layer's destruction (every round of
  // LayerSpatialServed.AProcessExitingMidDiscoveryEndsCleanly died of SIGSEGV). They end here, calling nothing
  // down the chain, as the analyzers' destructors do; so does the export worker.
  for (const auto& entry : sessions) {
    SessionState& session = *entry.second;
    std::shared_ptr<SpatialService> spatial;
    {
      std::lock_guard lock(session.mutex);
      spatial = std::move(session.spatial);
    }
    if (spatial) spatial->end();
    session.end_export();
  }
}

std::shared_ptr<InstanceState> Registry::instance(XrInstance handle) {
  std::lock_guard lock(mutex);
  const auto it = instances.find(handle);
  return it == instances.end() ? nullptr : it->second;
}

std::shared_ptr<SessionState> Registry::session(XrSession handle) {
  std::lock_guard lock(mutex);
  const auto it = sessions.find(handle);
  return it == sessions.end() ? nullptr : it->second;
}

std::vector<std::shared_ptr<Analyzer>> forget_session_locked(Registry& r, XrSession session) {
  std::vector<std::shared_ptr<Analyzer>> analyzers;
  for (auto it = r.analyzers.begin(); it != r.analyzers.end();) {
    if (it->second->session()->handle == session) {
      analyzers.push_back(it->second);
      it = r.analyzers.erase(it);
    } else {
      ++it;
    }
  }
  std::erase_if(r.spaces, [&](const auto& entry) { return entry.second.session == session; });
  r.sessions.erase(session);
  return analyzers;
}

SessionState::~SessionState() {
  end_export();  // the worker it returns ends here: ~jthread requests stop and joins
}

std::jthread SessionState::end_export() {
  std::jthread worker;
  {
    std::lock_guard lock(mutex);
    export_ending = true;
    worker = std::move(export_worker);
  }
  export_wake.notify_all();
  return worker;
}

void shut_down_session(SessionState& session, const std::vector<std::shared_ptr<Analyzer>>& analyzers) {
  // The spatial-entity API's handles of the session, then the analysis behind them.
  forget_spatial_session(session.handle);
  std::shared_ptr<SpatialService> spatial;
  {
    std::lock_guard lock(session.mutex);
    spatial = std::move(session.spatial);
  }
  if (spatial) spatial->shut_down();
  for (const auto& a : analyzers) a->shut_down();
  for (const EnabledSource& s : session.instance->sources) s.source->end_session(session.handle);
  session.end_export();  // joins the export worker before the last export below
  // Whatever the application read and no export-only analysis has seen yet.
  if (!session.instance->extx && !session.instance->config.export_dir.empty()) export_captured(session);
  XrSpace space;
  {
    std::lock_guard lock(session.mutex);
    space = session.capture_space;
    session.capture_space = XR_NULL_HANDLE;
    session.captured.clear();
  }
  if (space != XR_NULL_HANDLE) session.instance->next.xrDestroySpace(space);
}

}  // namespace roomsense::layer
