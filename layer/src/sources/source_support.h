// What the mesh sources share: how long the layer waits for a runtime, the location check, chunk ids made from
// a runtime's uuid, and waiting on an XR_EXT_future with a deadline and the analysis's stop token.
#pragma once
#include "mesh_source.h"

#include <openxr/openxr.h>

#include "roomsense/xr/ext/XR_EXT_future.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stop_token>
#include <string>
#include <thread>

namespace roomsense::layer {

inline constexpr auto kRuntimePollInterval = std::chrono::milliseconds(2);

// The pauses between polls of the runtime's work: 100 us first, doubling up to kRuntimePollInterval. A runtime
// whose work is done within a millisecond (a simulated one, or a scene query of a room it holds) is not kept
// waiting a whole interval: a fixed 5 ms pause was most of such a query.
class PollPause {
 public:
  void wait() {
    std::this_thread::sleep_for(next_);
    next_ = std::min<std::chrono::microseconds>(2 * next_, kRuntimePollInterval);
  }

 private:
  std::chrono::microseconds next_{100};
};
inline constexpr auto kRuntimeTimeout = std::chrono::seconds(10);  // a future or query that never completes

// kRuntimeTimeout, or ROOMSENSE_RUNTIME_TIMEOUT_MS as read at the last xrCreateInstance (config.cpp).
std::chrono::milliseconds runtime_timeout();
void set_runtime_timeout(std::chrono::milliseconds timeout);
inline constexpr std::size_t kMaxRuntimeBufferElements = 1u << 26;  // per mesh buffer: far beyond any room

// Position and orientation both valid: the only locations the layer places meshes with.
inline bool located(XrSpaceLocationFlags flags) {
  constexpr XrSpaceLocationFlags kBoth = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  return (flags & kBoth) == kBoth;
}

// "prefix:" and the 16 bytes of a runtime's uuid in hex: the chunk id the active and the passive capture share.
std::string uuid_chunk_id(const char* prefix, const std::uint8_t (&bytes)[16]);

// The chunks of one query with the runtime's broken triangles dropped, and chunks left without triangles (those
// that only ever had vertices stay, as points), each keyed (SourceChunk::key); a chunk listed as served before
// (same_as) is that one, as it was checked then. One warning names what was dropped. Throws std::runtime_error
// saying why when nothing usable is left of a non-empty list.
std::vector<ServedChunk> checked_chunks(const char* source, std::vector<SourceChunk> chunks);

// Polls `future` until it is ready (true), the stop token is set (cancels it, false) or runtime_timeout() passes
// (cancels it, throws std::runtime_error naming `what`). A failing poll throws too.
bool wait_for_future(PFN_xrPollFutureEXT poll, PFN_xrCancelFutureEXT cancel, XrInstance instance, XrFutureEXT future,
                     const char* what, std::stop_token stop);

}  // namespace roomsense::layer
