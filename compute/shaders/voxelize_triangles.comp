#version 450
#extension GL_GOOGLE_include_directive : require
// Triangle mode: the cells of a triangle's corners, and every voxel of its bounding box that passes
// triangle_overlaps_voxel. This is a line-by-line port of voxelize_cpu.cpp: the same operations in the same
// order, all `precise` (no fused multiply-add, no reassociation), and Vulkan rounds OpFAdd/OpFSub/OpFMul
// correctly, so every comparison comes out as on the CPU. No division anywhere.
#include "common.glsl"

const float kHalf = 0.5;                      // h: half extent of the test cube [i - eps, i + 1 - eps]
const float kOffset = 0.5 - kEpsilon;         // centre - i, exact in binary

precise float dot3(vec3 a, vec3 b) {
  precise float r = a.x * b.x + a.y * b.y + a.z * b.z;  // left to right, as the CPU
  return r;
}

precise float abs_sum(vec3 a) {
  precise float r = abs(a.x) + abs(a.y) + abs(a.z);
  return r;
}

// True when the projections p0..p2 lie outside [-r, r].
bool separated(float p0, float p1, float p2, float r) {
  const float lo = min(min(p0, p1), p2);
  const float hi = max(max(p0, p1), p2);
  return lo > r || hi < -r;
}

bool axis_separates(vec3 axis, vec3 v0, vec3 v1, vec3 v2) {
  precise float r = kHalf * abs_sum(axis);
  return separated(dot3(axis, v0), dot3(axis, v1), dot3(axis, v2), r);
}

bool triangle_overlaps_voxel(vec3 a, vec3 b, vec3 c, int x, int y, int z) {
  precise vec3 centre = vec3(float(x) + kOffset, float(y) + kOffset, float(z) + kOffset);
  precise vec3 v0 = a - centre;
  precise vec3 v1 = b - centre;
  precise vec3 v2 = c - centre;
  // The box's own axes.
  if (separated(v0.x, v1.x, v2.x, kHalf) || separated(v0.y, v1.y, v2.y, kHalf) || separated(v0.z, v1.z, v2.z, kHalf))
    return false;
  // The nine cross products of box axes and triangle edges, in the CPU's order.
  precise vec3 e0 = v1 - v0;
  precise vec3 e1 = v2 - v1;
  precise vec3 e2 = v0 - v2;
  // Unrolled: no loop counts against lavapipe's per-invocation iteration budget.
  if (axis_separates(vec3(0.0, -e0.z, e0.y), v0, v1, v2)) return false;
  if (axis_separates(vec3(e0.z, 0.0, -e0.x), v0, v1, v2)) return false;
  if (axis_separates(vec3(-e0.y, e0.x, 0.0), v0, v1, v2)) return false;
  if (axis_separates(vec3(0.0, -e1.z, e1.y), v0, v1, v2)) return false;
  if (axis_separates(vec3(e1.z, 0.0, -e1.x), v0, v1, v2)) return false;
  if (axis_separates(vec3(-e1.y, e1.x, 0.0), v0, v1, v2)) return false;
  if (axis_separates(vec3(0.0, -e2.z, e2.y), v0, v1, v2)) return false;
  if (axis_separates(vec3(e2.z, 0.0, -e2.x), v0, v1, v2)) return false;
  if (axis_separates(vec3(-e2.y, e2.x, 0.0), v0, v1, v2)) return false;
  // The triangle's plane.
  precise vec3 n = vec3(e0.y * e1.z - e0.z * e1.y, e0.z * e1.x - e0.x * e1.z, e0.x * e1.y - e0.y * e1.x);
  precise float d = dot3(n, v0);
  precise float r = kHalf * abs_sum(n);
  return !(d > r || d < -r);
}

