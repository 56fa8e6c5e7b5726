// Meshing of a voxel volume (Eq. 3.63/3.64) into a closed surface. Where the thesis covers each slice's
// mask with greedy rectangles, we take each connected region of equal faces whole, as one polygon with
// holes, and triangulate it with its own corners only. Every vertex is then a true corner of the volume's
// surface: the fewest a closed triangulation of the same surface can have, and a closed triangle mesh has
// about twice as many triangles as vertices.
#include "roomsense/bounds.h"
#include "roomsense/cancel.h"

#include "column_levels.h"
#include "../grid/changed_columns.h"
#include "key_table.h"
#include "mesh_memo.h"
#include "parallel.h"
#include "polygon_triangulation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <optional>
#include <span>
#include <unordered_map>

namespace roomsense {
namespace {

// Lattice points in integer coordinates: every comparison is exact.
struct Point {
  int v[3];
  bool operator==(const Point& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};

// The thesis's lexicographic order per plane: (a, b) = (X, Y) for slices along Z, (Y, Z) along X, (Z, X)
// along Y. In each, e_a x e_b = +e_c, so a loop counter-clockwise in (a, b) is counter-clockwise seen
// from +c.
struct Axes {
  int c, a, b;
};
constexpr Axes kAxes[] = {{2, 0, 1}, {0, 1, 2}, {1, 2, 0}};

using Box = detail::SolidBox;
using detail::solid_box;

// Whether a lattice point is a corner of some face region, from the 8 voxels around it (bit dx | dy << 1 |
// dz << 2 for voxel (x-1+dx, y-1+dy, z-1+dz)). In each of the three planes through the point, the four
// faces around it carry Eq. 3.63's mask with its orientation (+1, -1 or none); a region of one value turns
// at the point when it holds one or three of the four faces, or two diagonal ones.
constexpr std::array<bool, 256> make_corner_table() {
  std::array<bool, 256> table{};
  for (int pattern = 0; pattern < 256; ++pattern)
    for (const Axes& ax : kAxes) {
      int mask[2][2] = {};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          int below[3] = {}, above[3] = {};
          below[ax.a] = above[ax.a] = i;
          below[ax.b] = above[ax.b] = j;
          above[ax.c] = 1;
          const auto bit = [&](const int* d) { return (pattern >> (d[0] | d[1] << 1 | d[2] << 2)) & 1; };
          mask[i][j] = bit(below) - bit(above);
        }
      for (const int value : {1, -1}) {
        const bool m00 = mask[0][0] == value, m01 = mask[0][1] == value, m10 = mask[1][0] == value,
                   m11 = mask[1][1] == value;
        const int count = int(m00) + int(m01) + int(m10) + int(m11);
        if (count == 1 || count == 3 || (count == 2 && m00 == m11)) table[std::size_t(pattern)] = true;
      }
    }
  return table;
}
constexpr std::array<bool, 256> kCornerTable = make_corner_table();

// The corners of the whole surface, one bit per lattice point of the solid box. A face region's polygon
// takes every corner on its border: its own turns and the T-junctions where its neighbours turn, so the
// two sides of every crease are split at the same points.
class SurfaceCorners {
  // The 4 voxels of one level (bit k for column k = dz * 2 + dx) as the table's bits dx | dz << 2.
  static constexpr std::array<int, 16> kSpread = [] {
    std::array<int, 16> spread{};
    for (int bits = 0; bits < 16; ++bits)
      for (int k = 0; k < 4; ++k)
        if (bits >> k & 1) spread[std::size_t(bits)] |= 1 << ((k & 1) | (k >> 1) << 2);
    return spread;
  }();
  // A point between two levels of the same four voxels is no corner: every face around it continues straight on.
  static_assert([] {
    for (std::size_t level = 0; level < 16; ++level)
      if (kCornerTable[std::size_t(kSpread[level] | kSpread[level] << 2)]) return false;
    return true;
  }());

