#include "roomsense/error.h"
#include "roomsense/input.h"
#include "input_view.h"
#include "../parallel.h"
#include "../vertex_lanes.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace roomsense {
namespace {

// Not NaN or Inf: not every exponent bit set.
constexpr std::uint32_t kExponentBits = 0x7f800000u;
bool finite(float f) { return (std::bit_cast<std::uint32_t>(f) & kExponentBits) != kExponentBits; }
bool finite(const glm::vec3& v) { return int(finite(v.x)) + int(finite(v.y)) + int(finite(v.z)) == 3; }

using detail::TailCounts;
TailCounts count_tails(std::span<const float> v, float low, float high) {
  TailCounts c;
  for (const float x : v) c.add(x, low, high);
  return c;
}

// The k-th smallest and largest of a sample from its counts against bounds low <= high: where more than k but at
// most `most` values lie past a bound, the k-th of those (`gather(lower, upper)` gives the values below low and
// above high, at least their counts' many, those first); where more than k lie past a bound only with its ties, the
// bound; else none.
template <class Gather>
void pick_tails(const TailCounts& c, float low, float high, std::size_t k, std::size_t most, Gather gather,
                std::optional<float>& lo, std::optional<float>& hi) {
  const bool gather_below = c.below > k && c.below <= most, gather_above = c.above > k && c.above <= most;
  std::vector<float> lower, upper;
  if (gather_below || gather_above) gather(lower, upper);
  if (gather_below) {
    std::nth_element(lower.begin(), lower.begin() + std::ptrdiff_t(k), lower.begin() + std::ptrdiff_t(c.below));
    lo = lower[k];
  } else if (c.below <= k && c.below + c.low_ties > k) {
    lo = low;
  }
  if (gather_above) {
    std::nth_element(upper.begin(), upper.begin() + std::ptrdiff_t(k), upper.begin() + std::ptrdiff_t(c.above),
                     std::greater<float>());
    hi = upper[k];
  } else if (c.above <= k && c.above + c.high_ties > k) {
    hi = high;
  }
}

// both_tails's bounds are first sampled from every kStride-th value of the sample, at about twice k's share of it;
// a guess serves where each tail has at most twice the values past it that those leave.
constexpr std::size_t kStride = 8;
std::size_t sample_rank_of(std::size_t k) { return 2 * (k / kStride) + 8; }
std::size_t guess_most_of(std::size_t k) { return 2 * (sample_rank_of(k) + 1) * kStride; }
// Whether both_tails tries bounds (a guess, then sampled ones) on n values, for rank k.
bool tries_bounds(std::size_t n, std::size_t k) {
  return n >= 64 * kStride && 4 * sample_rank_of(k) < n / kStride && n <= std::numeric_limits<std::uint32_t>::max();
}

// The k-th smallest and the k-th largest value (from 0) of `v`, as std::nth_element finds them. For a k near the
// ends, bounds from every 8th value first; then one pass counts the values past each bound and at it (it
// vectorizes), and a second gathers the few past a bound where more than k are. Where more than k values lie
// past a bound, the k-th is among those few; where the bound's own ties reach past k, it is the bound (a scan's
// floor or walls: many equal values); else nth_element over all of `v`.
// `guess`, where it holds bounds, is tried first (an IncrementalAnalysis's previous bounds: its scan changed by a
// chunk); the counts decide whether they serve, so a guess changes the work, never the values. It receives the
// bounds that served.
std::pair<float, float> both_tails(std::span<float> v, std::size_t k, detail::QuantileBounds* guess) {
  const std::size_t n = v.size(), sample_rank = sample_rank_of(k);
  std::optional<float> lo, hi;
  // lo and hi from bounds low <= high: those of them that `most` or fewer values past a bound give.
  const auto from_bounds = [&](float low_bound, float high_bound, std::size_t most) {
    // The values past either bound, where more than k lie past one: by blocks of 16, most of which hold none of
    // them, a test of the block (it vectorizes), then its values without a branch (each written, then kept by
    // moving on: where they lie in a block is not predictable), into one slot more than there are.
    const TailCounts counts = count_tails(v, low_bound, high_bound);
    pick_tails(counts, low_bound, high_bound, k, most, [&](std::vector<float>& lower, std::vector<float>& upper) {
      lower.resize(std::size_t(counts.below) + 1), upper.resize(std::size_t(counts.above) + 1);
      constexpr std::size_t kBlock = 16;
      float* l = lower.data();
      float* u = upper.data();
      for (std::size_t begin = 0; begin < n; begin += kBlock) {
        const std::size_t end = std::min(n, begin + kBlock);
        std::uint32_t past = 0;
        for (std::size_t i = begin; i < end; ++i) past |= std::uint32_t(v[i] < low_bound) | std::uint32_t(v[i] > high_bound);
        if (past == 0) continue;
        for (std::size_t i = begin; i < end; ++i) {
          const float x = v[i];
          *l = x, l += x < low_bound;
          *u = x, u += x > high_bound;
        }
      }
    }, lo, hi);
  };
  if (tries_bounds(n, k)) {
    if (guess && *guess && (*guess)->first <= (*guess)->second) {
      from_bounds((*guess)->first, (*guess)->second, guess_most_of(k));
      if (!lo || !hi) lo.reset(), hi.reset();
    }
    if (!lo) {
      std::vector<float> sample;
      sample.reserve(n / kStride + 1);
      for (std::size_t i = 0; i < n; i += kStride) sample.push_back(v[i]);
      const auto at = [&](std::size_t rank) {
        std::nth_element(sample.begin(), sample.begin() + std::ptrdiff_t(rank), sample.end());
        return sample[rank];
      };
      // The low bound is at most the high one (ranks well apart), so no value lies past both.
      const float low_bound = at(sample_rank), high_bound = at(sample.size() - 1 - sample_rank);
      from_bounds(low_bound, high_bound, n);
      if (guess) *guess = lo && hi ? detail::QuantileBounds(std::pair(low_bound, high_bound)) : std::nullopt;
    }
  }
  if (!lo) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    lo = v[k];
  }
  if (!hi) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end(), std::greater<float>());
    hi = v[k];
  }
  return {*lo, *hi};
}

