// §3.4: centre deduplication (Eq. 3.42-3.44), then packing (reduce.h says why it replaces Eq. 3.45-3.53): each
// kept rectangle marks its half-voxel surface samples in a bit raster (sample_raster.h), so a candidate meets
// only what lies under it.
#include "reduce.h"

#include "../floor_int.h"
#include "../key_table.h"
#include "sample_raster.h"
#include "roomsense/cancel.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>

namespace roomsense::detail {
namespace {

// Half-voxel sample points of a rectangle's surface, strictly inside it: two rectangles that only share an
// edge share none, two that overlap by a strip of half a voxel or more share some.
constexpr double kSample = 0.5;  // voxels

// A wall rectangle's top edge from corner 1 (Eq. 3.26) as its samples walk it: its length and direction,
// which depend on its shape alone (corners 1 and 2 are voxel centres, so p2 - p1 is exactly (dx, dz)).
struct WallLine {
  double length = 0.0;
  glm::dvec2 dir{0.0};
};
WallLine wall_line(int dx, int dz) {
  const glm::dvec2 d(dx, dz);
  const double length = glm::length(d);
  return {length, length > 0.0 ? d / length : glm::dvec2(0.0)};
}

// Calls f(sx, sz, sy0, sy1) for each run of sample cells (half-voxel indices) sy0..sy1 of a wall rectangle at
// one (sx, sz), at `layer` voxels off its plane along its horizontal normal, until f returns false. The
// rectangle runs between voxel centres (Eq. 3.54); `line` is its top edge's. Returns whether every run was
// visited.
template <class F>
bool wall_samples(const PackedCandidate& wall, const WallLine& line, int layer, F f) {
  const glm::ivec3 first = wall.corner(0);
  const glm::dvec2 p1(first.x + 0.5, first.z + 0.5);
  if (line.length <= 0.0) return true;
  const glm::dvec2 dir = line.dir, normal(-dir.y, dir.x);
  // The samples up the wall, y_lo + 1/4, y_lo + 3/4, ... below y_hi (y = level + 1/2 at corners 3 and 1), are
  // the same run at every step along it: half-voxel cells 2 y3 + 1 to 2 y1.
  const long sy0 = 2L * wall.corner(2).y + 1, sy1 = 2L * first.y;
  if (sy1 < sy0) return true;
  for (double t = 0.5 * kSample; t < line.length; t += kSample) {
    const glm::dvec2 p = p1 + t * dir + double(layer) * normal;
    if (!f(long(floor_int(p.x / kSample)), long(floor_int(p.y / kSample)), sy0, sy1)) return false;
  }
  return true;
}

// Whether a square's corners run along the grid's axes, and if so the box of their voxels.
struct AxisBox {
  int lo_x, hi_x, lo_z, hi_z;
};
// For a Candidate or a PackedCandidate (its corners computed as needed, not unpacked into memory).
template <class Square>
std::optional<AxisBox> axis_box(const Square& square) {
  const auto corner = [&](std::size_t k) {
    if constexpr (std::is_same_v<Square, Candidate>) return square.corners[k];
    else return square.corner(k);
  };
  const glm::ivec3 first = corner(0), e = corner(1) - first;
  if (e.x != 0 && e.z != 0) return std::nullopt;
  AxisBox b{first.x, first.x, first.z, first.z};
  for (std::size_t i = 1; i < 4; ++i) {
    const glm::ivec3 k = corner(i);
    b.lo_x = std::min(b.lo_x, k.x), b.hi_x = std::max(b.hi_x, k.x);
    b.lo_z = std::min(b.lo_z, k.z), b.hi_z = std::max(b.hi_z, k.z);
  }
  return b;
}

// Calls f(sz, sx0, sx1) for each run of half-voxel sample cells sx0..sx1 in row sz whose centres lie strictly
// inside the square, until f returns false. Returns whether every run was visited.
template <class F>
bool square_samples(const Candidate& c, F f) {
  if (const std::optional<AxisBox> b = axis_box(c)) {
    // Along the grid's axes the inside samples are exactly those a quarter voxel or more from the edges:
    // half-voxel cells 2 min + 1 to 2 max on each axis (the corners are voxel centres), no tests needed.
    if (b->hi_x <= b->lo_x) return true;
    for (long sz = 2L * b->lo_z + 1; sz <= 2L * b->hi_z; ++sz)
      if (!f(sz, 2L * b->lo_x + 1, 2L * b->hi_x)) return false;
    return true;
  }
  std::array<glm::dvec2, 4> v;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (std::size_t i = 0; i < 4; ++i) {
    v[i] = glm::dvec2(c.corners[i].x + 0.5, c.corners[i].z + 0.5);
    lo = glm::min(lo, v[i]);
    hi = glm::max(hi, v[i]);
  }
  // The corners go round the square one way or the other: inside is on one side of every edge.
  const auto side = [&](std::size_t i, const glm::dvec2& p) {
    const glm::dvec2 e = v[(i + 1) % 4] - v[i], q = p - v[i];
    return e.x * q.y - e.y * q.x;
  };
  const double sign = side(0, 0.25 * (v[0] + v[1] + v[2] + v[3])) > 0.0 ? 1.0 : -1.0;
  // Corners and sample centres are multiples of 1/4 well below 2^20: every product in `side` is exact, so
  // `inside` is an exact half-plane test and a row's inside samples are one run. Its ends come from the
  // edges' crossings of the row and are then settled by `inside` itself, sample by sample.
  const auto inside = [&](long sx, long sz) {
    const glm::dvec2 p((double(sx) + 0.5) * kSample, (double(sz) + 0.5) * kSample);
    for (std::size_t i = 0; i < 4; ++i)
      if (!(sign * side(i, p) > 1e-9)) return false;
    return true;
  };
  const long x_first = long(floor_int(lo.x / kSample)), x_last = long(floor_int(hi.x / kSample));
  for (long sz = long(floor_int(lo.y / kSample)); sz <= long(floor_int(hi.y / kSample)); ++sz) {
    const double z = (double(sz) + 0.5) * kSample;
    double x_lo = INFINITY, x_hi = -INFINITY;  // where the row's line crosses the square's edges
    for (std::size_t i = 0; i < 4; ++i) {
      const glm::dvec2 a = v[i], b = v[(i + 1) % 4];
      if ((a.y - z) * (b.y - z) > 0.0 || a.y == b.y) continue;
      const double x = a.x + (b.x - a.x) * (z - a.y) / (b.y - a.y);
      x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
    }
    // Two samples of slack each way cover the crossings' rounding; the run lies within and is then trimmed.
    long s0 = x_first, s1 = x_last;
    if (x_lo <= x_hi) {
      s0 = std::max(x_first, long(floor_int(x_lo / kSample)) - 2);
      s1 = std::min(x_last, long(floor_int(x_hi / kSample)) + 2);
    }
    while (s0 <= s1 && !inside(s0, sz)) ++s0;
    while (s1 >= s0 && !inside(s1, sz)) --s1;
    if (s0 <= s1 && !f(sz, s0, s1)) return false;
  }
  return true;
}

// Contact's samples along edge i of square c (corner i to corner i + 1) where the edge runs off the grid's
// axes: every half voxel from corner i's voxel centre, 0.75 voxels outside the square. Calls f(p) for each, in
// voxels.
template <class F>
void off_axis_contact_samples(const Candidate& c, std::size_t i, F f) {
  const glm::ivec3 sum = corner_sum(c);  // 4 x the middle
  const glm::dvec2 mid = glm::dvec2(sum.x, sum.z) * 0.25 + 0.5;
  const glm::dvec2 a(c.corners[i].x + 0.5, c.corners[i].z + 0.5);
  const glm::dvec2 b(c.corners[(i + 1) % 4].x + 0.5, c.corners[(i + 1) % 4].z + 0.5);
  const double length = glm::distance(a, b);
  const glm::dvec2 dir = (b - a) / length;
  glm::dvec2 out(-dir.y, dir.x);
  if (glm::dot(out, 0.5 * (a + b) - mid) < 0.0) out = -out;
  for (double t = 0.0; t <= length; t += kSample) f(a + t * dir + 0.75 * out);
}

// The sample cell holding a square's middle, where it is one of the square's samples. Off the grid's axes it
// always is: an edge of integer steps along both axes is at least sqrt(2) voxels long, so the middle lies at
// least 0.7 voxels inside every edge, and its cell's centre at most 0.36 voxels from it.
std::optional<std::array<long, 2>> middle_sample(const PackedCandidate& c) {
  // Corners are voxel indices and voxel centres lie at index + 1/2: the middle lies at sum / 4 + 1/2 voxels, in
  // half-voxel cell floor(sum / 2) + 1 (an arithmetic shift floors).
  const glm::ivec3 sum = c.corner_sum();
  const std::array<long, 2> s{long(sum.x >> 1) + 1L, long(sum.z >> 1) + 1L};
  const std::optional<AxisBox> b = axis_box(c);
  if (b && !(b->hi_x > b->lo_x && s[0] >= 2L * b->lo_x + 1 && s[0] <= 2L * b->hi_x && s[1] >= 2L * b->lo_z + 1 &&
             s[1] <= 2L * b->hi_z))
    return std::nullopt;
  return s;
}

double angle_mod_90(int dx, int dz) {
  const double a = std::atan2(double(dz), double(dx)) * 180.0 / std::numbers::pi;
  return std::fmod(std::fmod(a, 90.0) + 90.0, 90.0);
}

}  // namespace

CentreDeduplicator::CentreDeduplicator(const GridSpec& spec, std::stop_token stop)
    : nx_(std::max(spec.nx, 0)), nz_(std::max(spec.nz, 0)), levels_(std::size_t(std::max(spec.ny, 0)) + 2),
      stop_(std::move(stop)) {}
CentreDeduplicator::~CentreDeduplicator() = default;

std::size_t CentreDeduplicator::add(const Candidates& rects, AreaSize size,
                                    const std::function<void(const Sized&)>& keep) {
  // A rectangle's centre voxels are corner 1's plus its shape's: corner_sum is 4 x corner 1 plus the shape's own
  // sum, and floor((4 c + s) / 4) = c + floor(s / 4). One voxel per axis, or two neighbours where the centre
  // lies between them: a box from lo, found once per shape.
  struct CentreBox {
    glm::ivec3 lo;
    int ex, ey, ez;  // the box's extent past lo on each axis: 0 or 1
    // lo + corner 1 lies in [0, limit) on each axis, y one level higher (y_Actual), where the box lies in the
    // grid's columns and levels.
    unsigned limit_x, limit_y, limit_z;
  };
  std::vector<CentreBox> offsets;
  const auto limit = [](int cells, int extent) { return unsigned(std::max(cells - extent, 0)); };
  for (const Candidates::Shape& shape : rects.shapes()) {
    const glm::ivec3 sum = PackedCandidate(glm::ivec3(0), shape.dx, shape.dz, shape.side).corner_sum();
    int x[2], y[2], z[2];
    const int nx = centre_voxels(sum.x, x), ny = centre_voxels(sum.y, y), nz = centre_voxels(sum.z, z);
    offsets.push_back({{x[0], y[0], z[0]}, nx - 1, ny - 1, nz - 1, limit(nx_, nx - 1),
                       limit(int(levels_.size()), ny - 1), limit(nz_, nz - 1)});
  }
  const std::size_t row = std::size_t(nx_);
  std::size_t kept = 0;
  for (std::size_t r = 0; r < rects.size(); ++r) {
    if (r % kStopEvery == 0) stop_point(stop_);
    const Candidates::Item& item = rects.item(r);
    const PackedCandidate p = rects.decode(item);
    const glm::ivec3 c = p.corner(0);
    const CentreBox& o = offsets[item.shape];
    const int x0 = c.x + o.lo.x, y0 = c.y + o.lo.y, z0 = c.z + o.lo.z;
    // Centres lie within their corners' box, in the grid's columns and levels: one unsigned comparison an axis.
    if (unsigned(x0) >= o.limit_x || unsigned(y0 + 1) >= o.limit_y || unsigned(z0) >= o.limit_z)
      throw std::logic_error("a rectangle's centre outside its grid");
    const std::size_t i = std::size_t(z0) * row + std::size_t(x0);
    // The box's cells at a level: (x0, z0), and x0 + 1 and z0 + 1 where it reaches them.
    const auto marked_at = [&](const BitSet& bits) {
      const auto in_row = [&](std::size_t at) { return bits.test(at) || (o.ex != 0 && bits.test(at + 1)); };
      return in_row(i) || (o.ez != 0 && in_row(i + row));
    };
    const std::optional<BitSet>& lower = levels_[std::size_t(y0 + 1)];
    if (lower && marked_at(*lower)) continue;
    if (o.ey != 0) {
      const std::optional<BitSet>& upper = levels_[std::size_t(y0 + 2)];
      if (upper && marked_at(*upper)) continue;
    }
    for (int y = y0; y <= y0 + o.ey; ++y) {
      std::optional<BitSet>& bits = levels_[std::size_t(y + 1)];
      if (!bits) bits.emplace(row * std::size_t(nz_));
      for (int z = 0; z <= o.ez; ++z)
        for (int x = 0; x <= o.ex; ++x) bits->set(i + std::size_t(z) * row + std::size_t(x));
    }
    keep({p, size});
    ++kept;
  }
  return kept;
}

double dominant_direction_deg(const std::vector<Sized>& walls) {
  std::array<double, 90> weight{};
  // Walls' first edges are ring offsets, a few hundred distinct ones among thousands of walls: each offset's
  // degree and length once (an atan2, two fmods and a hypot), added in the walls' order as before.
  struct Offset {
    std::size_t degree;
    double length;
  };
  std::vector<Offset> offsets;
  KeyTable index;  // an offset's place in `offsets`
  for (const Sized& w : walls) {
    const Candidate c = w.c();
    const glm::ivec3 e = c.corners[1] - c.corners[0];
    const std::uint64_t key = pack_key(e.x, 0, e.z);  // edges lie in the grid: far below 2^20 voxels an axis
    std::uint32_t at = index.find(key);
    if (at == KeyTable::kAbsent) {
      at = std::uint32_t(offsets.size());
      index.insert(key, at);
      offsets.push_back({std::size_t(std::lround(angle_mod_90(e.x, e.z))) % 90, std::hypot(double(e.x), double(e.z))});
    }
    weight[offsets[at].degree] += offsets[at].length;
  }
  std::size_t best = 0;
  double best_weight = 0.0;
  for (std::size_t a = 0; a < 90; ++a) {  // smoothed over ±1°
    const double w = weight[(a + 89) % 90] + weight[a] + weight[(a + 1) % 90];
    if (w > best_weight) best_weight = w, best = a;
  }
  return double(best);
}

double misalignment_deg(const Candidate& square, double dominant_deg) {
  const glm::ivec3 e = square.corners[1] - square.corners[0];
  const double d = std::fabs(angle_mod_90(e.x, e.z) - dominant_deg);
  return std::min(d, 90.0 - d);
}

ChangedRegion::Box ChangedRegion::around(const Candidate& c) {
  Box b{glm::ivec2(c.corners[0].x, c.corners[0].z), glm::ivec2(c.corners[0].x, c.corners[0].z)};
  for (const glm::ivec3& k : c.corners) b.lo = glm::min(b.lo, glm::ivec2(k.x, k.z)), b.hi = glm::max(b.hi, glm::ivec2(k.x, k.z));
  return {b.lo - 2, b.hi + 2};
}

std::vector<ChangedRegion::Box> ChangedRegion::around_shapes(std::span<const Candidates::Shape> shapes) {
  std::vector<Box> boxes;
  boxes.reserve(shapes.size());
  for (const Candidates::Shape& shape : shapes)
    boxes.push_back(around(PackedCandidate(glm::ivec3(0), shape.dx, shape.dz, shape.side).unpack()));
  return boxes;
}

ChangedRegion::Box ChangedRegion::around(const PackedCandidate& c, const Box& shape_box) {
  const glm::ivec3 first = c.corner(0);
  const glm::ivec2 at(first.x, first.z);
  return {at + shape_box.lo, at + shape_box.hi};
}

ChangedRegion::ChangedRegion(const Box& columns)
    : origin_(columns.lo),
      columns_(std::max(1, (columns.hi.x - columns.lo.x) / kBlock + 1)),
      rows_(std::max(1, (columns.hi.y - columns.lo.y) / kBlock + 1)),
      words_per_row_(std::size_t(columns_ + 63) / 64),
      bits_(words_per_row_ * std::size_t(rows_), 0) {}

ChangedRegion::Blocks ChangedRegion::blocks(const Box& b) const {
  const auto block = [&](glm::ivec2 column) {
    return glm::clamp((glm::max(column, origin_) - origin_) / kBlock, glm::ivec2(0), glm::ivec2(columns_ - 1, rows_ - 1));
  };
  return {block(b.lo), block(b.hi)};
}

void ChangedRegion::add(const Box& b) {
  added_ = empty_ ? b : Box{glm::min(added_.lo, b.lo), glm::max(added_.hi, b.hi)};
  const Blocks k = blocks(b);
  empty_ = false;
  for (int z = k.lo.y; z <= k.hi.y; ++z)
    for (int x = k.lo.x; x <= k.hi.x; ++x) bits_[std::size_t(z) * words_per_row_ + std::size_t(x / 64)] |= std::uint64_t{1} << (x % 64);
}

bool ChangedRegion::touches_blocks(const Box& b) const {
  const Blocks k = blocks(b);
  for (int z = k.lo.y; z <= k.hi.y; ++z) {
    const std::uint64_t* row = bits_.data() + std::size_t(z) * words_per_row_;
    for (int x = k.lo.x; x <= k.hi.x; x = (x / 64 + 1) * 64) {
      const int last = std::min(k.hi.x, (x / 64) * 64 + 63);
      const std::uint64_t mask = (~std::uint64_t{0} >> (63 - (last % 64))) & (~std::uint64_t{0} << (x % 64));
      if (row[x / 64] & mask) return true;
    }
  }
  return false;
}

namespace {

// A replayed packing (PackReplay): item i's previous decision where nothing that changed lies near it (`around`,
// ChangedRegion::around of the item), else nothing (the packer tests it, and notes the change where its decision
// differs).
std::optional<bool> previous_decision(const PackReplay* replay, std::size_t i, const ChangedRegion::Box& around,
                                      const ChangedRegion& changed) {
  if (!replay || replay->previous[i] == PackReplay::kUnknown || changed.touches(around)) return std::nullopt;
  return replay->previous[i] == PackReplay::kPacked;
}
void note_decision(const PackReplay* replay, std::size_t i, const ChangedRegion::Box& around, bool packed,
                   ChangedRegion& changed) {
  // An item refused now and unknown before changes nothing.
  if (replay && packed != (replay->previous[i] == PackReplay::kPacked)) changed.add(around);
}

}  // namespace

WallPacker::WallPacker(const GridSpec& spec, int y_lo, int y_hi, std::stop_token stop)
    // A wall's samples, and those a voxel off its plane, lie within a voxel and a half of its corners:
    // half-voxel cells 2 k - 4 to 2 k + 4 around a corner's index k on each axis.
    : taken_(std::make_unique<SampleRaster>(-4, 2L * spec.nx + 4, -4, 2L * spec.nz + 4, 2L * y_lo - 4, 2L * y_hi + 4)),
      changed_({{-2, -2}, {spec.nx + 1, spec.nz + 1}}),
      stop_(std::move(stop)) {}
WallPacker::~WallPacker() = default;

std::vector<std::size_t> WallPacker::pack(const Candidates& walls, const PackReplay* replay) {
  if (!replay) replayable_ = false;
  if (!replayable_) replay = nullptr;
  if (replay)
    for (const Candidate& c : replay->gone) changed_.add(ChangedRegion::around(c));
  // Each shape's top edge once: a rectangle's would be a square root and a division ahead of its samples.
  std::vector<WallLine> lines;
  for (const Candidates::Shape& shape : walls.shapes()) lines.push_back(wall_line(shape.dx, shape.dz));
  const std::vector<ChangedRegion::Box> shape_boxes = replay ? ChangedRegion::around_shapes(walls.shapes())
                                                             : std::vector<ChangedRegion::Box>();
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (i % kStopEvery == 0) stop_point(stop_);
    const Candidates::Item& item = walls.item(i);
    const PackedCandidate wall = walls.decode(item);
    const WallLine& line = lines[item.shape];
    const std::optional<ChangedRegion::Box> around =  // a replay's
        replay ? std::optional(ChangedRegion::around(wall, shape_boxes[item.shape])) : std::nullopt;
    const std::optional<bool> previous = around ? previous_decision(replay, i, *around, changed_) : std::nullopt;
    // Most walls are refused at their first sample, a quarter voxel along the top edge from corner 1: with dx >= 0
    // (ring_offsets) it lies in half-voxel cell 2 x1 + 1, and in 2 z1 + 1 or 2 z1 as dz >= 0 or not (a step of
    // |dz| / length keeps it off the cell's border). Tested first, without the edge's arithmetic.
    const Candidates::Shape& shape = walls.shapes()[item.shape];
    const glm::ivec3 first = wall.corner(0);
    const bool first_taken = !previous && taken_->any(2L * first.x + 1, 2L * first.z + (shape.dz >= 0 ? 1 : 0),
                                                      2L * (first.y - shape.side) + 1, 2L * first.y);
    const bool free = previous ? *previous : !first_taken && wall_samples(wall, line, 0, [&](long x, long z, long y0, long y1) {
      return !taken_->any(x, z, y0, y1);
    });
    if (around && !previous) note_decision(replay, i, *around, free, changed_);
    if (!free) continue;
    // Marked a voxel thick either side: a rectangle one voxel in front of another on a wall off the axes
    // (the staircase of its voxels) covers the same wall.
    for (int layer = -1; layer <= 1; ++layer)
      wall_samples(wall, line, layer, [&](long x, long z, long y0, long y1) { return taken_->set(x, z, y0, y1), true; });
    kept.push_back(i);
  }
  return kept;
}

