// The whole pipeline on one scan: input hygiene, voxel stage, room features, bounds, with stage timings.
#pragma once
#include "roomsense/areas.h"
#include "roomsense/bounds.h"
#include "roomsense/features.h"
#include "roomsense/grid.h"
#include "roomsense/input.h"
#include "roomsense/kept_threads.h"
#include "roomsense/scan.h"
#include "roomsense/voxelize.h"

#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace roomsense {

struct AnalysisOptions {
  float voxel_size = kDefaultVoxelSize;
  std::optional<VoxelMode> mode;  // default: triangles when the scan has indices, else vertices
  std::size_t voxel_budget = kDefaultVoxelBudget;            // voxels of the grid (memory)
  std::uint64_t voxel_test_budget = kDefaultVoxelTestBudget;  // triangle-voxel tests (time)
  bool reject_outliers = true;
  unsigned threads = 0;           // 0: one per hardware thread; results do not depend on it
  FeatureParams features;
  AreaParams areas;
  BoundsParams bounds;
  bool find_areas = true;     // §3.3-3.5; off for a bounds-only run (thesis StartRoomBounds)
  bool build_bounds = true;   // §3.6; off for an areas-only run (thesis StartRoomUnderstanding)
  // Off with find_areas off: the features only the areas and the placement queries read (furniture tops C, free
  // floor D, wall normals F, openings) are not derived and stay empty in the result, whose surfaces then have no
  // furniture tops and whose RoomQueries answer nothing; the bounds, levels, heights and rooms are the same. The
  // thesis API's StartRoomBounds, which returns the bounds alone, runs so. An IncrementalAnalysis derives them all.
  bool area_features = true;
  VoxelStage* voxel_stage = nullptr;  // not owned; nullptr: the CPU stage
  KeptThreads* kept_threads = nullptr;  // not owned; nullptr: threads started for the analysis
  std::stop_token stop;               // a stop request ends analyze() with Error(Cancelled) within ~100 ms
};

enum class AnalysisStatus {
  Ok,
  NoFloorCeiling,  // no two horizontal levels at least min_floor_ceiling apart: no room to analyse
};

// A floor/ceiling pair of the scan (Eq. 3.9/3.10 for the main storey; beyond the thesis, the pairs above and
// below it). Each storey has its own features, areas and bounds.
struct Storey {
  float floor_y = 0.0f;    // metres, the measured surfaces; a pitched roof's ceiling_y is its ridge
  float ceiling_y = 0.0f;
  FloorCeiling levels{};   // voxel levels
  // Beyond the thesis (issue 15): the planes of the facets of its ceiling that slope or step
  // (SurfaceLevels::ceiling_planes), empty where the ceiling is one level.
  std::vector<glm::vec3> ceiling_planes;
};

// Beyond the thesis (issue 15): a room of a storey, its free space bounded by walls and passages at most
// FeatureParams::min_passage wide (RoomFeatures::rooms).
struct Room {
  std::uint32_t storey = 0;   // index into AnalysisResult::storeys
  float floor_area = 0.0f;    // m² of its free columns
  glm::vec3 center{0.0f};     // the centroid of its free columns, on its floor
  float floor_y = 0.0f;       // metres, its storey's
  float ceiling_y = 0.0f;
};

// Milliseconds. The area stages (areas, reduce, classify) and bounds run side by side: total is the analysis's
// own time, less than the stages' sum.
struct StageTimings {
  double prepare = 0, voxelize = 0, features = 0, areas = 0, reduce = 0, classify = 0, bounds = 0, total = 0;
};

struct InputStats {
  std::size_t vertices = 0, triangles = 0;  // as given
  std::size_t skipped_vertices = 0;         // NaN / Inf
  std::size_t outlier_vertices = 0;
  std::size_t dropped_triangles = 0;        // touching a skipped or outlier vertex
};

struct AnalysisResult {
  AnalysisStatus status = AnalysisStatus::Ok;
  std::string status_message;     // one line, for people
  std::vector<std::string> warnings;
  InputStats input;
  VoxelMode mode = VoxelMode::Triangles;
  std::string backend;
  VoxelStageResult voxels;        // V, level and column counts
  std::optional<RoomFeatures> features;  // the main storey's; present when status is Ok
  std::vector<RoomFeatures> other_features;  // storeys[1..]'s, in that order
  float floor_y = 0.0f;           // metres; the scanned floor surface of the main storey
  float ceiling_y = 0.0f;
  std::vector<Storey> storeys;    // main storey first; empty when status is not Ok
  std::vector<Room> rooms;        // storey by storey, each storey's largest first; Area::room indexes it
  // Classified placement areas (§3.5) of every storey, storey by storey (Area::storey); empty unless Ok.
  std::vector<Area> areas;
  AreaCounts area_counts;         // summed over the storeys
  BoundsMesh bounds;              // one closed mesh around every storey's free space
  // Beyond the thesis (issue 15): one closed mesh per room (index as rooms), around its free space and the
  // walls nearest it, closed across its doorways where it meets the next room. With one room, `bounds`.
  std::vector<BoundsMesh> room_bounds;
  StageTimings timings;
  bool ok() const { return status == AnalysisStatus::Ok; }
  // The features of storeys[index]; requires ok() and index < storeys.size().
  const RoomFeatures& storey_features(std::size_t index) const {
    return index == 0 ? *features : other_features.at(index - 1);
  }
};

// What the bounds read of each storey of an ok() result (build_bounds over several storeys).
std::vector<BoundsStorey> bounds_storeys(const AnalysisResult& result);

// Beyond the thesis (issue 15): how far a point may lie from its room's free columns and still be in it (a
// wall's face, the walls around a room's floor), in metres, and in columns of a grid.
inline constexpr float kRoomReach = 0.3f;
int room_reach_columns(const GridSpec& spec);
// The index into result.rooms of storey `storey`'s first room.
int first_room_of(const AnalysisResult& result, std::uint32_t storey);
// The room (an index into result.rooms) of storey `storey` at p's column, or of the nearest column of a room
// within kRoomReach; kNoRoom if none.
int room_at_point(const AnalysisResult& result, std::uint32_t storey, const glm::vec3& p);

// Throws Error for bad input (see input.h and grid.h), Error(TooMuchWork) past voxel_test_budget and
// Error(Cancelled) on a stop request. A scan without a floor/ceiling pair at least
// features.min_floor_ceiling apart is no error: it returns status NoFloorCeiling with the grid and counts
// filled in.
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options = {});

}  // namespace roomsense