// The rank of the quantiles in a sample of n values, at least 1: at 200 vertices, the fewest the test takes, (n - 1) q
// rounds down to 0, and a lone stray vertex would be its own quantile, never rejected.
std::size_t quantile_rank(std::size_t n) { return std::max<std::size_t>(1, std::size_t(double(n - 1) * kOutlierQuantile)); }
// An axis's outlier range from its quantiles, widened by the outlier margin.
std::pair<float, float> widened(float lo, float hi) {
  const float margin = std::max(kOutlierMinMargin, hi - lo);
  return {lo - margin, hi + margin};
}

// The [q, 1-q] quantiles of each axis over the kept vertices, widened by the outlier margin. Quantiles of an evenly
// strided sample of at most kQuantileSample vertices are as good for this and keep large scans cheap.
constexpr std::size_t kQuantileSample = 16384;
std::size_t stride_of(std::size_t count) { return std::max<std::size_t>(1, count / kQuantileSample); }
// Each axis's values of that sample: vertex j * stride is sample j (of those kept, in order, where some are not).
struct AxisSample {
  // Not zeroed first: every value is written (a 76k-vertex scan's three are 0.23 MB, and their clearing was 1 % of
  // an added object's update).
  explicit AxisSample(std::size_t count) : stride(stride_of(count)), size((count + stride - 1) / stride) {
    for (std::unique_ptr<float[]>& axis : values) axis = std::make_unique_for_overwrite<float[]>(size);
  }
  // The samples among vertices [begin, end) of `all` (every vertex kept).
  void gather(std::span<const glm::vec3> all, std::size_t begin, std::size_t end) {
    for (std::size_t j = (begin + stride - 1) / stride, i = j * stride; i < end; ++j, i += stride)
      for (int axis = 0; axis < 3; ++axis) values[std::size_t(axis)][j] = all[i][axis];
  }
  std::size_t stride, size;
  std::array<std::unique_ptr<float[]>, 3> values;
};

// One axis's range from its sample.
std::pair<float, float> axis_range(const AxisSample& sample, int axis, detail::QuantileBounds* guess) {
  const std::span<float> v(sample.values[std::size_t(axis)].get(), sample.size);
  if (v.empty()) return {-INFINITY, INFINITY};
  const auto [lo, hi] = both_tails(v, quantile_rank(v.size()), guess);
  return widened(lo, hi);
}

