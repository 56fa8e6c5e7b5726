// XR_EXT_future, as the asynchronous scene extensions use it (XR_EXT_spatial_entity, XR_ML_world_mesh_detection):
// a future is READY once its simulated work time has passed; its *Complete function takes the result once.
#pragma once
#include "served_extension.h"

#include "roomsense/xr/ext/XR_EXT_future.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string_view>

namespace roomsense::sim {

const ServedExtension& ext_future_extension();

// A new future of `session`, of one kind (the async function that made it), ready `delay` from now with
// `result` for its Complete function; never ready with a delay of milliseconds::max() (faults::future_delay).
XrFutureEXT make_future(std::uint64_t instance, std::uint64_t session, std::string_view kind,
                        std::chrono::milliseconds delay, std::shared_ptr<const void> result);

// For a *Complete function: XR_ERROR_FUTURE_INVALID_EXT for an unknown, cancelled or already completed future
// or one of another session or kind, XR_ERROR_FUTURE_PENDING_EXT before it is ready; otherwise the result,
// and the future is spent.
XrResult take_future(XrFutureEXT future, std::uint64_t session, std::string_view kind, std::shared_ptr<const void>& result);

}  // namespace roomsense::sim
