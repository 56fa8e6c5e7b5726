#include "query_support.h"

#include "roomsense/error.h"
#include "roomsense/number_text.h"

#include <cmath>

namespace roomsense::detail {

void check_length(float metres, const char* what) {
  if (!(metres >= 0.0f && metres <= kMaxQueryLength))
    throw Error(ErrorCode::BadParameter, std::string(what) + " must be between 0 and " +
                                             fixed_or_g(kMaxQueryLength, 0) + " m (got " + fixed_or_g(metres, 3) + ")");
}

void check_surfaces(std::uint32_t surfaces) {
  if (surfaces == 0 || (surfaces & ~std::uint32_t(kOnAnySurface)) != 0)
    throw Error(ErrorCode::BadParameter, "surfaces must be a non-empty set of the wall, floor, ceiling and furniture bits");
}

void check_finite(const glm::vec3& v, const char* what) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw Error(ErrorCode::BadParameter, std::string(what) + " must be finite");
}

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

std::uint64_t SeededRandom::next() {
  state += 0x9E3779B97F4A7C15ull;
  return mix64(state - 0x9E3779B97F4A7C15ull);
}

double SeededRandom::unit() { return double(next() >> 11) * 0x1.0p-53; }

std::size_t SeededRandom::below(std::size_t n) { return std::size_t(unit() * double(n)) % n; }

std::string surface_names(std::uint32_t surfaces) {
  std::string out;
  const std::pair<std::uint32_t, const char*> names[] = {
      {kOnWall, "wall"}, {kOnFloor, "floor"}, {kOnCeiling, "ceiling"}, {kOnFurniture, "furniture top"}};
  for (const auto& [bit, name] : names)
    if (surfaces & bit) out += (out.empty() ? "" : " or ") + std::string(name);
  return out;
}

}  // namespace roomsense::detail
