// Space classification of §3.5: a reduced rectangle in metres with its pose, size and category
// (Eq. 3.54-3.58), and its interaction level (§3.5.1/3.5.2, Eq. 3.59).
#pragma once
#include "reduce.h"

namespace roomsense::detail {

struct PlacementContext {
  const GridSpec& spec;
  const RoomFeatures& features;
  SurfaceLevels surfaces;
  const FeatureParams& feature_params;
};

// The horizontal direction (not normalized) the wall-normal bits of F point to (Alg. 1).
glm::vec3 normal_bits_direction(std::uint8_t bits);

// Everything of an Area but its reach (left None) and the reach bits of its flags.
Area to_area(const Sized& found, AreaType type, const PlacementContext& context);

// §3.5.1/3.5.2 for each area of `areas`, against the deduplicated (not overlap-reduced) floor and wall areas
// (V_Floor, V_Wall). Sets reach and flags. Runs on up to `threads` threads; the result does not depend on it.
void assign_reach(std::vector<Area>& areas, const std::vector<Area>& floors, const std::vector<Area>& walls,
                  float floor_y, const AreaParams& params, unsigned threads);

}  // namespace roomsense::detail
