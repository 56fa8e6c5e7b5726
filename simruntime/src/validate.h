// The shared entry-point checks (roomsense/xr), bound to the runtime's log.
#pragma once
#include "log.h"

#include "roomsense/xr/guard.h"
#include "roomsense/xr/two_call.h"

namespace roomsense::sim {

using xr::find_next;
using xr::has_type;
using xr::terminated;
using xr::two_call;
using xr::two_call_typed;

// Every entry point runs its body through this: no exception ever crosses into the application.
template <typename Body>
XrResult guarded(const char* function, Body&& body) noexcept {
  return xr::guarded(function, [](const std::string& line) { log_error(line); }, std::forward<Body>(body));
}

}  // namespace roomsense::sim
