// A 64-bit hash of arrays' bytes, to tell a mesh that changed from one sent again as it was: an
// IncrementalAnalysis's chunks, the layer's meshes. Not for anything adversarial.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

namespace roomsense {

// FNV-1a over 64-bit words (an array's last bytes padded with zeros), each array preceded by its byte count, and
// a shift mixing each step's high bits down. Every step (an xor, a multiplication by an odd number, an xorshift)
// is one to one, so arrays that differ in one word always hash apart. A word at a time, not a byte, and an array's
// whole 64-byte blocks in eight lanes, word k of a block into lane k, the lanes then added in order as words: one
// chain of steps waits on each multiplication, eight side by side do not (the layer hashes every mesh of a room at
// every analysis: 2.7 MB for thesis-room1, 590 us in one chain, 110-130 in eight). A lane's steps, and each lane's
// word added after, are one to one too.
class ContentHash {
 public:
  void add_bytes(const void* data, std::size_t bytes);
  template <class T>
  void add(std::span<const T> values) {
    add_bytes(values.data(), values.size_bytes());
  }
  std::uint64_t value() const { return hash_; }

 private:
  static std::uint64_t step(std::uint64_t hash, std::uint64_t word) {
    hash = (hash ^ word) * 0x100000001b3ull;
    return hash ^ (hash >> 29);
  }
  void add_word(std::uint64_t word) { hash_ = step(hash_, word); }
  static constexpr std::size_t kLanes = 8;
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace roomsense