// For a level-free TileMap (floor or ceiling): how many cells of a run along a row or a column are not tiles,
// from prefix counts, cells outside the grid included (TileMap says they are no tiles).
class SquarePacker::NonTileCounts {
 public:
  explicit NonTileCounts(const TileMap& is_tile) : nx_(is_tile.spec.nx), nz_(is_tile.spec.nz) {
    along_x_.assign(std::size_t(nz_) * std::size_t(nx_ + 1), 0);
    along_z_.assign(std::size_t(nx_) * std::size_t(nz_ + 1), 0);
    for (int z = 0; z < nz_; ++z)
      for (int x = 0; x < nx_; ++x) {
        const int not_tile = is_tile(x, z, 0) ? 0 : 1;
        along_x_[x_at(x + 1, z)] = along_x_[x_at(x, z)] + not_tile;
        along_z_[z_at(x, z + 1)] = along_z_[z_at(x, z)] + not_tile;
      }
  }
  // contact() of a square along the axes, corners' box `b`, where the cells around it lie in the grid: along each
  // edge the next row or column out counted twice but its cell at the edge's lower end, once (contact's loop
  // below, edge by edge), by prefix differences alone. None for a box of no area (the loop passes over edges of no
  // length) or one next to the grid's edge.
  std::optional<int> around(const AxisBox& b) const {
    if (b.hi_x <= b.lo_x || b.hi_z <= b.lo_z || b.lo_x < 1 || b.lo_z < 1 || b.hi_x + 1 >= nx_ || b.hi_z + 1 >= nz_)
      return std::nullopt;
    const int twice = row_in_grid(b.lo_x, b.hi_x, b.lo_z - 1) + row_in_grid(b.lo_x, b.hi_x, b.hi_z + 1) +
                      column_in_grid(b.lo_x - 1, b.lo_z, b.hi_z) + column_in_grid(b.hi_x + 1, b.lo_z, b.hi_z);
    const int once = row_in_grid(b.lo_x, b.lo_x, b.lo_z - 1) + row_in_grid(b.lo_x, b.lo_x, b.hi_z + 1) +
                     row_in_grid(b.lo_x - 1, b.lo_x - 1, b.lo_z) + row_in_grid(b.hi_x + 1, b.hi_x + 1, b.lo_z);
    return 2 * twice - once;
  }
  // Cells (x0..x1, z) or (x, z0..z1), inclusive, lo <= hi.
  int row(int x0, int x1, int z) const {
    if (z < 0 || z >= nz_) return x1 - x0 + 1;
    const int a = std::clamp(x0, 0, nx_), b = std::clamp(x1 + 1, 0, nx_);
    return (x1 - x0 + 1) - (b - a) + row_in_grid(a, b - 1, z);
  }
  int column(int x, int z0, int z1) const {
    if (x < 0 || x >= nx_) return z1 - z0 + 1;
    const int a = std::clamp(z0, 0, nz_), b = std::clamp(z1 + 1, 0, nz_);
    return (z1 - z0 + 1) - (b - a) + column_in_grid(x, a, b - 1);
  }

