// Ear clipping of a lattice polygon with holes. The structure follows Eberly's "Triangulation by Ear
// Clipping" (holes joined to the outer loop by bridges to a visible vertex) as refined in Mapbox's earcut.
// Two changes for closed meshes: collinear vertices are never dropped (they are T-junctions that the
// neighbouring faces share), and an ear is rejected when any other vertex, not only a reflex one, lies in
// or on it. Coordinates are small integers, so every orientation test is exact.
#include "polygon_triangulation.h"

#include "roomsense/cancel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomsense::detail {
namespace {

struct Node {
  std::int64_t a, b;
  std::uint32_t id;
  int prev, next;
  bool removed = false;
};

class Ring {
 public:
  explicit Ring(std::size_t capacity) { nodes_.reserve(capacity); }

  // Links the points of `loop` after `last` (or as a new ring when last < 0); returns the last node.
  int link(const Loop& loop, int last) {
    for (const LatticePoint2& p : loop) {
      const int i = int(nodes_.size());
      nodes_.push_back({p.a, p.b, p.id, i, i, false});
      if (last >= 0) {
        nodes_[i].prev = last;
        nodes_[i].next = nodes_[last].next;
        nodes_[nodes_[last].next].prev = i;
        nodes_[last].next = i;
      }
      last = i;
    }
    return last;
  }

  const Node& operator[](int i) const { return nodes_[std::size_t(i)]; }
  int next(int i) const { return nodes_[std::size_t(i)].next; }
  int prev(int i) const { return nodes_[std::size_t(i)].prev; }

  bool removed(int i) const { return nodes_[std::size_t(i)].removed; }

  void remove(int i) {
    Node& n = nodes_[std::size_t(i)];
    n.removed = true;
    nodes_[std::size_t(n.prev)].next = n.next;
    nodes_[std::size_t(n.next)].prev = n.prev;
  }

  // Twice the signed area of (p, q, r): positive when it turns counter-clockwise.
  std::int64_t cross(int p, int q, int r) const {
    const Node &P = (*this)[p], &Q = (*this)[q], &R = (*this)[r];
    return (Q.a - P.a) * (R.b - P.b) - (Q.b - P.b) * (R.a - P.a);
  }
  bool same_place(int p, int q) const { return (*this)[p].a == (*this)[q].a && (*this)[p].b == (*this)[q].b; }

  // Removes nodes that repeat their successor's position (zero-length edges, left by bridges at a vertex
  // that a hole touches). Collinear nodes stay. Returns a node still in the ring.
  int drop_repeats(int start) {
    int p = start;
    for (bool removed = true; removed || p != start;) {
      removed = false;
      const int q = next(p);
      if (q != p && same_place(p, q)) {
        if (q == start) start = p;
        remove(q);
        removed = true;
      } else {
        p = q;
      }
    }
    return start;
  }

  // Joins the ring of `b` into the ring of `a` by the bridge a-b, walked both ways: a -> b ... b' -> a'.
  // Returns a', the copy of a after the bridge.
  int split(int a, int b) {
    const int a2 = int(nodes_.size());
    nodes_.push_back(nodes_[std::size_t(a)]);
    const int b2 = int(nodes_.size());
    nodes_.push_back(nodes_[std::size_t(b)]);
    const int an = next(a), bp = prev(b);
    nodes_[std::size_t(a)].next = b;
    nodes_[std::size_t(b)].prev = a;
    nodes_[std::size_t(a2)].next = an;
    nodes_[std::size_t(an)].prev = a2;
    nodes_[std::size_t(b2)].next = a2;
    nodes_[std::size_t(a2)].prev = b2;
    nodes_[std::size_t(bp)].next = b2;
    nodes_[std::size_t(b2)].prev = bp;
    return a2;
  }

