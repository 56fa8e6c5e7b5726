// Growth of packed areas into the free surface around them (grow.h).
#include "grow.h"

#include "../floor_int.h"
#include "candidate.h"
#include "../key_table.h"
#include "reduce.h"
#include "sample_owners.h"
#include "roomsense/cancel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <utility>

namespace roomsense::detail {
namespace {

glm::ivec3 sample_cell(const glm::vec3& p, float step) {
  // The bias keeps points that lie exactly on a cell border (walls' voxel centres, furniture levels) in one
  // cell whatever the rounding of the sum that gave them.
  return floor_ivec3(p / step + 1e-4f);
}

// An area as a rectangle [u0, u1] x [v0, v1] on the axes of its first corner; samples lie at half a step
// from its first corner's lattice, so a strip added later lines up with the samples already there.
struct Extent {
  glm::vec3 origin, x, y;
  float u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  glm::vec3 at(float u, float v) const { return origin + u * x + v * y; }
  // Its sample of column i and row j (step h), as every loop over its samples places it.
  glm::vec3 sample(int i, int j, float h) const { return at(u0 + (float(i) + 0.5f) * h, v0 + (float(j) + 0.5f) * h); }
};

// How many samples fit in [0, length): those at (i + 1/2) step. Counted, not accumulated, so that far from
// the origin (where adding a step to a float may change nothing) the loops still end.
int sample_count(float length, float step) {
  return length > 0.0f ? int(std::ceil(double(length) / double(step) - 0.5 - 1e-6)) : 0;
}

// The sample positions (u, v) of the strip one step beyond `edge` (0 bottom, 1 right, 2 top, 3 left), in order,
// until f returns false (a refused strip: the samples after the refusing one are not read).
template <class F>
void strip_samples(const Extent& e, int edge, float step, F f) {
  if (edge == 0 || edge == 2) {
    const float v = edge == 0 ? e.v0 - 0.5f * step : e.v1 + 0.5f * step;
    for (int i = 0, n = sample_count(e.u1 - e.u0, step); i < n; ++i)
      if (!f(e.u0 + (float(i) + 0.5f) * step, v)) return;
  } else {
    const float u = edge == 3 ? e.u0 - 0.5f * step : e.u1 + 0.5f * step;
    for (int j = 0, n = sample_count(e.v1 - e.v0, step); j < n; ++j)
      if (!f(u, e.v0 + (float(j) + 0.5f) * step)) return;
  }
}

// Where extent e lies along the grid's axes: per coordinate of its samples, whether it comes from the sample's row
// (v) alone rather than its column (u) alone. A sample's coordinate c is (origin + u x + v y)[c]: where x[c] is
// zero it is a function of v alone, where y[c] is, of u alone (adding a zero changes no float but a zero's sign,
// which no floor tells apart). None where e is turned, or not finite.
std::optional<std::array<bool, 3>> along_axes(const Extent& e) {
  if (!(std::isfinite(e.u0) && std::isfinite(e.u1) && std::isfinite(e.v0) && std::isfinite(e.v1) &&
        std::isfinite(e.origin.x) && std::isfinite(e.origin.y) && std::isfinite(e.origin.z)))
    return std::nullopt;
  std::array<bool, 3> from_v{};
  for (std::size_t c = 0; c < 3; ++c) {
    from_v[c] = e.x[int(c)] == 0.0f;
    if (!from_v[c] && e.y[int(c)] != 0.0f) return std::nullopt;
  }
  return from_v;
}

// A run of an extent's consecutive columns (or rows) whose samples map to one cell: the cell's coordinates of its
// side, the others 0.
struct SideRun {
  glm::ivec3 cell;
  int length;
};

// The runs of extent e's columns (rows: its rows) under `cell_of`, each to f(run) as it ends; along_axes(e) gave
// from_v.
template <class CellOf, class F>
void side_runs(const Extent& e, float h, bool rows, const std::array<bool, 3>& from_v, const CellOf& cell_of, const F& f) {
  SideRun run{glm::ivec3(0), 0};
  for (int i = 0, n = sample_count(rows ? e.v1 - e.v0 : e.u1 - e.u0, h); i < n; ++i) {
    glm::ivec3 cell = cell_of(rows ? e.sample(0, i, h) : e.sample(i, 0, h));
    for (std::size_t c = 0; c < 3; ++c)
      if (from_v[c] != rows) cell[int(c)] = 0;
    if (run.length > 0 && run.cell == cell) {
      ++run.length;
      continue;
    }
    if (run.length > 0) f(run);
    run = {cell, 1};
  }
  if (run.length > 0) f(run);
}

// An extent's row runs, as many as most areas' sides have on the stack, more on the heap: growth visits every
// strip it tries by runs, and a vector per visit was a third of a full analysis's allocations.
class RowRuns {
 public:
  void push_back(const SideRun& run) {
    if (size_ < kLocal) local_[size_] = run;
    else {
      if (size_ == kLocal) heap_.assign(local_.begin(), local_.end());
      heap_.push_back(run);
    }
    ++size_;
  }
  const SideRun* begin() const { return size_ <= kLocal ? local_.data() : heap_.data(); }
  const SideRun* end() const { return begin() + size_; }

