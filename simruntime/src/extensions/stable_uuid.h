// The uuids the simulated runtime gives a room's objects (anchors, submeshes, blocks): the same for the same
// room file, extension and object, so an app sees stable ids across snapshots, sessions and runs, as on a device.
#pragma once
#include "roomsense/xr/ext/base_types.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace roomsense::sim {

// `salt` tells extensions (and chunk sizes) apart, `key` the objects of one room.
inline XrUuidEXT stable_uuid(const std::string& room_source, std::uint64_t salt, std::uint64_t key) {
  const auto mix = [](std::uint64_t x) {  // splitmix64's finaliser
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  };
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a of the room's source
  for (unsigned char c : room_source) h = (h ^ c) * 0x100000001b3ull;
  const std::uint64_t a = mix(h ^ mix(salt) ^ mix(key)), b = mix(a ^ salt);
  XrUuidEXT u{};
  std::memcpy(u.data, &a, 8);
  std::memcpy(u.data + 8, &b, 8);
  u.data[6] = static_cast<std::uint8_t>((u.data[6] & 0x0f) | 0x40);  // RFC 4122 version 4 layout
  u.data[8] = static_cast<std::uint8_t>((u.data[8] & 0x3f) | 0x80);
  return u;
}

// A salt for objects that depend on the chunk size as well as the extension.
inline std::uint64_t chunked_salt(std::uint64_t extension_tag, double chunk_size) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &chunk_size, sizeof bits);
  return extension_tag ^ (bits * 0x9E3779B97F4A7C15ull);
}

inline bool same_uuid(const XrUuidEXT& a, const XrUuidEXT& b) { return std::memcmp(a.data, b.data, sizeof a.data) == 0; }

}  // namespace roomsense::sim
