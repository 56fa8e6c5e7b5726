#include "served_chunks.h"

namespace roomsense::layer {
namespace {

// Bit for bit: a pose that is not exactly the same moves the vertices elsewhere.
bool same_pose(const XrPosef& a, const XrPosef& b) {
  return a.orientation.x == b.orientation.x && a.orientation.y == b.orientation.y && a.orientation.z == b.orientation.z &&
         a.orientation.w == b.orientation.w && a.position.x == b.position.x && a.position.y == b.position.y &&
         a.position.z == b.position.z;
}

}  // namespace

ServedChunk ServedChunks::find(XrSession session, const std::string& id, std::uint64_t change, const XrPosef& placed) const {
  std::lock_guard lock(mutex_);
  if (session != session_) return nullptr;
  const auto it = by_id_.find(id);
  if (it == by_id_.end() || it->second->change != change || !same_pose(it->second->placed, placed)) return nullptr;
  return it->second;
}

void ServedChunks::keep(XrSession session, const std::vector<ServedChunk>& served) {
  std::unordered_map<std::string, ServedChunk> by_id;
  for (const ServedChunk& c : served) by_id.emplace(c->id, c);
  std::lock_guard lock(mutex_);
  session_ = session;
  by_id_.swap(by_id);  // the old map is freed after the lock, with the chunks no query serves any more
}

void ServedChunks::forget(XrSession session) {
  std::unordered_map<std::string, ServedChunk> by_id;
  std::lock_guard lock(mutex_);
  if (session != session_) return;
  session_ = XR_NULL_HANDLE;
  by_id_.swap(by_id);
}

}  // namespace roomsense::layer