 private:
  static constexpr std::size_t kLocal = 64;
  std::array<SideRun, kLocal> local_;
  std::vector<SideRun> heap_;
  std::size_t size_ = 0;
};

// Calls f(cell, samples) once per run of columns by run of rows of extent e in one cell, for e along the grid's
// axes (along_axes(e) gave from_v), `cell_of` being a map of a point to a cell each of whose coordinates is a floor
// of the point's same coordinate alone (a voxel, a sample cell): a sample's cell is its column run's plus its row
// run's.
template <class CellOf, class F>
void each_cell_by_runs(const Extent& e, float h, const std::array<bool, 3>& from_v, const CellOf& cell_of, const F& f) {
  RowRuns rows;
  side_runs(e, h, true, from_v, cell_of, [&](const SideRun& row) { rows.push_back(row); });
  side_runs(e, h, false, from_v, cell_of, [&](const SideRun& column) {
    for (const SideRun& row : rows) f(column.cell + row.cell, column.length * row.length);
  });
}

// Whether the cells given one after another (a side's runs, side_runs) are distinct cells along one axis, each next
// to the one before: then they are every cell of the box from the first to the last.
class CellLine {
 public:
  void add(const glm::ivec3& cell) {
    if (count_++ > 0) {
      const glm::ivec3 step = cell - last_;
      const int axis = step.x != 0 ? 0 : step.y != 0 ? 1 : 2;
      const bool unit = int(step.x != 0) + int(step.y != 0) + int(step.z != 0) == 1 && std::abs(step[axis]) == 1;
      line_ = line_ && unit && (count_ == 2 || step == step_);
      step_ = step;
    } else {
      first_ = cell;
    }
    last_ = cell;
  }
  bool line() const { return count_ > 0 && line_; }
  glm::ivec3 lo() const { return glm::min(first_, last_); }
  glm::ivec3 hi() const { return glm::max(first_, last_); }