 public:
  // Every lattice column of the box.
  SurfaceCorners(const GridSpec& s, const std::vector<std::uint8_t>& volume, const Box& box, unsigned threads,
                 const std::stop_token& stop) {
    for (int k = 0; k < 3; ++k) {
      lo_[k] = box.lo[k];
      n_[k] = box.hi[k] - box.lo[k] + 2;
    }
    // Each z layer starts on a word, so workers on different layers never share one.
    layer_words_ = (std::size_t(n_[0]) * std::size_t(n_[1]) + 63) / 64;
    bits_.assign(layer_words_ * std::size_t(n_[2]), 0);
    const std::vector<std::uint8_t> empty(std::size_t(s.ny), 0);
    detail::parallel_for(std::size_t(n_[2]), threads, 16, [&](std::size_t z_begin, std::size_t z_end, std::size_t) {
      for (int z = lo_[2] + int(z_begin); z < lo_[2] + int(z_end); ++z, stop_point(stop))
        for (int x = lo_[0]; x < lo_[0] + n_[0]; ++x) find_column(s, volume, empty, x, z);
    });
  }
  // The corners of the same box over a volume that differs from `previous`'s only in the voxel columns
  // `changed` (GridSpec::column): a point's corner bit reads the 8 voxels around it, so only the lattice
  // columns beside a changed voxel column are found again.
  SurfaceCorners(const GridSpec& s, const std::vector<std::uint8_t>& volume, SurfaceCorners previous,
                 std::span<const std::size_t> changed)
      : SurfaceCorners(std::move(previous)) {
    const std::vector<std::uint8_t> empty(std::size_t(s.ny), 0);
    const std::size_t lattice_columns = std::size_t(n_[0]) * std::size_t(n_[2]);
    std::vector<std::uint8_t> again(lattice_columns, 0);
    for (const std::size_t column : changed) {
      const int cx = int(column % std::size_t(s.nx)), cz = int(column / std::size_t(s.nx));
      for (int z = cz; z <= cz + 1; ++z)
        for (int x = cx; x <= cx + 1; ++x)
          if (x >= lo_[0] && z >= lo_[2] && x < lo_[0] + n_[0] && z < lo_[2] + n_[2])
            again[std::size_t(z - lo_[2]) * std::size_t(n_[0]) + std::size_t(x - lo_[0])] = 1;
    }
    for (int z = lo_[2]; z < lo_[2] + n_[2]; ++z)
      for (int x = lo_[0]; x < lo_[0] + n_[0]; ++x)
        if (again[std::size_t(z - lo_[2]) * std::size_t(n_[0]) + std::size_t(x - lo_[0])]) {
          const std::size_t first = bit(x, lo_[1], z);
          for (std::size_t i = first; i < first + std::size_t(n_[1]); ++i) bits_[i / 64] &= ~(std::uint64_t{1} << (i % 64));
          find_column(s, volume, empty, x, z);
        }
  }
  bool contains(const Point& p) const {
    for (int k = 0; k < 3; ++k)
      if (p.v[k] < lo_[k] || p.v[k] >= lo_[k] + n_[k]) return false;
    const std::size_t i = bit(p.v[0], p.v[1], p.v[2]);
    return (bits_[i / 64] >> (i % 64)) & 1;
  }

