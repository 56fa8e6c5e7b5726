// Placement queries on a finished analysis: where an object of a given size can go, random points on the
// room's surfaces and in its free space, whether a point is inside the room, and where a ray hits the room.
// What app developers ask their scene SDKs (Meta's MRUK answers some of it: spawn positions, random surface
// points, raycasts, "is the position in the room"), answered from the analysis's voxel features rather than
// from the three fixed area sizes of the thesis (§3.3).
//
// A RoomQueries is built once per analysis (a few milliseconds: one pass over the grid) and then answers
// each query in microseconds. It is immutable: copies share it, and any number of threads may query one.
// Every answer is deterministic for a given query and seed.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/surfaces.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roomsense {

// Surfaces a query may use, one bit per AreaType (surface_bit): walls, free floor, free ceiling and furniture tops.
enum SurfaceBits : std::uint32_t {
  kOnWall = 1u << 0,
  kOnFloor = 1u << 1,
  kOnCeiling = 1u << 2,
  kOnFurniture = 1u << 3,
  kOnAnySurface = kOnWall | kOnFloor | kOnCeiling | kOnFurniture,
};
constexpr std::uint32_t surface_bit(AreaType type) { return 1u << (std::uint32_t(type) - 1u); }

// Which reach a placement must have; values as Reach (0: any).
enum class ReachFilter : std::uint8_t { Any = 0, Close = 1, Distance = 2 };

// The limits a query's lengths must keep (metres): finite, non-negative, at most this.
inline constexpr float kMaxQueryLength = 100.0f;
inline constexpr std::uint32_t kMaxPlacements = 1024;

// An object to place, as a box in the frame of the pose a placement returns (the areas' convention): x (width)
// and y (depth) span its footprint on the surface, z is its height along the surface's normal. On a wall, x runs
// along the wall, y up it, and z is how far the object stands out of it.
struct PlacementQuery {
  glm::vec3 size{0.3f};
  std::uint32_t surfaces = kOnAnySurface;  // SurfaceBits
  // The clear box: the footprint grown by `clearance` on every side, and size.z + clearance_above along the
  // normal, holds no voxel of the scan and stays inside the room (on a furniture top it may reach past the top's
  // edge into free air; elsewhere it stays on free surface of the same kind).
  float clearance = 0.0f;
  float clearance_above = 0.0f;
  float edge_distance = 0.0f;  // the footprint stays this far inside the free surface's edge
  ReachFilter reach = ReachFilter::Any;
  // Reach is judged from here: close is within user_reach of it horizontally. Without it, close means within
  // AreaParams::close_distance (0.2 m) of free floor a person can stand on, as the thesis's areas (§3.5.1).
  // Either way close needs the placement's centre at most AreaParams::close_height (1.5 m) above the floor.
  std::optional<glm::vec3> user_position;
  float user_reach = 0.7f;
  std::optional<glm::vec3> near;  // best first means nearest this point; otherwise the most free space around
  // Non-zero: on horizontal surfaces the footprint's +Y points along its horizontal part; walls facing it are
  // preferred. Zero: footprints follow the room's walls where they fit, else turn in steps of 15°.
  glm::vec3 face_direction{0.0f};
  std::uint32_t max_count = 1;  // at most kMaxPlacements
  bool allow_overlap = false;   // false: no two placements' clear boxes overlap
  std::uint64_t seed = 0;       // breaks ties between equally good spots
};

// Why a query found fewer placements than max_count. Never an error: the room lacks what was asked.
enum class PlacementShortfall : std::uint8_t {
  None = 0,
  NoSurface = 1,   // the room has no free surface of the asked kinds (no analysis, or none found)
  NoSpace = 2,     // no spot of them holds the footprint with its clearance and edge distance
  NoHeadroom = 3,  // spots hold the footprint, but not the object's height and the clearance above it
  NoReach = 4,     // spots fit, none with the asked reach
  TooFew = 5,      // some found, but not max_count without overlapping
};
std::string_view to_string(PlacementShortfall shortfall);  // "none", "no_surface", ...

struct Placement {
  AreaType surface = AreaType::Floor;
  Reach reach = Reach::None;
  std::uint32_t storey = 0;
  glm::vec3 center{0.0f};              // the footprint's centre, on the surface
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // +Z, into free space
  glm::vec3 x_axis{1.0f, 0.0f, 0.0f};  // +X, the footprint's width; on walls horizontal
  glm::vec2 footprint{0.0f};           // the query's size.x, size.y
  float height = 0.0f;                 // the query's size.z: the object's box stands this far along the normal
  float margin = 0.0f;  // free surface beyond the footprint, its clearance and edge distance (metres, capped)

  glm::vec3 y_axis() const;        // normal × x_axis: on walls up
  glm::quat orientation() const;   // rotates (X, Y, Z) onto (x_axis, y_axis, normal): the OpenXR pose
  std::array<glm::vec3, 4> corners() const;  // counter-clockwise seen from the front, as Area::corners
};

struct PlacementResult {
  std::vector<Placement> placements;  // best first
  PlacementShortfall shortfall = PlacementShortfall::None;
  std::string reason;  // one line for people when shortfall is not None
};

struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  AreaType surface = AreaType::Floor;
};

struct RoomLocation {
  bool inside = false;   // within the room's walls, between its floor and its ceiling
  bool free = false;     // inside, and in no voxel of the scan
  std::uint32_t storey = 0;
};

struct RayHit {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // unit, against the ray
  float distance = 0.0f;   // along the unit direction
  AreaType surface = AreaType::Wall;
  // False where the ray left the room where the scan has no surface (a hole, an open door): the hit is on the
  // room's bounds there. A point a ray hits is a scanned surface's voxel or the room's edge, within a voxel.
  bool scanned = true;
};

class RoomQueries {
 public:
  RoomQueries() = default;  // no room: every query finds nothing
  // From an analysis; one that is not ok() gives an empty RoomQueries. The second form reuses surfaces already
  // extracted from it (extract_surfaces), which wall placements follow.
  explicit RoomQueries(const AnalysisResult& analysis);
  RoomQueries(const AnalysisResult& analysis, const std::vector<Surface>& surfaces);

  bool empty() const { return index_ == nullptr; }

  // Throws Error(BadParameter) for a query whose lengths are not finite, negative or past kMaxQueryLength, whose
  // size is not positive, whose max_count is 0 or past kMaxPlacements, or whose surfaces bits are none or unknown.
  PlacementResult find_placements(const PlacementQuery& query) const;

  // A point on free surface of the asked kinds, at least edge_distance inside its edge; uniform over their area.
  // None when there is no such surface. Throws Error(BadParameter) as find_placements does.
  std::optional<SurfacePoint> random_point_on_surface(std::uint32_t surfaces, float edge_distance,
                                                      std::uint64_t seed) const;
  // A point inside the room with no voxel of the scan and no room edge within `clearance`.
  std::optional<glm::vec3> random_point_in_room(float clearance, std::uint64_t seed) const;

  RoomLocation locate(const glm::vec3& point) const;
  bool is_inside_room(const glm::vec3& point) const { return locate(point).inside; }

  // The first scanned voxel or room edge along the ray, from its origin (inside or outside the room) up to
  // max_distance. Throws Error(BadParameter) for a non-finite origin or a zero or non-finite direction.
  std::optional<RayHit> raycast(const glm::vec3& origin, const glm::vec3& direction,
                                float max_distance = std::numeric_limits<float>::infinity()) const;

  struct Index;  // core/src/queries/room_index.h

 private:
  std::shared_ptr<const Index> index_;
};

}  // namespace roomsense
