// Shared by every voxel-stage shader: one descriptor set, one push-constant block, one pipeline layout.
//
// GPU grid encoding: V is bit-packed while it is built (binding 2, one bit per voxel, bit i of the grid in
// word i / 32 at bit i % 32, i = GridSpec::index), because GLSL has atomicOr on 32-bit words but no byte
// atomics. expand_grid.comp then writes the byte grid that the caller gets (binding 3, region `grid`).

#define LOCAL_SIZE 64
layout(local_size_x = LOCAL_SIZE) in;

layout(std430, set = 0, binding = 0) readonly buffer Vertices { float vertex_coords[]; };  // x,y,z per vertex, grid units
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };  // 3 per triangle
// V, bit-packed; from info_offset the triangle pass's sizing: its test count (2 words, low first), the number
// of big boxes, and their triangles.
layout(std430, set = 0, binding = 2) coherent buffer Bits { uint bits[]; };
// The results, one buffer: [grid bytes | level counts | levels | column counts | column any bytes], each
// region starting at a word offset given below; from work_offset the triangle pass's extra items
// (triangle, chunk), 2 words each, written by the host.
layout(std430, set = 0, binding = 3) buffer Out { uint out_words[]; };

layout(push_constant) uniform Params {
  int nx, ny, nz;
  uint vertex_count;
  uint work_count;     // triangle pass: the end of this dispatch's items
  uint work_offset;    // word offset of the extra items in `out_words`
  uint voxel_count;
  uint column_count;
  int min_separation;
  uint grid_offset;    // word offsets into out_words
  uint levels_offset;  // level counts |V_y|, ny words
  uint select_offset;  // 5 words: found, floor, ceiling, floor_peak, ceiling_peak
  uint columns_offset; // |V_xz|, column_count words
  uint any_offset;     // column_any, one byte per column, packed 4 per word
  uint item_base;      // triangle pass: the first item of this dispatch
  uint triangle_count; // triangle pass: items below it are the triangles' first chunks
  uint info_offset;    // word offset of the triangle pass's sizing in `bits`
} pc;

// One work item per invocation, over a 2D dispatch (65535 groups per dimension is the guaranteed limit).
// No shader loops over items: lavapipe (llvmpipe) silently stops any invocation after 65535 loop
// iterations in total, so every loop here is bounded well below that (see compute/README.md).
uint item_index() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}

uint voxel_index(int x, int y, int z) { return (uint(z) * uint(pc.nx) + uint(x)) * uint(pc.ny) + uint(y); }

void mark_voxel(uint index) { atomicOr(bits[index >> 5], 1u << (index & 31u)); }
bool voxel_marked(uint index) { return (bits[index >> 5] & (1u << (index & 31u))) != 0u; }

// Mirrors clamp_index of voxelize_cpu.cpp (Eq. 3.6): floor is exact, and so are the comparisons.
int clamp_index(float v, int n) {
  precise float f = floor(v);
  if (!(f >= 0.0)) return 0;
  if (f >= float(n - 1)) return n - 1;
  return int(f);
}

vec3 vertex_at(uint i) { return vec3(vertex_coords[3u * i], vertex_coords[3u * i + 1u], vertex_coords[3u * i + 2u]); }

// Mirrors box_index of voxelize_cpu.cpp: the voxel whose test cube [i - eps, i + 1 - eps] holds v.
const float kEpsilon = 1.0 / 1024.0;  // kVoxelTestEpsilon
int box_index(float v, int n) {
  precise float shifted = v + kEpsilon;
  return clamp_index(shifted, n);
}
