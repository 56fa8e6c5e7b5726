#include "spatial_service.h"

#include "../guard.h"
#include "../log.h"
#include "spatial_instance.h"

#include "roomsense/platform.h"

#include <stdexcept>

namespace roomsense::layer {
namespace {

constexpr auto kClockWait = std::chrono::milliseconds(20);  // between looks for a frame time

}  // namespace

SpatialService::SpatialService(std::shared_ptr<SessionState> session) : session_(std::move(session)) {}

SpatialService::~SpatialService() { shut_down(); }

void SpatialService::context_created() {
  std::lock_guard lock(mutex_);
  if (shut_) throw std::runtime_error("the session is going away");
  ++contexts_;
  if (worker_.joinable()) {
    wake_.notify_all();
    return;
  }
  const InstanceState& instance = *session_->instance;
  auto info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  info.poseInReferenceSpace.orientation.w = 1.0f;
  if (const XrResult r = instance.next.xrCreateReferenceSpace(session_->handle, &info, &space_); XR_FAILED(r))
    throw std::runtime_error("the layer's LOCAL space cannot be created: " + xr::result_name(r));
  Analyzer::Settings settings;
  settings.base_space = space_;
  settings.base_type = XR_REFERENCE_SPACE_TYPE_LOCAL;
  settings.voxel_size = kDefaultVoxelSize;
  settings.backend = instance.config.env_backend;
  analyzer_ = std::make_shared<Analyzer>(session_, settings);
  worker_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

void SpatialService::context_destroyed() {
  std::lock_guard lock(mutex_);
  if (contexts_ > 0) --contexts_;
}

std::shared_ptr<const EntitySet> SpatialService::entities() {
  std::lock_guard lock(mutex_);
  return entities_;
}

std::uint64_t SpatialService::finished() {
  std::lock_guard lock(mutex_);
  return finished_;
}

std::uint64_t SpatialService::published() {
  std::lock_guard lock(mutex_);
  return published_;
}

XrSpace SpatialService::space() {
  std::lock_guard lock(mutex_);
  return space_;
}

void SpatialService::stop(bool release_handles) {
  std::jthread worker;
  std::shared_ptr<Analyzer> analyzer;
  {
    std::lock_guard lock(mutex_);
    if (shut_) return;
    shut_ = true;
    worker_.request_stop();  // under the lock: the worker sees it with shut_, after any wait below
    worker = std::move(worker_);
    analyzer = analyzer_;
  }
  wake_.notify_all();
  // The analyzer's shut-down ends a compute the worker waits for (Analyzer::wait), and releases the space (its
  // base_space); the worker, its stop requested, touches neither after that wait.
  if (analyzer && release_handles) analyzer->shut_down();
  else if (analyzer) analyzer->end();
  if (worker.joinable()) worker.join();
}

// The runtime's clock now, or the latest frame time; 0 while neither is known.
XrTime SpatialService::now() const {
  const InstanceState& instance = *session_->instance;
  if (instance.spatial && instance.spatial->convert_time != nullptr) {
    XrTime t = 0;
    if (platform::xr_time_now(instance.spatial->convert_time, instance.handle, t) && t > 0) return t;
  }
  return session_->frame_time.load();
}

void SpatialService::run(std::stop_token stop) {
  const auto interval = session_->instance->config.spatial_interval;
  bool said_clock = false;
  while (!stop.stop_requested()) {
    const XrTime time = now();
    if (time <= 0) {  // no clock yet: the application's first xrWaitFrame gives one
      if (!said_clock) log_info("spatial entities: waiting for a frame time to locate the runtime's meshes");
      said_clock = true;
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, kClockWait, [&] { return shut_; });
      continue;
    }
    auto info = xr_struct<XrRoomComputeInfoEXTX>(XR_TYPE_ROOM_COMPUTE_INFO_EXTX);
    info.time = time;
    info.includeRuntimeMeshes = XR_TRUE;
    XrRoomComputeStateEXTX state = XR_ROOM_COMPUTE_STATE_FAILED_EXTX;
    if (XR_SUCCEEDED(analyzer_->compute(info))) state = analyzer_->wait();
    if (stop.stop_requested()) return;
    const std::shared_ptr<const RoomResult> latest = analyzer_->latest();
    {
      std::lock_guard lock(mutex_);
      if (state == XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX && latest) {
        auto next = std::make_shared<EntitySet>(build_entity_set(*latest, *entities_));
        if (!same_entities(*next, *entities_)) {
          entities_ = std::move(next);
          ++published_;
          log_info("spatial entities: " + std::to_string(entities_->entities.size()) + " published");
        }
      }
      ++finished_;
    }
    // The next look at the runtime's meshes: after the interval, and only while a context wants them.
    std::unique_lock lock(mutex_);
    wake_.wait_for(lock, interval, [&] { return shut_; });
    wake_.wait(lock, [&] { return shut_ || contexts_ > 0; });
  }
}

}  // namespace roomsense::layer