 private:
  // row() and column() of cells in the grid (none where the end lies one before the start): prefix differences.
  int row_in_grid(int x0, int x1, int z) const { return along_x_[x_at(x1 + 1, z)] - along_x_[x_at(x0, z)]; }
  int column_in_grid(int x, int z0, int z1) const { return along_z_[z_at(x, z1 + 1)] - along_z_[z_at(x, z0)]; }
  std::size_t x_at(int x, int z) const { return std::size_t(z) * std::size_t(nx_ + 1) + std::size_t(x); }
  std::size_t z_at(int x, int z) const { return std::size_t(x) * std::size_t(nz_ + 1) + std::size_t(z); }
  int nx_, nz_;
  std::vector<int> along_x_, along_z_;
};

const SquareSampleRuns::Shape* SquareSampleRuns::shape_of(const Candidate& c) {
  const glm::ivec3 e1 = c.corners[1] - c.corners[0], e3 = c.corners[3] - c.corners[0];
  const std::uint64_t key = pack_key(e1.x, e1.z, e3.x);  // edges lie in the grid: far below 2^20 voxels
  std::uint32_t at = index_.find(key);
  if (at == KeyTable::kAbsent) {
    if (runs_.size() > kMaxRuns || contacts_.size() > kMaxRuns) *this = {};  // shapes of many sizes and grids
    at = std::uint32_t(shapes_.size());
    index_.insert(key, at);
    Shape shape{e1, e3, runs_.size(), 0, contacts_.size(), 0, true};
    const long x0 = 2L * c.corners[0].x, z0 = 2L * c.corners[0].z;
    square_samples(c, [&](long z, long first, long last) {
      runs_.push_back({int(z - z0), int(first - x0), int(last - x0)});
      return true;
    });
    // The contact samples of the same square with corner 1 at (0, 0): moved by whole voxels, a sample at least
    // kBorder from a cell's border stays in the same cell moved alike (rounding at coordinates below 2^21 moves
    // it less than 1e-9).
    constexpr double kBorder = 1e-6;
    Candidate origin = c;
    for (glm::ivec3& corner : origin.corners) corner -= c.corners[0];
    if (e1.x != 0 && e1.z != 0)  // a square's edges: all off the axes or none
      for (std::size_t i = 0; i < 4; ++i)
        off_axis_contact_samples(origin, i, [&](const glm::dvec2& p) {
          const glm::dvec2 cell = glm::floor(p), from_border = glm::min(p - cell, cell + 1.0 - p);
          shape.contact_exact = shape.contact_exact && from_border.x >= kBorder && from_border.y >= kBorder;
          const int dx = int(cell.x), dz = int(cell.y);
          if (contacts_.size() > shape.contact_begin && contacts_.back().dx == dx && contacts_.back().dz == dz)
            ++contacts_.back().samples;
          else
            contacts_.push_back({dx, dz, 1});
        });
    shape.end = runs_.size(), shape.contact_end = contacts_.size();
    shapes_.push_back(shape);
  }
  const Shape& shape = shapes_[at];
  return shape.e1 == e1 && shape.e3 == e3 ? &shape : nullptr;
}