// Work item (t, chunk): voxels [chunk * kChunkVoxels, (chunk + 1) * kChunkVoxels) of triangle t's bounding
// box, numbered y fastest, then x, then z. Item t < triangles is (t, 0): the first dispatch runs those and
// also sizes the work, adding each box's tests to the 64-bit count in `bits` at pc.info_offset and listing
// the triangles whose boxes pass kChunkVoxels after it. From that list the host writes the further chunks'
// items (triangle_work.h) to `out_words` at pc.work_offset, and a second dispatch runs them (items from
// `triangles` on). So a big triangle is spread over many invocations, no invocation loops more than
// kChunkVoxels times, and the host does no work per triangle. A box of one voxel is marked without a test,
// and so are the corners' cells of any box.
// kChunkVoxels must match triangle_work.h.
const uint kChunkVoxels = 512u;

// The test count is summed per workgroup first: one global atomic per group, not one per triangle on a
// single address.
shared uint group_tests[2];  // low word, high word

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    group_tests[0] = 0u;
    group_tests[1] = 0u;
  }
  barrier();
  // No return before the second barrier: every invocation of the group must reach it.
  const uint item = item_index() + pc.item_base;
  const bool valid = item < pc.work_count;
  const uint triangles = pc.triangle_count;
  uint t = item, chunk = 0u;
  if (valid && item >= triangles) {
    const uint extra = pc.work_offset + 2u * (item - triangles);
    t = out_words[extra];
    chunk = out_words[extra + 1u];
  }
  vec3 a = vec3(0.0), b = vec3(0.0), c = vec3(0.0);
  if (valid) {
    a = vertex_at(indices[3u * t]);
    b = vertex_at(indices[3u * t + 1u]);
    c = vertex_at(indices[3u * t + 2u]);
  }
  const vec3 lo = min(min(a, b), c);
  const vec3 hi = max(max(a, b), c);
  const int x0 = box_index(lo.x, pc.nx), x1 = box_index(hi.x, pc.nx);
  const int y0 = box_index(lo.y, pc.ny), y1 = box_index(hi.y, pc.ny);
  const int z0 = box_index(lo.z, pc.nz), z1 = box_index(hi.z, pc.nz);
  const uint sy = uint(y1 - y0 + 1), sx = uint(x1 - x0 + 1), sz = uint(z1 - z0 + 1);
  const uint volume = valid ? sy * sx * sz : 0u;
  if (chunk == 0u && volume > 1u) {  // the first chunk sizes the box's work
    const uint before = atomicAdd(group_tests[0], volume);
    if (before + volume < before) atomicAdd(group_tests[1], 1u);  // the carry
    if (volume > kChunkVoxels) bits[pc.info_offset + 3u + atomicAdd(bits[pc.info_offset + 2u], 1u)] = t;
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && (group_tests[0] | group_tests[1]) != 0u) {
    const uint low = group_tests[0];
    uint high = group_tests[1];
    const uint before = atomicAdd(bits[pc.info_offset], low);
    if (before + low < before) ++high;  // the carry
    if (high != 0u) atomicAdd(bits[pc.info_offset + 1u], high);
  }
  if (volume == 0u) return;
  if (volume == 1u) {  // inside one test cube: no test needed, as on the CPU
    mark_voxel(voxel_index(x0, y0, z0));
    return;
  }
  // The corners' cells are marked untested, as on the CPU: a corner lies in its cell's test cube.
  const ivec3 ca = ivec3(box_index(a.x, pc.nx), box_index(a.y, pc.ny), box_index(a.z, pc.nz));
  const ivec3 cb = ivec3(box_index(b.x, pc.nx), box_index(b.y, pc.ny), box_index(b.z, pc.nz));
  const ivec3 cc = ivec3(box_index(c.x, pc.nx), box_index(c.y, pc.ny), box_index(c.z, pc.nz));
  const uint end = min(volume, (chunk + 1u) * kChunkVoxels);
  for (uint v = chunk * kChunkVoxels; v < end; ++v) {
    const int y = y0 + int(v % sy);
    const int x = x0 + int((v / sy) % sx);
    const int z = z0 + int(v / (sy * sx));
    const uint index = voxel_index(x, y, z);
    const ivec3 here = ivec3(x, y, z);
    if (!voxel_marked(index) && (here == ca || here == cb || here == cc || triangle_overlaps_voxel(a, b, c, x, y, z)))
      mark_voxel(index);
  }
}
