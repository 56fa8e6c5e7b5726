#include "roomsense/content_hash.h"

#include <cstring>

namespace roomsense {

void ContentHash::add_bytes(const void* data, std::size_t bytes) {
  add_word(bytes);
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
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
