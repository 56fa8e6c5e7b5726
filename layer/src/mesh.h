// Meshes on their way into the analysis: rigid transforms (roomsense/xr/rigid.h), content hashes
// (to recognise the same runtime mesh read twice), and the merge of every piece into one core Scan.
#pragma once
#include "roomsense/scan.h"

#include <openxr/openxr.h>

#include "roomsense/xr/rigid.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace roomsense::layer {

using xr::is_valid_pose;
using xr::is_yaw_only;
using xr::Rigid;
using xr::to_rigid;

// One mesh in the analyzer's base space (or, for captures, the session's capture space).
struct MeshPiece {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;  // triangles; empty for a point cloud
};

// Positions moved by `pose` (computed in double; identity poses copy the floats bit for bit).
std::vector<glm::vec3> transformed(const XrVector3f* vertices, std::size_t count, const Rigid& pose);
void transform_in_place(std::vector<glm::vec3>& vertices, const Rigid& pose);

// ContentHash (roomsense/content_hash.h) of the raw vertex and index bytes as the runtime served them (component
// space).
std::uint64_t content_hash(const XrVector3f* vertices, std::size_t vertex_count, const std::uint32_t* indices,
                           std::size_t index_count);

// The same over a mesh already copied (vertices as floats, then indices).
std::uint64_t content_hash(const MeshPiece& mesh);

// Every piece into one scan, in order. Point clouds among triangle meshes become one-point triangles, so
// that their vertices still count; a scan of point clouds only stays a point cloud (vertex mode).
Scan merge(const std::vector<const MeshPiece*>& pieces);

// Appends a chunk's triangles with the runtime's label of each (one per triangle) to `out`, the labels a scan
// carries (Scan::labels). A count that does not match adds nothing.
void add_labelled(LabelledTriangles& out, const MeshPiece& piece, const std::vector<SurfaceLabel>& labels);

}  // namespace roomsense::layer