 private:
  // Sets the corner bits of lattice column (x, z), all clear before.
  void find_column(const GridSpec& s, const std::vector<std::uint8_t>& volume, const std::vector<std::uint8_t>& empty,
                   int x, int z) {
    const auto column = [&](int cx, int cz) {
      return cx >= 0 && cz >= 0 && cx < s.nx && cz < s.nz ? volume.data() + s.column(cx, cz) * std::size_t(s.ny)
                                                          : empty.data();
    };
    const int y_first = lo_[1], y_last = lo_[1] + n_[1] - 1;  // lattice levels; voxel levels y-1 and y
    const std::ptrdiff_t read_from = std::max(y_first - 1, 0), read_to = std::min(y_last, s.ny - 1) + 1;
    const std::uint8_t* cols[4] = {column(x - 1, z - 1), column(x, z - 1), column(x - 1, z), column(x, z)};
    // Four equal columns turn nowhere: each level's four voxels are alike, so every plane through a
    // point sees four equal faces or none.
    const auto same = [&](const std::uint8_t* a, const std::uint8_t* b) {
      return a == b || std::equal(a + read_from, a + read_to, b + read_from);
    };
    if (same(cols[0], cols[1]) && same(cols[0], cols[2]) && same(cols[0], cols[3])) return;
    // The four voxels of level y - 1 (bits dy = 0), carried up from the previous level.
    const auto level = [&](int y) {
      int bits = 0;
      if (y >= 0 && y < s.ny)
        for (int k = 0; k < 4; ++k) bits |= int(cols[k][y] != 0) << k;
      return bits;
    };
    int below = level(y_first - 1);
    for (int y = y_first; y <= y_last; ++y) {
      // A level whose four voxels are those of the level below turns nowhere (kCornerTable): skipped, eight at a
      // time where they lie in the grid, up to the first that differs.
      if (y >= 1 && y + 8 <= s.ny && y + 7 <= y_last) {
        std::uint64_t differ = 0;
        for (const std::uint8_t* col : cols) differ |= detail::eight_levels(col, y) ^ detail::eight_levels(col, y - 1);
        if (differ == 0) {
          y += 7;
          continue;
        }
        y += std::countr_zero(differ) / 8;
      }
      const int above = level(y);
      if (kCornerTable[std::size_t(kSpread[std::size_t(below)] | kSpread[std::size_t(above)] << 2)]) {
        const std::size_t i = bit(x, y, z);
        bits_[i / 64] |= std::uint64_t{1} << (i % 64);
      }
      below = above;
    }
  }
  std::size_t bit(int x, int y, int z) const {
    return std::size_t(z - lo_[2]) * layer_words_ * 64 + std::size_t(x - lo_[0]) * std::size_t(n_[1]) +
           std::size_t(y - lo_[1]);
  }
  int lo_[3], n_[3];
  std::size_t layer_words_ = 0;
  std::vector<std::uint64_t> bits_;
};

// One slice's share of an axis's MeshBuilder: the points it added, in order, and its triangles over them. Every
// point of a slice lies in the slice's plane, so no other slice of the axis has it: a slice adds each of its
// points, and its triangles use those alone.
struct SliceRecord {
  std::vector<Point> points;
  std::vector<std::uint32_t> triangles;  // into `points`
};

// One axis's triangles over its own numbering of the points; the axes are merged in order at the end.
class MeshBuilder {
 public:
  // Begins a slice: no point of an earlier slice lies in its plane. Returns where it begins, for since().
  std::pair<std::size_t, std::size_t> begin_slice() const { return {points_.size(), indices_.size()}; }
  SliceRecord since(std::pair<std::size_t, std::size_t> mark) const {
    SliceRecord r{{points_.begin() + std::ptrdiff_t(mark.first), points_.end()}, {}};
    for (std::size_t i = mark.second; i < indices_.size(); ++i) r.triangles.push_back(indices_[i] - std::uint32_t(mark.first));
    return r;
  }
  // Adds a slice as meshing it added it (its points are new to the builder, and no later slice looks them up).
  void replay(const SliceRecord& r) {
    const auto first = std::uint32_t(points_.size());
    points_.insert(points_.end(), r.points.begin(), r.points.end());
    for (const std::uint32_t i : r.triangles) indices_.push_back(first + i);
  }
  std::size_t point_count() const { return points_.size(); }
  // A point new to the slice being meshed (SliceMesher finds each once): its index.
  std::uint32_t add_point(const Point& p) {
    points_.push_back(p);
    return std::uint32_t(points_.size() - 1);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { indices_.insert(indices_.end(), {a, b, c}); }
  std::size_t index_count() const { return indices_.size(); }

  // The mesh's vertices by point, each once across all parts.
  struct MeshPoints {
    detail::FirstIndex first;
    std::vector<Point> points;  // of each mesh vertex
  };
  // Appends this part to `mesh`, each position once across all parts.
  void append_to(BoundsMesh& mesh, MeshPoints& index, const GridSpec& s) const {
    std::vector<std::uint32_t> global(points_.size());
    index.first.reserve(index.points.size() + points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const Point& p = points_[i];
      const auto next = std::uint32_t(index.points.size());
      const std::uint32_t at = index.first.insert(
          detail::WordHash().add(std::uint32_t(p.v[0])).add(std::uint32_t(p.v[1])).add(std::uint32_t(p.v[2])).value(), next,
          [&](std::uint32_t j) { return index.points[j] == p; });
      if (at == next) {
        index.points.push_back(p);
        mesh.vertices.push_back(s.lattice_to_world(float(p.v[0]), float(p.v[1]), float(p.v[2])));
      }
      global[i] = at;
    }
    for (const std::uint32_t i : indices_) mesh.indices.push_back(global[i]);
  }

 private:
  std::vector<Point> points_;
  std::vector<std::uint32_t> indices_;
};

// One slice's mask (Eq. 3.63 with the orientation folded in: +1 where the face points +c, -1 where it points
// -c, 0 where there is none), cut into 4-connected regions of one value, each traced into an outer loop and
// its holes and triangulated.
class SliceMesher {
 public:
  SliceMesher(int na, int nb)
      : width_(std::size_t(na) + 2),
        mask_(width_ * (std::size_t(nb) + 2), 0),
        label_(mask_.size(), -1),
        visited_(mask_.size(), 0),
        sides_(mask_.size(), 0),
        point_(mask_.size(), kNoPoint),
        neighbour_{-std::ptrdiff_t(width_), 1, std::ptrdiff_t(width_), -1} {}
  // One non-zero cell (a, b) of the slice, in any order. Labelling and tracing visit only these, not the
  // whole slice, most of which a room's surface never crosses.
  void set(int a, int b, signed char value) {
    mask_[cell(a, b)] = value;
    filled_.push_back(cell(a, b));
  }
  bool empty() const { return filled_.empty(); }