 private:
  std::size_t count_ = 0;
  bool line_ = true;
  glm::ivec3 first_{0}, last_{0}, step_{0};
};

// The box of sample cells extent e's samples lie in, where e lies along the grid's axes (along_axes gave from_v)
// and its samples' cells are every cell of a box: its rows' cells a line (CellLine) and its columns' too, each
// cell a row's plus a column's (each_cell_by_runs). Else none.
template <class CellOf>
std::optional<std::pair<glm::ivec3, glm::ivec3>> cell_box(const Extent& e, float h, const std::array<bool, 3>& from_v,
                                                          const CellOf& cell_of) {
  CellLine rows, columns;
  side_runs(e, h, true, from_v, cell_of, [&](const SideRun& row) { rows.add(row.cell); });
  side_runs(e, h, false, from_v, cell_of, [&](const SideRun& column) { columns.add(column.cell); });
  if (!rows.line() || !columns.line()) return std::nullopt;
  return std::pair(rows.lo() + columns.lo(), rows.hi() + columns.hi());
}

// Calls f(cell, samples) for the cells `cell_of` gives extent e's samples: by runs where e lies along the grid's
// axes (each_cell_by_runs), else once per sample.
template <class CellOf, class F>
void each_cell(const Extent& e, float h, const CellOf& cell_of, const F& f) {
  if (const std::optional<std::array<bool, 3>> from_v = along_axes(e)) {
    each_cell_by_runs(e, h, *from_v, cell_of, f);
    return;
  }
  for (int i = 0, nu = sample_count(e.u1 - e.u0, h); i < nu; ++i)
    for (int j = 0, nv = sample_count(e.v1 - e.v0, h); j < nv; ++j) f(cell_of(e.sample(i, j, h)), 1);
}

// How many of extent e's samples (of area a) are Usable: by runs of samples in one voxel where the rule gives
// voxels and e lies along the grid's axes, else sample by sample (a turned area: one cell_at a sample).
int usable_samples(const Extent& e, float h, const GrowthRule& rule, const Area& a) {
  int count = 0;
  const std::optional<std::array<bool, 3>> from_v = rule.voxel_at && rule.cell_of ? along_axes(e) : std::nullopt;
  if (from_v) {
    each_cell_by_runs(e, h, *from_v, [&](const glm::vec3& p) { return rule.voxel_at(p, a); },
                      [&](const glm::ivec3& voxel, int samples) {
                        if (rule.cell_of(voxel, a) == SurfaceCell::Usable) count += samples;
                      });
    return count;
  }
  for (int i = 0, nu = sample_count(e.u1 - e.u0, h); i < nu; ++i)
    for (int j = 0, nv = sample_count(e.v1 - e.v0, h); j < nv; ++j)
      count += rule.cell_at(e.sample(i, j, h), a) == SurfaceCell::Usable;
  return count;
}

void set_size(Area& a, const AreaParams& params) {
  const float width = 2.0f * a.half_width, height = 2.0f * a.half_height;
  for (std::size_t s = 0; s < kAreaSizes.size() && kAreaSizes[s] < a.size; ++s) {
    const bool holds =
        a.type == AreaType::Wall
            ? width >= params.wall_width[s] - params.width_tolerance &&
                  height >= params.wall_height[s] - params.width_tolerance
            : std::min(width, height) >= params.square_width[s] - params.width_tolerance;
    if (holds) {
      a.size = kAreaSizes[s];
      return;
    }
  }
}

// Bit for bit, so that a -0 is not taken for a 0.
bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(const glm::vec3& a, const glm::vec3& b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

// A hash of an area's corners' bits (their heights left out where the rule's cells read none), for finding it
// among another growth's (grows_alike decides).
std::uint64_t corner_hash(const Area& a, const GrowthRule& rule) {
  WordHash h;
  for (const glm::vec3& c : a.corners) {
    h.add(c.x).add(c.z);
    if (rule.cells_read_height) h.add(c.y);
  }
  return h.value();
}

// Whether growth reads `a` and `b` alike: the same bits; or, where the rule's cells read no height, flat
// horizontal areas the same but for their heights, whose samples lie in the same layers of sample cells at every
// conflict depth. An extent's axes then have no height, so the samples' x and z are the same numbers, every
// cell_at answers alike, and two areas' samples share a cell in one growth exactly when they do in the other.
bool grows_alike(const Area& a, const Area& b, const GrowthRule& rule) {
  if (detail::same_bits(a, b)) return true;
  const auto flat = [](const Area& x) {
    return x.normal.x == 0.0f && x.normal.z == 0.0f && std::ranges::all_of(x.corners, [&](const glm::vec3& c) {
             return same_bits(c.y, x.corners[0].y);
           });
  };
  if (rule.cells_read_height || !flat(a) || !flat(b)) return false;
  Area lifted = b;  // b at a's height
  for (glm::vec3& c : lifted.corners) c.y = a.corners[0].y;
  lifted.center.y = a.center.y;
  if (!detail::same_bits(a, lifted)) return false;
  const auto layer = [&](const Area& x, float depth) {
    return sample_cell(glm::vec3(0.0f, x.corners[0].y, 0.0f) + depth * x.normal, rule.step).y;
  };
  return layer(a, 0.0f) == layer(b, 0.0f) &&
         std::ranges::all_of(rule.conflict_depths, [&](float depth) { return layer(a, depth) == layer(b, depth); });
}

constexpr std::uint32_t kNew = ~std::uint32_t{0};

// Each of `areas`' index among `previous`, where an area that grows alike is there after the one the area before
// it has (kNew otherwise): the matched areas keep their order, so that any sample cell two of them share has the
// same first owner (SampleOwners) in both growths. Of such areas, the first is matched.
std::vector<std::uint32_t> match_previous(std::span<const Area> areas, const std::vector<Area>& previous,
                                          const GrowthRule& rule) {
  FirstIndex where;
  where.reserve(previous.size());
  for (std::uint32_t j = 0; j < previous.size(); ++j)
    where.insert(corner_hash(previous[j], rule), j,
                 [&](std::uint32_t i) { return grows_alike(previous[i], previous[j], rule); });
  std::vector<std::uint32_t> matched(areas.size(), kNew);
  std::int64_t last = -1;
  for (std::size_t k = 0; k < areas.size(); ++k) {
    const std::uint32_t j = where.find(corner_hash(areas[k], rule),
                                       [&](std::uint32_t i) { return grows_alike(previous[i], areas[k], rule); });
    if (j != FirstIndex::kAbsent && std::int64_t(j) > last) matched[k] = j, last = j;
  }
  return matched;
}

// The grid columns under an area's corners, `margin` more each way (the whole grid for corners not finite).
ChangedRegion::Box columns_under(const Area& a, const GridSpec& spec, int margin) {
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& c : a.corners) {
    const glm::vec2 v = glm::vec2(c.x - spec.origin.x, c.z - spec.origin.z) / spec.voxel_size;
    lo = glm::min(lo, v), hi = glm::max(hi, v);
  }
  if (!(std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(hi.x) && std::isfinite(hi.y)))
    return {glm::ivec2(0), glm::ivec2(spec.nx - 1, spec.nz - 1)};
  const auto column = [&](glm::vec2 v) {  // clamped near the grid: ChangedRegion clamps to it
    return glm::ivec2(glm::floor(glm::clamp(v, glm::vec2(-4.0f), glm::vec2(float(spec.nx) + 4.0f, float(spec.nz) + 4.0f))));
  };
  return {column(lo) - margin, column(hi) + margin};
}

// A replay's growth asks the sample owners only near the few areas it grows again: each area's own samples are
// marked once a cell they may lie in is asked for, not all of them before growth (on an added object, 60 % of the
// update's growth). The areas are listed by buckets of 16 x 16 sample cells in x-z that their samples' cells, a
// cell more each way against rounding, touch; an area too large for that, or not finite, is marked at once.
class LazyMarks {
 public:
  static constexpr int kShift = 4;                // a bucket's side: 2^kShift sample cells
  static constexpr std::size_t kMostBuckets = 1 << 20;  // past it (areas strewn over kilometres) all are marked

