// The shared entry-point checks (roomsense/xr), bound to the layer's log.
#pragma once
#include "log.h"

#include "roomsense/xr/guard.h"
#include "roomsense/xr/two_call.h"

namespace roomsense::layer {

using xr::find_next;
using xr::has_type;
using xr::xr_struct;

// Every entry point runs its body through this and returns an XrResult whatever happens inside.
template <typename Body>
XrResult guarded(const char* function, Body&& body) noexcept {
  return xr::guarded(function, [](const std::string& line) { log_error(line); }, std::forward<Body>(body));
}

}  // namespace roomsense::layer
