// The report's input from a finished analysis, areas from OpenXR-style poses, and the reach colours.
#include "roomsense/report.h"

#include <glm/geometric.hpp>

#include <iterator>

namespace roomsense {

ReportInput report_input(const AnalysisResult& result, const Scan& scan, std::string title) {
  ReportInput in;
  in.title = std::move(title);
  in.floor_y = result.floor_y;
  in.ceiling_y = result.ceiling_y;
  in.storeys = result.storeys;
  in.rooms = result.rooms;
  in.areas = result.areas;
  in.bounds = &result.bounds;
  in.scan = std::span<const Scan>(&scan, 1);
  if (result.features) in.voxels = {&result.voxels.grid.spec, &*result.features, result.other_features};
  return in;
}

Area area_from_pose(AreaType type, AreaSize size, Reach reach, const glm::vec3& center,
                    const glm::quat& orientation, float width, float height) {
  const glm::quat q = glm::normalize(orientation);
  const glm::vec3 x = q * glm::vec3(1, 0, 0), y = q * glm::vec3(0, 1, 0);
  Area a;
  a.type = type;
  a.size = size;
  a.reach = reach;
  a.center = center;
  a.normal = q * glm::vec3(0, 0, 1);
  a.half_width = 0.5f * width;
  a.half_height = 0.5f * height;
  // Counter-clockwise seen from the front (+Z towards the viewer, X right, Y up).
  a.corners = {center - a.half_width * x - a.half_height * y, center + a.half_width * x - a.half_height * y,
               center + a.half_width * x + a.half_height * y, center - a.half_width * x + a.half_height * y};
  a.flags = category_flags(type, size, reach);
  return a;
}

std::string_view reach_colour(Reach reach) {
  switch (reach) {
    case Reach::Close: return "#d7191c";
    case Reach::Distance: return "#1a9641";
    case Reach::None: break;
  }
  return "#2166ac";
}

std::string_view room_colour(std::size_t room) {
  // Tableau-like hues without pure red, green or blue, which mean reach.
  static constexpr std::string_view kPalette[] = {"#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
                                                  "#bcbd22", "#17becf", "#7f7f7f", "#b8860b"};
  return kPalette[room % std::size(kPalette)];
}

}  // namespace roomsense