 private:
  std::vector<Node> nodes_;
};

// The ring's nodes in a uniform grid of buckets over their bounding box, about four to a bucket, so an ear
// test looks only at the nodes near its triangle: without it, a region with thousands of holes (a floor
// among pillars) takes time quadratic in its vertex count. Built once the ring is final; clipping only
// removes nodes, which the tests skip.
class NodeGrid {
 public:
  NodeGrid(const Ring& r, int start) {
    std::int64_t lo_a = r[start].a, hi_a = lo_a, lo_b = r[start].b, hi_b = lo_b;
    std::size_t n = 0;
    int p = start;
    do {
      lo_a = std::min(lo_a, r[p].a), hi_a = std::max(hi_a, r[p].a);
      lo_b = std::min(lo_b, r[p].b), hi_b = std::max(hi_b, r[p].b);
      ++n;
      p = r.next(p);
    } while (p != start);
    lo_a_ = lo_a;
    lo_b_ = lo_b;
    const std::int64_t span = std::max<std::int64_t>({hi_a - lo_a, hi_b - lo_b, 1});
    const std::int64_t side = std::max<std::int64_t>(1, std::int64_t(std::sqrt(double(n) / 4.0)));
    cell_ = std::max<std::int64_t>(1, (span + side) / side);
    na_ = (hi_a - lo_a) / cell_ + 1;
    nb_ = (hi_b - lo_b) / cell_ + 1;
    first_.assign(std::size_t(na_ * nb_) + 1, 0);
    p = start;
    do {
      ++first_[bucket(r[p].a, r[p].b) + 1];
      p = r.next(p);
    } while (p != start);
    for (std::size_t i = 1; i < first_.size(); ++i) first_[i] += first_[i - 1];
    ids_.resize(n);
    std::vector<std::size_t> fill(first_.begin(), first_.end() - 1);
    p = start;
    do {
      ids_[fill[bucket(r[p].a, r[p].b)]++] = p;
      p = r.next(p);
    } while (p != start);
  }

  // Calls visit(node) for every node in the buckets that meet the box; stops when visit returns false.
  template <class Visit>
  bool all_of(std::int64_t lo_a, std::int64_t hi_a, std::int64_t lo_b, std::int64_t hi_b, const Visit& visit) const {
    const std::int64_t a0 = std::max<std::int64_t>(0, (lo_a - lo_a_) / cell_), a1 = std::min(na_ - 1, (hi_a - lo_a_) / cell_);
    const std::int64_t b0 = std::max<std::int64_t>(0, (lo_b - lo_b_) / cell_), b1 = std::min(nb_ - 1, (hi_b - lo_b_) / cell_);
    for (std::int64_t b = b0; b <= b1; ++b)
      for (std::int64_t a = a0; a <= a1; ++a) {
        const std::size_t cell = std::size_t(b * na_ + a);
        for (std::size_t i = first_[cell]; i < first_[cell + 1]; ++i)
          if (!visit(ids_[i])) return false;
      }
    return true;
  }