  // `cells(k)`: the lowest and highest sample cell (x, z) area k's samples may lie in, or nullopt where unknown.
  template <class Cells>
  LazyMarks(std::size_t areas, const Cells& cells) : marked_(areas, 0) {
    std::vector<std::optional<std::pair<glm::ivec2, glm::ivec2>>> range(areas);  // of buckets; none: marked at once
    glm::ivec2 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
    for (std::size_t k = 0; k < areas; ++k) {
      const std::optional<std::pair<glm::ivec2, glm::ivec2>> lies_in = cells(k);
      if (!lies_in) continue;
      const glm::ivec2 b0 = (lies_in->first - 1) >> kShift, b1 = (lies_in->second + 1) >> kShift;
      if (std::size_t(b1.x - b0.x + 1) * std::size_t(b1.y - b0.y + 1) > 64) continue;  // in too many buckets
      range[k] = {b0, b1};
      lo = glm::min(lo, b0), hi = glm::max(hi, b1);
    }
    if (lo.x <= hi.x && std::size_t(hi.x - lo.x + 1) * std::size_t(hi.y - lo.y + 1) <= kMostBuckets) {
      lo_ = lo, count_ = hi - lo + 1;
    } else {
      for (auto& r : range) r.reset();
    }
    const std::size_t buckets = std::size_t(count_.x) * std::size_t(count_.y);
    start_.assign(buckets + 1, 0);
    const auto each_bucket = [&](std::size_t k, auto f) {
      for (int z = range[k]->first.y; z <= range[k]->second.y; ++z)
        for (int x = range[k]->first.x; x <= range[k]->second.x; ++x) f(bucket(x, z));
    };
    for (std::size_t k = 0; k < areas; ++k) {
      if (range[k]) each_bucket(k, [&](std::size_t b) { ++start_[b + 1]; });
      else now_.push_back(std::uint32_t(k));
    }
    for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    areas_.resize(start_[buckets]);
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < areas; ++k)
      if (range[k]) each_bucket(k, [&](std::size_t b) { areas_[next[b]++] = std::uint32_t(k); });
    resolved_.assign(buckets, 0);
  }

