// The analysis behind the standard spatial-entity API, one per session: the application never calls
// xrComputeRoomEXTX, so the layer analyses the runtime's meshes itself when the first of its spatial contexts
// is created, and again every ROOMSENSE_SPATIAL_INTERVAL_MS while one exists (a query of the runtime's meshes;
// the analysis itself runs only when they changed). Everything runs on the service's own thread; each result
// becomes an EntitySet with stable ids, published whole.
#pragma once
#include "../analyzer.h"
#include "entity_set.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>

namespace roomsense::layer {

class SpatialService {
 public:
  explicit SpatialService(std::shared_ptr<SessionState> session);
  ~SpatialService();  // shut_down()
  SpatialService(const SpatialService&) = delete;
  SpatialService& operator=(const SpatialService&) = delete;

  // A context of the layer's was created (the first starts the worker and the layer's LOCAL space) or
  // destroyed (with none left the worker idles). Start throws std::runtime_error when the space cannot be made.
  void context_created();
  void context_destroyed();

  // The entities of the latest analysis that found a room (never null: empty before the first).
  std::shared_ptr<const EntitySet> entities();
  // Analyses finished so far, whether they found a room or not: a discovery waits for the first.
  std::uint64_t finished();
  // Bumped whenever a finished analysis changed the entities: each context recommends a new discovery then.
  std::uint64_t published();
  // The layer's LOCAL space the entities are in (null before the first context).
  XrSpace space();

  // Stops and joins the worker and destroys the layer's space. Idempotent; call without the registry lock,
  // before the session is destroyed down the chain.
  void shut_down() { stop(true); }
  // The same without calling down the chain (the space is left to the session): at exit (~Registry).
  void end() { stop(false); }

 private:
  void stop(bool release_handles);
  void run(std::stop_token stop);
  XrTime now() const;

  std::shared_ptr<SessionState> session_;
  std::mutex mutex_;  // guards everything below
  // The worker's pauses end on shut_, not on its stop token (why: Analyzer's mutex_, analyzer.h).
  std::condition_variable wake_;
  bool shut_ = false;
  int contexts_ = 0;
  XrSpace space_ = XR_NULL_HANDLE;
  std::shared_ptr<Analyzer> analyzer_;
  std::shared_ptr<const EntitySet> entities_ = std::make_shared<EntitySet>();
  std::uint64_t finished_ = 0, published_ = 0;
  std::jthread worker_;
};

}  // namespace roomsense::layer
