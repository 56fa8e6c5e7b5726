// Voxelization on the CPU: the reference for every backend (thesis Eq. 3.6/3.7, plus triangle mode).
// This file is compiled with -ffp-contract=off: a fused multiply-add would round differently from the
// Vulkan shaders, which mark their arithmetic `precise`.
#include "voxelize_cpu.h"

#include "../floor_int.h"
#include "../parallel.h"
#include "../vertex_lanes.h"
#include "roomsense/cancel.h"
#include "roomsense/error.h"
#include "roomsense/voxelize.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace roomsense {
namespace {

float dot3(const glm::vec3& a, const glm::vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float abs_sum(const glm::vec3& a) { return std::fabs(a.x) + std::fabs(a.y) + std::fabs(a.z); }

// True when the projections p0..p2 of the triangle on an axis lie outside [-r, r].
bool separated(float p0, float p1, float p2, float r) {
  const float lo = std::min(std::min(p0, p1), p2);
  const float hi = std::max(std::max(p0, p1), p2);
  return lo > r || hi < -r;
}

void mark(std::uint8_t& cell) { std::atomic_ref<std::uint8_t>(cell).store(1, std::memory_order_relaxed); }
bool marked(std::uint8_t& cell) { return std::atomic_ref<std::uint8_t>(cell).load(std::memory_order_relaxed) != 0; }

// The work of triangle mode, counted in triangle-voxel tests: the budget bounds what hostile input costs
// (a few room-sized triangles at a fine voxel need billions of tests), and the stop token is checked
// wherever the count is flushed.
class TestCounter {
 public:
  static constexpr std::uint64_t kFlushEvery = 1 << 14;
  explicit TestCounter(const VoxelizeRequest& r) : budget_(r.test_budget), stop_(r.stop) {}
  std::uint64_t total() const { return total_.load(std::memory_order_relaxed); }
  void flush(std::uint64_t& tests) {
    const std::uint64_t total = total_.fetch_add(tests, std::memory_order_relaxed) + tests;
    tests = 0;
    stop_point(stop_);
    if (total > budget_) throw Error(ErrorCode::TooMuchWork, too_much_work_message(budget_));
  }

 private:
  const std::uint64_t budget_;
  const std::stop_token& stop_;
  std::atomic<std::uint64_t> total_{0};
};

// The voxel whose test cube holds a point, box_index per axis, in lanes 0-2, and in lane 3 the voxel's index in
// the grid (of use where the grid's voxels fit 32 bits). A triangle's box is its corners' lanes compared four at
// a time (GCC's vector extensions), and a corner's voxel is marked without its index computed again.
typedef std::int32_t CornerCell __attribute__((vector_size(16)));
typedef float CornerPoint __attribute__((vector_size(16)));
typedef std::uint32_t CornerIndex __attribute__((vector_size(16)));
// box_index on the lanes at once, as clamp_index does it per axis: 0 below 0 (and for NaN), n - 1 from n - 1
// on, else truncated.
class CornerCellOf {
 public:
  explicit CornerCellOf(const GridSpec& s)
      : s_(s), last_{s.nx - 1, s.ny - 1, s.nz - 1, 0}, last_at_{float(s.nx - 1), float(s.ny - 1), float(s.nz - 1), 0.0f} {
    for (int k = 0; k < 3; ++k)
      for (int lane = 0; lane < 4; ++lane) {
        last_lanes_[k][lane] = last_[detail::lane_axis(k, lane)];
        last_at_lanes_[k][lane] = last_at_[detail::lane_axis(k, lane)];
      }
  }
  CornerCell operator()(const glm::vec3& v) const {
    CornerCell cell = axes(CornerPoint{v.x, v.y, v.z, 0.0f}, last_, last_at_);
    // s.index modulo 2^32: exact where the grid's voxels fit 32 bits.
    const auto u = [&](int lane) { return std::uint32_t(cell[lane]); };
    cell[3] = std::int32_t((u(2) * std::uint32_t(s_.nx) + u(0)) * std::uint32_t(s_.ny) + u(1));
    return cell;
  }
  // operator() of the four vertices from `first`, into out[0..3]: the same operations per float on the vertices'
  // lanes (vertex_lanes.h), the indices four at a time. A scan's corners with SSE4.1 (a multiply of four 32-bit
  // lanes): thesis-room1's 76k, 133 -> 108 us on one thread.
  [[gnu::always_inline]] void four(const glm::vec3* first, CornerCell* out) const {
    // Lanes x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3.
    CornerCell c[3];
    for (int k = 0; k < 3; ++k) c[k] = axes(detail::load_lanes(first, k), last_lanes_[k], last_at_lanes_[k]);
    const CornerCell x01y1 = __builtin_shufflevector(c[0], c[1], 0, 3, 6, 4), y03z = __builtin_shufflevector(c[0], c[1], 1, 4, 7, 2);
    const CornerCell z01 = __builtin_shufflevector(c[0], c[1], 2, 5, 0, 0);
    const CornerIndex x = CornerIndex(__builtin_shufflevector(x01y1, c[2], 0, 1, 2, 5));
    const CornerIndex y = CornerIndex(__builtin_shufflevector(y03z, c[2], 0, 1, 2, 6));
    const CornerIndex z = CornerIndex(__builtin_shufflevector(z01, c[2], 0, 1, 4, 7));
    const CornerCell index = CornerCell((z * std::uint32_t(s_.nx) + x) * std::uint32_t(s_.ny) + y);
    out[0] = __builtin_shufflevector(c[0], index, 0, 1, 2, 4);
    out[1] = __builtin_shufflevector(__builtin_shufflevector(c[0], c[1], 3, 4, 5, 5), index, 0, 1, 2, 5);
    out[2] = __builtin_shufflevector(__builtin_shufflevector(c[1], c[2], 2, 3, 4, 4), index, 0, 1, 2, 6);
    out[3] = __builtin_shufflevector(c[2], index, 1, 2, 3, 7);
  }

 private:
  // box_index on each lane of `v` against the lanes' last cells.
  [[gnu::always_inline]] static CornerCell axes(const CornerPoint& v, const CornerCell& last, const CornerPoint& last_at) {
    const CornerPoint zero{0.0f, 0.0f, 0.0f, 0.0f};
    const CornerPoint at = v + kVoxelTestEpsilon;
    const CornerPoint inside = at >= zero ? at : zero;
    return at >= last_at ? last : __builtin_convertvector(inside < last_at ? inside : last_at, CornerCell);
  }
  const GridSpec& s_;
  const CornerCell last_;
  const CornerPoint last_at_;
  CornerCell last_lanes_[3];  // last_ and last_at_ in the lanes of vertex_lanes.h
  CornerPoint last_at_lanes_[3];
};
CornerCell lowest(const CornerCell& a, const CornerCell& b, const CornerCell& c) {
  const CornerCell ab = a < b ? a : b;
  return ab < c ? ab : c;
}
CornerCell highest(const CornerCell& a, const CornerCell& b, const CornerCell& c) {
  const CornerCell ab = a > b ? a : b;
  return ab > c ? ab : c;
}
// Where a corner lies: lane 3, or its lanes 0-2 where the index does not fit 32 bits.
std::size_t corner_voxel(const CornerCell& c, const GridSpec& s, bool index_fits) {
  return index_fits ? std::size_t(std::uint32_t(c[3])) : s.index(c[0], c[1], c[2]);
}

// How triangle mode visits one triangle: its box, and the axis d along which its columns run. Only the
// voxels near the triangle's plane are tested: along the axis where the normal is largest, each column
// of the other two axes gets the plane's range over the column's square, widened by a voxel each way
// against rounding, so the marked set is exactly that of testing the whole box, and the cost follows the
// surface, not the box. A degenerate triangle has no plane: its whole box is tested, columns along y.
struct TriangleScan {
  int first[3], last[3];
  int d = 1, u = 0, v = 2;
  glm::dvec3 normal{0.0};
  bool one_voxel() const { return first[0] == last[0] && first[1] == last[1] && first[2] == last[2]; }
  std::uint64_t box_volume() const {
    return std::uint64_t(last[0] - first[0] + 1) * std::uint64_t(last[1] - first[1] + 1) *
           std::uint64_t(last[2] - first[2] + 1);
  }
  // A box of at most 2 x 2 x 2 voxels, each tested but its corners' cells: columns of the plane would spare none.
  bool small() const { return last[0] - first[0] < 2 && last[1] - first[1] < 2 && last[2] - first[2] < 2; }
  bool planar() const { return normal[d] != 0.0; }

  // The box alone, from the corners' cells: box_index is monotone, so the box of the corners' cells is the
  // cells of the corners' box.
  TriangleScan(const CornerCell& lo, const CornerCell& hi) : first{lo[0], lo[1], lo[2]}, last{hi[0], hi[1], hi[2]} {}
  // The box and, beyond a few voxels, the plane.
  TriangleScan(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const CornerCell& ca, const CornerCell& cb,
               const CornerCell& cc)
      : TriangleScan(lowest(ca, cb, cc), highest(ca, cb, cc)) {
    if (small()) return;  // no plane needed: most of a fine scan's triangles
    normal = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const glm::dvec3 m = glm::abs(normal);
    if (m.x >= m.y && m.x >= m.z && m.x != 0.0) d = 0;
    else if (m.z > m.y) d = 2;
    u = d == 0 ? 1 : 0;
    v = d == 2 ? 1 : 2;
  }

  // At least the tests scan_triangle does (each column spans the plane's rise over a unit square, plus
  // the margins): summed before the scan, it refuses hopeless input at once.
  std::uint64_t tests_bound() const {
    if (one_voxel()) return 0;
    if (small()) return box_volume();
    const auto extent = [&](int k) { return std::uint64_t(last[k] - first[k] + 1); };
    std::uint64_t span = extent(d);
    if (planar())
      span = std::min<std::uint64_t>(
          span, std::uint64_t(std::ceil((std::fabs(normal[u]) + std::fabs(normal[v])) / std::fabs(normal[d]))) + 3);
    return extent(u) * extent(v) * span;
  }
};

// Marks the cells of the triangle's corners, untested: a corner lies in its cell's test cube, so the triangle
// touches that cube. Shared by some six triangles, a corner's cell is mostly marked already; in a box of two
// voxels both are corners' cells, so most of a fine scan's triangles need no test at all.
inline void mark_corners(const CornerCell& ca, const CornerCell& cb, const CornerCell& cc, const GridSpec& s,
                         bool index_fits, std::uint8_t* voxels) {
  const auto mark_cell = [&](const CornerCell& c) {
    if (std::uint8_t& voxel = voxels[corner_voxel(c, s, index_fits)]; !marked(voxel)) mark(voxel);
  };
  mark_cell(ca), mark_cell(cb), mark_cell(cc);
}

// Marks each voxel of a box of a few whose test cube the triangle touches, testing each not yet marked (its
// corners' cells are, by mark_corners).
inline void test_small_box(const TriangleScan& scan, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                           const GridSpec& s, std::uint8_t* voxels, std::uint64_t& tests) {
  for (int z = scan.first[2]; z <= scan.last[2]; ++z)
    for (int x = scan.first[0]; x <= scan.last[0]; ++x)
      for (int y = scan.first[1]; y <= scan.last[1]; ++y) {
        std::uint8_t& voxel = voxels[s.index(x, y, z)];
        if (!marked(voxel) && triangle_overlaps_voxel(a, b, c, x, y, z)) mark(voxel);
      }
  tests += scan.box_volume();
}

// test_small_box for a box two voxels wide along two axes and one along the third (`extent` 1, 1 and 0 in some
// order; `lo` its first voxel): its four voxels from the first by strides, without the loops over three axes.
// Most of a room's triangles that need a test have such a box.
[[gnu::always_inline]] inline void test_box_of_four(const CornerCell& lo, const CornerCell& extent, const glm::vec3& a,
                                                   const glm::vec3& b, const glm::vec3& c, const GridSpec& s,
                                                   std::uint8_t* voxels, std::uint64_t& tests) {
  const int u = extent[0] != 0 ? 0 : 1, v = extent[2] != 0 ? 2 : 1;  // the two axes two voxels wide
  const std::size_t stride[3] = {std::size_t(s.ny), 1, std::size_t(s.nx) * std::size_t(s.ny)};  // GridSpec::index's
  std::uint8_t* const first = voxels + s.index(lo[0], lo[1], lo[2]);
  const std::size_t step[4] = {0, stride[u], stride[v], stride[u] + stride[v]};
  for (int k = 0; k < 4; ++k) {
    std::uint8_t& voxel = first[step[k]];
    if (marked(voxel)) continue;  // nearly always: the corners' cells, or a neighbour triangle's
    int cell[3] = {lo[0], lo[1], lo[2]};
    cell[u] += k & 1, cell[v] += k >> 1;
    if (triangle_overlaps_voxel(a, b, c, cell[0], cell[1], cell[2])) mark(voxel);
  }
  tests += 4;
}

// Marks every voxel of a box larger than small() whose test cube the triangle touches (see TriangleScan).
void scan_triangle(const TriangleScan& scan, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                   const GridSpec& s, std::uint8_t* voxels, std::uint64_t& tests, TestCounter& counter) {
  const int(&first)[3] = scan.first;
  const int(&last)[3] = scan.last;
  const int d = scan.d, u = scan.u, v = scan.v;
  // The plane as d = a[d] - su (u - a[u]) - sv (v - a[v]): over a column's unit square its extremes are at the
  // corners, base + min/max(0, -su) + min/max(0, -sv). One division per triangle, not four per column.
  const double su = scan.planar() ? scan.normal[u] / scan.normal[d] : 0.0;
  const double sv = scan.planar() ? scan.normal[v] / scan.normal[d] : 0.0;
  const double rise_lo = std::min(0.0, -su) + std::min(0.0, -sv), rise_hi = std::max(0.0, -su) + std::max(0.0, -sv);
  int cell[3];
  for (cell[v] = first[v]; cell[v] <= last[v]; ++cell[v]) {
    const double along_v = sv * (cell[v] - double(kVoxelTestEpsilon) - a[v]);
    for (cell[u] = first[u]; cell[u] <= last[u]; ++cell[u]) {
      int from = first[d], to = last[d];
      if (scan.planar()) {
        // The plane's d over the square [i - eps, i + 1 - eps] of this column.
        const double base = a[d] - su * (cell[u] - double(kVoxelTestEpsilon) - a[u]) - along_v;
        const double d_lo = base + rise_lo, d_hi = base + rise_hi;
        // from = max(from, floor(lo) - 1), to = min(to, floor(hi) + 1), without libm's floor; a bound past
        // the box's far side empties the column as the plain formula would. The voxel of margin each way
        // also covers the rounding of d_lo and d_hi: the triangle-box test decides.
        const double lo = d_lo + double(kVoxelTestEpsilon), hi = d_hi + double(kVoxelTestEpsilon);
        if (lo >= double(last[d]) + 2.0) from = last[d] + 1;
        else if (lo >= double(from) + 1.0) from = detail::floor_int(lo) - 1;
        if (hi < double(first[d]) - 2.0) to = first[d] - 1;
        else if (hi < double(to) - 1.0) to = detail::floor_int(hi) + 1;
      }
      for (cell[d] = from; cell[d] <= to; ++cell[d]) {
        std::uint8_t& voxel = voxels[s.index(cell[0], cell[1], cell[2])];
        if (!marked(voxel) && triangle_overlaps_voxel(a, b, c, cell[0], cell[1], cell[2])) mark(voxel);
      }
      if (to >= from) tests += std::uint64_t(to - from + 1);
      if (tests >= TestCounter::kFlushEvery) counter.flush(tests);
    }
  }
}

// A copy of the loops for SSE4.1 (voxelize_cpu.h), where x86's baseline lacks it and GCC or Clang build: a loop's
// body is inlined (always_inline) into a function compiled for SSE4.1, which the CPU's check chooses. Only code
// inlined into that function uses SSE4.1; every function it calls stays baseline code, so nothing another caller
// shares can fault on an older CPU.
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__SSE4_1__)
#define ROOMSENSE_VOXEL_SSE41_COPY 1
#define ROOMSENSE_INLINE_BODY __attribute__((always_inline))
#else
#define ROOMSENSE_VOXEL_SSE41_COPY 0
#define ROOMSENSE_INLINE_BODY
#endif

// loop(body), `loop` taking a body of slices (detail::parallel_for or parallel_for_apart over it), the body built for
// SSE4.1 where `sse41`.
template <class Body, class Loop>
void run_loop_on([[maybe_unused]] bool sse41, const Body& body, const Loop& loop) {
#if ROOMSENSE_VOXEL_SSE41_COPY
  if (sse41) {
    loop([&](std::size_t begin, std::size_t end, std::size_t slice) __attribute__((target("sse4.1"))) {
      body(begin, end, slice);
    });
    return;
  }
#endif
  loop(body);
}

// A pass over a scan's vertices in the workers' own parts (parallel_for_apart), the same parts for every such pass:
// to_grid_units_into's and the corner cells' (and the input checks' before them), so that each worker reads the
// vertices it wrote (a pass over another worker's output ran some 20 % slower on this project's 2-core VM).
template <class Body>
void each_vertex_part(std::size_t vertices, unsigned threads, Body&& body) {
  detail::parallel_for_apart(vertices, threads, detail::parallel_slices(vertices, threads, 1 << 14), body);
}

}  // namespace