  // Marks (mark(k)) the areas whose samples may lie in `cell` and are not marked yet; the first call, every area
  // listed in no bucket.
  template <class Mark>
  void cover(glm::ivec3 cell, const Mark& mark) {
    for (const std::uint32_t k : now_) mark_once(k, mark);
    now_.clear();
    const glm::ivec2 b = (glm::ivec2(cell.x, cell.z) >> kShift) - lo_;
    if (b.x < 0 || b.y < 0 || b.x >= count_.x || b.y >= count_.y) return;  // no area's samples there
    const std::size_t i = std::size_t(b.y) * std::size_t(count_.x) + std::size_t(b.x);
    if (resolved_[i]) return;
    for (std::size_t a = start_[i]; a < start_[i + 1]; ++a) mark_once(areas_[a], mark);
    resolved_[i] = 1;
  }

 private:
  std::size_t bucket(int x, int z) const {
    return std::size_t(z - lo_.y) * std::size_t(count_.x) + std::size_t(x - lo_.x);
  }
  template <class Mark>
  void mark_once(std::uint32_t k, const Mark& mark) {
    if (!marked_[k]) marked_[k] = 1, mark(k);
  }

  glm::ivec2 lo_{0}, count_{0};
  std::vector<std::size_t> start_;   // per bucket: its areas in areas_[start_[b], start_[b + 1])
  std::vector<std::uint32_t> areas_;
  std::vector<std::uint32_t> now_;   // listed in no bucket: marked at the first call
  std::vector<std::uint8_t> resolved_, marked_;
};

}  // namespace

bool same_bits(const Area& a, const Area& b) {
  // Every field: a field added to Area changes its size and must be compared here.
  static_assert(sizeof(Area) == 4 + 4 * 12 + 2 * 12 + 4 * 4 + 3 * 4);
  for (std::size_t i = 0; i < 4; ++i)
    if (!same_bits(a.corners[i], b.corners[i])) return false;
  return a.type == b.type && a.size == b.size && a.reach == b.reach && same_bits(a.center, b.center) &&
         same_bits(a.normal, b.normal) && same_bits(a.half_width, b.half_width) &&
         same_bits(a.half_height, b.half_height) && same_bits(a.rotation_deg, b.rotation_deg) &&
         same_bits(a.volume_height, b.volume_height) && a.flags == b.flags && a.storey == b.storey && a.room == b.room;
}

