// The checked input of one analysis without a copy of the scan: prepare_input copies the scan's arrays even
// where it removed nothing (a 50 x 50 m floor's are 21 MB); an analysis reads them in place instead.
#pragma once
#include "roomsense/input.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace roomsense::detail {

struct InputView {
  InputView() = default;
  InputView(const InputView&) = delete;  // the views may point into `checked`
  InputView& operator=(const InputView&) = delete;
  InputView(InputView&&) = default;  // moving keeps the arrays' storage, so the views stay valid
  InputView& operator=(InputView&&) = default;

  PreparedInput checked;  // every count and the bounds; the arrays only where something was removed
  std::span<const glm::vec3> vertices;  // the scan's own arrays, or `checked`'s where something was removed
  std::span<const std::uint32_t> indices;
};

// A run of a scan's vertices (a chunk's, for an IncrementalAnalysis): how many there are, how many are finite,
// and the bounds of those.
struct VertexRun {
  std::size_t count = 0, finite = 0;
  glm::vec3 lo{INFINITY}, hi{-INFINITY};
};
VertexRun summarize_vertices(std::span<const glm::vec3> vertices);

// What the caller of view_input knows of the scan already: its vertices as consecutive runs (summed, every
// vertex), and whether every index is known to be in range. An IncrementalAnalysis knows both for each chunk, so
// a chunk that did not change costs the checks nothing but its run.
struct KnownInput {
  std::vector<VertexRun> runs;
  bool indices_in_range = false;
};

// Where the outlier quantiles of each axis were found last: bounds with a few sampled values below the first and
// above the second. An IncrementalAnalysis keeps them for its next analysis, whose scan changed by a chunk or
// two: the selection tries them before it samples bounds afresh. The values' counts decide whether they serve,
// so a guess changes the work, never the ranges.
using QuantileBounds = std::optional<std::pair<float, float>>;
// How many values of a sample lie below `low`, above `high`, and at each.
struct TailCounts {
  std::uint32_t below = 0, above = 0, low_ties = 0, high_ties = 0;  // 32 bits: four lanes to a register
  void add(float x, float low, float high) {
    below += x < low, above += x > high, low_ties += x == low, high_ties += x == high;
  }
  TailCounts& operator+=(const TailCounts& o) {
    below += o.below, above += o.above, low_ties += o.low_ties, high_ties += o.high_ties;
    return *this;
  }
};
// One axis's sampled values against bounds low <= high (QuantileBounds): their counts, and the values below and
// above, in sample order (where more lie past a bound than the selection gathers, some of them).
struct SampleTails : TailCounts {
  float low = 0.0f, high = 0.0f;
  std::vector<float> lower, upper;
};
// A part's share of the outlier sample (every stride-th vertex of the parts end to end, from its vertex `first` on):
// each axis's tails against the bounds last tried there, where known.
struct PartSample {
  std::uint64_t hash = 0;
  std::size_t stride = 0, first = 0;
  std::array<std::optional<SampleTails>, 3> tails;
};
// A part's name and content (an IncrementalAnalysis's chunk id and hash): a part kept under the same id and hash
// holds the same vertices.
struct PartKey {
  std::uint64_t id = 0, hash = 0;
};
struct QuantileGuess {
  std::array<QuantileBounds, 3> axes;
  // Where check_parts is given the parts' keys: by part id, its samples at the last few places and strides the
  // sample took it at (a part moves in the sample where one before it changes its vertex count, and the stride
  // changes with the count: an object set down and taken away moves the rest by turns), the latest first. Where the bounds serve, an analysis reads the vertices of the
  // parts that changed or moved to a new place, not a sample of every part's: a strided read of a room's every chunk
  // was a tenth of an added object's update (cache misses, not instructions).
  std::map<std::uint64_t, std::vector<PartSample>> parts;
};

// prepare_input's checks and errors; the views are valid while `scan` and the result live. `known`, where not
// null, must describe `scan` (runs that do not cover its vertices exactly are ignored). `guess`, where not null,
// is tried and updated (above).
InputView view_input(const Scan& scan, bool reject_outliers, const KnownInput* known = nullptr, unsigned threads = 1,
                     QuantileGuess* guess = nullptr);

// view_input's checks of a scan held as parts (an IncrementalAnalysis's chunks, in order) with `index_count`
// indices, all known in range, and a run per part (`known`): its errors, and where nothing is to be removed its
// counts and bounds, with the outlier ranges view_input finds (their sample walks the parts as one array). Where a
// vertex is to be removed (not finite, or an outlier), std::nullopt: view_input of the whole scan renumbers.
// `keys`, a key per part where given, with a guess: the guess's part samples serve and are kept (QuantileGuess).
std::optional<PreparedInput> check_parts(std::span<const std::span<const glm::vec3>> parts, std::size_t index_count,
                                         bool reject_outliers, const KnownInput& known, unsigned threads = 1,
                                         QuantileGuess* guess = nullptr, std::span<const PartKey> keys = {});

}  // namespace roomsense::detail