  // Meshes the cells set since the last call, then clears them. `to_point` maps mask lattice point (a, b)
  // to the 3D lattice.
  template <class ToPoint>
  void mesh(const SurfaceCorners& corners, const ToPoint& to_point, MeshBuilder& out, const std::stop_token& stop) {
    // Row order (b, then a): regions are numbered and traced in it, so the mesh does not depend on how the
    // cells were found.
    if (!std::is_sorted(filled_.begin(), filled_.end())) std::sort(filled_.begin(), filled_.end());
    first_point_ = out.point_count();
    label_regions();
    loops_.clear();
    for (const std::size_t c : filled_) {
      if (sides_[c] == 0) continue;  // inside its region: most of a floor's or a ceiling's cells
      for (int side = 0; side < 4; ++side)
        if (sides_[c] & ~visited_[c] & (1 << side)) trace(int(c % width_) - 1, int(c / width_) - 1, side, corners, to_point, out);
    }
    // Each region: its outer loop (positive area) and its holes.
    std::sort(loops_.begin(), loops_.end(), [](const Traced& x, const Traced& y) {
      return x.region != y.region ? x.region < y.region : x.outer > y.outer;
    });
    for (std::size_t i = 0; i < loops_.size();) {
      std::size_t j = i + 1;
      holes_.clear();
      while (j < loops_.size() && loops_[j].region == loops_[i].region) holes_.push_back(std::move(loops_[j++].points));
      triangles_.clear();
      detail::triangulate_polygon(loops_[i].points, holes_, triangles_, stop);
      for (const auto& t : triangles_) {
        if (loops_[i].value > 0) out.triangle(t[0], t[1], t[2]);
        else out.triangle(t[0], t[2], t[1]);  // the face points -c: reverse the turn
      }
      i = j;
    }
    // Outside the set cells mask, labels and visits stay at their cleared values between slices.
    for (const std::size_t c : filled_) mask_[c] = 0, label_[c] = -1, visited_[c] = 0, sides_[c] = 0;
    filled_.clear();
  }

 private:
  // Directions 0..3: +a, +b, -a, -b; the side of a cell a boundary edge in that direction runs along
  // (bottom, right, top, left) when the cell is on its left.
  static constexpr int kStep[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  static constexpr int kStart[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};     // start corner of each side
  static constexpr int kLeftCell[4][2] = {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}};  // of an edge leaving a point

  struct Traced {
    int region;
    bool outer;
    signed char value;
    detail::Loop points;
  };

  // The slice is stored with a border of empty cells, so (a, b) from (-1, -1) to (na, nb) is read unchecked.
  std::size_t cell(int a, int b) const { return std::size_t(b + 1) * width_ + std::size_t(a + 1); }
  signed char value(int a, int b) const { return mask_[cell(a, b)]; }

  // Numbers the 4-connected regions of one value, and notes each cell's sides on its region's border (sides_),
  // which the tracing then starts from: the neighbours are read once, here.
  void label_regions() {
    int next = 0;
    for (const std::size_t seed : filled_) {
      if (label_[seed] >= 0) continue;
      label_[seed] = next;
      stack_.assign(1, seed);
      while (!stack_.empty()) {
        const std::size_t c = stack_.back();
        stack_.pop_back();
        for (int side = 0; side < 4; ++side) {
          const std::size_t nc = c + neighbour_[side];  // a border cell is empty: never the seed's value
          if (mask_[nc] != mask_[seed]) {
            sides_[c] |= std::uint8_t(1 << side);
          } else if (label_[nc] < 0) {
            label_[nc] = next;
            stack_.push_back(nc);
          }
        }
      }
      ++next;
    }
  }

