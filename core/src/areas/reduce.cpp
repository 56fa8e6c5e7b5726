// §3.4: centre deduplication and overlap reduction. The overlap tests use a bucket grid over X-Z so each
// rectangle meets only the kept ones near it; the result is that of the thesis's all-pairs loop.
#include "reduce.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace roomsense::detail {
namespace {

// The thesis tests corners (Eq. 3.45, 3.52) and, for squares, edge midpoints. We test the centre too, and
// the edge midpoints for walls as well: that also catches a rectangle crossing a kept one with all its
// corners outside it.
std::array<glm::dvec3, 9> test_points(const Candidate& c) {
  std::array<glm::dvec3, 9> p;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 a(c.corners[std::size_t(i)]), b(c.corners[std::size_t((i + 1) % 4)]);
    p[std::size_t(i)] = a;
    p[std::size_t(4 + i)] = 0.5 * (a + b);
    sum += a;
  }
  p[8] = 0.25 * sum;
  return p;
}

// Kept rectangles, bucketed by the X-Z cells (of kBucket voxels) their widened footprint covers.
class KeptIndex {
 public:
  static constexpr int kBucket = 8;
  void insert(std::size_t id, glm::dvec2 lo, glm::dvec2 hi) {
    for (int bz = bucket(lo.y); bz <= bucket(hi.y); ++bz)
      for (int bx = bucket(lo.x); bx <= bucket(hi.x); ++bx) buckets_[key(bx, bz)].push_back(id);
  }
  const std::vector<std::size_t>* near(const glm::dvec3& p) const {
    const auto it = buckets_.find(key(bucket(p.x), bucket(p.z)));
    return it == buckets_.end() ? nullptr : &it->second;
  }

 private:
  static int bucket(double v) { return int(std::floor(v / kBucket)); }
  static std::uint64_t key(int bx, int bz) { return (std::uint64_t(std::uint32_t(bx)) << 32) | std::uint32_t(bz); }
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;
};

// Keeps in[i] in order unless inside(m, q, p) holds for one of its test points m and a kept q.
template <class Inside>
std::vector<std::size_t> reduce_overlaps(const std::vector<Sized>& in, double widen, Inside inside) {
  std::vector<std::size_t> kept;  // positions in `in`
  KeptIndex index;                // holds positions in `kept`
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Candidate& p = in[i].c;
    bool overlaps = false;
    for (const glm::dvec3& m : test_points(p)) {
      if (const auto* near = index.near(m))
        overlaps = std::any_of(near->begin(), near->end(), [&](std::size_t k) { return inside(m, in[kept[k]].c, p); });
      if (overlaps) break;
    }
    if (overlaps) continue;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::ivec3& q : p.corners) {
      lo = glm::min(lo, glm::dvec2(q.x, q.z));
      hi = glm::max(hi, glm::dvec2(q.x, q.z));
    }
    index.insert(kept.size(), lo - widen, hi + widen);
    kept.push_back(i);
  }
  return kept;
}

}  // namespace

std::vector<Sized> deduplicate_centres(const std::array<Candidates, 3>& by_size) {
  std::vector<Sized> out;
  std::unordered_set<std::uint64_t> marked;
  for (std::size_t s = 0; s < by_size.size(); ++s)
    for (const Candidate& c : by_size[s]) {
      const glm::ivec3 sum = corner_sum(c);
      int xs[2], ys[2], zs[2];
      const int nx = centre_voxels(sum.x, xs), ny = centre_voxels(sum.y, ys), nz = centre_voxels(sum.z, zs);
      std::uint64_t keys[8];
      int n = 0;
      for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
          for (int k = 0; k < nz; ++k) keys[n++] = pack_key(xs[i], ys[j], zs[k]);
      if (std::any_of(keys, keys + n, [&](std::uint64_t key) { return marked.contains(key); })) continue;
      marked.insert(keys, keys + n);
      out.push_back({c, kAreaSizes[s]});
    }
  return out;
}

std::vector<std::size_t> reduce_wall_overlaps(const std::vector<Sized>& walls, int offset) {
  const double off = offset;
  return reduce_overlaps(walls, off, [&](const glm::dvec3& m, const Candidate& q, const Candidate&) {
    const glm::ivec3 &q1 = q.corners[0], &q2 = q.corners[1], &q3 = q.corners[2];
    return q3.y <= m.y && m.y < q1.y &&                                            // Eq. 3.45
           q1.x - off < m.x && m.x < q2.x + off &&                                 // Eq. 3.46
           std::min(q1.z, q2.z) - off < m.z && m.z < std::max(q1.z, q2.z) + off;  // Eq. 3.47
  });
}

std::vector<std::size_t> reduce_square_overlaps(const std::vector<Sized>& squares, int offset, bool furniture) {
  return reduce_overlaps(squares, 0.0, [&](const glm::dvec3& m, const Candidate& q, const Candidate& p) {
    if (furniture && !(q.corners[0].y - offset < p.corners[0].y && p.corners[0].y < q.corners[0].y + offset))
      return false;  // Eq. 3.49: another furniture level
    // Eq. 3.50 with A = q1, B = q2, D = q4 (Eq. 3.52), in the X-Z plane where the squares lie.
    const glm::dvec2 a(q.corners[0].x, q.corners[0].z), b(q.corners[1].x, q.corners[1].z),
        d(q.corners[3].x, q.corners[3].z), am(m.x - a.x, m.z - a.y);
    const glm::dvec2 ab = b - a, ad = d - a;
    const double u = glm::dot(am, ab), v = glm::dot(am, ad);
    return 0.0 < u && u < glm::dot(ab, ab) && 0.0 < v && v < glm::dot(ad, ad);
  });
}

}  // namespace roomsense::detail
