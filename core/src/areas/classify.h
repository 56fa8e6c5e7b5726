// Space classification of §3.5: a reduced rectangle in metres with its pose, size and category
// (Eq. 3.54-3.58), and its interaction level (§3.5.1/3.5.2, Eq. 3.59).
#pragma once
#include "reduce.h"

#include <glm/vec2.hpp>

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

// What reach reads of an area of V_Floor, in the X-Z plane: its centre and half width. A large floor has hundreds
// of thousands: 12 bytes each, not an Area's hundred.
struct ReachFloor {
  glm::vec2 center{0.0f};
  float half_width = 0.0f;
  explicit ReachFloor(const Area& a) : center(a.center.x, a.center.z), half_width(a.half_width) {}
};

// And of an area of V_Wall: the same, and its top edge.
struct ReachWall : ReachFloor {
  glm::vec2 top_left{0.0f}, top_right{0.0f};  // corners 3 and 2
  explicit ReachWall(const Area& a)
      : ReachFloor(a), top_left(a.corners[3].x, a.corners[3].z), top_right(a.corners[2].x, a.corners[2].z) {}
};

// §3.5.1/3.5.2 for each area of `areas`, against the deduplicated (not overlap-reduced) floor and wall areas
// (V_Floor, V_Wall). Sets reach and flags. Runs on up to `threads` threads; the result does not depend on it.
void assign_reach(std::vector<Area>& areas, const std::vector<ReachFloor>& floors, const std::vector<ReachWall>& walls,
                  float floor_y, const AreaParams& params, unsigned threads);

}  // namespace roomsense::detail
