// Synthetic rooms with known ground truth: floor, ceiling, walls (at any angle), furniture boxes, tables with
// open space below, window openings, scan holes and noise, and walls of a few large triangles. Tests check
// every pipeline stage against the truth kept here; the CLI serves them as built-in rooms (synthetic:NAME).
#pragma once
#include "roomsense/scan.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace roomsense::synth {

// A solid box standing on the floor, e.g. a cabinet or a sofa. Footprint centre (x, z), size, yaw (radians).
struct Box {
  glm::vec2 centre{0.0f};
  glm::vec2 size{0.5f};
  float height = 0.5f;
  float yaw = 0.0f;
};

// A table: a thin top at `height` on four legs, open below.
struct Table {
  glm::vec2 centre{0.0f};
  glm::vec2 size{1.2f, 0.8f};
  float height = 0.75f;
  float yaw = 0.0f;
};

// A window opening in wall `wall` (the edge from outline[wall] to outline[wall + 1]); u runs along the wall
// from its start, in metres; y is the height above the floor.
struct Window {
  int wall = 0;
  float u0 = 1.0f, u1 = 2.0f;
  float y0 = 0.9f, y1 = 2.0f;
};

// A patch the scanner missed: triangles whose centroid lies within `radius` of `centre` are left out.
struct Hole {
  glm::vec3 centre{0.0f};
  float radius = 0.3f;
};

// An axis-aligned rectangle in (x, z), e.g. a stairwell cut out of a floor and the ceiling below it.
struct Rect {
  glm::vec2 lo{0.0f}, hi{0.0f};
};

// A straight stair of treads and risers, open below, rising from the storey's floor by `rise` in `steps`
// equal risers; the last riser ends at the next floor's edge, so the stair has steps - 1 treads.
struct Stair {
  glm::vec2 start{0.0f};  // the foot of the first riser, the middle of its width, (x, z)
  float yaw = 0.0f;       // the way up: +X turned by yaw about +Y (towards +Z for a positive yaw)
  float width = 1.0f;
  float tread = 0.26f;
  float rise = 2.75f;
  int steps = 15;
};

// A doorway in a partition: from u0 to u1 metres along it from its start, from the floor up to `height`.
struct Doorway {
  float u0 = 1.0f, u1 = 1.9f;
  float height = 2.0f;
};

// An interior wall from the floor to the ceiling along a -> b, `thickness` thick, both faces scanned.
struct Partition {
  glm::vec2 a{0.0f}, b{1.0f, 0.0f};
  float thickness = 0.1f;
  std::vector<Doorway> doorways;
};

// A pitched roof as the ceiling: it rises from `eave_y` at two opposite sides of the outline's bounding box
// to RoomSpec::ceiling_y at a ridge along its middle, running along x (or z). The walls end at the roof.
struct Pitch {
  float eave_y = 1.2f;
  bool ridge_along_x = true;
};

struct RoomSpec {
  std::string name = "room";
  std::vector<glm::vec2> outline;  // convex floor polygon in (x, z), counter-clockwise seen from above (+Y)
  float floor_y = 0.0f;
  float ceiling_y = 2.6f;
  std::vector<Box> boxes;
  std::vector<Table> tables;
  std::vector<Window> windows;
  std::vector<Hole> holes;
  std::vector<Rect> floor_openings;    // cut out of the floor (only where cell > 0)
  std::vector<Rect> ceiling_openings;  // cut out of the ceiling (only where cell > 0)
  std::vector<Stair> stairs;
  std::vector<Partition> partitions;   // interior walls dividing it into rooms
  std::optional<Pitch> pitch;          // a pitched ceiling instead of a flat one (needs cell > 0)
  std::vector<Box> hanging;            // soffits and beams: boxes whose top is the ceiling, `height` deep
  float cell = 0.05f;    // triangle size; 0: every planar piece is two large triangles
  float noise = 0.0f;    // standard deviation of the vertex jitter, metres
  std::uint32_t seed = 1;
};

// Storeys stacked in one scan, bottom to top, each a room of its own (its name, noise and seed are the
// house's); stairs and the stairwells they rise through are in the storeys' specs.
struct HouseSpec {
  std::string name = "house";
  std::vector<RoomSpec> storeys;
};

// A rectangular outline of width (x) by depth (z), centred at the origin, turned by yaw radians.
std::vector<glm::vec2> rectangle(float width, float depth, float yaw = 0.0f);

Scan generate(const RoomSpec& spec);
Scan generate(const HouseSpec& spec);
// The footprint of a stair in (x, z), counter-clockwise seen from above.
std::vector<glm::vec2> stair_footprint(const Stair& stair);

// Ground-truth queries.
bool inside_outline(const RoomSpec& spec, glm::vec2 p);
float distance_to_walls(const RoomSpec& spec, glm::vec2 p);  // the outline's and the partitions' (doorways too)
// The furniture (box or table top) whose footprint covers p: its top height above floor_y, if any.
std::optional<float> furniture_top_at(const RoomSpec& spec, glm::vec2 p);
// Distance from p to the nearest furniture footprint edge (0 inside one).
float distance_to_furniture(const RoomSpec& spec, glm::vec2 p);
// The height (y) of the ceiling's surface above p: the roof of a pitched ceiling, the underside of a soffit
// or beam, else ceiling_y.
float ceiling_at(const RoomSpec& spec, glm::vec2 p);

// Built-in rooms.
RoomSpec default_room();                 // 5 x 4 m, table, sofa, cabinet, window, light noise
RoomSpec large_triangle_room();          // the thesis's failing room 4: walls and floor of a few big triangles
RoomSpec rotated_room(float yaw_degrees);  // default_room turned about +Y: walls off the axes
RoomSpec pentagon_room();                // walls at five different angles
RoomSpec hall_room(float width = 20.0f, float depth = 14.0f);  // a large hall with furniture rows
RoomSpec thesis_room1();                 // about 78k vertices, the size of the thesis's room 1
// A 9 x 6 m flat of three rooms: a living room (x < 0.5), a bedroom (x > 0.5, z < 0) and a bathroom
// (x > 0.5, z > 0), joined by 0.9 m doorways in 0.1 m partitions.
RoomSpec three_room_flat();
// The rectangles (x, z) of three_room_flat's rooms inside their walls, largest first.
std::vector<Rect> three_room_flat_rooms();
// Ceilings that are not flat (issue 15): a 6 x 5 m loft under a roof pitched from 1.2 m eaves to a 3.2 m ridge
// along x; a 5 x 4 m room whose ceiling steps down 0.35 m over a 1.2 m soffit along one wall; a 5 x 4 m room
// crossed by a 0.25 m wide, 0.3 m deep beam.
RoomSpec pitched_loft();
RoomSpec soffit_room();
RoomSpec beam_room();
std::optional<RoomSpec> builtin(const std::string& name);
std::vector<std::string> builtin_names();
// Built-in buildings of several storeys.
HouseSpec two_storey_house();            // 7 x 5 m, two storeys 0.25 m of slab apart, a stair between them
std::optional<HouseSpec> builtin_house(const std::string& name);
std::vector<std::string> builtin_house_names();

// "synthetic:NAME", the way the CLI and the simulated runtime name a built-in room in place of a file.
inline constexpr const char* kSourcePrefix = "synthetic:";
bool is_builtin_source(const std::string& source);
// The room or house a "synthetic:NAME" source names. Throws Error(BadParameter), listing the names, for an unknown one.
Scan generate_builtin_source(const std::string& source);

}  // namespace roomsense::synth