std::optional<std::span<const SquareSampleRuns::Run>> SquareSampleRuns::of(const Candidate& c) {
  const Shape* shape = shape_of(c);
  if (!shape) return std::nullopt;
  return std::span<const Run>(runs_).subspan(shape->begin, shape->end - shape->begin);
}

std::optional<std::span<const SquareSampleRuns::ContactCell>> SquareSampleRuns::contact_cells(const Candidate& c) {
  const Shape* shape = shape_of(c);
  if (!shape || !shape->contact_exact) return std::nullopt;
  return std::span<const ContactCell>(contacts_).subspan(shape->contact_begin, shape->contact_end - shape->contact_begin);
}

// The runs of square_samples(c), in its order, until f returns false; returns whether every run was visited.
template <class F>
bool SquarePacker::each_sample_run(const Candidate& c, F f) {
  const glm::ivec3 e = c.corners[1] - c.corners[0];
  if (e.x == 0 || e.z == 0) return square_samples(c, f);  // along the axes: runs without tests (axis_box)
  const std::optional<std::span<const SquareSampleRuns::Run>> runs = samples_->of(c);
  if (!runs) return square_samples(c, f);
  const long x0 = 2L * c.corners[0].x, z0 = 2L * c.corners[0].z;
  for (const SquareSampleRuns::Run& r : *runs)
    if (!f(z0 + r.dz, x0 + r.dx0, x0 + r.dx1)) return false;
  return true;
}