bool detail::voxel_sse41_copy() {
#if ROOMSENSE_VOXEL_SSE41_COPY
  return __builtin_cpu_supports("sse4.1");
#else
  return false;
#endif
}

std::vector<glm::vec3> to_grid_units(std::span<const glm::vec3> world, const GridSpec& spec, unsigned threads) {
  std::vector<glm::vec3> out(world.size());
  detail::to_grid_units_into(world, spec, threads, out.data());
  return out;
}

void detail::to_grid_units_into(std::span<const glm::vec3> world, const GridSpec& spec, unsigned threads, glm::vec3* out) {
  const auto one = [&](std::size_t i) { out[i] = (world[i] - spec.origin) / spec.voxel_size; };
  // Whole fours of vertices at a time (vertex_lanes.h), the same subtraction and division per float; the slices'
  // other vertices one at a time.
  const detail::VertexLanes origin[3] = {detail::repeat_lanes(spec.origin, 0), detail::repeat_lanes(spec.origin, 1),
                                         detail::repeat_lanes(spec.origin, 2)};
  each_vertex_part(world.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    const std::size_t first = std::min(end, (begin + 3) / 4 * 4), last = std::max(first, end / 4 * 4);
    for (std::size_t i = begin; i < first; ++i) one(i);
    for (std::size_t i = first; i < last; i += 4)
      for (int k = 0; k < 3; ++k)
        detail::store_lanes(out + i, k, (detail::load_lanes(world.data() + i, k) - origin[k]) / spec.voxel_size);
    for (std::size_t i = last; i < end; ++i) one(i);
  });
}