// The ranges over the kept vertices (`keep` empty: all), the axes side by side. The sample is gathered in one pass
// (a strided read touches every cache line of the vertices), by slices side by side where every vertex is kept.
// `parts`: the vertices as consecutive parts (an IncrementalAnalysis's chunks), sampled as one array; `keep`
// (indexed over all of them) only with one part.
std::array<std::pair<float, float>, 3> robust_ranges(std::span<const std::span<const glm::vec3>> parts,
                                                     const std::vector<std::uint8_t>& keep, unsigned threads,
                                                     detail::QuantileGuess* guess) {
  std::vector<std::size_t> part_end;  // where each part ends among all the vertices
  std::size_t count = 0;
  for (const std::span<const glm::vec3> part : parts) part_end.push_back(count += part.size());
  AxisSample sample(count);
  if (keep.empty()) {  // every vertex kept (the usual scan): gathered side by side
    detail::parallel_for(sample.size, threads, 4096, [&](std::size_t begin, std::size_t end, std::size_t) {
      // The part holding the slice's first sample, then part by part: each one's samples a stride apart.
      std::size_t part = std::size_t(std::upper_bound(part_end.begin(), part_end.end(), begin * sample.stride) - part_end.begin());
      for (std::size_t j = begin; j < end; ++part) {
        const std::size_t part_begin = part_end[part] - parts[part].size();
        const std::size_t part_samples_end = std::min(end, (part_end[part] + sample.stride - 1) / sample.stride);
        for (std::size_t at = j * sample.stride - part_begin; j < part_samples_end; ++j, at += sample.stride)
          for (int axis = 0; axis < 3; ++axis) sample.values[std::size_t(axis)][j] = parts[part][at][axis];
      }
    });
  } else {
    const std::span<const glm::vec3> vertices = parts.front();
    std::size_t taken = 0;
    for (std::size_t i = 0; i < vertices.size(); i += sample.stride)
      if (keep[i]) {
        for (int axis = 0; axis < 3; ++axis) sample.values[std::size_t(axis)][taken] = vertices[i][axis];
        ++taken;
      }
    sample.size = taken;
  }
  std::array<std::pair<float, float>, 3> ranges;
  detail::parallel_tasks(3, threads, [&](std::size_t axis) {
    ranges[axis] = axis_range(sample, int(axis), guess ? &guess->axes[axis] : nullptr);
  });
  return ranges;
}

// robust_ranges of parts with keys (every vertex kept), from the guess's part samples (QuantileGuess::parts) where
// the guess's bounds serve on every axis: a part's tails are read again only where it is new, changed, or at a place
// in the sample not kept, and the tails of all are summed. Where a guess does not serve, none: robust_ranges samples
// them all (and finds the bounds again). Keeps each part's samples in the guess either way.
std::optional<std::array<std::pair<float, float>, 3>> ranges_from_part_samples(
    std::span<const std::span<const glm::vec3>> parts, std::span<const detail::PartKey> keys, detail::QuantileGuess& guess) {
  constexpr std::size_t kPlacesKept = 4;
  std::size_t count = 0;
  for (const std::span<const glm::vec3> part : parts) count += part.size();
  const std::size_t stride = stride_of(count), n = (count + stride - 1) / stride, k = quantile_rank(n);
  // The guess's parts are those given: the others dropped. Two parts under one id: neither's is known.
  std::vector<std::uint64_t> ids(keys.size());
  for (std::size_t p = 0; p < keys.size(); ++p) ids[p] = keys[p].id;
  std::sort(ids.begin(), ids.end());
  if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) {
    guess.parts.clear();
    return std::nullopt;
  }
  std::erase_if(guess.parts, [&](const auto& part) { return !std::binary_search(ids.begin(), ids.end(), part.first); });
  // Each part's sample at its place now, first among its places: the one kept where its content and place are as
  // before, else a new one; then the others kept for its content, in their order. Updated in place: a node and its
  // places' storage each part, made anew every update, were some 47 allocations of an added object's update on the
  // default room.
  std::vector<detail::PartSample*> samples;
  samples.reserve(parts.size());
  std::size_t begin = 0;  // the part's first vertex among all
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const std::size_t first = (stride - begin % stride) % stride;
    begin += parts[p].size();
    std::vector<detail::PartSample>& places = guess.parts[keys[p].id];
    std::erase_if(places, [&](const detail::PartSample& before) { return before.hash != keys[p].hash; });
    const auto here = std::find_if(places.begin(), places.end(), [&](const detail::PartSample& before) {
      return before.stride == stride && before.first == first;
    });
    if (here != places.end()) std::rotate(places.begin(), here, here + 1);
    else places.insert(places.begin(), {keys[p].hash, stride, first, {}});
    if (places.size() > kPlacesKept) places.resize(kPlacesKept);
    samples.push_back(&places.front());
  }
  if (!tries_bounds(n, k)) return std::nullopt;
  const std::size_t most = guess_most_of(k);
  std::array<std::pair<float, float>, 3> ranges;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const detail::QuantileBounds& bounds = guess.axes[axis];
    if (!bounds || bounds->first > bounds->second) return std::nullopt;
    const float low = bounds->first, high = bounds->second;
    TailCounts total;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      std::optional<detail::SampleTails>& tails = samples[p]->tails[axis];
      if (!tails || tails->low != low || tails->high != high) {
        // A part's values past a bound are gathered only as long as the whole sample's may be (at most `most`).
        detail::SampleTails t{{}, low, high, {}, {}};
        const glm::vec3* v = parts[p].data();
        for (std::size_t i = samples[p]->first; i < parts[p].size(); i += stride) {
          const float x = v[i][int(axis)];
          t.add(x, low, high);
          if (x < low && t.lower.size() <= most) t.lower.push_back(x);
          if (x > high && t.upper.size() <= most) t.upper.push_back(x);
        }
        tails = std::move(t);
      }
      total += *tails;
    }
    std::optional<float> lo, hi;
    pick_tails(total, low, high, k, most, [&](std::vector<float>& lower, std::vector<float>& upper) {
      for (const detail::PartSample* sample : samples) {
        const detail::SampleTails& tails = *sample->tails[axis];
        lower.insert(lower.end(), tails.lower.begin(), tails.lower.end());
        upper.insert(upper.end(), tails.upper.begin(), tails.upper.end());
      }
    }, lo, hi);
    if (!lo || !hi) return std::nullopt;
    ranges[axis] = widened(*lo, *hi);
  }
  return ranges;
}