SquarePacker::SquarePacker(const GridSpec& spec, int level_tolerance, double dominant_deg, const TileMap& is_tile,
                           std::stop_token stop, SquareSampleRuns* shared_samples)
    : level_tolerance_(level_tolerance),
      dominant_deg_(dominant_deg),
      is_tile_(is_tile),
      runs_(is_tile.mask.empty() ? nullptr : std::make_unique<NonTileCounts>(is_tile)),
      own_samples_(shared_samples ? nullptr : std::make_unique<SquareSampleRuns>()),
      samples_(shared_samples ? shared_samples : own_samples_.get()),
      // Per level, rows of half-voxel samples along x over the grid's columns: corners are voxel indices in the
      // grid (at most a level beyond, for a top's y_Actual) and samples lie within a voxel and a half of them.
      taken_(std::make_unique<SampleRaster>(-2, spec.ny + 2, -4, 2L * spec.nz + 4, -4, 2L * spec.nx + 4)),
      changed_({{0, 0}, {spec.nx - 1, spec.nz - 1}}),  // the squares' corners lie in the grid's columns
      stop_(std::move(stop)) {}
SquarePacker::~SquarePacker() = default;

// Contact: unusable cells just outside the square's edges, sampled every half voxel.
int SquarePacker::contact(const Candidate& c) {
  if (runs_)
    if (const std::optional<AxisBox> b = axis_box(c))
      if (const std::optional<int> n = runs_->around(*b)) return *n;
  int n = 0;
  const glm::ivec3 e1 = c.corners[1] - c.corners[0];
  if (e1.x != 0 && e1.z != 0)
    if (const std::optional<std::span<const SquareSampleRuns::ContactCell>> cells = samples_->contact_cells(c)) {
      const int x = c.corners[0].x, z = c.corners[0].z, level = c.corners[0].y;
      for (const SquareSampleRuns::ContactCell& cell : *cells)
        n += is_tile_(x + cell.dx, z + cell.dz, level) ? 0 : cell.samples;
      return n;
    }
  const glm::ivec3 sum = corner_sum(c);  // 4 x the middle
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::ivec3 e = c.corners[(i + 1) % 4] - c.corners[i];
    if (e.x == 0 && e.z == 0) continue;
    if (e.x == 0 || e.z == 0) {
      // Along a grid axis every sample below is exact: the 2L + 1 samples of an edge of L voxels fall
      // on its L + 1 cells twice each, but for the cell at the far end of the direction of travel
      // (x + 0.5 + t rounds down to x + floor((1 + 2t) / 2); x + 0.5 - t to x - floor(2t / 2)), and
      // 0.75 voxels out (away from the middle) is the neighbouring row. Counted by cell, without the doubles.
      const bool along_x = e.z == 0;
      const int steps = std::abs(along_x ? e.x : e.z), step = (along_x ? e.x : e.z) > 0 ? 1 : -1;
      const int side = (along_x ? 4 * c.corners[i].z - sum.z : 4 * c.corners[i].x - sum.x) > 0 ? 1 : -1;
      const int once = step > 0 ? 0 : steps;  // the cell one sample meets
      const int x = c.corners[i].x, z = c.corners[i].z;
      if (runs_) {
        const int far_x = x + step * steps, far_z = z + step * steps;
        const int all = along_x ? runs_->row(std::min(x, far_x), std::max(x, far_x), z + side)
                                : runs_->column(x + side, std::min(z, far_z), std::max(z, far_z));
        const int at_once = along_x ? runs_->row(x + step * once, x + step * once, z + side)
                                    : runs_->column(x + side, z + step * once, z + step * once);
        n += 2 * all - at_once;
        continue;
      }
      for (int j = 0; j <= steps; ++j)
        n += is_tile_(along_x ? x + step * j : x + side, along_x ? z + side : z + step * j, c.corners[0].y)
                 ? 0
                 : (j == once ? 1 : 2);
      continue;
    }
    off_axis_contact_samples(c, i, [&](const glm::dvec2& p) {
      n += is_tile_(floor_int(p.x), floor_int(p.y), c.corners[0].y) ? 0 : 1;
    });
  }
  return n;
}