std::string too_much_work_message(std::uint64_t budget) {
  return "voxelization needs more than " + std::to_string(budget) +
         " triangle-voxel tests (large triangles at a small voxel size): use a larger voxel size";
}

bool triangle_overlaps_voxel(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int x, int y, int z) {
  constexpr float h = 0.5f;                         // half extent of [i - eps, i + 1 - eps]
  constexpr float offset = 0.5f - kVoxelTestEpsilon;  // centre - i, exact in binary
  const glm::vec3 centre(float(x) + offset, float(y) + offset, float(z) + offset);
  const glm::vec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // The box's own axes.
  if (separated(v0.x, v1.x, v2.x, h) || separated(v0.y, v1.y, v2.y, h) || separated(v0.z, v1.z, v2.z, h))
    return false;
  // The nine cross products of box axes and triangle edges.
  const glm::vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  for (const glm::vec3& e : edges) {
    const glm::vec3 axes[3] = {glm::vec3(0.0f, -e.z, e.y), glm::vec3(e.z, 0.0f, -e.x), glm::vec3(-e.y, e.x, 0.0f)};
    for (const glm::vec3& axis : axes)
      if (separated(dot3(axis, v0), dot3(axis, v1), dot3(axis, v2), h * abs_sum(axis))) return false;
  }
  // The triangle's plane.
  const glm::vec3& e0 = edges[0];
  const glm::vec3& e1 = edges[1];
  const glm::vec3 n(e0.y * e1.z - e0.z * e1.y, e0.z * e1.x - e0.x * e1.z, e0.x * e1.y - e0.y * e1.x);
  const float d = dot3(n, v0);
  const float r = h * abs_sum(n);
  return !(d > r || d < -r);
}

