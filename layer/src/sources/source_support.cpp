#include "source_support.h"

#include "../chunk_feed.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace roomsense::layer {
namespace {

std::atomic<std::int64_t> g_timeout_ms{std::chrono::milliseconds(kRuntimeTimeout).count()};

std::string timeout_text() {
  const std::int64_t ms = g_timeout_ms.load();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

}  // namespace

std::chrono::milliseconds runtime_timeout() { return std::chrono::milliseconds(g_timeout_ms.load()); }

void set_runtime_timeout(std::chrono::milliseconds timeout) { g_timeout_ms.store(timeout.count()); }

MeshSource::Answer MeshSource::query(const QueryContext& context, std::stop_token stop) {
  const std::shared_ptr<SessionState> session = registry().session(context.session);
  if (session && session->lost.load()) return {};
  std::vector<SourceChunk> chunks;
  try {
    chunks = run_query(context, stop);
  } catch (const xr::CallFailed& e) {
    if (e.result == XR_ERROR_SESSION_LOST && session) session->lost.store(true);
    throw;
  }
  Answer answer;
  answer.read = static_cast<std::size_t>(std::count_if(chunks.begin(), chunks.end(), [](const SourceChunk& c) { return !c.same_as; }));
  answer.chunks = checked_chunks(name, std::move(chunks));
  if (!stop.stop_requested()) served_.keep(context.session, answer.chunks);
  return answer;
}

std::optional<SourceChunk> MeshSource::served_before(const QueryContext& context, const std::string& id,
                                                     std::uint64_t change, const XrPosef& placed) const {
  ServedChunk kept = served_.find(context.session, id, change, placed);
  if (!kept) return std::nullopt;
  SourceChunk listed;
  listed.id = id;
  listed.same_as = std::move(kept);
  return listed;
}

std::vector<ServedChunk> checked_chunks(const char* source, std::vector<SourceChunk> chunks) {
  const std::size_t served = chunks.size();
  std::size_t ragged = 0, non_finite = 0, out_of_range = 0, dropped = 0, empty = 0;
  std::vector<ServedChunk> out;
  out.reserve(chunks.size());
  for (SourceChunk& chunk : chunks) {
    if (chunk.same_as) {
      out.push_back(std::move(chunk.same_as));  // checked when it was served first
      continue;
    }
    MeshPiece& m = chunk.mesh;
    if (m.indices.size() % 3 != 0) ++ragged, m.indices.resize(m.indices.size() / 3 * 3);
    const std::size_t triangles = m.indices.size() / 3;
    if (chunk.labels.size() != triangles) chunk.labels.clear();  // one per triangle, or none
    std::vector<bool> finite(m.vertices.size());
    bool any_non_finite = false;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      finite[v] = std::isfinite(m.vertices[v].x) && std::isfinite(m.vertices[v].y) && std::isfinite(m.vertices[v].z);
      any_non_finite = any_non_finite || !finite[v];
    }
    non_finite += any_non_finite ? 1 : 0;
    bool any_out_of_range = false;
    std::size_t kept = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
      bool good = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t i = m.indices[3 * t + k];
        if (i >= m.vertices.size()) good = false, any_out_of_range = true;
        else if (!finite[i]) good = false;
      }
      if (!good) continue;
      for (std::size_t k = 0; k < 3; ++k) m.indices[3 * kept + k] = m.indices[3 * t + k];
      if (!chunk.labels.empty()) chunk.labels[kept] = chunk.labels[t];
      ++kept;
    }
    out_of_range += any_out_of_range ? 1 : 0;
    dropped += triangles - kept;
    m.indices.resize(3 * kept);
    if (!chunk.labels.empty()) chunk.labels.resize(kept);
    if (kept == 0 && (triangles > 0 || m.vertices.empty())) {
      ++empty;  // nothing left to analyse (vertices no triangle ever used still count: they stay, as a point cloud)
      continue;
    }
    chunk.key = piece_key(m, chunk.labels.empty() ? nullptr : &chunk.labels);
    out.push_back(std::make_shared<const SourceChunk>(std::move(chunk)));
  }
  std::string problems;
  const auto add = [&](std::size_t n, const std::string& what) {
    if (n > 0) problems += (problems.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(non_finite, "with non-finite vertices");
  add(out_of_range, "with indices out of range");
  add(ragged, "with an index count not a multiple of 3");
  if (!problems.empty()) problems += " (" + std::to_string(dropped) + " triangles dropped)";
  if (out.empty() && served > 0) {
    add(empty, "empty");
    throw std::runtime_error("the runtime served no usable triangles: of " + std::to_string(served) + " meshes, " + problems);
  }
  if (!problems.empty())
    log_warn(std::string(source) + ": of the runtime's " + std::to_string(served) + " meshes, " + problems + "; the rest is used");
  return out;
}

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
  const auto deadline = std::chrono::steady_clock::now() + runtime_timeout();
  PollPause pause;
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
      throw std::runtime_error(std::string(what) + ": the runtime's future was not ready within " + timeout_text());
    }
    pause.wait();
  }
}

}  // namespace roomsense::layer
