// Interaction levels of §3.5.1 (walls) and §3.5.2 (floors, ceilings, furniture): the nearest floor area that
// the area can see past the walls, in the X-Z plane, with line of sight by segment intersection (Eq. 3.59).
#include "../parallel.h"
#include "classify.h"
#include "list_match.h"
#include "../key_table.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace roomsense::detail {
namespace {

using P2 = glm::dvec2;

P2 xz(const glm::vec3& v) { return {v.x, v.z}; }

// Eq. 3.59: the sign of (z_b - z_a)(x_c - x_b) - (z_c - z_b)(x_b - x_a): 0 collinear, 1 and 2 the two turns.
int orientation(P2 a, P2 b, P2 c) {
  const double v = (b.y - a.y) * (c.x - b.x) - (c.y - b.y) * (b.x - a.x);
  return v == 0.0 ? 0 : (v > 0.0 ? 1 : 2);
}

bool on_segment(P2 a, P2 b, P2 p) {  // p collinear with a-b: does it lie between them?
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect(P2 p1, P2 q1, P2 p2, P2 q2) {  // [Geeks, 2020] as §3.5.1 describes it
  const int o1 = orientation(p1, q1, p2), o2 = orientation(p1, q1, q2);
  const int o3 = orientation(p2, q2, p1), o4 = orientation(p2, q2, q1);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(p1, q1, p2)) || (o2 == 0 && on_segment(p1, q1, q2)) ||
         (o3 == 0 && on_segment(p2, q2, p1)) || (o4 == 0 && on_segment(p2, q2, q1));
}

}  // namespace

// The upper edges of the wall areas V_Wall, bucketed on a grid in X-Z, so a line of sight meets only the
// walls along it (a grid walk) instead of all of them.
class WallSegments {
 public:
  struct Segment {
    P2 a, b;
  };
  // Walls of one footprint in X-Z (areas one above another on a wall: most of V_Wall) block and are excluded
  // alike, as reach reads nothing but that footprint: each footprint is bucketed once, by its first wall.
  WallSegments(const std::vector<ReachWall>& walls, double bucket) : size_(bucket) {
    segments_.reserve(walls.size());
    const auto footprint = [&](std::size_t i) {
      const ReachWall& w = walls[i];
      return std::array<float, 7>{w.top_left.x, w.top_left.y, w.top_right.x, w.top_right.y, w.center.x, w.center.y,
                                  w.half_width};
    };
    // A footprint's first wall, by a hash of its values (-0 as 0, as == compares them).
    const auto hash = [](const std::array<float, 7>& f) {
      WordHash h;
      for (const float v : f) h.add(v + 0.0f);
      return h.value();
    };
    FirstIndex first;
    first.reserve(walls.size());
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const ReachWall& w = walls[i];
      const Segment s{P2(w.top_left), P2(w.top_right)};
      segments_.push_back(s);
      const std::array<float, 7> mine = footprint(i);
      if (first.insert(hash(mine), std::uint32_t(i), [&](std::uint32_t j) { return footprint(j) == mine; }) != i)
        continue;  // repeated
      for (int bz = cell(std::min(s.a.y, s.b.y)); bz <= cell(std::max(s.a.y, s.b.y)); ++bz)
        for (int bx = cell(std::min(s.a.x, s.b.x)); bx <= cell(std::max(s.a.x, s.b.x)); ++bx)
          buckets_[key(bx, bz)].push_back(i);
    }
  }
  const Segment& segment(std::size_t i) const { return segments_[i]; }

  // Does any wall segment but the excluded ones cross the sight line from p to q? (The crossing, the cheaper
  // test, goes first.)
  template <class Excluded>
  bool blocked(P2 p, P2 q, Excluded excluded) const {
    bool hit = false;
    walk(p, q, [&](const std::vector<std::size_t>& ids) {
      for (std::size_t i : ids)
        if (segments_intersect(p, q, segments_[i].a, segments_[i].b) && !excluded(i)) return hit = true;
      return false;
    });
    return hit;
  }

 private:
  int cell(double v) const { return int(std::floor(v / size_)); }
  static std::uint64_t key(int bx, int bz) { return (std::uint64_t(std::uint32_t(bx)) << 32) | std::uint32_t(bz); }

  // Visits the buckets the segment p-q passes through (Amanatides-Woo), and where it passes exactly through a
  // bucket corner, the two buckets beside that corner; stops as soon as visit returns true.
  template <class Visit>
  void walk(P2 p, P2 q, Visit visit) const {
    const auto visit_bucket = [&](int bx, int bz) {
      const auto it = buckets_.find(key(bx, bz));
      return it != buckets_.end() && visit(it->second);
    };
    int bx = cell(p.x), bz = cell(p.y);
    const int ex = cell(q.x), ez = cell(q.y);
    const P2 d = q - p;
    const int sx = d.x > 0 ? 1 : -1, sz = d.y > 0 ? 1 : -1;
    const auto first_crossing = [&](double from, int c, int step, double delta) {
      return delta == 0.0 ? INFINITY : ((step > 0 ? c + 1 : c) * size_ - from) / delta;
    };
    double tx = first_crossing(p.x, bx, sx, d.x), tz = first_crossing(p.y, bz, sz, d.y);
    const double dtx = d.x == 0.0 ? INFINITY : size_ / std::abs(d.x);
    const double dtz = d.y == 0.0 ? INFINITY : size_ / std::abs(d.y);
    if (visit_bucket(bx, bz)) return;
    for (int steps = std::abs(ex - bx) + std::abs(ez - bz); steps > 0;) {
      if (tx < tz) {
        bx += sx, tx += dtx, steps -= 1;
      } else if (tz < tx) {
        bz += sz, tz += dtz, steps -= 1;
      } else {
        if (visit_bucket(bx + sx, bz) || visit_bucket(bx, bz + sz)) return;
        bx += sx, bz += sz, tx += dtx, tz += dtz, steps -= 2;
      }
      if (visit_bucket(bx, bz)) return;
    }
    if ((bx != ex || bz != ez) && visit_bucket(ex, ez)) return;  // rounding at a bucket border
  }

  double size_;
  std::vector<Segment> segments_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;
};