VoxelGrid voxelize_cpu(const VoxelizeRequest& request, unsigned threads, std::uint64_t* tests_done) {
  VoxelGrid grid(request.spec);
  voxelize_cpu_into(request, grid, threads, tests_done);
  return grid;
}

void voxelize_cpu_into(const VoxelizeRequest& request, VoxelGrid& grid, unsigned threads, std::uint64_t* tests_done) {
  detail::voxelize_cpu_into(request, grid, threads, tests_done, detail::VoxelInstructions::Best);
}

void detail::voxelize_cpu_into(const VoxelizeRequest& request, VoxelGrid& grid, unsigned threads,
                               std::uint64_t* tests_done, VoxelInstructions instructions) {
  const bool sse41 = instructions == VoxelInstructions::Best && voxel_sse41_copy();
  if (!(grid.spec.nx == request.spec.nx && grid.spec.ny == request.spec.ny && grid.spec.nz == request.spec.nz) ||
      grid.cells.size() != request.spec.voxel_count())
    throw Error(ErrorCode::BadParameter, "voxelize_cpu_into: the grid is not the request's");
  const GridSpec& s = request.spec;
  const auto& p = request.grid_vertices;
  // The workers mark bytes side by side with relaxed atomics; through the vector, GCC would load its data
  // pointer again at every mark.
  std::uint8_t* const voxels = grid.cells.data();
  const auto voxel_of = [&](const glm::vec3& v) -> std::uint8_t& {
    return voxels[s.index(clamp_index(v.x, s.nx), clamp_index(v.y, s.ny), clamp_index(v.z, s.nz))];
  };
  if (request.mode == VoxelMode::Vertices) {  // Eq. 3.6
    detail::parallel_for(p.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t i = begin; i < end; ++i) {
        if ((i & 0xffff) == 0) stop_point(request.stop);
        mark(voxel_of(p[i]));
      }
    });
    return;
  }
  // Triangle mode marks the voxels whose test cubes the triangles touch, and nothing else: a vertex no
  // triangle uses adds nothing, as it has no surface.
  const std::size_t triangles = request.indices.size() / 3;
  // A whole scan's corners are its vertices, each shared by some six triangles: their cells are found once
  // each, and most triangles then cost three lookups, a box of vector minima and maxima, and their corners'
  // marks. A few triangles of a large scan (a chunk re-sent) find their corners' cells as they go.
  const CornerCellOf corner_cell(s);
  std::unique_ptr<CornerCell[]> cells;  // not zeroed first: every one is written
  if (request.indices.size() >= 2 * p.size()) {
    cells = std::make_unique_for_overwrite<CornerCell[]>(p.size());
    const auto cells_of = [&](std::size_t begin, std::size_t end, std::size_t) ROOMSENSE_INLINE_BODY {
      std::size_t i = begin;
      for (; i + 4 <= end; i += 4) {
        if ((i & 0xfffc) == 0) stop_point(request.stop);
        corner_cell.four(p.data() + i, cells.get() + i);
      }
      for (; i < end; ++i) cells[i] = corner_cell(p[i]);
    };
    // The small triangles below take their parts alike (their corners mostly their own part's vertices): each
    // reads the cells it wrote.
    run_loop_on(sse41, cells_of, [&](const auto& body) { each_vertex_part(p.size(), threads, body); });
  }
  // The table's pointer held by value: through the unique_ptr, the marks' atomics would have GCC load it again
  // at every triangle.
  const CornerCell* const cell_table = cells.get();
  const auto cell_of = [cell_table, &corner_cell, &p](std::uint32_t i) { return cell_table ? cell_table[i] : corner_cell(p[i]); };
  const bool index_fits = s.voxel_count() <= std::numeric_limits<std::uint32_t>::max();
  // One pass over the triangles does those whose box has at most 2 x 2 x 2 voxels: most of a room's, their
  // corners' cells marked and the other voxels tested, at most 6 tests each. The others wait in a list, with
  // their boxes summed. Hopeless input is then refused before any of them is scanned: where their boxes (at most
  // the tests a scan does) could exceed the budget, the sum of TriangleScan's lower bounds decides, a room's few
  // large triangles each costing a plane in double.
  TestCounter counter(request);
  // Slices of some 5,000 triangles of a room's scan (most of the stage's time), each worker in its own part of the
  // scan: the workers' last slices end at most one of them apart.
  constexpr std::size_t kSmallSlicesPerThread = 16;
  const std::size_t slices = detail::parallel_slices(triangles, threads, 1 << 12, kSmallSlicesPerThread);
  std::vector<std::vector<std::size_t>> large(slices);
  std::vector<std::uint64_t> small_boxes(slices, 0), large_boxes(slices, 0);  // box voxels: one-voxel ones count 1
  const auto corners_of = [indices = request.indices.data()](std::size_t t) {
    const std::uint32_t* corner = indices + 3 * t;
    return std::array<std::uint32_t, 3>{corner[0], corner[1], corner[2]};
  };
  // The pass below made once per way of finding a corner's cell (`corner_of`, the table's or the corner's own), not
  // a branch between the two at each of a triangle's three corners.
  const auto small_triangles_by = [&](auto corner_of) {
    return [&, corner_of](std::size_t begin, std::size_t end, std::size_t slice) ROOMSENSE_INLINE_BODY {
      std::uint64_t tests = 0, boxes = 0, large_box = 0;
      std::vector<std::size_t> own_large;  // moved to large[slice] at the end: the slices' vectors share cache lines
      // The count flushed before each run of kFlushTriangles triangles (at most 8 tests each: kFlushEvery), not
      // more often: the shared count's atomic add moves its cache line between the workers, and every 256 cost
      // thesis-room1's pass 3 %. By runs, not a test at every triangle.
      constexpr std::size_t kFlushTriangles = TestCounter::kFlushEvery / 8;
      for (std::size_t run = begin; run < end; run += kFlushTriangles) {
        counter.flush(tests);
        for (std::size_t t = run, run_end = std::min(end, run + kFlushTriangles); t < run_end; ++t) {
          const auto [i, j, k] = corners_of(t);
          const CornerCell ca = corner_of(i), cb = corner_of(j), cc = corner_of(k);
          const CornerCell lo = lowest(ca, cb, cc), hi = highest(ca, cb, cc), extent = hi - lo;
          if ((extent[0] | extent[1] | extent[2]) < 2) {  // TriangleScan::small
            mark_corners(ca, cb, cc, s, index_fits, voxels);
            const int axes = extent[0] + extent[1] + extent[2];  // of two voxels; the box holds 2^axes
            // The work counted stays a box's voxels (but one voxel's): the budget does not depend on what was
            // marked.
            if (axes == 2) test_box_of_four(lo, extent, p[i], p[j], p[k], s, voxels, tests);
            else if (axes > 2) test_small_box(TriangleScan(lo, hi), p[i], p[j], p[k], s, voxels, tests);
            else if (axes == 1) tests += 2;
            boxes += std::uint64_t{1} << axes;
          } else {
            own_large.push_back(t);
            large_box += TriangleScan(lo, hi).box_volume();
          }
        }
      }
      counter.flush(tests);
      small_boxes[slice] = boxes, large_boxes[slice] = large_box, large[slice] = std::move(own_large);
    };
  };
  const auto small_triangles = [&](const auto& body) {
    run_loop_on(sse41, body, [&](const auto& b) { detail::parallel_for_apart(triangles, threads, slices, b); });
  };
  if (cell_table) small_triangles(small_triangles_by([cell_table](std::uint32_t i) { return cell_table[i]; }));
  else small_triangles(small_triangles_by([&corner_cell, &p](std::uint32_t i) { return corner_cell(p[i]); }));
  std::vector<std::size_t> listed;
  for (std::vector<std::size_t>& part : large) listed.insert(listed.end(), part.begin(), part.end()), part = {};
  const auto sum = [](const std::vector<std::uint64_t>& v) { return std::accumulate(v.begin(), v.end(), std::uint64_t{0}); };
  const auto scan_of = [&](std::size_t t) {
    const auto [i, j, k] = corners_of(t);
    return TriangleScan(p[i], p[j], p[k], cell_of(i), cell_of(j), cell_of(k));
  };
  if (sum(small_boxes) + sum(large_boxes) > request.test_budget) {
    // A one-voxel triangle's lower bound is 0 and a small box's its volume: together the tests counted above.
    std::atomic<std::uint64_t> bound{counter.total()};
    detail::parallel_for(listed.size(), threads, 1 << 12, [&](std::size_t begin, std::size_t end, std::size_t) {
      std::uint64_t part = 0;
      for (std::size_t n = begin; n < end; ++n) {
        part += scan_of(listed[n]).tests_bound();
        if ((n & 0xffff) == 0) stop_point(request.stop);
      }
      bound.fetch_add(part, std::memory_order_relaxed);
    });
    if (bound.load() > request.test_budget) throw Error(ErrorCode::TooMuchWork, too_much_work_message(request.test_budget));
  }
  // The large triangles, shared by the workers from 128 of them on (each may take many tests).
  detail::parallel_for(listed.size(), threads, 64, [&](std::size_t begin, std::size_t end, std::size_t) {
    std::uint64_t tests = 0;
    for (std::size_t n = begin; n < end; ++n) {
      const auto [i, j, k] = corners_of(listed[n]);
      mark_corners(cell_of(i), cell_of(j), cell_of(k), s, index_fits, voxels);
      scan_triangle(scan_of(listed[n]), p[i], p[j], p[k], s, voxels, tests, counter);
      if (tests >= TestCounter::kFlushEvery || (n & 0xff) == 0) counter.flush(tests);
    }
    counter.flush(tests);
  });
  if (tests_done != nullptr) *tests_done = counter.total();
}