  // Walks the boundary with the region on the left, from the given side of cell (a, b). At a point where
  // two cells of the region touch only diagonally it turns left, keeping to 4-connected regions. Keeps the
  // points where it turns and the surface corners it passes.
  template <class ToPoint>
  void trace(int a, int b, int side, const SurfaceCorners& corners, const ToPoint& to_point, MeshBuilder& out) {
    const signed char m = value(a, b);
    Traced loop{label_[cell(a, b)], false, m, {}};
    const int sa = a + kStart[side][0], sb = b + kStart[side][1];
    int pa = sa, pb = sb, d = side, ca = a, cb = b;
    std::int64_t twice_area = 0;
    do {
      visited_[cell(ca, cb)] |= std::uint8_t(1 << d);
      const int ea = pa + kStep[d][0], eb = pb + kStep[d][1];
      twice_area += std::int64_t(pa) * eb - std::int64_t(ea) * pb;
      const int l = d, r = (d + 3) % 4;  // the cells left and right of the straight way on
      const bool ahead_left = value(ea + kLeftCell[l][0], eb + kLeftCell[l][1]) == m;
      const bool ahead_right = value(ea + kLeftCell[r][0], eb + kLeftCell[r][1]) == m;
      const int nd = !ahead_left ? (d + 1) % 4 : ahead_right ? (d + 3) % 4 : d;
      const Point p = to_point(ea, eb);
      if (nd != d || corners.contains(p)) loop.points.push_back({ea, eb, vertex(ea, eb, p, out)});
      pa = ea;
      pb = eb;
      d = nd;
      ca = pa + kLeftCell[d][0];
      cb = pb + kLeftCell[d][1];
    } while (pa != sa || pb != sb || d != side);
    loop.outer = twice_area > 0;
    loops_.push_back(std::move(loop));
  }

  // Lattice point (a, b)'s index in `out`, each point added once per slice: an index from before this slice's
  // first point (an earlier slice's) or kNoPoint is none. No hashing: the slice's points are its lattice's.
  std::uint32_t vertex(int a, int b, const Point& p, MeshBuilder& out) {
    std::uint32_t& at = point_[cell(a, b)];  // a in [0, na], b in [0, nb]: inside the bordered mask
    if (at == kNoPoint || at < first_point_) at = out.add_point(p);
    return at;
  }

