// Four vertices at a time as three vectors of four floats, for loops over a scan's vertices that GCC does not
// vectorize as written (glm::vec3 is three floats with no padding). GCC's vector extensions: SSE2 on x86-64,
// NEON on ARM. Lane l of vector k holds axis (4 k + l) % 3: x y z x | y z x y | z x y z.
#pragma once
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstring>

namespace roomsense::detail {

typedef float VertexLanes __attribute__((vector_size(16)));
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));

constexpr int lane_axis(int k, int lane) { return (4 * k + lane) % 3; }

// Vector k of the four vertices from `first`.
inline VertexLanes load_lanes(const glm::vec3* first, int k) {
  VertexLanes v;
  std::memcpy(&v, &first->x + 4 * k, sizeof v);
  return v;
}
inline void store_lanes(glm::vec3* first, int k, const VertexLanes& v) { std::memcpy(&first->x + 4 * k, &v, sizeof v); }

// Vector k of four copies of `p`: its axes in vector k's lanes.
inline VertexLanes repeat_lanes(const glm::vec3& p, int k) {
  return VertexLanes{p[lane_axis(k, 0)], p[lane_axis(k, 1)], p[lane_axis(k, 2)], p[lane_axis(k, 3)]};
}

}  // namespace roomsense::detail
