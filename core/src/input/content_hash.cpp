#include "roomsense/content_hash.h"

#include <array>
#include <cstring>

namespace roomsense {

void ContentHash::add_bytes(const void* data, std::size_t bytes) {
  add_word(bytes);
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
  if (bytes >= 8 * kLanes) {
    // The lanes start from the hash so far, seeded apart from one another.
    std::array<std::uint64_t, kLanes> lanes;
    for (std::size_t k = 0; k < kLanes; ++k) lanes[k] = hash_ ^ (0x9e3779b97f4a7c15ull * k);
    for (; i + 8 * kLanes <= bytes; i += 8 * kLanes)
      for (std::size_t k = 0; k < kLanes; ++k) {
        std::uint64_t word;
        std::memcpy(&word, p + i + 8 * k, 8);
        lanes[k] = step(lanes[k], word);
      }
    for (const std::uint64_t lane : lanes) add_word(lane);
  }
  for (; i + 8 <= bytes; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, p + i, 8);
    add_word(word);
  }
  if (i < bytes) {
    std::uint64_t word = 0;
    std::memcpy(&word, p + i, bytes - i);
    add_word(word);
  }
}

}  // namespace roomsense
