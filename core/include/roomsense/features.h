// Room features of thesis §3.2: walls A (Eq. 3.11), room mask B (Eq. 3.12), furniture levels C (Eq. 3.13),
// free floor and ceiling tiles D and E (Eq. 3.14/3.15), wall normals F (Alg. 1).
#pragma once
#include "roomsense/grid.h"
#include "roomsense/labels.h"
#include "roomsense/voxelize.h"

#include <cstdint>
#include <optional>
#include <stop_token>
#include <vector>

namespace roomsense {

// The thesis's constants, in metres (DESIGN.md's table). Converted to voxels with voxels_for().
struct FeatureParams {
  float min_floor_ceiling = 1.5f;  // Eq. 3.9/3.10: floor-ceiling separation
  float wall_fill = 0.5f;          // Eq. 3.11: share of [floor, ceiling] a wall column fills (strictly more)
  float furniture_top = 1.5f;      // Eq. 3.13: I_yEnd, furniture tops up to this height (also free floor)
  float furniture_clear = 1.0f;    // Eq. 3.13: clear space above a furniture top
  float ceiling_clear = 1.0f;      // Eq. 3.15: clear space below a free ceiling tile
  float wall_normal_reach = 1.0f;  // Eq. 3.19: I_Bounds
  // Beyond the thesis (issue 14), what a person accepts in a real room:
  // A wall column reaches the ceiling: its scan ends within this of the ceiling (or of where most walls' scans
  // end, for scans that barely reach the ceiling). A column that ends lower is the side of a free-standing
  // object (a cabinet, a screen, a shelf), not a wall: it is furniture to the later steps.
  float wall_top_gap = 0.25f;
  // Wall openings up to this wide (doors) are closed when telling the room's inside from what the scan saw
  // through them; areas stay inside.
  float max_opening = 1.0f;
  // How far behind the face of a wall its surface may lie (a recess, a voxel's noise) before the wall counts
  // as open there (a window, a hole).
  float wall_recess = 0.12f;
  // Bumps on the floor up to this high are floor (a rug, a floor that crosses a voxel boundary): free floor
  // tiles ignore them and furniture tops lie above them.
  float floor_roughness = 0.1f;
  // Rooms (issue 15): a passage at most this wide between wall columns (a doorway, a narrow corridor) divides
  // a storey's free space into rooms of at least min_room_area (smaller ones join a neighbour).
  float min_passage = 1.2f;
  float min_room_area = 1.5f;
  // Ceilings that are not one level (issue 15): a facet of free ceiling below I_Ceiling (a slope, a soffit's
  // underside) holds areas from this size up; smaller ones (a lamp, a fitting) are no free ceiling.
  float min_ceiling_facet = 1.0f;
};

// Throws Error(BadParameter) naming the first field outside its range: lengths in [0, 100] m (min_floor_ceiling
// above 0), areas in [0, 10⁴] m², wall_fill in [0, 1]. NaN and Inf are outside every range.
void check_params(const FeatureParams& params);

// ⌊metres / S_Voxel⌋, robust to the float error of e.g. 1.5 / 0.1.
int voxels_for(float metres, float voxel_size);

// Bits of F (Eq. 3.17).
enum WallNormalBits : std::uint8_t {
  kNormalLeft = 1,      // (-1, 0, 0)
  kNormalRight = 2,     // (+1, 0, 0)
  kNormalForward = 4,   // (0, 0, +1)
  kNormalBackward = 8,  // (0, 0, -1)
};

inline constexpr int kNoFurniture = -1;
inline constexpr int kNoRoom = -1;
inline constexpr int kNoFacet = -1;

// Beyond the thesis (issue 15): one plane of a ceiling that is not one level (a roof's slope, a soffit's
// underside). Facet 0 is the ceiling at I_Ceiling.
struct CeilingFacet {
  int level = 0;            // the level its squares are searched at: the one below its mean ceiling level
  std::size_t columns = 0;  // its free ceiling tiles
  // Its ceiling levels fitted (least squares): level = slope_x * (x + 0.5) + slope_z * (z + 0.5) + offset.
  float slope_x = 0.0f, slope_z = 0.0f, offset = 0.0f;
};

// Beyond the thesis (issue 15): per column, the room (0 the largest, then by size) or kNoRoom.
struct RoomSplit {
  std::vector<int> room;
  int count = 0;
};

struct RoomFeatures {
  FloorCeiling levels;
  int y_end = 0;                         // I_yEnd = I_Floor + ⌊1.5 / S⌋
  std::vector<std::uint8_t> walls;       // A, per column
  std::vector<std::uint8_t> room;        // B, per column
  // C, D, F and wall_blocked are empty where the analysis skipped them (AnalysisOptions::area_features).
  std::vector<int> furniture;            // C, per column: the level above a furniture top, or kNoFurniture
  std::vector<std::uint8_t> free_floor;  // D, per column
  std::vector<std::uint8_t> free_ceiling;  // E, per column
  std::vector<std::uint8_t> normals;     // F, per voxel (GridSpec::index), WallNormalBits
  // Beyond the thesis:
  std::vector<std::uint8_t> enclosed;    // per column: inside the walls (all 1 where the walls do not close)
  // Per voxel, or empty when there is none: before an opening in the wall behind (a window, a hole, a door
  // gap) or a surface the runtime labels a window, door or screen; no wall area may cover it.
  std::vector<std::uint8_t> wall_blocked;
  RoomSplit rooms;                       // the inside's free columns (not walls) by room
  // Per column, the level of the ceiling above it: the first scanned voxel above the free space the floor
  // reaches (column_ceilings), at most I_Ceiling. I_Ceiling where the ceiling is flat.
  std::vector<int> ceiling;
  std::vector<int> ceiling_facet;        // per column: the facet its free ceiling tile lies on, or kNoFacet
  std::vector<CeilingFacet> facets;      // facet 0: I_Ceiling
};

// Beyond the thesis (issue 15): per column, the ceiling over a wall there: the highest of RoomFeatures::ceiling
// over the column and its 8 neighbours in `room` (B), I_Ceiling where none is. A ceiling counts as lower only
// where it lies `step_levels` or more below I_Ceiling over at least `min_columns` 4-connected columns.
std::vector<int> wall_ceilings(const GridSpec& spec, const FloorCeiling& levels, const std::vector<int>& ceiling,
                               const std::vector<std::uint8_t>& room, int step_levels, std::size_t min_columns);
// Eq. 3.11 against the ceiling over each column (`over_walls`, wall_ceilings) rather than I_Ceiling: a knee
// wall under a roof is a wall though it fills less than half of the room's full height.
std::vector<std::uint8_t> detect_walls(const GridSpec& spec, const std::vector<std::uint32_t>& column_counts,
                                       const FloorCeiling& levels, const std::vector<int>& over_walls, float wall_fill);
std::vector<std::uint8_t> detect_room(const GridSpec& spec, const std::vector<std::uint8_t>& column_any);
// Clears the wall columns whose scan ends more than `gap_levels` below the ceiling over them (`over_walls`), or
// below where most wall columns end: sides of free-standing furniture.
void drop_free_standing(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& over_walls,
                        int gap_levels, std::vector<std::uint8_t>& walls);
// Columns the walls enclose: not reachable from the grid's edge once openings up to `max_opening_voxels` wide
// are closed. All 1 when that leaves less than half of the room inside (walls that do not close).
std::vector<std::uint8_t> detect_enclosed(const GridSpec& spec, const std::vector<std::uint8_t>& walls,
                                          const std::vector<std::uint8_t>& room, int max_opening_voxels);
// With the runtime's labels: the walls, door and window frames it labels, from low in the room to above
// furniture height, close the room too. Enclosed parts
// they cut off (an alcove beyond them, what the scan saw through a door) are outside: only the largest part
// the labels close, and parts at least half its size, stay.
void cut_at_labelled_walls(const GridSpec& spec, const FloorCeiling& levels, int y_end, const LabelGrid& labels,
                           const std::vector<std::uint8_t>& room, std::vector<std::uint8_t>& enclosed);
// B cut to what the walls enclose, with the patches the scan missed inside them (a floor and a ceiling not
// seen); B itself where the walls do not close (`enclosed` all 1).
std::vector<std::uint8_t> room_inside(const GridSpec& spec, const std::vector<std::uint8_t>& room,
                                      const std::vector<std::uint8_t>& enclosed);
// The voxels no wall area may cover (RoomFeatures::wall_blocked); empty when there are none.
std::vector<std::uint8_t> detect_wall_openings(const VoxelGrid& grid, const FloorCeiling& levels,
                                               const std::vector<std::uint8_t>& walls,
                                               const std::vector<std::uint8_t>& room, int recess_voxels,
                                               int max_opening_voxels, const LabelGrid& labels);
// Where the runtime labels furniture: no free floor below it, and furniture tops only on labelled tops.
void apply_furniture_labels(const GridSpec& spec, const FloorCeiling& levels, const LabelGrid& labels,
                            std::vector<std::uint8_t>& free_floor, std::vector<int>& furniture);
// `rough_levels`: levels above I_Floor that still count as floor (FeatureParams::floor_roughness).
// C, D, E and F read each column's ceiling (RoomFeatures::ceiling) where the thesis reads I_Ceiling.
std::vector<int> detect_furniture(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling,
                                  int y_end, const std::vector<std::uint8_t>& walls, int clear_levels, int rough_levels);
// D: beyond the thesis, a column without floor but with scanned surface below it (a stairwell) is not free,
// nor is one whose ceiling is less than `headroom_levels` above the floor (under a roof's eaves).
std::vector<std::uint8_t> detect_free_floor(const VoxelGrid& grid, const FloorCeiling& levels,
                                            const std::vector<int>& ceiling, int y_end,
                                            const std::vector<std::uint8_t>& walls,
                                            const std::vector<std::uint8_t>& room, int rough_levels,
                                            int headroom_levels);
std::vector<std::uint8_t> detect_free_ceiling(const VoxelGrid& grid, const std::vector<int>& ceiling,
                                              int clear_levels, const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room);
std::vector<std::uint8_t> detect_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels,
                                              const std::vector<int>& ceiling, int reach,
                                              const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room,
                                              const std::vector<int>& furniture);

