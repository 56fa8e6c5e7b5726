// What the queries share: argument checks, the seeded hash that breaks ties and draws random points, and the
// names of surface kinds for reasons.
#pragma once
#include "roomsense/queries.h"

#include <cstdint>
#include <string>

namespace roomsense::detail {

// Throws Error(BadParameter) naming `what` unless 0 <= metres <= kMaxQueryLength (and finite).
void check_length(float metres, const char* what);
// Throws Error(BadParameter) unless `surfaces` is a non-empty set of SurfaceBits.
void check_surfaces(std::uint32_t surfaces);
// Throws Error(BadParameter) naming `what` unless every component is finite.
void check_finite(const glm::vec3& v, const char* what);

// SplitMix64: a fixed, portable sequence for a seed (std::uniform_*_distribution differ between libraries).
struct SeededRandom {
  std::uint64_t state;
  std::uint64_t next();
  double unit();  // in [0, 1)
  std::size_t below(std::size_t n);  // in [0, n), n > 0
};
std::uint64_t mix64(std::uint64_t x);

// "wall", "floor", "ceiling" and "furniture top" joined with " or ", for the asked bits.
std::string surface_names(std::uint32_t surfaces);

}  // namespace roomsense::detail
