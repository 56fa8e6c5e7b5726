// std::floor to an int without libm: x86-64's baseline (no SSE4.1 roundsd) makes std::floor a library call,
// and packing calls it for every half-voxel sample of every candidate (millions per room).
#pragma once
#include <glm/vec3.hpp>

namespace roomsense::detail {

// Exactly int(std::floor(x)) for finite x within int's range (a grid coordinate, not arbitrary input).
constexpr int floor_int(double x) {
  const int i = int(x);                 // truncation: floor for x >= 0
  return i - (double(i) > x ? 1 : 0);   // one less for a negative non-integer
}

// Exactly glm::ivec3(glm::floor(v)), each component as floor_int.
constexpr glm::ivec3 floor_ivec3(const glm::vec3& v) { return {floor_int(v.x), floor_int(v.y), floor_int(v.z)}; }

}  // namespace roomsense::detail