namespace {

// The floor areas V_Floor bucketed by centre on a grid in X-Z, to visit them nearest first without measuring
// the distance to every one of them from every area.
class FloorIndex {
 public:
  FloorIndex(const std::vector<ReachFloor>& floors, double bucket) : floors_(floors), size_(bucket) {
    if (floors.empty()) return;
    P2 lo(INFINITY), hi(-INFINITY);
    for (const ReachFloor& f : floors) {
      lo = glm::min(lo, P2(f.center)), hi = glm::max(hi, P2(f.center));
      max_half_ = std::max(max_half_, double(f.half_width));
    }
    origin_ = lo;
    nx_ = int((hi.x - lo.x) / size_) + 1, nz_ = int((hi.y - lo.y) / size_) + 1;
    // Bucket by bucket in one array, each bucket's floors in order (counted, then placed): a floor's areas are
    // tens of thousands, and a vector per bucket cost an allocation per few of them while the other thread waited.
    std::vector<std::size_t> bucket_of(floors.size());
    start_.assign(std::size_t(nx_) * std::size_t(nz_) + 1, 0);
    for (std::size_t i = 0; i < floors.size(); ++i) {
      const glm::ivec2 b = cell(P2(floors[i].center));
      bucket_of[i] = std::size_t(b.y) * std::size_t(nx_) + std::size_t(b.x);
      ++start_[bucket_of[i] + 1];
    }
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    members_.resize(floors.size());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < floors.size(); ++i) members_[next[bucket_of[i]]++] = i;
  }

