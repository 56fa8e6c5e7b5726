// The shared entry-point checks (roomsense/xr), bound to the runtime's log.
#pragma once
#include "faults.h"
#include "log.h"

#include "roomsense/xr/guard.h"
#include "roomsense/xr/two_call.h"

namespace roomsense::sim {

using xr::find_next;
using xr::has_type;
using xr::terminated;
using xr::two_call;
using xr::two_call_typed;

// Every entry point runs its body through this: no exception ever crosses into the application, and an
// injected fault (ROOMSENSE_SIM_FAULTS, faults.h) answers before the body runs.
template <typename Body>
XrResult guarded(const char* function, Body&& body) noexcept {
  if (const XrResult injected = faults::on_call(function); injected != XR_SUCCESS) return injected;
  return xr::guarded(function, [](const std::string& line) { log_error(line); }, std::forward<Body>(body));
}

}  // namespace roomsense::sim