// Beyond the thesis (issue 15): ceilings that are not one level. The free space is flooded (6-connected empty
// voxels of `room`'s columns, from the level above I_Floor up to below `cap`, its parts that rise to the level
// below `cap`: not the inside of a hollow box); a column's ceiling is the level above the highest voxel the
// flood reaches in it, so a soffit, a beam or a roof lowers it and furniture does not (the flood passes over
// it). A column the flood does not reach (a wall) takes the highest ceiling of its four neighbours', else `cap`.
std::vector<int> column_ceilings(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& room,
                                 int cap);
// A ceiling above I_Ceiling: Eq. 3.9/3.10 take a pitched roof's fullest level, part way up its slope. The
// free space is flooded up to `upper` (the next storey's floor, or the grid's top); when at least a quarter of
// the columns it reaches have a ceiling 0.3 m or more above I_Ceiling, and at most 5 % of them reach `upper`
// (the flood did not leak through a hole), I_Ceiling becomes the highest ceiling found. Nothing otherwise.
std::optional<FloorCeiling> raised_ceiling(const VoxelGrid& grid, const FloorCeiling& levels,
                                           const std::vector<std::uint8_t>& room, int upper);
// The facets of E: facet 0 holds the tiles under I_Ceiling; the others are 4-connected tiles under a ceiling
// of one slope (level steps of at most 2 between neighbours, the same direction of slope over 2 columns either
// side), of at least `min_columns` tiles; a level one at least 2 levels below I_Ceiling (a step, not the
// ceiling's unevenness). Tiles on no facet are kNoFacet.
void find_ceiling_facets(const GridSpec& spec, const FloorCeiling& levels, const std::vector<int>& ceiling,
                         const std::vector<std::uint8_t>& free_ceiling, std::size_t min_columns,
                         std::vector<int>& facet_of, std::vector<CeilingFacet>& facets);

