// Names and category bits (Eq. 3.58) of area types, sizes and reach, and the pose axes of an area.
#include "roomsense/areas.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace roomsense {

std::uint32_t category_flags(AreaType type, AreaSize size, Reach reach) {
  constexpr std::uint32_t kSize[] = {kSizeBig, kSizeMedium, kSizeSmall};
  constexpr std::uint32_t kReach[] = {kInteractClose, kInteractDistance, kInteractNo};
  constexpr std::uint32_t kType[] = {kTypeWall, kTypeFloor, kTypeCeiling, kTypeFurniture};
  return kSize[int(size) - 1] | kReach[int(reach) - 1] | kType[int(type) - 1];
}

std::string_view to_string(AreaType type) {
  constexpr std::string_view kNames[] = {"wall", "floor", "ceiling", "furniture"};
  return kNames[int(type) - 1];
}

std::string_view to_string(AreaSize size) {
  constexpr std::string_view kNames[] = {"large", "medium", "small"};
  return kNames[int(size) - 1];
}

std::string_view to_string(Reach reach) {
  constexpr std::string_view kNames[] = {"close", "distance", "none"};
  return kNames[int(reach) - 1];
}

glm::vec3 Area::x_axis() const { return glm::normalize(corners[1] - corners[0]); }
glm::vec3 Area::y_axis() const { return glm::normalize(corners[2] - corners[1]); }

glm::quat orientation_of(const glm::vec3& x_axis, const glm::vec3& y_axis, const glm::vec3& z_axis) {
  // The columns of a rotation matrix are the images of the unit axes.
  return glm::normalize(glm::quat_cast(glm::mat3(x_axis, y_axis, z_axis)));
}

glm::quat Area::orientation() const { return orientation_of(x_axis(), y_axis(), normal); }

}  // namespace roomsense
