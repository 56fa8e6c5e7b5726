// Placement areas of thesis §3.3-3.5: the search for suitable wall, floor, ceiling and furniture areas
// (Alg. 2, Alg. 3), their reduction (Eq. 3.42-3.53) and their classification (Eq. 3.54-3.59).
#pragma once
#include "roomsense/features.h"
#include "roomsense/grid.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <stop_token>
#include <string_view>
#include <vector>

namespace roomsense {

// The numeric values are those of XrRoomAreaTypeEXTX, XrRoomAreaSizeEXTX and XrRoomInteractionEXTX.
enum class AreaType : std::uint8_t { Wall = 1, Floor = 2, Ceiling = 3, Furniture = 4 };
enum class AreaSize : std::uint8_t { Large = 1, Medium = 2, Small = 3 };
enum class Reach : std::uint8_t { Close = 1, Distance = 2, None = 3 };

inline constexpr std::array<AreaType, 4> kAreaTypes = {AreaType::Wall, AreaType::Floor, AreaType::Ceiling,
                                                       AreaType::Furniture};
inline constexpr std::array<AreaSize, 3> kAreaSizes = {AreaSize::Large, AreaSize::Medium, AreaSize::Small};

// Category bits of Eq. 3.58: exactly one bit of each group (size, interaction, type) is set.
enum CategoryFlag : std::uint32_t {
  kCategoryNone = 0,
  kSizeBig = 1,
  kSizeMedium = 2,
  kSizeSmall = 4,
  kInteractClose = 8,
  kInteractDistance = 16,
  kInteractNo = 32,
  kTypeWall = 64,
  kTypeFloor = 128,
  kTypeFurniture = 256,
  kTypeCeiling = 512,
};
std::uint32_t category_flags(AreaType type, AreaSize size, Reach reach);

// "wall", "floor", "ceiling", "furniture"; "large", "medium", "small"; "close", "distance", "none".
std::string_view to_string(AreaType type);
std::string_view to_string(AreaSize size);
std::string_view to_string(Reach reach);

// The thesis's constants (DESIGN.md's table), in metres unless said otherwise.
struct AreaParams {
  // Wall rectangles, width x height (§3.3.1). The height of a found rectangle is ⌊d·height/width⌋ voxels for
  // a width of d voxels: Eq. 3.20's ⌊d/2⌋ for the large and medium sizes, and the stated 0.3 m (not 0.25 m)
  // for the small one.
  std::array<float, 3> wall_width = {2.0f, 1.0f, 0.5f};
  std::array<float, 3> wall_height = {1.0f, 0.5f, 0.3f};
  std::array<float, 3> square_width = {2.0f, 1.0f, 0.5f};  // floors, ceilings, furniture (§3.3.2-3.3.4)
  float width_tolerance = 0.1f;   // w ± 0.1 m
  float wall_fill = 0.8f;         // Eq. 3.25
  float horizontal_fill = 0.95f;  // Eq. 3.38
  int reduction_offset = 2;       // levels: furniture tops this far apart are separate (Eq. 3.49)
  float close_distance = 0.2f;    // §3.5.1/3.5.2: a floor area this near makes an area "close"
  float close_height = 1.5f;      // §3.5.1: wall areas centred higher above the floor are never "close"
  float wall_view_cone_deg = 60.0f;  // §3.5.1: a floor area at most this far off a wall area's normal
  // Beyond the thesis: packed areas grow along their axes into the free surface around them, so an area is at
  // least its class's size rather than exactly it (issue 14). False keeps the thesis's fixed sizes.
  bool grow = true;
  bool operator==(const AreaParams&) const = default;
};

// Throws Error(BadParameter) naming the first field outside its range: widths and heights in (0, 100] m, each width
// above width_tolerance (in [0, 100] m), fills in [0, 1], reduction_offset in [1, 100], close_distance in
// [0, 100] m, close_height in [-100, 100] m, wall_view_cone_deg in [0, 180]. NaN and Inf are outside every range.
void check_params(const AreaParams& params);

// One classified area (§3.5), in metres, in the scan's frame (right-handed, +Y up).
// Corners go counter-clockwise seen from the front (from free space, looking against the normal):
// corners[0] -> corners[1] is the width (+X of the area's pose), corners[1] -> corners[2] the height (+Y).
// For walls +Y is world up; the normal is +Z = X × Y and points into the room.
// The rotation taking (X, Y, Z) onto three orthonormal axes: an OpenXR pose's orientation. The one conversion of
// a frame into a quaternion (areas and surfaces).
glm::quat orientation_of(const glm::vec3& x_axis, const glm::vec3& y_axis, const glm::vec3& z_axis);

struct Area {
  AreaType type = AreaType::Wall;
  AreaSize size = AreaSize::Large;
  Reach reach = Reach::None;
  std::array<glm::vec3, 4> corners{};
  glm::vec3 center{0.0f};        // Eq. 3.42 / 3.54
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // Eq. 3.55, into free space
  float half_width = 0.0f;       // centre to the right edge (Eq. 3.56)
  float half_height = 0.0f;      // centre to the upper edge (Eq. 3.56)
  float rotation_deg = 0.0f;     // Eq. 3.57, right-handed, about the normal; in [0, 90) for squares, 0 for walls
  float volume_height = 0.0f;    // clear space checked in front of the surface, along the normal
  std::uint32_t flags = 0;       // Eq. 3.58
  std::uint32_t storey = 0;      // beyond the thesis: index into AnalysisResult::storeys (0: the main storey)
  int room = kNoRoom;            // beyond the thesis: index into AnalysisResult::rooms, or kNoRoom

