// What one analysis leaves behind for the getters, in the extension's own types, and the files
// ROOMSENSE_EXPORT_DIR asks for.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/queries.h"
#include "roomsense/surfaces.h"

#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace roomsense::layer {

// The JSON's input.file for an analysis made inside an OpenXR app.
inline constexpr const char* kJsonSourceName = "openxr:XR_APILAYER_ROOMSENSE_room_understanding";

// Where the meshes of one analysis came from, for the JSON's "openxr" member and the log.
struct MeshSources {
  std::string source;               // the extension the runtime's meshes came through (empty: none)
  std::string source_reason;        // why that one (or why none)
  double query_ms = 0.0;            // the layer's own query through it
  std::size_t runtime_meshes = 0;   // the layer's own query
  std::size_t app_read_meshes = 0;  // scene meshes the application read (passive capture)
  std::size_t submitted_meshes = 0; // xrSubmitRoomMeshEXTX
  std::string base_space;           // "LOCAL", "STAGE", ...
};

// What only some applications ask of a result, built at the first ask (on the asking thread; concurrent asks wait
// for the one build): the placement queries' index, the JSON and the surfaces the spatial-entity API serves.
// Built at every compute, the first two took most of a compute after an update of thesis-room1: 22.6 ms p50
// through the layer on Magic Leap, 3.4 ms without them (bench/README.md, stop 63); the surfaces some 0.1 ms of
// the 0.57 ms left (stop 94).
class LazyResultParts {
 public:
  LazyResultParts(std::shared_ptr<const AnalysisResult> analysis, MeshSources sources, XrDuration duration)
      : analysis_(std::move(analysis)), sources_(std::move(sources)), duration_(duration) {}
  const std::vector<Surface>& surfaces() const;
  const RoomQueries& queries() const;  // on surfaces(), not extracted again
  const std::string& json() const;

 private:
  std::shared_ptr<const AnalysisResult> analysis_;
  MeshSources sources_;
  XrDuration duration_ = 0;
  mutable std::once_flag surfaces_once_, queries_once_, json_once_;
  mutable std::vector<Surface> surfaces_;
  mutable RoomQueries queries_;
  mutable std::string json_;
};

struct RoomResult {
  float floor_y = 0.0f, ceiling_y = 0.0f;
  std::vector<XrRoomStoreyEXTX> storeys;        // main first
  std::vector<XrRoomInfoEXTX> rooms;
  std::vector<XrRoomAreaEXTX> areas;            // type set, next null
  std::vector<XrRoomAreaLocationEXTX> area_locations;  // one per area; type set, next null
  std::vector<XrVector3f> bounds_vertices;
  std::vector<std::uint32_t> bounds_indices;
  struct Mesh {
    std::vector<XrVector3f> vertices;
    std::vector<std::uint32_t> indices;
  };
  std::vector<Mesh> room_bounds;  // one per room (XrRoomBoundsMeshRoomEXTX)
  XrVector3f bounds_min{0, 0, 0}, bounds_max{0, 0, 0};
  std::uint32_t input_vertices = 0, input_triangles = 0;
  XrDuration duration = 0;
  std::uint64_t input_hash = 0;   // of the meshes and labels analysed (Analyzer::compute)
  std::shared_ptr<const LazyResultParts> lazy;
  // The planes the standard spatial-entity API serves (spatial/).
  const std::vector<Surface>& surfaces() const { return lazy->surfaces(); }
  // Placement queries, raycasts, random points (queries.cpp).
  const RoomQueries& queries() const { return lazy->queries(); }
  // roomsense.analysis/1, with an "openxr" member saying where the meshes came from.
  const std::string& json() const { return lazy->json(); }
};

// The result keeps `analysis` for the parts built at first use (LazyResultParts).
RoomResult make_room_result(std::shared_ptr<const AnalysisResult> analysis, const MeshSources& sources,
                            XrDuration duration);

// Writes analysis.json and bounds.obj into `dir` (created when missing). Failures are logged, never thrown.
void export_files(const std::string& dir, const RoomResult& result, const BoundsMesh& bounds);

const char* space_name(XrReferenceSpaceType type);

}  // namespace roomsense::layer