// The rooms of a storey: its inside columns that are not walls, split where a passage is at most
// `min_passage` wide. Cores (columns more than half of it from the nearest blocked column) make the rooms;
// every free column joins the core it reaches first; free space without a core is a room of its own. A room
// under `min_room_area` m² joins the neighbour it shares the longest border with, or no room without one.
RoomSplit split_rooms(const GridSpec& spec, const std::vector<std::uint8_t>& inside,
                      const std::vector<std::uint8_t>& walls, float min_passage, float min_room_area);
// The room of column (x, z), or of the nearest column with one within `reach` columns; kNoRoom if none.
int room_at(const GridSpec& spec, const RoomSplit& rooms, int x, int z, int reach);
// Per column of `mask` (e.g. B), its room_at: the room of its free columns, and for the walls and doorway
// columns the room nearest them; kNoRoom off the mask and beyond `reach` of every room.
std::vector<int> rooms_of_mask(const GridSpec& spec, const std::vector<std::uint8_t>& mask, const RoomSplit& rooms,
                               int reach);
// One room's columns of such a map (1), the others 0.
std::vector<std::uint8_t> room_mask(const std::vector<int>& rooms_of, int room);
// room_mask of rooms_of_mask, for one room.
std::vector<std::uint8_t> room_mask(const GridSpec& spec, const std::vector<std::uint8_t>& mask, const RoomSplit& rooms,
                                    int room, int reach);

// All of §3.2 on one storey of a grid: its levels and count_columns over them. C, D and E run in parallel when threads allows; the result does not
// depend on the thread count. A stop request throws Error(Cancelled) between the steps.
// `labels`, when not empty, are the runtime's semantics on the same grid.
RoomFeatures detect_features(const VoxelGrid& grid, const FloorCeiling& levels,
                             const std::vector<std::uint32_t>& column_counts,
                             const std::vector<std::uint8_t>& column_any, const FeatureParams& params,
                             unsigned threads = 0, const std::stop_token& stop = {}, const LabelGrid& labels = {});
// The same on a voxel stage's result that found a floor and a ceiling: its main storey.
RoomFeatures detect_features(const VoxelStageResult& voxels, const FeatureParams& params, unsigned threads = 0,
                             const std::stop_token& stop = {}, const LabelGrid& labels = {});

}  // namespace roomsense
