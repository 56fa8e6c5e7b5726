#include "ext_future.h"
#include "../process_state.h"

#include "../runtime.h"
#include "../validate.h"

#include <mutex>
#include <string>
#include <unordered_map>

namespace roomsense::sim {
namespace {

struct Future {
  std::uint64_t instance = 0, session = 0;
  std::string kind;
  std::chrono::steady_clock::time_point ready_at;
  std::shared_ptr<const void> result;
};

// Futures live apart from the runtime's lock: completing one never waits on anything else.
struct Futures {
  std::mutex mutex;
  std::unordered_map<std::uint64_t, Future> live;
  std::uint64_t next = 0x46550001;
};

Futures& futures() {
  return process_wide<Futures>();
}

std::uint64_t id_of_future(XrFutureEXT f) { return id_of(f); }

XrResult XRAPI_CALL xrPollFutureEXT(XrInstance instance, const XrFuturePollInfoEXT* pollInfo, XrFuturePollResultEXT* pollResult) {
  return guarded("xrPollFutureEXT", [&]() -> XrResult {
    {
      std::lock_guard lock(runtime().mutex);
      if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    }
    if (!has_type(pollInfo, XR_TYPE_FUTURE_POLL_INFO_EXT) || !has_type(pollResult, XR_TYPE_FUTURE_POLL_RESULT_EXT))
      return XR_ERROR_VALIDATION_FAILURE;
    Futures& f = futures();
    std::lock_guard lock(f.mutex);
    const auto it = f.live.find(id_of_future(pollInfo->future));
    if (it == f.live.end() || it->second.instance != id_of(instance)) return XR_ERROR_FUTURE_INVALID_EXT;
    pollResult->state = std::chrono::steady_clock::now() >= it->second.ready_at ? XR_FUTURE_STATE_READY_EXT
                                                                                : XR_FUTURE_STATE_PENDING_EXT;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCancelFutureEXT(XrInstance instance, const XrFutureCancelInfoEXT* cancelInfo) {
  return guarded("xrCancelFutureEXT", [&]() -> XrResult {
    {
      std::lock_guard lock(runtime().mutex);
      if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    }
    if (!has_type(cancelInfo, XR_TYPE_FUTURE_CANCEL_INFO_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    Futures& f = futures();
    std::lock_guard lock(f.mutex);
    const auto it = f.live.find(id_of_future(cancelInfo->future));
    if (it == f.live.end() || it->second.instance != id_of(instance)) return XR_ERROR_FUTURE_INVALID_EXT;
    f.live.erase(it);
    return XR_SUCCESS;
  });
}

void forget_session(std::uint64_t session) {
  Futures& f = futures();
  std::lock_guard lock(f.mutex);
  std::erase_if(f.live, [&](const auto& e) { return e.second.session == session; });
}

void forget_instance(std::uint64_t instance) {
  Futures& f = futures();
  std::lock_guard lock(f.mutex);
  std::erase_if(f.live, [&](const auto& e) { return e.second.instance == instance; });
}

}  // namespace

XrFutureEXT make_future(std::uint64_t instance, std::uint64_t session, std::string_view kind,
                        std::chrono::milliseconds delay, std::shared_ptr<const void> result) {
  Futures& f = futures();
  std::lock_guard lock(f.mutex);
  const std::uint64_t id = f.next++;
  const auto ready_at = delay == std::chrono::milliseconds::max() ? std::chrono::steady_clock::time_point::max()  // never
                                                                  : std::chrono::steady_clock::now() + delay;
  f.live[id] = Future{instance, session, std::string(kind), ready_at, std::move(result)};
  return handle_of<XrFutureEXT>(id);
}

XrResult take_future(XrFutureEXT future, std::uint64_t session, std::string_view kind, std::shared_ptr<const void>& result) {
  Futures& f = futures();
  std::lock_guard lock(f.mutex);
  const auto it = f.live.find(id_of_future(future));
  if (it == f.live.end() || it->second.session != session || it->second.kind != kind) return XR_ERROR_FUTURE_INVALID_EXT;
  if (std::chrono::steady_clock::now() < it->second.ready_at) return XR_ERROR_FUTURE_PENDING_EXT;
  result = std::move(it->second.result);
  f.live.erase(it);
  return XR_SUCCESS;
}

const ServedExtension& ext_future_extension() {
  static const ServedExtension e{XR_EXT_FUTURE_EXTENSION_NAME,
                                 XR_EXT_future_SPEC_VERSION,
                                 false,
                                 {{"xrPollFutureEXT", reinterpret_cast<PFN_xrVoidFunction>(&xrPollFutureEXT)},
                                  {"xrCancelFutureEXT", reinterpret_cast<PFN_xrVoidFunction>(&xrCancelFutureEXT)}},
                                 &forget_session,
                                 &forget_instance};
  return e;
}

}  // namespace roomsense::sim