  glm::vec3 x_axis() const;      // unit, along the width
  glm::vec3 y_axis() const;      // unit, along the height
  glm::quat orientation() const; // rotates (X, Y, Z) onto (x_axis, y_axis, normal): the OpenXR pose
};

// How many areas each stage kept, per type (index = int(AreaType) - 1), for reports and tests.
struct AreaCounts {
  std::array<std::size_t, 4> found{};         // valid rectangles of all three sizes, before any reduction
  std::array<std::size_t, 4> deduplicated{};  // after centre deduplication (Eq. 3.42-3.44)
  std::array<std::size_t, 4> reduced{};       // after packing (in place of Eq. 3.45-3.53)
};

struct AreaTimings {  // milliseconds
  // search: until the last search of §3.3 ends, with the reductions (§3.4, growth) that run beside the searches;
  // reduce: the reductions left after it.
  double search = 0, reduce = 0, classify = 0;
};

struct AreaResult {
  std::vector<Area> areas;  // walls, floors, ceilings, furniture; large before medium before small
  AreaCounts counts;
  AreaTimings timings;
  std::vector<std::string> warnings;  // searches skipped for their cost (see kAreaSearchBudget)
};

// The most corner pairs one of the 12 searches may try. The pairs grow with the fourth power of 1 / voxel
// size; at 0.1 m voxels the 20 x 14 m hall needs about 2 % of this. Past it (voxels much finer than the
// thesis's, or a hall of thousands of square metres) that search is skipped with a warning, rather than
// running for minutes.
inline constexpr double kAreaSearchBudget = 1.0e8;

// Where horizontal areas sit, in metres: the measured floor and ceiling surfaces of the main storey.
struct SurfaceLevels {
  float floor_y = 0.0f;
  float ceiling_y = 0.0f;
  // Beyond the thesis (issue 15): per facet of RoomFeatures::facets but the first, its ceiling's plane in metres,
  // y = p.x * x + p.y * z + p.z. Ceiling areas on a facet without one lie at ceiling_y.
  std::vector<glm::vec3> ceiling_planes;
};

// §3.3-3.5 on the features of one grid. The 12 searches run in parallel unless threads == 1; the result
// does not depend on the thread count.
AreaResult find_areas(const VoxelGrid& grid, const RoomFeatures& features, const SurfaceLevels& surfaces,
                      const AreaParams& params, const FeatureParams& feature_params, unsigned threads = 0,
                      std::stop_token stop = {});

}  // namespace roomsense
