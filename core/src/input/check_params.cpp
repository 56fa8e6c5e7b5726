// The analysis parameters' ranges: a value outside them (NaN, Inf, a negative length, a fill above 1, a size of
// zero) would take a search, a loop or an index past what the grid allows, so it is refused with its name.
#include "roomsense/areas.h"
#include "roomsense/error.h"
#include "roomsense/features.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace roomsense {
namespace {

// Lengths and heights in metres, areas in m²: a room's, not a city's.
constexpr float kMaxLength = 100.0f;
constexpr float kMaxArea = kMaxLength * kMaxLength;

std::string shown(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(v));
  return text;
}

void check(float value, float lo, float hi, bool lo_open, const char* name) {
  const bool above_lo = lo_open ? value > lo : value >= lo;
  if (!(above_lo && value <= hi))  // NaN fails both
    throw Error(ErrorCode::BadParameter, std::string(name) + " is " + shown(value) + ", outside " +
                                             (lo_open ? "(" : "[") + shown(lo) + ", " + shown(hi) + "]");
}
void length(float value, const char* name) { check(value, 0.0f, kMaxLength, false, name); }
void area(float value, const char* name) { check(value, 0.0f, kMaxArea, false, name); }
void share(float value, const char* name) { check(value, 0.0f, 1.0f, false, name); }

}  // namespace

void check_params(const FeatureParams& p) {
  check(p.min_floor_ceiling, 0.0f, kMaxLength, true, "min_floor_ceiling");
  share(p.wall_fill, "wall_fill");
  using Field = std::pair<float FeatureParams::*, const char*>;
  for (const auto& [field, name] :
       {Field{&FeatureParams::furniture_top, "furniture_top"}, Field{&FeatureParams::furniture_clear, "furniture_clear"},
        Field{&FeatureParams::ceiling_clear, "ceiling_clear"}, Field{&FeatureParams::wall_normal_reach, "wall_normal_reach"},
        Field{&FeatureParams::wall_top_gap, "wall_top_gap"}, Field{&FeatureParams::max_opening, "max_opening"},
        Field{&FeatureParams::wall_recess, "wall_recess"}, Field{&FeatureParams::floor_roughness, "floor_roughness"},
        Field{&FeatureParams::min_passage, "min_passage"}})
    length(p.*field, name);
  area(p.min_room_area, "min_room_area");
  area(p.min_ceiling_facet, "min_ceiling_facet");
}

void check_params(const AreaParams& p) {
  length(p.width_tolerance, "width_tolerance");
  // Each size is wider than the tolerance: a range of widths reaching 0 would pair a corner with itself.
  for (std::size_t s = 0; s < 3; ++s) {
    const auto size = [&](float value, const char* name, bool width) {
      const std::string field = std::string(name) + "[" + std::to_string(s) + "]";
      check(value, 0.0f, kMaxLength, true, field.c_str());
      if (width && !(value > p.width_tolerance))
        throw Error(ErrorCode::BadParameter, field + " (" + shown(value) + ") is not wider than width_tolerance (" +
                                                 shown(p.width_tolerance) + ")");
    };
    size(p.wall_width[s], "wall_width", true);
    size(p.wall_height[s], "wall_height", false);
    size(p.square_width[s], "square_width", true);
  }
  share(p.wall_fill, "wall_fill");
  share(p.horizontal_fill, "horizontal_fill");
  if (!(p.reduction_offset >= 1 && p.reduction_offset <= 100))
    throw Error(ErrorCode::BadParameter, "reduction_offset is " + std::to_string(p.reduction_offset) + ", outside [1, 100]");
  length(p.close_distance, "close_distance");
  check(p.close_height, -kMaxLength, kMaxLength, false, "close_height");
  check(p.wall_view_cone_deg, 0.0f, 180.0f, false, "wall_view_cone_deg");
}

}  // namespace roomsense
