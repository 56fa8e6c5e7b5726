#include "chunk_ids.h"

namespace roomsense::layer {

std::vector<std::uint64_t> ChunkIds::assign(const std::vector<std::string>& keys) {
  std::vector<std::uint64_t> ids;
  std::unordered_map<std::string, std::vector<std::uint64_t>> now;
  for (const std::string& key : keys) {
    std::vector<std::uint64_t>& uses = now[key];
    const auto before = ids_.find(key);
    const bool kept = before != ids_.end() && uses.size() < before->second.size();
    uses.push_back(kept ? before->second[uses.size()] : next_++);
    ids.push_back(uses.back());
  }
  ids_ = std::move(now);
  return ids;
}

}  // namespace roomsense::layer
