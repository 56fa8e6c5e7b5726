// Room bounds of thesis §3.6: the bounds volume I (Eq. 3.60-3.62) with its hole filling, and a closed,
// crack-free greedy mesh of it (Eq. 3.63/3.64) whose counter-clockwise front faces face free space.
#pragma once
#include "roomsense/grid.h"
#include "roomsense/voxelize.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace roomsense {

struct BoundsMesh {
  std::vector<glm::vec3> vertices;     // world space, each position once
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from free space
};

// G, H and I (Eq. 3.60-3.62), then the three-plane hole filling of §3.6. One byte per voxel, GridSpec::index.
std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                        const std::vector<std::uint8_t>& room);

// Ours: fills the empty voxels of every 2x2 block around an edge where two solid voxels touch only along
// that edge. Their surface would have an edge shared by four faces; after this, every edge has two.
void fill_edge_contacts(const GridSpec& spec, std::vector<std::uint8_t>& volume);

// Greedy meshing (Eq. 3.63/3.64, after Lysenko 2012) of a volume. Quads of the same orientation merge; each
// quad is then split at the corners of its neighbours that lie on its edges (T-junctions), so the surface
// is closed: every edge belongs to exactly two triangles. The thesis's half-voxel shift is built in: the
// mesh is made on the voxel lattice, where voxel (x,y,z) spans [x, x+1), not on voxel centres.
BoundsMesh greedy_mesh(const GridSpec& spec, const std::vector<std::uint8_t>& volume);

// bounds_volume, fill_edge_contacts and greedy_mesh in order.
BoundsMesh build_bounds(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                        const std::vector<std::uint8_t>& room);

// Edges used by other than exactly two triangles, and edges not used once in each direction (a closed,
// consistently oriented surface has none of either). For tests and for the CLI's report.
struct MeshClosure {
  std::size_t boundary_or_nonmanifold_edges = 0;
  std::size_t misoriented_edges = 0;
  bool closed() const { return boundary_or_nonmanifold_edges == 0 && misoriented_edges == 0; }
};
MeshClosure check_closure(const BoundsMesh& mesh);

}  // namespace roomsense
