// Greedy meshing of a voxel volume (Eq. 3.63/3.64), made watertight by splitting quads at T-junctions.
#include "roomsense/bounds.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <unordered_map>

namespace roomsense {
namespace {

// Lattice points in integer coordinates: every comparison is exact.
struct Point {
  int v[3];
  bool operator==(const Point& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};
struct PointHash {
  std::size_t operator()(const Point& p) const {
    std::size_t h = std::size_t(std::uint32_t(p.v[0]));
    h = h * 0x9E3779B97F4A7C15ull ^ std::size_t(std::uint32_t(p.v[1]));
    h = h * 0x9E3779B97F4A7C15ull ^ std::size_t(std::uint32_t(p.v[2]));
    return h;
  }
};

struct Quad {
  std::array<Point, 4> corners;  // counter-clockwise seen from free space
};

// The thesis's lexicographic order per plane: (a, b) = (X, Y) for slices along Z, (Y, Z) along X, (Z, X)
// along Y. In each, e_a x e_b = +e_c, so corners (a,b) (a+w,b) (a+w,b+h) (a,b+h) turn counter-clockwise
// seen from +c.
struct Axes {
  int c, a, b;
};
constexpr Axes kAxes[] = {{2, 0, 1}, {0, 1, 2}, {1, 2, 0}};

// Rectangles of equal non-zero mask values, merged greedily (Eq. 3.64): run along the first axis, then
// grow along the second while the whole run matches. `major_a` picks which mask axis is the first.
struct Rect {
  int a, b, w, h;
  signed char value;
};
void greedy_rectangles(std::vector<signed char> mask, int na, int nb, bool major_a, std::vector<Rect>& out) {
  const int n1 = major_a ? na : nb, n2 = major_a ? nb : na;
  const auto at = [&](int i, int j) -> signed char& {  // i along the first axis, j along the second
    return major_a ? mask[std::size_t(j) * std::size_t(na) + std::size_t(i)]
                   : mask[std::size_t(i) * std::size_t(na) + std::size_t(j)];
  };
  for (int j = 0; j < n2; ++j)
    for (int i = 0; i < n1;) {
      const signed char m = at(i, j);
      if (m == 0) {
        ++i;
        continue;
      }
      int w = 1;
      while (i + w < n1 && at(i + w, j) == m) ++w;
      int h = 1;
      for (; j + h < n2; ++h) {
        bool full = true;
        for (int k = 0; k < w && full; ++k) full = at(i + k, j + h) == m;
        if (!full) break;
      }
      for (int jj = j; jj < j + h; ++jj)
        for (int k = 0; k < w; ++k) at(i + k, jj) = 0;
      out.push_back(major_a ? Rect{i, j, w, h, m} : Rect{j, i, h, w, m});
      i += w;
    }
}

// The box of solid voxels: meshing stops at its faces (outside it every mask entry is 0).
struct Box {
  int lo[3], hi[3];  // inclusive; hi < lo when empty
};
Box solid_box(const GridSpec& s, const std::vector<std::uint8_t>& volume) {
  Box box{{s.nx, s.ny, s.nz}, {-1, -1, -1}};
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::uint8_t* v = volume.data() + s.column(x, z) * std::size_t(s.ny);
      for (int y = 0; y < s.ny; ++y)
        if (v[y]) {
          const int p[3] = {x, y, z};
          for (int k = 0; k < 3; ++k) {
            box.lo[k] = std::min(box.lo[k], p[k]);
            box.hi[k] = std::max(box.hi[k], p[k]);
          }
        }
    }
  return box;
}

// Eq. 3.63's mask with the orientation folded in: +1 where the face points +c (solid at c, free at c+1),
// -1 where it points -c, 0 where there is no face. Equal non-zero values merge (Eq. 3.64). The thesis fixes
// one lexicographic order per plane; we run both orders on each slice and keep the one with fewer
// rectangles, which costs little and saves a few.
void mesh_axis(const GridSpec& s, const std::vector<std::uint8_t>& volume, const Box& box, const Axes& ax,
               std::vector<Quad>& quads) {
  // Strides of GridSpec::index per axis: x -> ny, y -> 1, z -> nx * ny.
  const std::ptrdiff_t stride[3] = {s.ny, 1, std::ptrdiff_t(s.nx) * s.ny};
  const std::ptrdiff_t sa = stride[ax.a], sb = stride[ax.b], sc = stride[ax.c];
  const int a0 = box.lo[ax.a], b0 = box.lo[ax.b], c0 = box.lo[ax.c];
  const int na = box.hi[ax.a] - a0 + 1, nb = box.hi[ax.b] - b0 + 1, c_end = box.hi[ax.c];
  const std::uint8_t* base = volume.data() + a0 * sa + b0 * sb;
  std::vector<signed char> mask(std::size_t(na) * std::size_t(nb));
  std::vector<Rect> first, second;
  for (int c = c0 - 1; c <= c_end; ++c) {
    const std::uint8_t* below = c >= c0 ? base + c * sc : nullptr;
    const std::uint8_t* above = c + 1 <= c_end ? base + (c + 1) * sc : nullptr;
    bool any = false;
    for (int b = 0; b < nb; ++b) {
      signed char* row = &mask[std::size_t(b) * std::size_t(na)];
      for (int a = 0; a < na; ++a) {
        const std::ptrdiff_t off = a * sa + b * sb;
        row[a] = static_cast<signed char>((below ? below[off] : 0) - (above ? above[off] : 0));
        any = any || row[a] != 0;
      }
    }
    if (!any) continue;
    first.clear();
    second.clear();
    greedy_rectangles(mask, na, nb, true, first);
    greedy_rectangles(mask, na, nb, false, second);
    for (const Rect& r : second.size() < first.size() ? second : first) {
      const auto corner = [&](int ca, int cb) {
        Point p;
        p.v[ax.a] = a0 + ca;
        p.v[ax.b] = b0 + cb;
        p.v[ax.c] = c + 1;
        return p;
      };
      Quad q{{corner(r.a, r.b), corner(r.a + r.w, r.b), corner(r.a + r.w, r.b + r.h), corner(r.a, r.b + r.h)}};
      if (r.value < 0) std::swap(q.corners[1], q.corners[3]);  // face points -c: reverse the turn
      quads.push_back(q);
    }
  }
}

// Every quad corner, indexed by the three axis-aligned lines through it, to find the points inside a quad
// edge. One sorted array of (line, position along it): lookups are two binary searches.
class LineIndex {
 public:
  void add(const Point& p) {
    for (int k = 0; k < 3; ++k) entries_.push_back({key(p, k), p.v[k]});
  }
  void finish() {
    std::sort(entries_.begin(), entries_.end());
    entries_.erase(std::unique(entries_.begin(), entries_.end()), entries_.end());
  }
  // Appends the points strictly between p and q (which differ along one axis), in order from p to q.
  void between(const Point& p, const Point& q, std::vector<Point>& out) const {
    int k = 0;
    while (p.v[k] == q.v[k]) ++k;
    const std::uint64_t line = key(p, k);
    const int lo = std::min(p.v[k], q.v[k]), hi = std::max(p.v[k], q.v[k]);
    const auto first = std::lower_bound(entries_.begin(), entries_.end(), Entry{line, lo + 1});
    const auto last = std::lower_bound(first, entries_.end(), Entry{line, hi});
    const std::size_t start = out.size();
    for (auto e = first; e != last; ++e) {
      Point r = p;
      r.v[k] = e->position;
      out.push_back(r);
    }
    if (p.v[k] > q.v[k]) std::reverse(out.begin() + std::ptrdiff_t(start), out.end());
  }