  // Which floor areas `from` sees. Reach reads only whether the nearest visible one's gap is below `close`,
  // not the gap itself, so rather than every floor in gap order: the floors with a gap below `close` (only
  // those near `from`) in any order, then the others. Within at the first visible one of the first, Beyond at
  // the first of the second, None when no floor for which gap_of gives a value is visible; with the floor that
  // decided. gap_of must be at least the centre distance less `slack` and less the floor's half width, which
  // bounds where the near ones lie. Buckets are visited nearest first, where a visible floor is likeliest.
  enum class Visible : std::uint8_t { None, Within, Beyond };
  struct Found {
    Visible visible = Visible::None;
    const ReachFloor* floor = nullptr;
  };
  template <class GapOf, class IsVisible>
  Found visible_floor(P2 from, double slack, double close, GapOf gap_of, IsVisible visible) const {
    if (floors_.empty()) return {};
    const glm::ivec2 c = cell(from);  // may lie outside the grid
    const int last_ring = std::max({std::abs(c.x), std::abs(c.y), std::abs(nx_ - 1 - c.x), std::abs(nz_ - 1 - c.y)});
    // Centres in ring r lie at least r - 1 buckets away, so their gaps are at least that less the slack and
    // the largest half width.
    const double near_reach = std::ceil((close + slack + max_half_) / size_) + 1.0;
    // Clamped before the conversion: an engine's AreaParams may hold any close distance, NaN included.
    const int near_rings = near_reach >= -1.0 && near_reach <= double(last_ring) ? int(near_reach)
                           : near_reach < -1.0                                    ? -1
                                                                                  : last_ring;
    const auto first_visible = [&](int rings, bool near) -> const ReachFloor* {
      for (int ring = 0; ring <= rings; ++ring)
        for (int bz = c.y - ring; bz <= c.y + ring; ++bz)
          for (int bx = c.x - ring; bx <= c.x + ring; ++bx) {
            if (std::max(std::abs(bx - c.x), std::abs(bz - c.y)) != ring || bx < 0 || bz < 0 || bx >= nx_ || bz >= nz_)
              continue;
            const std::size_t b = std::size_t(bz) * std::size_t(nx_) + std::size_t(bx);
            for (std::size_t k = start_[b]; k < start_[b + 1]; ++k) {
              const std::size_t i = members_[k];
              const std::optional<double> gap = gap_of(floors_[i]);
              if (gap && (*gap < close) == near && visible(floors_[i], *gap)) return &floors_[i];
            }
          }
      return nullptr;
    };
    if (const ReachFloor* near = first_visible(near_rings, true)) return {Visible::Within, near};
    if (const ReachFloor* far = first_visible(last_ring, false)) return {Visible::Beyond, far};
    return {};
  }

 private:
  glm::ivec2 cell(P2 p) const {
    return {int(std::floor((p.x - origin_.x) / size_)), int(std::floor((p.y - origin_.y) / size_))};
  }
  const std::vector<ReachFloor>& floors_;
  double size_;
  P2 origin_{0.0};
  int nx_ = 0, nz_ = 0;
  double max_half_ = 0.0;
  std::vector<std::size_t> start_;    // bucket b's floors: members_[start_[b], start_[b + 1])
  std::vector<std::size_t> members_;  // indices into floors_, bucket by bucket
};

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

ReachMemo::FloorKey key_of(const ReachFloor& f) { return {bits(f.center.x), bits(f.center.y), bits(f.half_width)}; }

// What reach_of reads of an area to find what it sees (its height only decides Close, anew each time).
ReachMemo::AreaKey key_of(const Area& a) {
  return {std::uint32_t(a.type), bits(a.center.x), bits(a.center.z), bits(a.half_width),
          bits(a.normal.x), bits(a.normal.z), bits(a.corners[3].x), bits(a.corners[3].z), bits(a.corners[2].x),
          bits(a.corners[2].z)};
}

template <std::size_t N>
std::uint64_t hash_of(const std::array<std::uint32_t, N>& key) {
  WordHash h;
  for (const std::uint32_t word : key) h.add(word);
  return h.value();
}

// The first index of each key of a list.
template <class Key>
class KeyIndex {
 public:
  explicit KeyIndex(const std::vector<Key>& keys) : keys_(keys) {
    index_.reserve(keys.size());
    for (std::uint32_t i = 0; i < keys.size(); ++i)
      index_.insert(hash_of(keys[i]), i, [&](std::uint32_t j) { return keys[j] == keys[i]; });
  }
  std::uint32_t find(const Key& key) const {
    return index_.find(hash_of(key), [&](std::uint32_t j) { return keys_[j] == key; });
  }

 private:
  const std::vector<Key>& keys_;
  FirstIndex index_;
};