std::vector<std::uint32_t> count_levels(const VoxelGrid& grid, unsigned threads) {
  const GridSpec& s = grid.spec;
  return detail::counts_by_slices(s.column_count(), threads, detail::kColumnGrain, std::size_t(s.ny),
                                  [&](std::size_t begin, std::size_t end, std::vector<std::uint32_t>& counts) {
    for (std::size_t col = begin; col < end; ++col) {
      const std::uint8_t* cells = grid.cells.data() + col * std::size_t(s.ny);
      for (int y = 0; y < s.ny; ++y) counts[std::size_t(y)] += cells[y];
    }
  });
}

std::optional<FloorCeiling> select_floor_ceiling(std::span<const std::uint32_t> counts, int min_separation) {
  min_separation = std::max(1, min_separation);  // a floor is never its own ceiling
  const auto argmax = [&](auto&& allowed) {
    int best = -1;
    for (int y = 0; y < int(counts.size()); ++y)
      if (counts[std::size_t(y)] > 0 && allowed(y) && (best < 0 || counts[std::size_t(y)] > counts[std::size_t(best)]))
        best = y;
    return best;
  };
  const int first = argmax([](int) { return true; });
  if (first < 0) return std::nullopt;
  const int second = argmax([&](int y) { return std::abs(y - first) >= min_separation; });
  if (second < 0) return std::nullopt;
  FloorCeiling fc;
  fc.floor_peak = fc.floor = std::min(first, second);
  fc.ceiling_peak = fc.ceiling = std::max(first, second);
  const auto in_band = [&](int y, int peak) {
    return kSurfaceBandDivisor * counts[std::size_t(y)] >= counts[std::size_t(peak)];
  };
  // A band never reaches the other surface: I_Floor < I_Ceiling stays true.
  if (fc.floor + 1 < fc.ceiling && in_band(fc.floor + 1, fc.floor_peak)) ++fc.floor;
  if (fc.ceiling - 1 > fc.floor && in_band(fc.ceiling - 1, fc.ceiling_peak)) --fc.ceiling;
  return fc;
}