void grow_areas(std::span<Area> areas, const GrowthRule& rule, const AreaParams& params, const std::stop_token& stop,
                const GrowthReplay& replay, GrowthRecord* record) {
  const float h = rule.step;
  if (record) *record = {std::vector<Area>(areas.begin(), areas.end()), {}, {}, {}};
  std::vector<Extent> extents;
  extents.reserve(areas.size());
  std::vector<bool> grows;  // rectangles of no width (a small wall at very coarse voxels) stay as they are
  for (const Area& a : areas) {
    const glm::vec3 edge = a.corners[1] - a.corners[0];
    grows.push_back(glm::length(edge) > 1e-3f * h);
    const glm::vec3 x = grows.back() ? glm::normalize(edge) : glm::vec3(1, 0, 0);
    extents.push_back({a.corners[0], x, glm::cross(a.normal, x), 0.0f, 2.0f * a.half_width, 0.0f, 2.0f * a.half_height});
  }

  // Replay (issue 19): what an area reads while it grows lies within a few columns of where it ends (its last
  // strips tested, the lookahead, the conflict depths, half a voxel to a wall's voxel, a sample cell across a
  // column border). An area the previous growth grew, nothing within that of whose end there changed, moves
  // as it did there: the same cells answer, and the same areas own the same samples. `changed` gathers the
  // feature columns that changed, the areas new or gone, and the areas that moved otherwise than there.
  constexpr int kReadMargin = 4;
  const GrowthRecord* previous = replay.previous;
  std::vector<std::uint32_t> previous_of;
  std::optional<ChangedRegion> changed;
  // Where nothing changed, every area moves as it did (a moved area only adds to `changed`) and no growth reads
  // the sample owners: none are kept (a re-sent chunk that refined a floor height).
  bool every_area_replayed = false;
  if (previous) {
    const GridSpec& spec = *replay.spec;
    previous_of = match_previous(areas, previous->before, rule);
    changed.emplace(ChangedRegion::Box{glm::ivec2(0), glm::ivec2(spec.nx - 1, spec.nz - 1)});
    bool any_change = false;
    const auto add = [&](const ChangedRegion::Box& box) { changed->add(box), any_change = true; };
    for (std::size_t z = 0; z < replay.changed_rows.size(); ++z)
      if (const glm::ivec2 span = replay.changed_rows[z]; span.x <= span.y)
        add({glm::ivec2(span.x, int(z)), glm::ivec2(span.y, int(z))});
    std::vector<std::uint8_t> kept(previous->before.size(), 0);
    for (std::size_t k = 0; k < areas.size(); ++k) {
      if (previous_of[k] != kNew) kept[previous_of[k]] = 1;
      else add(columns_under(areas[k], spec, 0));
    }
    for (std::size_t j = 0; j < kept.size(); ++j)
      if (!kept[j]) add(columns_under(previous->after[j], spec, 0));
    every_area_replayed = !any_change;
  }
  // Which area holds each sample cell: the areas' own samples, lowest area first, then the strips growth adds, in
  // the order it adds them. Opposite faces of a thin wall lie a voxel apart and never conflict.
  const bool horizontal = std::all_of(areas.begin(), areas.end(), [](const Area& a) { return std::fabs(a.normal.y) > 0.5f; });
  const glm::ivec3 tile_shift = horizontal ? glm::ivec3(3, 0, 3) : glm::ivec3(2, 2, 2);
  SampleOwners owner(tile_shift);
  // A replay marks the areas' own samples as growth asks for them (LazyMarks), and the strips apart.
  const std::vector<Extent> own_extents = previous && !every_area_replayed ? extents : std::vector<Extent>();
  std::optional<LazyMarks> lazy;
  std::optional<SampleOwners> strips;
  const auto mark_area = [&](std::uint32_t k) {
    const Extent& e = lazy ? own_extents[k] : extents[k];
    const auto cell_of = [h](const glm::vec3& p) { return sample_cell(p, h); };
    if (const std::optional<std::array<bool, 3>> from_v = along_axes(e))
      if (const auto box = cell_box(e, h, *from_v, cell_of)) {
        owner.lower_box(box->first, box->second, k);
        return;
      }
    each_cell(e, h, cell_of, [&](const glm::ivec3& cell, int) { owner.lower(cell, k); });
  };
  const auto mark = [&](std::uint32_t k, const glm::vec3& p) { (strips ? *strips : owner).insert(sample_cell(p, h), k); };
  if (!own_extents.empty()) {
    lazy.emplace(own_extents.size(), [&](std::size_t k) -> std::optional<std::pair<glm::ivec2, glm::ivec2>> {
      const Extent& e = own_extents[k];
      glm::ivec2 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
      for (const glm::vec3& c : {e.at(e.u0, e.v0), e.at(e.u1, e.v0), e.at(e.u1, e.v1), e.at(e.u0, e.v1)}) {
        const glm::vec3 q = c / h;
        if (!(std::fabs(q.x) < 1e6f && std::fabs(q.z) < 1e6f)) return std::nullopt;
        const glm::ivec3 cell = sample_cell(c, h);
        lo = glm::min(lo, glm::ivec2(cell.x, cell.z)), hi = glm::max(hi, glm::ivec2(cell.x, cell.z));
      }
      return std::pair(lo, hi);
    });
    strips.emplace(tile_shift);
  } else if (!every_area_replayed) {
    // The tiles the areas' samples take before growth: a horizontal plane fills its flat tiles' 64 cells, a wall
    // along an axis a quarter of its cubes'.
    std::size_t samples = 0;
    for (const Extent& e : extents) samples += std::size_t(sample_count(e.u1 - e.u0, h)) * std::size_t(sample_count(e.v1 - e.v0, h));
    owner.reserve(samples / (horizontal ? 64 : 16) + 1);
    for (std::uint32_t k = 0; k < extents.size(); ++k) mark_area(k);
  }
  // Per conflict depth, the tiles its last find read, in the owners and the strips.
  std::vector<std::array<SampleOwners::Cursor, 2>> cursors(rule.conflict_depths.size());
  const auto owner_of = [&](glm::ivec3 cell, std::array<SampleOwners::Cursor, 2>& at) {
    if (!lazy) return owner.find(cell, at[0]);
    lazy->cover(cell, mark_area);
    const std::uint32_t own = owner.find(cell, at[0]);
    return own != SampleOwners::kAbsent ? own : strips->find(cell, at[1]);
  };
  const auto conflicts = [&](std::uint32_t k, const glm::vec3& p) {
    for (std::size_t d = 0; d < rule.conflict_depths.size(); ++d) {
      const float depth = rule.conflict_depths[d];
      const std::uint32_t other = owner_of(sample_cell(p + depth * areas[k].normal, h), cursors[d]);
      if (other != SampleOwners::kAbsent && other != k && glm::dot(areas[other].normal, areas[k].normal) > 0.0f)
        return true;
    }
    return false;
  };

  // An area's growth: moves its edges by `move` (an edge one step out) while they may.
  const auto grow_one = [&](std::uint32_t k, const auto& move) {
    const Extent& e = extents[k];
    // The whole area keeps the search's fill; a strip may hold less, so that a speck the scan missed does not
    // stop an edge. The area's own samples are counted once a strip passes its own tests (many an area's edges
    // all stop at once).
    int area_usable = 0, area_total = -1;
    const auto count_area = [&] {
      area_total = sample_count(e.u1 - e.u0, h) * sample_count(e.v1 - e.v0, h);
      area_usable = usable_samples(e, h, rule, areas[k]);
    };
    // An edge refused for a Forbidden or another area's sample stays refused while its strip starts where it
    // did: the strip's first samples are then computed from the same numbers, cells do not change, and other
    // areas' samples do not while this one grows. Growth stops at a room's corners and tops: most tests
    // after the first of such an edge were of this kind.
    struct Refusal {
      bool known = false;
      float line = 0.0f, start = 0.0f;  // the edge's own coordinate and its strip's first
      int sample = 0;                   // the sample that refused it
    };
    std::array<Refusal, 4> refusals{};
    for (bool moved = true; moved; stop_point(stop)) {
      moved = false;
      for (int edge = 0; edge < 4; ++edge) {
        if ((edge % 2 == 0 ? e.v1 - e.v0 : e.u1 - e.u0) + h > rule.max_length) continue;
        const float line = edge == 0 ? e.v0 : edge == 1 ? e.u1 : edge == 2 ? e.v1 : e.u0;
        const float start = edge % 2 == 0 ? e.u0 : e.v0;
        const Refusal& before = refusals[std::size_t(edge)];
        if (before.known && before.line == line && before.start == start &&
            before.sample < sample_count(edge % 2 == 0 ? e.u1 - e.u0 : e.v1 - e.v0, h))
          continue;
        int usable = 0, total = 0;
        bool refused = false;
        const glm::vec3 outward = edge == 0 ? -e.y : edge == 1 ? e.x : edge == 2 ? e.y : -e.x;
        strip_samples(e, edge, h, [&](float u, float v) {
          const glm::vec3 p = e.at(u, v);
          const SurfaceCell cell = rule.cell_at(p + rule.lookahead * outward, areas[k]);
          refused = cell == SurfaceCell::Forbidden || conflicts(k, p);
          usable += cell == SurfaceCell::Usable ? 1 : 0;
          ++total;
          return !refused;
        });
        if (refused) refusals[std::size_t(edge)] = {true, line, start, total - 1};
        if (refused || total == 0 || double(usable) < double(rule.strip_fill) * double(total)) continue;
        if (area_total < 0) count_area();
        if (double(area_usable + usable) < double(rule.fill) * double(area_total + total)) continue;
        area_usable += usable;
        area_total += total;
        move(edge);
        moved = true;
      }
    }
  };

  const auto previous_moves = [&](std::uint32_t j) {
    const std::uint32_t begin = j == 0 ? 0 : previous->moves_end[j - 1];
    return std::span<const std::uint8_t>(previous->moves.data() + begin, previous->moves_end[j] - begin);
  };

  std::vector<std::uint8_t> moves;  // the current area's, in order
  for (std::uint32_t k = 0; k < extents.size(); ++k) {
    Extent& e = extents[k];
    moves.clear();
    const auto move = [&](int edge) {  // the strip beyond `edge` becomes the area's
      if (!every_area_replayed) strip_samples(e, edge, h, [&](float u, float v) {
        mark(k, e.at(u, v));
        return true;
      });
      (edge == 0 ? e.v0 : edge == 1 ? e.u1 : edge == 2 ? e.v1 : e.u0) += (edge == 0 || edge == 3 ? -h : h);
      moves.push_back(std::uint8_t(edge));
    };
    const std::uint32_t was = previous ? previous_of[k] : kNew;
    const bool replayed =
        was != kNew && !changed->touches(columns_under(previous->after[was], *replay.spec, kReadMargin));
    if (replayed) {
      for (const std::uint8_t edge : previous_moves(was)) move(edge);
    } else if (grows[k]) {
      grow_one(k, move);
    }
    if (grows[k]) {  // its corners from its extent, moved or not
      Area& a = areas[k];
      a.corners = {e.at(e.u0, e.v0), e.at(e.u1, e.v0), e.at(e.u1, e.v1), e.at(e.u0, e.v1)};
      a.center = e.at(0.5f * (e.u0 + e.u1), 0.5f * (e.v0 + e.v1));
      a.half_width = 0.5f * (e.u1 - e.u0);
      a.half_height = 0.5f * (e.v1 - e.v0);
      set_size(a, params);
      a.flags = category_flags(a.type, a.size, a.reach);
    }
    if (changed && !replayed && (was == kNew || !std::ranges::equal(moves, previous_moves(was)))) {
      if (was != kNew) changed->add(columns_under(previous->after[was], *replay.spec, 0));
      changed->add(columns_under(areas[k], *replay.spec, 0));
    }
    if (record) {
      record->moves.insert(record->moves.end(), moves.begin(), moves.end());
      record->moves_end.push_back(std::uint32_t(record->moves.size()));
    }
  }
  if (record) record->after.assign(areas.begin(), areas.end());
}

}  // namespace roomsense::detail