bool contact_may_read(const Candidate& c, const ChangedRegion::Box& columns) {
  if (columns.lo.x > columns.hi.x || columns.lo.y > columns.hi.y) return false;  // no column
  // The box of the columns in continuous coordinates, a voxel wider each way: a sample within 0.75 of an edge
  // lies in it exactly where the edge passes through it (with room for rounding).
  const glm::dvec2 lo = glm::dvec2(columns.lo) - 1.0, hi = glm::dvec2(columns.hi) + 2.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::dvec2 a(c.corners[i].x + 0.5, c.corners[i].z + 0.5);
    const glm::dvec2 b(c.corners[(i + 1) % 4].x + 0.5, c.corners[(i + 1) % 4].z + 0.5);
    // The edge clipped to the box axis by axis (Liang-Barsky): what is left of [0, 1] lies in it.
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 2 && t0 <= t1; ++k) {
      const double d = b[k] - a[k];
      if (d == 0.0) {
        if (a[k] < lo[k] || a[k] > hi[k]) t0 = 2.0;
        continue;
      }
      const double u = (lo[k] - a[k]) / d, v = (hi[k] - a[k]) / d;
      t0 = std::max(t0, std::min(u, v)), t1 = std::min(t1, std::max(u, v));
    }
    if (t0 <= t1) return true;
  }
  return false;
}