 private:
  std::size_t bucket(std::int64_t a, std::int64_t b) const {
    return std::size_t((b - lo_b_) / cell_ * na_ + (a - lo_a_) / cell_);
  }
  std::int64_t lo_a_ = 0, lo_b_ = 0, cell_ = 1, na_ = 1, nb_ = 1;
  std::vector<std::size_t> first_;
  std::vector<int> ids_;
};

// Closed test for a counter-clockwise triangle.
bool in_triangle(double ax, double ay, double bx, double by, double cx, double cy, double px, double py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0 && (cx - bx) * (py - by) - (cy - by) * (px - bx) >= 0 &&
         (ax - cx) * (py - cy) - (ay - cy) * (px - cx) >= 0;
}

// Whether the diagonal from a toward b starts inside the polygon's angle at a.
bool locally_inside(const Ring& r, int a, int b) {
  if (r.cross(r.prev(a), a, r.next(a)) > 0) return r.cross(a, b, r.next(a)) <= 0 && r.cross(a, r.prev(a), b) <= 0;
  return r.cross(a, b, r.prev(a)) > 0 || r.cross(a, r.next(a), b) > 0;
}

// Of two nodes at one position, whether the angle at p lies inside the angle at m.
bool sector_contains_sector(const Ring& r, int m, int p) {
  return r.cross(r.prev(m), m, r.prev(p)) > 0 && r.cross(r.next(p), m, r.next(m)) > 0;
}

// Eberly's visible vertex for hole vertex `h` (the hole's leftmost): cast a ray toward -a, take the nearest
// edge it hits, then prefer any vertex inside the triangle (h, hit, endpoint) of the smallest angle.
int find_bridge(const Ring& r, int h, int outer) {
  const double hx = double(r[h].a), hy = double(r[h].b);
  double qx = -std::numeric_limits<double>::infinity();
  int m = -1;
  int p = outer;
  do {
    const Node &P = r[p], &N = r[r.next(p)];
    // Edges running down (-b) bound the polygon on its -a side.
    if (hy <= double(P.b) && hy >= double(N.b) && N.b != P.b) {
      const double x = double(P.a) + (hy - double(P.b)) * double(N.a - P.a) / double(N.b - P.b);
      if (x <= hx && x > qx) {
        qx = x;
        m = P.a < N.a ? p : r.next(p);
        if (x == hx) return m;  // the hole touches this edge
      }
    }
    p = r.next(p);
  } while (p != outer);
  if (m < 0) return -1;

  const int stop = m;
  const double mx = double(r[m].a), my = double(r[m].b);
  double best_tan = std::numeric_limits<double>::infinity();
  p = m;
  do {
    const double px = double(r[p].a), py = double(r[p].b);
    if (hx >= px && px >= mx && hx != px &&
        in_triangle(hy < my ? hx : qx, hy, mx, my, hy < my ? qx : hx, hy, px, py)) {
      const double tan = std::abs(hy - py) / (hx - px);
      if (locally_inside(r, p, h) &&
          (tan < best_tan ||
           (tan == best_tan && (px > double(r[m].a) || (px == double(r[m].a) && sector_contains_sector(r, m, p)))))) {
        m = p;
        best_tan = tan;
      }
    }
    p = r.next(p);
  } while (p != stop);
  return m;
}

bool is_ear(const Ring& r, const NodeGrid& grid, int ear) {
  const int a = r.prev(ear), c = r.next(ear);
  if (r.cross(a, ear, c) <= 0) return false;  // reflex, or flat (a T-junction that must stay)
  const std::int64_t lo_a = std::min({r[a].a, r[ear].a, r[c].a}), hi_a = std::max({r[a].a, r[ear].a, r[c].a});
  const std::int64_t lo_b = std::min({r[a].b, r[ear].b, r[c].b}), hi_b = std::max({r[a].b, r[ear].b, r[c].b});
  return grid.all_of(lo_a, hi_a, lo_b, hi_b, [&](int p) {
    if (r.removed(p) || p == a || p == ear || p == c) return true;
    const Node& P = r[p];
    if (P.a < lo_a || P.a > hi_a || P.b < lo_b || P.b > hi_b) return true;
    if (r.same_place(p, a) || r.same_place(p, ear) || r.same_place(p, c)) return true;
    return !(r.cross(a, ear, p) >= 0 && r.cross(ear, c, p) >= 0 && r.cross(c, a, p) >= 0);
  });
}

void clip_ears(Ring& r, int ear, Triangles& out, const std::stop_token& cancel) {
  const NodeGrid grid(r, ear);
  int stop = ear;
  for (std::uint32_t step = 1; r.prev(ear) != r.next(ear); ++step) {
    if (step % 4096 == 0) stop_point(cancel);
    const int prev = r.prev(ear), next = r.next(ear);
    if (is_ear(r, grid, ear)) {
      out.push_back({r[prev].id, r[ear].id, r[next].id});
      r.remove(ear);
      ear = stop = next;
      continue;
    }
    ear = next;
    if (ear == stop) {  // a full turn without an ear: not a valid polygon; fan the rest
      for (int p = r.next(ear); r.next(p) != ear; p = r.next(p))
        out.push_back({r[ear].id, r[p].id, r[r.next(p)].id});
      return;
    }
  }
}

}  // namespace

void triangulate_polygon(const Loop& outer, const std::vector<Loop>& holes, Triangles& out,
                         const std::stop_token& stop) {
  if (outer.size() < 3) return;
  std::size_t total = outer.size();
  for (const Loop& h : holes) total += h.size() + 2;
  Ring r(total + 2 * holes.size());
  int start = r.link(outer, -1);

  // Holes in order of their leftmost vertex, so that each bridge reaches the outer loop or an earlier hole.
  std::vector<int> lefts;
  for (const Loop& hole : holes) {
    if (hole.size() < 3) continue;
    const int last = r.link(hole, -1);
    int left = last;
    for (int p = r.next(last); p != last; p = r.next(p))
      if (r[p].a < r[left].a || (r[p].a == r[left].a && r[p].b < r[left].b)) left = p;
    lefts.push_back(left);
  }
  std::sort(lefts.begin(), lefts.end(), [&](int x, int y) { return r[x].a != r[y].a ? r[x].a < r[y].a : r[x].b < r[y].b; });
  for (const int h : lefts) {
    stop_point(stop);
    const int bridge = find_bridge(r, h, start);
    if (bridge < 0) continue;  // the hole is not inside the outer loop: left open (breaks the contract)
    start = r.drop_repeats(r.split(bridge, h));
  }
  clip_ears(r, r.drop_repeats(start), out, stop);
}

}  // namespace roomsense::detail
