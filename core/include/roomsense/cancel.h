// Cooperative cancellation. An app that destroys an analyzer, session or instance must get its thread back
// within 100 ms whatever the analysis is doing, so every loop that can run long calls stop_point() every
// few thousand items. The check is one atomic load.
#pragma once
#include "roomsense/error.h"

#include <stop_token>

namespace roomsense {

// Throws Error(Cancelled) once a stop was requested on `stop`. A default std::stop_token never stops.
inline void stop_point(const std::stop_token& stop) {
  if (stop.stop_requested()) throw Error(ErrorCode::Cancelled, "the analysis was cancelled");
}

}  // namespace roomsense