// The kept vertices in order, and the triangles all of whose corners were kept, renumbered.
void renumber_kept(const Scan& scan, const std::vector<std::uint8_t>& keep, PreparedInput& out) {
  constexpr std::uint32_t kRemoved = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> remap(scan.vertices.size(), kRemoved);
  out.vertices.reserve(scan.vertices.size() - out.skipped_vertices - out.outlier_vertices);
  for (std::size_t i = 0; i < scan.vertices.size(); ++i) {
    if (!keep[i]) continue;
    remap[i] = std::uint32_t(out.vertices.size());
    out.vertices.push_back(scan.vertices[i]);
  }
  if (out.vertices.empty())
    throw Error(ErrorCode::NoValidVertices, "no usable vertex: all " + std::to_string(out.input_vertices) +
                                                " are NaN, Inf or outliers");

  out.indices.reserve(scan.indices.size());
  for (std::size_t t = 0; t < out.input_triangles; ++t) {
    const std::uint32_t a = remap[scan.indices[3 * t]], b = remap[scan.indices[3 * t + 1]],
                        c = remap[scan.indices[3 * t + 2]];
    if (a == kRemoved || b == kRemoved || c == kRemoved) {
      ++out.dropped_triangles;
      continue;
    }
    out.indices.push_back(a);
    out.indices.push_back(b);
    out.indices.push_back(c);
  }
}

}  // namespace

