// Room bounds of thesis §3.6: the bounds volume I (Eq. 3.60-3.62) with its hole filling, and a closed,
// crack-free mesh of it (Eq. 3.63/3.64) whose counter-clockwise front faces face free space.
#pragma once
#include "roomsense/grid.h"
#include "roomsense/voxelize.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <stop_token>
#include <vector>

namespace roomsense {

struct BoundsMesh {
  std::vector<glm::vec3> vertices;     // world space, each position once
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from free space
};

struct BoundsParams {
  // Ours, not the thesis's: a plateau of G or H (neighbouring columns of one height) smaller than this, in
  // m², takes its neighbours' height before I is built. It removes voxel-sized jitter and specks that scans
  // leave on furniture tops and ceilings, which would each add a ring of corners to the mesh; a real object
  // at least this large keeps its shape. 0 turns it off (the thesis's volume).
  float min_plateau_area = 0.04f;
};

// G and H (Eq. 3.60/3.61) with their small plateaus flattened (BoundsParams), I (Eq. 3.62), then the
// three-plane hole filling of §3.6. One byte per voxel, GridSpec::index.
std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                        const std::vector<std::uint8_t>& room, const BoundsParams& params = {},
                                        unsigned threads = 0, const std::stop_token& stop = {});

// Ours: fills the empty voxels of every 2x2 block around an edge where two solid voxels touch only along
// that edge. Their surface would have an edge shared by four faces; after this, every edge has two. The same
// voxels on any number of threads (0: one per core; by default one, as before the parameter existed).
void fill_edge_contacts(const GridSpec& spec, std::vector<std::uint8_t>& volume, unsigned threads = 1);

// Meshing of a volume (Eq. 3.63/3.64). The thesis merges each slice's faces of one orientation into greedy
// rectangles (after Lysenko 2012); we merge them further, into whole regions, each a polygon with holes,
// triangulated with no vertex but the surface's corners, including the corners of neighbouring regions
// that lie on its border (T-junctions). So the surface is closed, every edge belonging to exactly two
// triangles, with the fewest vertices any closed mesh of the volume can have. The thesis's half-voxel shift
// is built in: the mesh is made on the voxel lattice, where voxel (x,y,z) spans [x, x+1), not on centres.
// `threads`: as AnalysisOptions::threads; the mesh does not depend on it.
BoundsMesh mesh_volume(const GridSpec& spec, const std::vector<std::uint8_t>& volume, unsigned threads = 0,
                       std::stop_token stop = {});

// bounds_volume, fill_edge_contacts and mesh_volume in order.
BoundsMesh build_bounds(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                        const std::vector<std::uint8_t>& room, const BoundsParams& params = {},
                        unsigned threads = 0, std::stop_token stop = {});

// What bounds_volume reads of one storey.
struct BoundsStorey {
  FloorCeiling levels;
  int y_end = 0;
  const std::vector<std::uint8_t>* room = nullptr;  // B of the storey; not owned
  // Beyond the thesis (issue 15): RoomFeatures::ceiling, each column's own ceiling, below which the free space
  // ends (a roof's slope, a soffit); not owned. Null: I_Ceiling everywhere.
  const std::vector<int>* ceiling = nullptr;
};
// Beyond the thesis: the union of the storeys' bounds volumes. Storeys lie in disjoint levels, so each keeps
// its own shell unless their volumes touch.
std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, std::span<const BoundsStorey> storeys,
                                        const BoundsParams& params = {}, unsigned threads = 0,
                                        const std::stop_token& stop = {});
// That union, fill_edge_contacts and mesh_volume: one closed mesh, as apps get one bounds mesh.
BoundsMesh build_bounds(const VoxelGrid& grid, std::span<const BoundsStorey> storeys, const BoundsParams& params = {},
                        unsigned threads = 0, std::stop_token stop = {});

// Beyond the thesis (issue 15): the bounds volume of one room of a storey. The storey's volume built over
// `room_columns` (the room's part of its B) and, on the rest of its B (the other rooms), solid from floor to
// ceiling: the room's shell closes across its doorways where the next room begins.
std::vector<std::uint8_t> room_bounds_volume(const VoxelGrid& grid, const BoundsStorey& storey,
                                             const std::vector<std::uint8_t>& room_columns,
                                             const BoundsParams& params = {}, unsigned threads = 0,
                                             const std::stop_token& stop = {});
// That volume, fill_edge_contacts and mesh_volume, on the room's columns and two more around them: where the
// free space leaves the room past them (through a window), the shell closes there rather than at the grid's edge.
BoundsMesh build_room_bounds(const VoxelGrid& grid, const BoundsStorey& storey,
                             const std::vector<std::uint8_t>& room_columns, const BoundsParams& params = {},
                             unsigned threads = 0, std::stop_token stop = {});

// Edges used by other than exactly two triangles, and edges not used once in each direction (a closed,
// consistently oriented surface has none of either). For tests and for the CLI's report.
struct MeshClosure {
  std::size_t boundary_or_nonmanifold_edges = 0;
  std::size_t misoriented_edges = 0;
  bool closed() const { return boundary_or_nonmanifold_edges == 0 && misoriented_edges == 0; }
};
MeshClosure check_closure(const BoundsMesh& mesh);

}  // namespace roomsense