 private:
  struct Entry {
    std::uint64_t line;
    int position;
    auto operator<=>(const Entry&) const = default;
  };
  // Lattice coordinates are below 2^26 (the voxel budget bounds every dimension): 2 + 31 + 31 bits.
  static std::uint64_t key(const Point& p, int axis) {
    return std::uint64_t(axis) << 62 | std::uint64_t(std::uint32_t(p.v[(axis + 1) % 3])) << 31 |
           std::uint64_t(std::uint32_t(p.v[(axis + 2) % 3]));
  }
  std::vector<Entry> entries_;
};

class MeshBuilder {
 public:
  explicit MeshBuilder(const GridSpec& s) : spec_(s) {}
  std::uint32_t vertex(const Point& p) {
    const auto [it, inserted] = index_.try_emplace(p, std::uint32_t(mesh_.vertices.size()));
    if (inserted)
      mesh_.vertices.push_back(spec_.lattice_to_world(float(p.v[0]), float(p.v[1]), float(p.v[2])));
    return it->second;
  }
  void triangle(const Point& a, const Point& b, const Point& c) {
    mesh_.indices.insert(mesh_.indices.end(), {vertex(a), vertex(b), vertex(c)});
  }
  BoundsMesh take() { return std::move(mesh_); }

 private:
  const GridSpec& spec_;
  BoundsMesh mesh_;
  std::unordered_map<Point, std::uint32_t, PointHash> index_;
};

// Triangulates a quad whose edges carry extra points (T-junctions), listed counter-clockwise in `ring`,
// into ring.size() - 2 triangles without adding a vertex, by ear clipping. An ear (a, b, c) must turn at
// b (b not collinear with a and c) and its new edge a-c must not run along the quad's border: then the
// points left on that border would lie on a-c and the rest of the ring would be flat. A convex ring always
// has such an ear; the pass counter only guards against a bug turning into a hang.
void triangulate_ring(std::vector<Point>& ring, MeshBuilder& out) {
  const auto aligned = [](const Point& a, const Point& c) {  // on one axis-parallel line
    int same = 0;
    for (int k = 0; k < 3; ++k) same += a.v[k] == c.v[k] ? 1 : 0;
    return same >= 2;
  };
  std::size_t i = 0, misses = 0;
  while (ring.size() > 3 && misses <= ring.size()) {
    const std::size_t n = ring.size();
    const Point& a = ring[(i + n - 1) % n];
    const Point& b = ring[i];
    const Point& c = ring[(i + 1) % n];
    if (aligned(a, c)) {  // also when b lies on the border between them
      i = (i + 1) % n;
      ++misses;
      continue;
    }
    out.triangle(a, b, c);
    ring.erase(ring.begin() + std::ptrdiff_t(i));
    i %= ring.size();
    misses = 0;
  }
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) out.triangle(ring[0], ring[k], ring[k + 1]);
}

}  // namespace

BoundsMesh greedy_mesh(const GridSpec& spec, const std::vector<std::uint8_t>& volume) {
  std::vector<Quad> quads;
  const Box box = solid_box(spec, volume);
  if (box.hi[0] < box.lo[0]) return {};
  for (const Axes& ax : kAxes) mesh_axis(spec, volume, box, ax, quads);

  LineIndex lines;
  for (const Quad& q : quads)
    for (const Point& p : q.corners) lines.add(p);
  lines.finish();

  MeshBuilder out(spec);
  std::vector<Point> ring;
  for (const Quad& q : quads) {
    ring.clear();
    for (std::size_t k = 0; k < 4; ++k) {
      ring.push_back(q.corners[k]);
      lines.between(q.corners[k], q.corners[(k + 1) % 4], ring);
    }
    triangulate_ring(ring, out);
  }
  return out.take();
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