bool same_walls(const std::vector<ReachWall>& a, const std::vector<ReachWall>& b) {
  const auto words = [](const ReachWall& w) {
    return std::array<std::uint32_t, 7>{bits(w.center.x), bits(w.center.y), bits(w.half_width), bits(w.top_left.x),
                                        bits(w.top_left.y), bits(w.top_right.x), bits(w.top_right.y)};
  };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](const ReachWall& x, const ReachWall& y) { return words(x) == words(y); });
}

std::vector<ReachMemo::FloorKey> floor_keys(const std::vector<ReachFloor>& floors) {
  std::vector<ReachMemo::FloorKey> keys;
  keys.reserve(floors.size());
  for (const ReachFloor& f : floors) keys.push_back(key_of(f));
  return keys;
}

}  // namespace

std::shared_ptr<const WallSegments> reach_segments(const std::vector<ReachWall>& walls, const ReachMemo* memo) {
  if (memo != nullptr && memo->segments && same_walls(memo->walls, walls)) return memo->segments;
  return std::make_shared<const WallSegments>(walls, 1.0);
}

struct ReachView::State {
  State(const std::vector<ReachFloor>& floors_, const std::vector<ReachWall>& walls_,
        std::shared_ptr<const WallSegments> segments_, const ReachMemo* memo_, const AreaParams& params)
      : floors(floors_), walls(walls_), segments(std::move(segments_)), memo(memo_),
        scalars{bits(params.close_distance), bits(params.wall_view_cone_deg)}, close(params.close_distance),
        cone_cos(std::cos(double(params.wall_view_cone_deg) * std::numbers::pi / 180.0)) {}
  const std::vector<ReachFloor>& floors;
  const std::vector<ReachWall>& walls;
  std::shared_ptr<const WallSegments> segments;
  const ReachMemo* memo;
  std::array<std::uint32_t, 2> scalars;
  double close, cone_cos;
  bool known = false;        // the memo's areas were seen against these walls and parameters
  bool same_floors = false;  // and these floors, in this order
  std::vector<ReachMemo::FloorKey> keys;  // with a memo: the floors'
  // Where known and the floors differ: the floors the memo's did not have, and where the memo's still are. A change
  // moves the floors near it alone, and the lists keep their order (list_match.h). (V_Floor holds a centre once,
  // Eq. 3.44, so a key names one floor; a floor taken for added or gone has its areas searched again, never
  // misread.)
  std::vector<std::size_t> added;
  std::vector<std::uint32_t> now_at;  // per floor of the memo: its index in `floors`, or FirstIndex::kAbsent
  // The index in `floors` of the memo's floor `before` (its key `key`), if it is still there.
  std::uint32_t now_of(std::uint32_t before, const ReachMemo::FloorKey& key) const {
    const std::uint32_t at = before < now_at.size() ? now_at[before] : FirstIndex::kAbsent;
    return at < keys.size() && keys[at] == key ? at : FirstIndex::kAbsent;
  }
  // The floors' buckets, made by the first search: where the memo decides every area (a re-sent chunk), none.
  std::once_flag index_made;
  std::optional<FloorIndex> floor_index;
  const FloorIndex& index() {
    std::call_once(index_made, [&] { floor_index.emplace(floors, 1.0); });
    return *floor_index;
  }
};

ReachView::ReachView(const std::vector<ReachFloor>& floors, const std::vector<ReachWall>& walls, const AreaParams& params,
                     const ReachMemo* memo, std::shared_ptr<const WallSegments> wall_segments)
    // The walls' buckets, the memo's where its walls are these (then reach_segments gave its own).
    : state_(std::make_unique<State>(floors, walls, wall_segments ? std::move(wall_segments) : reach_segments(walls, memo),
                                     memo, params)) {
  State& v = *state_;
  if (memo == nullptr) return;
  v.known = memo->segments && v.segments == memo->segments && memo->scalars == v.scalars;
  v.keys = floor_keys(floors);
  v.same_floors = v.known && v.keys == memo->floors;
  if (!v.known || v.same_floors) return;
  const std::vector<ReachMemo::FloorKey>& before = memo->floors;
  const std::vector<std::uint32_t> was_at = match_in_order(
      std::span<const ReachMemo::FloorKey>(before), std::span<const ReachMemo::FloorKey>(v.keys),
      [](const ReachMemo::FloorKey& a, const ReachMemo::FloorKey& b) { return a == b; },
      [](const ReachMemo::FloorKey& key) { return hash_of(key); });
  v.now_at.assign(before.size(), FirstIndex::kAbsent);
  for (std::size_t i = 0; i < was_at.size(); ++i)
    if (was_at[i] == FirstIndex::kAbsent) v.added.push_back(i);
    else v.now_at[was_at[i]] = std::uint32_t(i);
}