  static constexpr std::uint32_t kNoPoint = ~std::uint32_t{0};
  std::size_t width_;  // na + 2
  std::vector<signed char> mask_;
  std::vector<std::size_t> filled_;
  std::vector<int> label_;
  std::vector<std::uint8_t> visited_;
  std::vector<std::uint8_t> sides_;  // per cell, bit `side` where the neighbour that way holds another value
  std::vector<std::uint32_t> point_;
  std::size_t first_point_ = 0;
  std::vector<std::size_t> stack_;
  std::vector<Traced> loops_;
  std::vector<detail::Loop> holes_;
  detail::Triangles triangles_;
  std::array<std::ptrdiff_t, 4> neighbour_;  // the index steps of directions 0..3's neighbours
};

// Each slice of an axis, by c - c0 + 1 (slice c lies between voxel layers c and c + 1): the previous volume's
// record where both layers are as they were (`kept`), else meshed; `records`, where not null, gets every slice's.
struct SliceReuse {
  std::vector<SliceRecord>* kept = nullptr;  // moved into `records` as they are replayed
  const std::vector<std::uint8_t>* changed = nullptr;  // per voxel layer along the axis
  std::vector<SliceRecord>* records = nullptr;
};

// The slices c_from..c_to (within c0 - 1..c_end along ax.c) of one axis, into `out`. `reuse.records`, where set, is
// sized for all the axis's slices by the caller: the two halves of an axis write their own slots of it side by side.
void mesh_axis(const GridSpec& s, const std::vector<std::uint8_t>& volume, const Box& box, const Axes& ax, int c_from,
               int c_to, const SurfaceCorners* corners, MeshBuilder& out, const std::stop_token& stop,
               const SliceReuse& reuse) {
  // Strides of GridSpec::index per axis: x -> ny, y -> 1, z -> nx * ny.
  const std::ptrdiff_t stride[3] = {s.ny, 1, std::ptrdiff_t(s.nx) * s.ny};
  const std::ptrdiff_t sa = stride[ax.a], sb = stride[ax.b], sc = stride[ax.c];
  const int a0 = box.lo[ax.a], b0 = box.lo[ax.b], c0 = box.lo[ax.c];
  const int na = box.hi[ax.a] - a0 + 1, nb = box.hi[ax.b] - b0 + 1, c_end = box.hi[ax.c];
  const std::uint8_t* base = volume.data() + a0 * sa + b0 * sb;
  // Slice c is replayed where layers c and c + 1 are as they were; with every slice replayed nothing is meshed.
  const auto replayed = [&](int c) {
    return reuse.kept && !(c >= c0 && (*reuse.changed)[std::size_t(c)]) && !(c + 1 <= c_end && (*reuse.changed)[std::size_t(c + 1)]);
  };
  // The slices meshed lie in [first, last].
  int first = c_to + 1, last = c_from - 1;
  for (int c = c_from; c <= c_to; ++c)
    if (!replayed(c)) first = std::min(first, c), last = c;
  const bool meshes = first <= last;
  SliceMesher slice(meshes ? na : 0, meshes ? nb : 0);
  // Slice c lies between voxel layers c and c + 1; outside the box both are empty. Along y (stride 1) the
  // faces are found once, column by column, and kept per slice, each slice's in row order: those of the slices
  // from first to last (a change's few levels read, not every column's every level).
  std::vector<std::vector<std::array<int, 2>>> y_faces;
  if (sc == 1 && meshes) {
    y_faces.resize(std::size_t(c_end - c0 + 2));
    const int inner_first = std::max(first, c0), inner_end = std::min(last + 1, c_end);  // slices c0..c_end-1
    for (int b = 0; b < nb; ++b)
      for (int a = 0; a < na; ++a) {
        const std::uint8_t* v = base + a * sa + b * sb;
        const auto face_at = [&](int c) { y_faces[std::size_t(c - c0 + 1)].push_back({a, b}); };
        if (first == c0 - 1 && v[c0] != 0) face_at(c0 - 1);
        for (int c = inner_first; c < inner_end;) {
          // Eight levels at a time where they hold no change (most of a column).
          if (c + 8 <= inner_end) {
            std::uint64_t here, next;
            std::memcpy(&here, v + c, 8);
            std::memcpy(&next, v + c + 1, 8);
            if (here == next) {
              c += 8;
              continue;
            }
          }
          if (v[c] != v[c + 1]) face_at(c);
          ++c;
        }
        if (last == c_end && v[c_end] != 0) face_at(c_end);
      }
  }
  std::vector<int> differing;
  for (int c = c_from; c <= c_to; ++c) {
    stop_point(stop);
    const std::size_t slot = std::size_t(c - c0 + 1);
    if (replayed(c)) {
      SliceRecord& kept = (*reuse.kept)[slot];
      out.replay(kept);
      if (reuse.records) (*reuse.records)[slot] = std::move(kept);
      continue;
    }
    const auto mark = out.begin_slice();
    const std::uint8_t* below = c >= c0 ? base + c * sc : nullptr;
    const std::uint8_t* above = c + 1 <= c_end ? base + (c + 1) * sc : nullptr;
    const auto face = [&](std::ptrdiff_t off) {
      return static_cast<signed char>((below ? below[off] : 0) - (above ? above[off] : 0));
    };
    if (sc == 1) {
      for (const auto& [a, b] : y_faces[std::size_t(c - c0 + 1)]) slice.set(a, b, face(a * sa + b * sb));
    } else if (sa == 1) {
      // a runs along y, contiguous in memory: a row equal in both layers has no face.
      for (int b = 0; b < nb; ++b) {
        const std::ptrdiff_t off = b * sb;
        if (below && above && std::equal(below + off, below + off + na, above + off)) continue;
        for (int a = 0; a < na; ++a)
          if (const signed char m = face(off + a); m != 0) slice.set(a, b, m);
      }
    } else {
      // b runs along y: the columns of a equal in both layers have no face; the others are read row by row.
      differing.clear();
      for (int a = 0; a < na; ++a)
        if (!below || !above || !std::equal(below + a * sa, below + a * sa + nb, above + a * sa)) differing.push_back(a);
      for (int b = 0; b < nb; ++b)
        for (const int a : differing)
          if (const signed char m = face(a * sa + b); m != 0) slice.set(a, b, m);
    }
    if (!slice.empty())
      slice.mesh(
          *corners,  // meshing a slice: the volume changed, and its corners were found
          [&](int a, int b) {
            Point p;
            p.v[ax.a] = a0 + a;
            p.v[ax.b] = b0 + b;
            p.v[ax.c] = c + 1;
            return p;
          },
          out, stop);
    if (reuse.records) (*reuse.records)[slot] = out.since(mark);
  }
}

// Where two volumes of one grid differ: the voxel layers along each axis, and the voxel columns.
struct VolumeChanges {
  std::array<std::vector<std::uint8_t>, 3> layers;
  std::vector<std::size_t> columns;  // GridSpec::column, ascending
};
// `may_differ`, where not null: the columns outside it are equal (FilledVolume).
VolumeChanges volume_changes(const GridSpec& s, const std::vector<std::uint8_t>& before,
                             const std::vector<std::uint8_t>& after, const std::vector<std::uint8_t>* may_differ) {
  VolumeChanges changed{{std::vector<std::uint8_t>(std::size_t(s.nx), 0), std::vector<std::uint8_t>(std::size_t(s.ny), 0),
                         std::vector<std::uint8_t>(std::size_t(s.nz), 0)},
                        {}};
  const std::size_t ny = std::size_t(s.ny);
  const auto differ = [&](std::size_t col) {
    return !std::equal(before.begin() + std::ptrdiff_t(col * ny), before.begin() + std::ptrdiff_t((col + 1) * ny),
                       after.begin() + std::ptrdiff_t(col * ny));
  };
  const std::vector<std::uint8_t> compared = may_differ ? std::vector<std::uint8_t>() : detail::changed_columns(ny, before, after);
  const std::vector<std::uint8_t>& differs = may_differ ? *may_differ : compared;
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    if (!differs[col] || (may_differ && !differ(col))) continue;
    const std::uint8_t *a = before.data() + col * ny, *b = after.data() + col * ny;
    changed.columns.push_back(col);
    changed.layers[0][col % std::size_t(s.nx)] = changed.layers[2][col / std::size_t(s.nx)] = 1;
    for (std::size_t y = 0; y < ny; ++y)
      if (a[y] != b[y]) changed.layers[1][y] = 1;
  }
  return changed;
}

}  // namespace

struct detail::MeshMemo::State {
  GridSpec spec{};
  std::vector<std::uint8_t> volume;
  Box box{};
  std::array<std::vector<SliceRecord>, 3> slices;  // per axis (kAxes), per slice
  std::optional<SurfaceCorners> corners;           // of `volume`, where found
  MeshBuilder::MeshPoints index;  // the vertices' index the mesh was built with: its storage, for the next one
};

detail::MeshMemo::MeshMemo() = default;
detail::MeshMemo::~MeshMemo() = default;
detail::MeshMemo::MeshMemo(MeshMemo&&) noexcept = default;
detail::MeshMemo& detail::MeshMemo::operator=(MeshMemo&&) noexcept = default;

BoundsMesh mesh_volume(const GridSpec& spec, const std::vector<std::uint8_t>& volume, unsigned threads,
                       std::stop_token stop) {
  const detail::StagePool pool(threads);
  return detail::mesh_volume(spec, volume, threads, std::move(stop), nullptr);
}

BoundsMesh detail::mesh_volume(const GridSpec& spec, const std::vector<std::uint8_t>& volume, unsigned threads,
                               std::stop_token stop, MeshMemo* memo, const FilledVolume* filled) {
  const Box box = filled ? filled->box : solid_box(spec, volume, threads);
  // Where the volume may differ from the memo's (its other columns are equal), where that is known.
  const std::vector<std::uint8_t>* may_differ =
      filled && filled->may_differ.size() == spec.column_count() ? &filled->may_differ : nullptr;
  if (box.hi[0] < box.lo[0]) {
    if (memo) memo->state_.reset();
    return {};
  }
  // The previous volume's slices, where it had this grid and solid box. Taken out of the memo: its slices and
  // corners move into the next state, and a failure on the way leaves the memo empty, not half moved.
  const std::unique_ptr<MeshMemo::State> previous = memo ? std::move(memo->state_) : nullptr;
  MeshMemo::State* kept =
      previous && previous->spec == spec && previous->box == box && previous->volume.size() == volume.size()
          ? previous.get()
          : nullptr;
  VolumeChanges changed;
  if (kept) changed = volume_changes(spec, kept->volume, volume, may_differ);
  auto next = memo ? std::make_unique<MeshMemo::State>() : nullptr;
  // Every slice replayed: no corner is read.
  const bool all_kept = kept != nullptr && changed.columns.empty();
  std::optional<SurfaceCorners> corners;
  // The previous corners with the columns beside a change found again, where those are few (one thread finds
  // them); else all, on the threads.
  const std::size_t columns = std::size_t(box.hi[0] - box.lo[0] + 2) * std::size_t(box.hi[2] - box.lo[2] + 2);
  if (all_kept) {
    if (next) next->corners = std::move(kept->corners);
  } else if (kept && kept->corners && 4 * changed.columns.size() < columns / 8) {
    corners.emplace(spec, volume, std::move(*kept->corners), changed.columns);
  } else {
    corners.emplace(spec, volume, box, threads, stop);
  }
  // Each axis in two halves of its slices, each half its own task and part: a part holds its slices' points and
  // triangles in order and no slice shares a point with another (MeshBuilder), so the parts appended in order are
  // the axis's whole. The halves along y first: a storey's floor and ceiling are most of the faces (thesis-room1:
  // y 0.40 ms of the three axes' 0.77 on one thread), one in each half, so two workers take one each and then share
  // the walls' four.
  constexpr std::size_t kHalves = 2;
  MeshBuilder parts[3][kHalves];
  constexpr std::size_t kMeshOrder[3] = {2, 0, 1};
  static_assert(kAxes[2].c == 1);
  for (std::size_t axis = 0; axis < 3 && next; ++axis) {
    const int c = kAxes[axis].c;
    next->slices[axis].resize(std::size_t(box.hi[c] - box.lo[c] + 2));  // slices lo - 1 .. hi, by mesh_axis's slots
  }
  detail::parallel_tasks(3 * kHalves, threads, [&](std::size_t task) {
    const std::size_t axis = kMeshOrder[task / kHalves], half = task % kHalves;
    const int c = kAxes[axis].c, middle = (box.lo[c] - 1 + box.hi[c]) / 2;
    // Built in the task's own builder and moved in after: the parts' vectors lie side by side, and growing them in
    // place had the workers pass their cache lines back and forth.
    MeshBuilder part;
    mesh_axis(spec, volume, box, kAxes[axis], half == 0 ? box.lo[c] - 1 : middle + 1, half == 0 ? middle : box.hi[c],
              corners ? &*corners : nullptr, part, stop,
              {kept ? &kept->slices[axis] : nullptr, kept ? &changed.layers[std::size_t(c)] : nullptr,
               next ? &next->slices[axis] : nullptr});
    parts[axis][half] = std::move(part);
  });
  BoundsMesh mesh;
  MeshBuilder::MeshPoints index;
  if (previous) {  // its storage (a home's index is a megabyte: fresh pages each update, each a page fault)
    index = std::move(previous->index);
    index.first.clear(), index.points.clear();
  }
  // Room for every part's points at once (at most that many vertices): grown part by part, the index was
  // built again at each doubling (a home's mesh: 1.7 M instructions an update).
  std::size_t points = 0, indices = 0;
  for (const auto& axis_parts : parts)
    for (const MeshBuilder& part : axis_parts) points += part.point_count(), indices += part.index_count();
  index.first.reserve(points);
  mesh.indices.reserve(indices);
  for (const auto& axis_parts : parts)
    for (const MeshBuilder& part : axis_parts) {
      stop_point(stop);
      part.append_to(mesh, index, spec);
    }
  if (memo) {
    if (previous) next->volume = std::move(previous->volume);  // its storage, not a new allocation
    if (previous && previous->spec == spec && next->volume.size() == volume.size() && may_differ) {
      detail::copy_columns(std::size_t(spec.ny), volume, next->volume, *may_differ);
    } else {
      next->volume.assign(volume.begin(), volume.end());
    }
    next->spec = spec, next->box = box;
    if (corners) next->corners = std::move(corners);
    next->index = std::move(index);
    memo->state_ = std::move(next);
  }
  return mesh;
}

MeshClosure check_closure(const BoundsMesh& mesh) {
  // Count each directed edge; a closed, consistently oriented surface has every undirected edge exactly
  // once in each direction.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = mesh.indices[t + std::size_t(k)], b = mesh.indices[t + std::size_t((k + 1) % 3)];
      ++directed[(a << 32) | b];
    }
  MeshClosure result;
  for (const auto& [edge, count] : directed) {
    const std::uint64_t a = edge >> 32, b = edge & 0xFFFFFFFFull;
    const auto reverse = directed.find((b << 32) | a);
    const int back = reverse == directed.end() ? 0 : reverse->second;
    if (count != 1 || back != 1) {
      if (count + back != 2) ++result.boundary_or_nonmanifold_edges;
      else ++result.misoriented_edges;
    }
  }
  return result;
}

}  // namespace roomsense
