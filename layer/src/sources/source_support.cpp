#include "source_support.h"

#include "../guard.h"

#include <cstdio>
#include <stdexcept>
#include <thread>

namespace roomsense::layer {

std::string uuid_chunk_id(const char* prefix, const std::uint8_t (&bytes)[16]) {
  std::string s = std::string(prefix) + ":";
  char hex[3];
  for (std::uint8_t b : bytes) {
    std::snprintf(hex, sizeof hex, "%02x", b);
    s += hex;
  }
  return s;
}

bool wait_for_future(PFN_xrPollFutureEXT poll, PFN_xrCancelFutureEXT cancel, XrInstance instance, XrFutureEXT future,
                     const char* what, std::stop_token stop) {
  const auto give_up = [&] {
    auto info = xr_struct<XrFutureCancelInfoEXT>(XR_TYPE_FUTURE_CANCEL_INFO_EXT);
    info.future = future;
    cancel(instance, &info);
  };
  const auto deadline = std::chrono::steady_clock::now() + kRuntimeTimeout;
  for (;;) {
    auto poll_info = xr_struct<XrFuturePollInfoEXT>(XR_TYPE_FUTURE_POLL_INFO_EXT);
    poll_info.future = future;
    auto state = xr_struct<XrFuturePollResultEXT>(XR_TYPE_FUTURE_POLL_RESULT_EXT);
    xr::check(poll(instance, &poll_info, &state), "xrPollFutureEXT");
    if (state.state == XR_FUTURE_STATE_READY_EXT) return true;
    if (stop.stop_requested()) {
      give_up();
      return false;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      give_up();
      throw std::runtime_error(std::string(what) + ": the runtime's future was not ready within " +
                               std::to_string(kRuntimeTimeout.count()) + " s");
    }
    std::this_thread::sleep_for(kRuntimePollInterval);
  }
}

}  // namespace roomsense::layer
