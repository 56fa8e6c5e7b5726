// The IncrementalAnalysis chunk id of each mesh an analyzer analyses, kept from one compute to the next (issue 19,
// item 2). A mesh the runtime keeps serving under one id (SourceChunk::id) keeps its chunk wherever the runtime
// lists it, and a mesh first seen now sorts after every one seen before. Chunks combine in id order, so a new mesh
// is appended to the combined scan, and the meshes after it in the runtime's list are neither voxelized nor
// placed again (by position, one listed first moved every other to a new chunk).
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace roomsense::layer {

class ChunkIds {
 public:
  // Each key's id: the one the previous call gave it, or the next unused one, in the keys' order. A key given
  // twice is two meshes, each its own chunk (its n-th use keeps its n-th id). A key the previous call had and
  // this one has not is forgotten: seen again, it is a new mesh.
  std::vector<std::uint64_t> assign(const std::vector<std::string>& keys);

 private:
  std::unordered_map<std::string, std::vector<std::uint64_t>> ids_;  // per key, per use
  std::uint64_t next_ = 0;
};

}  // namespace roomsense::layer
