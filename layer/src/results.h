// What one analysis leaves behind for the getters, in the extension's own types, and the files
// ROOMSENSE_EXPORT_DIR asks for.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/queries.h"
#include "roomsense/surfaces.h"

#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

namespace roomsense::layer {

// The JSON's input.file for an analysis made inside an OpenXR app.
inline constexpr const char* kJsonSourceName = "openxr:XR_APILAYER_ROOMSENSE_room_understanding";

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
  std::vector<Surface> surfaces;  // the planes the standard spatial-entity API serves (spatial/)
  RoomQueries queries;            // placement queries, raycasts, random points (queries.cpp)
  std::uint64_t input_hash = 0;   // of the meshes and labels analysed (Analyzer::compute)
  std::string json;  // roomsense.analysis/1, with an "openxr" member saying where the meshes came from
};

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

// A stop request throws Error(Cancelled) (the surfaces are extracted here).
RoomResult make_room_result(const AnalysisResult& analysis, const MeshSources& sources, XrDuration duration,
                            const std::stop_token& stop = {});

// Writes analysis.json and bounds.obj into `dir` (created when missing). Failures are logged, never thrown.
void export_files(const std::string& dir, const RoomResult& result, const BoundsMesh& bounds);

const char* space_name(XrReferenceSpaceType type);

}  // namespace roomsense::layer