namespace {

bool covers(std::span<const detail::VertexRun> runs, std::size_t vertices) {
  std::size_t n = 0;
  for (const detail::VertexRun& run : runs) n += run.count;
  return !runs.empty() && n == vertices;
}

// prepare_input but for copying the scan's arrays where nothing was removed: returns whether it renumbered
// (then `out` holds the kept vertices and triangles). The bounds are those of the kept vertices either way.
// The three axes' outlier ranges are sampled on up to `threads` threads (the same ranges on any number), from
// `guess` where it serves (view_input).
// The checks of the arrays' sizes alone, and the counts they give.
void check_sizes(std::size_t vertices, std::size_t indices, PreparedInput& out) {
  if (vertices == 0) throw Error(ErrorCode::EmptyInput, "the scan has no vertices");
  if (vertices > std::numeric_limits<std::uint32_t>::max())
    throw Error(ErrorCode::BadIndices, "the scan has more vertices than 32-bit indices can address");
  if (indices % 3 != 0)
    throw Error(ErrorCode::BadIndices, "the index count " + std::to_string(indices) + " is not a multiple of 3");
  out.input_vertices = vertices;
  out.input_triangles = indices / 3;
}

// Whether a run's finite vertices all lie within the outlier ranges: its bounds are its extremes, so a run that
// is not has an outlier.
bool run_inside(const detail::VertexRun& run, const std::array<std::pair<float, float>, 3>& range) {
  bool inside = true;
  for (int axis = 0; axis < 3; ++axis)
    inside = inside && run.lo[axis] >= range[axis].first && run.hi[axis] <= range[axis].second;
  return inside;
}

// The bounds of the runs' finite vertices.
void bounds_of_runs(std::span<const detail::VertexRun> runs, PreparedInput& out) {
  out.lo = glm::vec3(INFINITY), out.hi = glm::vec3(-INFINITY);
  for (const detail::VertexRun& run : runs) {
    out.lo = glm::min(out.lo, run.lo);
    out.hi = glm::max(out.hi, run.hi);
  }
}

bool check_input(const Scan& scan, bool reject_outliers, PreparedInput& out, const detail::KnownInput* known,
                 unsigned threads, detail::QuantileGuess* guess) {
  check_sizes(scan.vertices.size(), scan.indices.size(), out);
  const std::uint32_t vertex_count = std::uint32_t(scan.vertices.size());

  // The vertices by runs: the caller's, or one over them all. That run comes from one pass over slices of the
  // vertices, side by side. Where the outlier ranges may be wanted, the pass also gathers their sample, which
  // serves where every vertex is finite (robust_ranges samples the kept ones otherwise), and the indices are
  // checked beside the three axes' selections (two workers would otherwise take those one after the other);
  // else in the same pass, by slices of the indices.
  const bool check_indices = known == nullptr || !known->indices_in_range;
  std::vector<detail::VertexRun> own;
  if (known == nullptr || !covers(known->runs, scan.vertices.size())) own.emplace_back();
  std::optional<AxisSample> sample;
  if (!own.empty() && reject_outliers && scan.vertices.size() >= kOutlierMinVertices) sample.emplace(scan.vertices.size());
  const bool indices_beside_ranges = check_indices && sample.has_value();
  constexpr std::size_t kGrain = 1 << 15;
  // An or of comparisons of indices [begin, end), which vectorizes (a max of unsigned does not on SSE2).
  const auto any_out_of_range = [&](std::size_t begin, std::size_t end) {
    std::uint32_t bad = 0;
    for (std::size_t i = begin; i < end; ++i) bad |= std::uint32_t(scan.indices[i] >= vertex_count);
    return std::uint8_t(bad);
  };
  std::vector<std::uint8_t> out_of_range;  // per slice or part of the indices
  if ((check_indices && !indices_beside_ranges) || !own.empty()) {
    const std::size_t count = detail::parallel_slices(
        std::max(scan.vertices.size(), indices_beside_ranges ? 0 : scan.indices.size()), threads, kGrain);
    std::vector<detail::VertexRun> slices(count);
    out_of_range.assign(count, 0);
    // Each worker its own part of the arrays, as the passes after take them (to_grid_units_into).
    detail::parallel_for_apart(count, threads, count, [&](std::size_t first, std::size_t last, std::size_t) {
      for (std::size_t w = first; w < last; ++w) {
        const auto slice = [&](std::size_t n) { return std::pair(n * w / count, n * (w + 1) / count); };
        if (!own.empty()) {
          const auto [begin, end] = slice(scan.vertices.size());
          slices[w] = detail::summarize_vertices(std::span(scan.vertices).subspan(begin, end - begin));
          if (sample) sample->gather(scan.vertices, begin, end);
        }
        if (check_indices && !indices_beside_ranges) {
          const auto [begin, end] = slice(scan.indices.size());
          out_of_range[w] = any_out_of_range(begin, end);
        }
      }
    });
    // In slice order, as one pass would (min and max keep the first of equal values, ±0 included).
    for (const detail::VertexRun& slice : slices) {
      if (own.empty()) break;
      detail::VertexRun& all = own.front();
      all.count += slice.count, all.finite += slice.finite;
      all.lo = glm::min(all.lo, slice.lo), all.hi = glm::max(all.hi, slice.hi);
    }
  }
  const std::span<const detail::VertexRun> runs =
      own.empty() ? std::span<const detail::VertexRun>(known->runs) : std::span<const detail::VertexRun>(own);
  std::size_t finite_count = 0;
  for (const detail::VertexRun& run : runs) finite_count += run.finite;
  out.skipped_vertices = scan.vertices.size() - finite_count;
  const bool ranges_wanted = reject_outliers && finite_count >= kOutlierMinVertices;

  std::array<std::pair<float, float>, 3> range;
  const bool ranges_from_sample = ranges_wanted && sample && out.skipped_vertices == 0;
  if (indices_beside_ranges) {
    const std::size_t parts = std::clamp<std::size_t>(scan.indices.size() / kGrain, 1, 4);
    const std::size_t axes = ranges_from_sample ? 3 : 0;
    out_of_range.assign(parts, 0);
    detail::parallel_tasks(axes + parts, threads, [&](std::size_t task) {
      if (task < axes) {
        range[task] = axis_range(*sample, int(task), guess ? &guess->axes[task] : nullptr);
        return;
      }
      const std::size_t part = task - axes, n = scan.indices.size();
      out_of_range[part] = any_out_of_range(n * part / parts, n * (part + 1) / parts);
    });
  }
  // Where an index is out of range, the first one names the error.
  if (std::find(out_of_range.begin(), out_of_range.end(), 1) != out_of_range.end())
    for (std::size_t i = 0; i < scan.indices.size(); ++i)
      if (scan.indices[i] >= vertex_count)
        throw Error(ErrorCode::BadIndices, "index " + std::to_string(scan.indices[i]) + " of triangle " +
                                               std::to_string(i / 3) + " is out of range (" +
                                               std::to_string(scan.vertices.size()) + " vertices)");

  // Which vertices are kept: made only once one is removed (the usual scan removes none).
  std::vector<std::uint8_t> keep;
  const auto make_keep = [&] {
    if (!keep.empty()) return;
    keep.resize(scan.vertices.size());
    for (std::size_t i = 0; i < scan.vertices.size(); ++i) keep[i] = finite(scan.vertices[i]) ? 1 : 0;
  };
  if (out.skipped_vertices != 0) make_keep();

  if (ranges_wanted) {
    if (!ranges_from_sample) {
      const std::span<const glm::vec3> all(scan.vertices);
      range = robust_ranges(std::span(&all, 1), keep, threads, guess);
    }
    std::size_t first = 0;
    for (const detail::VertexRun& run : runs) {
      const bool inside = run_inside(run, range);
      for (std::size_t i = first; !inside && i < first + run.count; ++i) {
        const glm::vec3& v = scan.vertices[i];
        if (!finite(v)) continue;
        for (int axis = 0; axis < 3; ++axis)
          if (v[axis] < range[axis].first || v[axis] > range[axis].second) {
            make_keep();
            keep[i] = 0;
            ++out.outlier_vertices;
            break;
          }
      }
      first += run.count;
    }
  }

  const bool renumbered = out.skipped_vertices != 0 || out.outlier_vertices != 0;  // else: the usual case
  // The kept vertices' bounds: the runs' where none was removed.
  if (renumbered) {
    renumber_kept(scan, keep, out);
    const detail::VertexRun kept = detail::summarize_vertices(out.vertices);
    out.lo = kept.lo, out.hi = kept.hi;
  } else {
    bounds_of_runs(runs, out);
  }
  return renumbered;
}

}  // namespace

