#version 450
#extension GL_GOOGLE_include_directive : require
// Eq. 3.6/3.7: the voxel holding each vertex is active (vertex mode, and the vertex voxels of triangle mode).
#include "common.glsl"

void main() {
  const uint i = item_index();
  if (i >= pc.vertex_count) return;
  const vec3 v = vertex_at(i);
  mark_voxel(voxel_index(clamp_index(v.x, pc.nx), clamp_index(v.y, pc.ny), clamp_index(v.z, pc.nz)));
}
