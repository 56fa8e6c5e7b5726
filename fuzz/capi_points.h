// Point clouds for the C API harnesses: coordinates of one byte each, b * 0.02 m (+-2.56 m, a small room at
// 0.1 m voxels), where the byte 0x80 instead takes the next byte to pick a special value (NaN, +-Inf, values far
// outside any grid budget, the float extremes). Small grids keep every compute at a few milliseconds.
#pragma once
#include "fuzz_input.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace roomsense::fuzz {

inline float coordinate(FuzzInput& in) {
  const std::int8_t b = in.i8();
  if (b != -128) return b * 0.02f;
  static const float special[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                                  -std::numeric_limits<float>::infinity(), 1e30f, -1e30f,
                                  std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(), 1e4f};
  return special[in.u8() % (sizeof special / sizeof special[0])];
}

// count floats (not vertices: the thesis API takes any size).
inline std::vector<float> floats(FuzzInput& in, std::size_t count) {
  std::vector<float> out(count);
  for (float& f : out) f = coordinate(in);
  return out;
}

}  // namespace roomsense::fuzz