void count_columns(const VoxelGrid& grid, const std::optional<FloorCeiling>& levels,
                   std::vector<std::uint32_t>& column_counts, std::vector<std::uint8_t>& column_any, unsigned threads) {
  const GridSpec& s = grid.spec;
  column_counts.assign(s.column_count(), 0);
  column_any.assign(s.column_count(), 0);
  if (!levels) return;
  detail::parallel_for(s.column_count(), threads, detail::kColumnGrain, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t col = begin; col < end; ++col) {
      column_counts[col] = count_column(grid, col, *levels);
      column_any[col] = column_counts[col] > 0 ? 1 : 0;
    }
  });
}

std::uint32_t count_column(const VoxelGrid& grid, std::size_t column, const FloorCeiling& levels) {
  const std::uint8_t* cells = grid.cells.data() + column * std::size_t(grid.spec.ny);
  std::uint32_t n = 0;
  for (int y = levels.floor; y <= levels.ceiling; ++y) n += cells[y];
  return n;
}

void detail::count_columns_again(const VoxelGrid& grid, const FloorCeiling& levels, std::span<const std::uint8_t> which,
                                 std::vector<std::uint32_t>& counts, std::vector<std::uint8_t>& any) {
  for (std::size_t col = 0; col < which.size(); ++col)
    if (which[col]) counts[col] = count_column(grid, col, levels), any[col] = counts[col] > 0 ? 1 : 0;
}

VoxelStageResult CpuVoxelStage::run(const VoxelizeRequest& request) {
  VoxelStageResult r;
  const detail::StagePool pool(threads_);
  r.grid = voxelize_cpu(request, threads_, &r.voxel_tests);
  r.level_counts = count_levels(r.grid, threads_);
  r.levels = select_floor_ceiling(r.level_counts, request.min_separation_levels);
  count_columns(r.grid, r.levels, r.column_counts, r.column_any, threads_);
  return r;
}

}  // namespace roomsense