ReachView::~ReachView() = default;

void ReachView::keep(ReachMemo& memo, std::span<ReachMemo::Seen> next) const {
  const State& v = *state_;
  for (std::size_t i = 0; i < next.size() && i < memo.lists.size(); ++i) {
    if (next[i].same) memo.lists[i].searched = next[i].searched;
    else memo.lists[i] = std::move(next[i]);
  }
  if (!v.same_floors) memo.floors = v.keys;
  if (v.known) return;  // the walls, their segments and the parameters are the memo's
  memo.walls = v.walls;
  memo.scalars = v.scalars;
  memo.segments = v.segments;
}

void assign_reach(std::vector<Area>& areas, const ReachView& view, float floor_y, const AreaParams& params,
                  unsigned threads, std::size_t list, ReachMemo::Seen* next) {
  ReachView::State& v = *view.state_;
  const ReachMemo::Seen* memo = v.memo != nullptr ? &v.memo->lists[list] : nullptr;
  const std::vector<ReachFloor>& floors = v.floors;
  const std::vector<ReachWall>& walls = v.walls;
  const WallSegments& segments = *v.segments;
  const double close = v.close;
  const double cone_cos = v.cone_cos;
  using Visible = FloorIndex::Visible;
  std::vector<ReachMemo::AreaKey> area_keys;
  if (memo != nullptr) {
    area_keys.reserve(areas.size());
    for (const Area& a : areas) area_keys.push_back(key_of(a));
  }
  // The same floors and areas in the same order (a re-sent chunk that moved none): each area sees what it saw,
  // through the same floor, and the memo stays as it is.
  const bool same_lists = v.known && v.same_floors && area_keys == memo->areas;
  std::optional<KeyIndex<ReachMemo::AreaKey>> areas_before;
  if (v.known && !same_lists) areas_before.emplace(memo->areas);
  std::vector<FloorIndex::Found> found(memo != nullptr ? areas.size() : 0);
  std::atomic<std::size_t> searched = 0;

  // What an area sees: from its previous analysis's, where that holds, else by a search of the floors. Previously
  // Within: while the floor that showed it is there. Beyond or None: no floor then was near and visible, so only an
  // added one can be; and Beyond holds while its floor is there. (`j`: the area's entry in the memo.)
  const auto look = [&](P2 c, double slack, auto gap_of, auto visible, std::uint32_t j) -> FloorIndex::Found {
    if (j != FirstIndex::kAbsent) {
      const auto seen = Visible(memo->seen[j]);
      const std::uint32_t at = seen == Visible::None ? FirstIndex::kAbsent
                               : v.same_floors        ? memo->witness_at[j]
                                                      : v.now_of(memo->witness_at[j], memo->witness[j]);
      const FloorIndex::Found before{seen, at == FirstIndex::kAbsent ? nullptr : &floors[at]};
      if (seen == Visible::Within && before.floor) return before;
      if (seen == Visible::None || (seen == Visible::Beyond && before.floor)) {
        FloorIndex::Found now = before;
        for (const std::size_t i : v.added) {
          const std::optional<double> gap = gap_of(floors[i]);
          if (!gap || (*gap >= close && now.visible != Visible::None)) continue;
          if (visible(floors[i], *gap)) {
            if (*gap < close) return {Visible::Within, &floors[i]};
            now = {Visible::Beyond, &floors[i]};
          }
        }
        return now;
      }
    }
    searched.fetch_add(1, std::memory_order_relaxed);
    return v.index().visible_floor(c, slack, close, gap_of, visible);
  };

  const auto reach_of = [&](const Area& area, std::uint32_t j, FloorIndex::Found* decided) {
    const P2 c = xz(area.center);
    const auto sight = [&](const ReachFloor& floor, auto excluded) {
      return !segments.blocked(c, P2(floor.center), excluded);
    };
    if (area.type == AreaType::Wall) {
      // §3.5.1: a floor area within 60° of the normal, seen past every wall area not on this same wall (those
      // whose top edge meets ours, or that come within 20 cm of it).
      const P2 n = glm::normalize(xz(area.normal));
      const P2 top_a = xz(area.corners[3]), top_b = xz(area.corners[2]);
      const auto same_wall = [&](std::size_t i) {
        const WallSegments::Segment& s = segments.segment(i);
        return segments_intersect(top_a, top_b, s.a, s.b) ||
               glm::distance(c, P2(walls[i].center)) - area.half_width - walls[i].half_width < close;
      };
      const auto gap = [&](const ReachFloor& floor) -> std::optional<double> {
        const P2 u = P2(floor.center) - c;
        const double len = glm::length(u);
        if (len == 0.0 || glm::dot(u, n) < cone_cos * len) return std::nullopt;
        return len - floor.half_width;
      };
      const auto visible = [&](const ReachFloor& f, double) { return sight(f, same_wall); };
      const FloorIndex::Found seen = *decided = look(c, 0.0, gap, visible, j);
      if (seen.visible == Visible::None) return Reach::None;
      const bool low = area.center.y - floor_y <= params.close_height;
      return low && seen.visible == Visible::Within ? Reach::Close : Reach::Distance;
    }
    // §3.5.2: the distance between centres less both half sizes; overlapping areas need no line of sight.
    const auto none = [](std::size_t) { return false; };
    const auto gap = [&](const ReachFloor& floor) -> std::optional<double> {
      return glm::distance(c, P2(floor.center)) - area.half_width - floor.half_width;
    };
    const FloorIndex::Found seen = *decided = look(c, area.half_width, gap, [&](const ReachFloor& f, double g) {
      return g <= 0.0 || sight(f, none);
    }, j);
    if (seen.visible == Visible::None) return Reach::None;
    if (area.type == AreaType::Ceiling) return Reach::Distance;  // never within reach of a hand
    return seen.visible == Visible::Within ? Reach::Close : Reach::Distance;
  };

  // Where the memo holds for the whole list (a re-sent chunk that moved nothing), each area is a lookup: on one
  // thread, as the list is one task of the area graph beside the others' (a loop's hand-over would cost more).
  parallel_for(areas.size(), same_lists ? 1 : threads, 16, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t i = begin; i < end; ++i) {
      FloorIndex::Found decided;
      const std::uint32_t j = same_lists ? std::uint32_t(i)
                              : v.known  ? areas_before->find(area_keys[i])
                                         : FirstIndex::kAbsent;
      areas[i].reach = reach_of(areas[i], j, &decided);
      areas[i].flags = category_flags(areas[i].type, areas[i].size, areas[i].reach);
      if (memo != nullptr) found[i] = decided;
    }
  });
  if (memo == nullptr || next == nullptr) return;
  if (same_lists) {
    *next = {{}, {}, {}, {}, searched.load(), true};  // none searched
    return;
  }
  *next = {std::move(area_keys), {}, {}, {}, searched.load(), false};
  next->seen.reserve(found.size());
  next->witness.reserve(found.size());
  next->witness_at.reserve(found.size());
  for (const FloorIndex::Found& f : found) {
    next->seen.push_back(std::uint8_t(f.visible));
    next->witness.push_back(f.floor ? key_of(*f.floor) : ReachMemo::FloorKey{});
    next->witness_at.push_back(f.floor ? std::uint32_t(f.floor - floors.data()) : FirstIndex::kAbsent);
  }
}

void assign_reach(std::vector<Area>& areas, const std::vector<ReachFloor>& floors, const std::vector<ReachWall>& walls,
                  float floor_y, const AreaParams& params, unsigned threads, ReachMemo* memo,
                  std::shared_ptr<const WallSegments> wall_segments) {
  const ReachView view(floors, walls, params, memo, std::move(wall_segments));
  std::array<ReachMemo::Seen, 1> next;
  assign_reach(areas, view, floor_y, params, threads, 0, memo != nullptr ? &next[0] : nullptr);
  if (memo != nullptr) view.keep(*memo, next);
}

}  // namespace roomsense::detail