PreparedInput prepare_input(const Scan& scan, bool reject_outliers) {
  PreparedInput out;
  if (!check_input(scan, reject_outliers, out, nullptr, 1, nullptr)) {
    out.vertices = scan.vertices;
    out.indices = scan.indices;
  }
  return out;
}

namespace detail {

namespace {

// summarize_vertices one vertex at a time: glm::min and glm::max per axis (the first of equal values kept),
// skipping vertices that are not finite, without a branch.
VertexRun summarize_in_order(std::span<const glm::vec3> vertices) {
  VertexRun run;
  run.count = vertices.size();
  std::array<float, 3> lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
  std::size_t finite_count = 0;
  for (const glm::vec3& v : vertices) {
    const bool f = finite(v);
    finite_count += f;
    for (int axis = 0; axis < 3; ++axis) {
      const float x = v[axis];
      float& l = lo[std::size_t(axis)];
      float& h = hi[std::size_t(axis)];
      l = f && x < l ? x : l;
      h = f && h < x ? x : h;
    }
  }
  run.finite = finite_count;
  run.lo = {lo[0], lo[1], lo[2]}, run.hi = {hi[0], hi[1], hi[2]};
  return run;
}

}  // namespace

VertexRun summarize_vertices(std::span<const glm::vec3> vertices) {
  // Four vertices at a time (vertex_lanes.h): the loop above does not vectorize, and was 5 % of a bounds-only run
  // of thesis-room1 on one thread. Where every vertex is finite its extremes are those of the loop above but for
  // the sign of a zero (the loop keeps the first of equal values, +0 or -0): an extreme of zero takes the sign of
  // the first vertex that holds it. A vertex that is not finite: the loop.
  typedef std::uint32_t Bits __attribute__((vector_size(16)));
  const std::size_t quads = vertices.size() / 4;
  VertexLanes lo[3], hi[3];
  Bits not_finite{0, 0, 0, 0};
  for (int k = 0; k < 3; ++k) lo[k] = VertexLanes{} + INFINITY, hi[k] = VertexLanes{} - INFINITY;
  for (std::size_t q = 0; q < quads; ++q)
    for (int k = 0; k < 3; ++k) {
      const VertexLanes v = load_lanes(vertices.data() + 4 * q, k);
      not_finite |= (std::bit_cast<Bits>(v) & kExponentBits) == kExponentBits;  // finite() on each lane
      lo[k] = v < lo[k] ? v : lo[k];
      hi[k] = hi[k] < v ? v : hi[k];
    }
  if ((not_finite[0] | not_finite[1] | not_finite[2] | not_finite[3]) != 0) return summarize_in_order(vertices);
  VertexRun run = summarize_in_order(vertices.subspan(4 * quads));  // the last few
  run.count = vertices.size();
  run.finite += 4 * quads;
  for (int k = 0; k < 3; ++k)
    for (int lane = 0; lane < 4; ++lane) {
      const int axis = lane_axis(k, lane);
      run.lo[axis] = std::min(run.lo[axis], lo[k][lane]);
      run.hi[axis] = std::max(run.hi[axis], hi[k][lane]);
    }
  for (int axis = 0; axis < 3; ++axis) {
    const auto first_zero = [&] {
      return (*std::find_if(vertices.begin(), vertices.end(),
                            [&](const glm::vec3& v) { return finite(v) && v[axis] == 0.0f; }))[axis];
    };
    for (float* extreme : {&run.lo[axis], &run.hi[axis]})
      if (*extreme == 0.0f) *extreme = first_zero();
  }
  return run;
}

std::optional<PreparedInput> check_parts(std::span<const std::span<const glm::vec3>> parts, std::size_t index_count,
                                         bool reject_outliers, const KnownInput& known, unsigned threads,
                                         QuantileGuess* guess, std::span<const PartKey> keys) {
  PreparedInput out;
  std::size_t vertex_count = 0;
  for (const std::span<const glm::vec3> part : parts) vertex_count += part.size();
  check_sizes(vertex_count, index_count, out);
  if (!known.indices_in_range || known.runs.size() != parts.size()) return std::nullopt;
  std::size_t finite_count = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (known.runs[k].count != parts[k].size()) return std::nullopt;
    finite_count += known.runs[k].finite;
  }
  if (finite_count != vertex_count) return std::nullopt;  // a vertex to skip: check_input renumbers
  if (reject_outliers && finite_count >= kOutlierMinVertices) {
    std::optional<std::array<std::pair<float, float>, 3>> from_parts;
    if (guess && keys.size() == parts.size()) from_parts = ranges_from_part_samples(parts, keys, *guess);
    const std::array<std::pair<float, float>, 3> range = from_parts ? *from_parts : robust_ranges(parts, {}, threads, guess);
    for (const VertexRun& run : known.runs)
      if (!run_inside(run, range)) return std::nullopt;  // an outlier: check_input renumbers
  }
  bounds_of_runs(known.runs, out);
  return out;
}

InputView view_input(const Scan& scan, bool reject_outliers, const KnownInput* known, unsigned threads,
                     QuantileGuess* guess) {
  InputView view;
  const bool renumbered = check_input(scan, reject_outliers, view.checked, known, threads, guess);
  view.vertices = renumbered ? std::span<const glm::vec3>(view.checked.vertices) : std::span<const glm::vec3>(scan.vertices);
  view.indices = renumbered ? std::span<const std::uint32_t>(view.checked.indices) : std::span<const std::uint32_t>(scan.indices);
  return view;
}

}  // namespace detail

}  // namespace roomsense