// A packing rank in 32 bits, as a floor's squares are millions: the step (0 to 9: misalignment is at most 45°)
// above the contact.
constexpr int kContactBits = 28;
constexpr std::uint32_t kContactMask = (std::uint32_t{1} << kContactBits) - 1;

// Squares of a size share a few hundred edge directions: each direction's 5° step is computed once.
int SquarePacker::misalignment_step(const Candidate& c) {
  const glm::ivec3 e = c.corners[1] - c.corners[0];
  const std::uint64_t key = pack_key(e.x, 0, e.z);
  if (const std::uint32_t step = steps_of_direction_.find(key); step != KeyTable::kAbsent) return int(step);
  const int step = int(std::lround(misalignment_deg(c, dominant_deg_) / 5.0));  // 0 to 9: at most 45°
  steps_of_direction_.insert(key, std::uint32_t(step));
  return step;
}

// [0, n) ordered by bucket_of(i) ascending, stable: a counting sort, as packing's buckets are few (ten steps,
// contacts up to the samples around a square at any usual voxel size); a comparison sort past that.
template <class BucketOf>
std::vector<std::uint32_t> order_by_bucket(std::size_t n, std::size_t buckets, BucketOf bucket_of) {
  std::vector<std::uint32_t> order(n);
  if (buckets <= std::max<std::size_t>(n, 1 << 20)) {
    std::vector<std::uint32_t> first(buckets + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++first[bucket_of(i) + 1];
    for (std::size_t b = 0; b < buckets; ++b) first[b + 1] += first[b];
    for (std::size_t i = 0; i < n; ++i) order[first[bucket_of(i)]++] = std::uint32_t(i);
  } else {
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return bucket_of(a) < bucket_of(b); });
  }
  return order;
}

// Free when no level within the tolerance has a sample of c taken: each row's run found once for all levels.
bool SquarePacker::free(const Candidate& c) {
  const int level = c.corners[0].y;
  return each_sample_run(c, [&](long z, long x0, long x1) {
    for (int y = level - level_tolerance_; y <= level + level_tolerance_; ++y)
      if (taken_->any(y, z, x0, x1)) return false;
    return true;
  });
}
// Whether the middle sample of `square`, of the shape whose facts are `f`, is taken at a level within the
// tolerance: then it is not free.
inline bool SquarePacker::middle_taken(const ShapeFacts& f, const PackedCandidate& square) const {
  if (!f.has_middle) return false;
  const glm::ivec3 p1 = square.corner(0);
  const long x = 2L * p1.x + f.middle_x, z = 2L * p1.z + f.middle_z;
  for (int y = p1.y - level_tolerance_; y <= p1.y + level_tolerance_; ++y)
    if (taken_->test(y, z, x)) return true;
  return false;
}

// What pack_fresh (and a replay, of the squares it tests) reads of a square that its shape alone decides. Corner 1
// moves a square whole, and its middle sample by twice that (middle_sample: floor((4 p1 + q) / 2) = 2 p1 +
// floor(q / 2)), inside it or not alike.
SquarePacker::ShapeFacts SquarePacker::shape_facts(const Candidates::Shape& shape) {
  const PackedCandidate at_origin(glm::ivec3(0), shape.dx, shape.dz, shape.side);
  const std::optional<std::array<long, 2>> middle = middle_sample(at_origin);
  return {misalignment_step(at_origin.unpack()), middle.has_value(), middle ? (*middle)[0] : 0, middle ? (*middle)[1] : 0};
}

void SquarePacker::take(const Candidate& c) {
  each_sample_run(c, [&](long z, long x0, long x1) { return taken_->set(c.corners[0].y, z, x0, x1), true; });
}

// The whole analysis's packing, in the order pack() describes, computing contact only where it can matter: a
// square whose middle sample is taken when its step begins is refused at its turn whatever its contact (taken
// samples stay taken), so only the others get a contact and are ordered by it. Most of a room's squares lie
// on the larger or better aligned ones kept before their step.
// A floor's squares are millions (two types packed side by side held some 34 MB each on a 90 x 90 m floor): the
// squares go by step into one array of their indices, exactly as long as the squares, and each step's open
// squares into the front of its own part of it; beside them only their contacts and their order.
std::vector<std::size_t> SquarePacker::pack_fresh(const Candidates& squares) {
  replayable_ = false;
  constexpr std::size_t kSteps = 10;  // misalignment is at most 45°: steps 0 to 9
  // A size's squares have a few hundred shapes: what each decides, found once.
  std::vector<ShapeFacts> facts;
  facts.reserve(squares.shapes().size());
  for (const Candidates::Shape& shape : squares.shapes()) facts.push_back(shape_facts(shape));
  std::array<std::size_t, kSteps + 1> step_begin{};
  std::vector<std::uint32_t> by_step;  // the squares' indices, step by step, each step's in search order
  {
    std::vector<std::uint8_t> step_of(squares.size());
    for (std::size_t i = 0; i < squares.size(); ++i) {
      if (i % kStopEvery == 0) stop_point(stop_);
      step_of[i] = std::uint8_t(std::min(facts[squares.item(i).shape].step, int(kSteps - 1)));
      ++step_begin[step_of[i] + 1];
    }
    for (std::size_t step = 0; step < kSteps; ++step) step_begin[step + 1] += step_begin[step];
    by_step = order_by_bucket(squares.size(), kSteps, [&](std::size_t i) { return std::size_t(step_of[i]); });
  }
  std::vector<std::size_t> kept;
  std::vector<std::uint32_t> contacts;  // of a step's squares still free, as they lie in by_step
  for (std::size_t step = 0; step < kSteps; ++step) {
    const std::span<std::uint32_t> items(by_step.data() + step_begin[step], step_begin[step + 1] - step_begin[step]);
    contacts.clear();
    contacts.reserve(items.size());
    std::uint32_t max_contact = 0;
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (k % kStopEvery == 0) stop_point(stop_);
      const Candidates::Item& item = squares.item(items[k]);
      const PackedCandidate square = squares.decode(item);
      if (middle_taken(facts[item.shape], square)) continue;  // taken: refused at its turn, whatever its contact
      items[contacts.size()] = items[k];
      contacts.push_back(std::min(std::uint32_t(contact(square.unpack())), kContactMask));
      max_contact = std::max(max_contact, contacts.back());
    }
    // Contact descending, then search order.
    const std::vector<std::uint32_t> order = order_by_bucket(
        contacts.size(), std::size_t(max_contact) + 1, [&](std::size_t k) { return std::size_t(max_contact - contacts[k]); });
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k % kStopEvery == 0) stop_point(stop_);
      const std::uint32_t i = items[order[k]];
      // Its middle sample first, as above: taken by a square kept earlier in this step (a large floor's squares
      // mostly lie on those before them), it refuses the square without the rest of its samples.
      const Candidates::Item& item = squares.item(i);
      const PackedCandidate square = squares.decode(item);
      if (middle_taken(facts[item.shape], square)) continue;
      const Candidate c = square.unpack();
      if (!free(c)) continue;
      take(c);
      kept.push_back(i);
    }
  }
  std::sort(kept.begin(), kept.end());  // the output keeps the search's order
  return kept;
}

std::vector<std::size_t> SquarePacker::pack(const Candidates& squares, const PackReplay* replay,
                                           std::vector<std::uint32_t>* ranks_out) {
  if (squares.size() > 0xffffffffu) throw std::length_error("more squares than packing can rank");
  if (!replay && !ranks_out) return pack_fresh(squares);
  // Within a size, aligned with the room first (in steps of 5°), then by contact, then in search order. Each
  // square's rank is computed once, then ordered stably (order_by_bucket), so that equal ranks keep the search
  // order.
  std::vector<std::uint32_t> ranks(squares.size());
  std::uint32_t max_step = 0, max_contact = 0;
  for (std::size_t i = 0; i < squares.size(); ++i) {
    if (i % kStopEvery == 0) stop_point(stop_);
    if (replay && replay->ranks[i] != PackReplay::kUnknownRank) {
      ranks[i] = replay->ranks[i];
    } else {
      const Candidate c = squares[i].unpack();
      ranks[i] = std::uint32_t(misalignment_step(c)) << kContactBits | std::min(std::uint32_t(contact(c)), kContactMask);
    }
    max_step = std::max(max_step, ranks[i] >> kContactBits), max_contact = std::max(max_contact, ranks[i] & kContactMask);
  }
  // Bucket step * (max_contact + 1) + (max_contact - contact): step ascending, contact descending.
  const std::size_t contacts = std::size_t(max_contact) + 1, buckets = (std::size_t(max_step) + 1) * contacts;
  const auto bucket_of = [&](std::uint32_t rank) {
    return std::size_t(rank >> kContactBits) * contacts + std::size_t(max_contact - (rank & kContactMask));
  };
  const std::vector<std::uint32_t> order =
      order_by_bucket(squares.size(), buckets, [&](std::size_t i) { return bucket_of(ranks[i]); });
  if (ranks_out) *ranks_out = std::move(ranks);  // the caller's, once ordered: no copy
  ranks = {};
  // A size packed without a replay changes what is unknown: the sizes after it cannot replay either.
  if (!replay) replayable_ = false;
  if (!replayable_) replay = nullptr;
  if (replay)
    for (const Candidate& c : replay->gone) changed_.add(ChangedRegion::around(c));
  const std::vector<ChangedRegion::Box> shape_boxes = replay ? ChangedRegion::around_shapes(squares.shapes())
                                                             : std::vector<ChangedRegion::Box>();
  // The shapes' facts, found for a shape when a square of it is first tested (most squares replay untested).
  std::vector<std::optional<ShapeFacts>> facts(squares.shapes().size());
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k % kStopEvery == 0) stop_point(stop_);
    const std::size_t i = order[k];
    const Candidates::Item& item = squares.item(i);
    const PackedCandidate square = squares.decode(item);
    const std::optional<ChangedRegion::Box> around =  // a replay's
        replay ? std::optional(ChangedRegion::around(square, shape_boxes[item.shape])) : std::nullopt;
    const std::optional<bool> previous = around ? previous_decision(replay, i, *around, changed_) : std::nullopt;
    if (previous && !*previous) continue;  // refused as before: its corners are not needed
    if (!previous) {
      // Tested: its middle sample first, as pack_fresh does. Most squares tested again lie on one kept before them,
      // and one taken sample refuses them without the rest.
      std::optional<ShapeFacts>& f = facts[item.shape];
      if (!f) f = shape_facts(squares.shapes()[item.shape]);
      const bool is_free = !middle_taken(*f, square) && free(square.unpack());
      if (around) note_decision(replay, i, *around, is_free, changed_);
      if (!is_free) continue;
    }
    take(square.unpack());
    kept.push_back(i);
  }
  std::sort(kept.begin(), kept.end());  // the output keeps the search's order
  return kept;
}

}  // namespace roomsense::detail
