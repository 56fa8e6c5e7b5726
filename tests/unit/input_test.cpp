// Input hygiene, frames and the grid budget (thesis Eq. 3.1-3.5).
#include "roomsense/analysis.h"
#include "roomsense/content_hash.h"
#include "roomsense/error.h"
#include "roomsense/input.h"
#include "roomsense/scan.h"
#include "roomsense/synthetic.h"
#include "../../core/src/input/input_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <limits>

namespace roomsense {
namespace {

// ContentHash tells every one-byte change of a mesh's arrays, and an array one zero byte longer, from the original
// (an IncrementalAnalysis takes a chunk whose hash is unchanged for one sent again as it was).
TEST(ContentHash, TellsEveryChangedByteAndLength) {
  std::mt19937 random(7);
  std::vector<float> vertices(3 * 101);
  for (float& v : vertices) v = std::uniform_real_distribution<float>(-5.0f, 5.0f)(random);
  const auto hash = [](const std::vector<float>& v) {
    ContentHash h;
    h.add(std::span<const float>(v));
    return h.value();
  };
  const std::uint64_t original = hash(vertices);
  EXPECT_EQ(hash(vertices), original);
  for (std::size_t byte = 0; byte < vertices.size() * sizeof(float); ++byte)
    for (const unsigned char flip : {0x01, 0x80}) {
      std::vector<float> changed = vertices;
      auto* bytes = reinterpret_cast<unsigned char*>(changed.data());
      bytes[byte] ^= flip;
      ASSERT_NE(hash(changed), original) << "byte " << byte;
    }
  std::vector<unsigned char> raw(vertices.size() * sizeof(float));
  std::memcpy(raw.data(), vertices.data(), raw.size());
  ContentHash shorter, longer;
  shorter.add(std::span<const unsigned char>(raw));
  raw.push_back(0);
  longer.add(std::span<const unsigned char>(raw));
  EXPECT_NE(shorter.value(), longer.value());
  // Hashed in lanes, word k of each 64-byte block into lane k (content_hash.h): two words swapped, within a block
  // (two lanes: one block alone, where nothing after tells the lanes apart) or between blocks (one lane's order, or
  // two lanes'), hash apart too, as do the two words after the last whole block.
  const auto hash_words = [](const std::vector<std::uint64_t>& w) {
    ContentHash h;
    h.add(std::span<const std::uint64_t>(w));
    return h.value();
  };
  for (const std::size_t count : {8, 2 * 8 + 2}) {
    std::vector<std::uint64_t> words(count);
    for (std::size_t k = 0; k < words.size(); ++k) words[k] = 0x0123456789abcdefull * (k + 1);
    const std::uint64_t in_order = hash_words(words);
    for (std::size_t a = 0; a < words.size(); ++a)
      for (std::size_t b = a + 1; b < words.size(); ++b) {
        std::vector<std::uint64_t> swapped = words;
        std::swap(swapped[a], swapped[b]);
        EXPECT_NE(hash_words(swapped), in_order) << count << " words: " << a << " and " << b;
      }
  }
}

ErrorCode code_of(auto&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  ADD_FAILURE() << "no Error thrown";
  return ErrorCode::Io;
}

TEST(FlatArray, ThesisErrorCodes) {
  const float data[6] = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(code_of([&] { scan_from_flat_array(nullptr, 6); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, 0); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, -3); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, 5); }), ErrorCode::SizeNotMultipleOfThree);
  const Scan scan = scan_from_flat_array(data, 6);
  ASSERT_EQ(scan.vertices.size(), 2u);
  EXPECT_EQ(scan.vertices[1], glm::vec3(3, 4, 5));
}

TEST(PrepareInput, SkipsNonFiniteVerticesAndTheirTriangles) {
  Scan scan;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  scan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 0, 0}, {0, inf, 0}};
  scan.indices = {0, 1, 2, 0, 1, 3, 2, 4, 1};
  const PreparedInput in = prepare_input(scan);
  EXPECT_EQ(in.skipped_vertices, 2u);
  EXPECT_EQ(in.dropped_triangles, 2u);
  EXPECT_EQ(in.vertices.size(), 3u);
  EXPECT_EQ(in.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(PrepareInput, RejectsBadIndices) {
  Scan scan;
  scan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  scan.indices = {0, 1};
  EXPECT_EQ(code_of([&] { prepare_input(scan); }), ErrorCode::BadIndices);
  scan.indices = {0, 1, 3};
  EXPECT_EQ(code_of([&] { prepare_input(scan); }), ErrorCode::BadIndices);
  EXPECT_EQ(code_of([&] { prepare_input(Scan{}); }), ErrorCode::EmptyInput);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(code_of([&] { prepare_input(Scan{{{nan, nan, nan}}, {}}); }), ErrorCode::NoValidVertices);
}

TEST(PrepareInput, RejectsAStrayVertexOneKilometreAway) {
  Scan scan = synth::generate(synth::default_room());
  scan.vertices.push_back({1000.0f, 0.0f, 0.0f});
  const AnalysisResult r = analyze(scan);
  EXPECT_EQ(r.input.outlier_vertices, 1u);
  EXPECT_TRUE(r.ok());
  EXPECT_LT(r.voxels.grid.spec.nx, 60);  // the room is 5 m wide
  ASSERT_FALSE(r.warnings.empty());
}

// At 200 vertices, the fewest the outlier test takes, (n - 1) q rounds down to rank 0: the quantiles are taken at
// rank 1 at least (input.h), so a lone stray vertex is not its own quantile. It was kept, and its 1,000 km made the
// grid too large to analyse (TooMuchWork).
TEST(PrepareInput, RejectsAStrayVertexAmongTheFewestTheTestTakes) {
  Scan scan;
  for (std::size_t i = 0; i + 1 < kOutlierMinVertices; ++i)
    scan.vertices.push_back({float(i % 10) * 0.5f, float(i / 10 % 4) * 0.8f, float(i / 40) * 0.9f});
  for (const glm::vec3 far : {glm::vec3(1.0e6f, 1.0f, 1.0f), glm::vec3(-1.0e6f, 1.0f, 1.0f)}) {
    Scan stray = scan;
    stray.vertices.push_back(far);
    ASSERT_EQ(stray.vertices.size(), kOutlierMinVertices);
    const PreparedInput in = prepare_input(stray);
    EXPECT_EQ(in.outlier_vertices, 1u);
    EXPECT_EQ(in.vertices.size(), kOutlierMinVertices - 1);
    EXPECT_EQ(in.lo, glm::vec3(0.0f));
    EXPECT_EQ(in.hi, glm::vec3(9 * 0.5f, 3 * 0.8f, 4 * 0.9f));
  }
  // Without a stray vertex, nothing is rejected: the ranges reach the margin past the data.
  scan.vertices.push_back({2.0f, 1.0f, 2.0f});
  EXPECT_EQ(prepare_input(scan).outlier_vertices, 0u);
}

// The outlier ranges are exact order statistics (input.h), found without sorting: against a full sort of
// every vertex (at most 16384 vertices are all sampled), on axes with many equal values at the quantiles (a
// scan's floor and walls), continuous ones, and vertices exactly at a range's end (kept) and just past it.
TEST(PrepareInput, OutlierRangesAreTheExactQuantiles) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 10.0f);
    std::uniform_int_distribution<int> step(0, 20);
    const std::size_t n = 16000;
    Scan scan;
    for (std::size_t i = 0; i < n; ++i) {
      // x: continuous; y: ties, a third of all exactly at the floor; z: ties at the top.
      const float y = i % 3 == 0 ? 0.0f : 0.5f * float(step(random));
      const float z = i % 4 == 0 ? 10.0f : seed % 2 ? uniform(random) : 0.5f * float(step(random));
      scan.vertices.push_back({uniform(random), y, z});
    }
    const auto range_of = [&](int axis) {
      std::vector<float> v;
      for (const glm::vec3& p : scan.vertices) v.push_back(p[axis]);
      std::sort(v.begin(), v.end());
      const std::size_t k = std::size_t(double(v.size() - 1) * kOutlierQuantile);
      const float lo = v[k], hi = v[v.size() - 1 - k], margin = std::max(kOutlierMinMargin, hi - lo);
      return std::pair(lo - margin, hi + margin);
    };
    // Far below the data, a few vertices at the end of x's range and a few just past it: below every other
    // vertex wherever they are there, they leave the quantiles where they were.
    for (int i = 0; i < 5; ++i) scan.vertices.push_back({-100.0f, 1.0f, 1.0f});
    const std::pair<float, float> x = range_of(0);
    for (std::size_t i = 0; i < 5; ++i)
      scan.vertices[n + i].x = i < 3 ? x.first : std::nextafter(x.first, -INFINITY);
    std::array<std::pair<float, float>, 3> ranges = {range_of(0), range_of(1), range_of(2)};
    ASSERT_EQ(ranges[0], x);
    std::size_t outliers = 0;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : scan.vertices) {
      bool out = false;
      for (int axis = 0; axis < 3; ++axis)
        out = out || p[axis] < ranges[std::size_t(axis)].first || p[axis] > ranges[std::size_t(axis)].second;
      outliers += out;
      if (!out) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    const PreparedInput in = prepare_input(scan);
    EXPECT_EQ(outliers, 2u) << seed;
    EXPECT_EQ(in.outlier_vertices, outliers) << seed;
    EXPECT_EQ(in.lo, lo) << seed;
    EXPECT_EQ(in.hi, hi) << seed;
    EXPECT_EQ(in.lo.x, x.first) << seed;  // the vertices at the range's end are kept
  }
}

// A large scan's outlier ranges come from every stride-th vertex (a sample of about 16k): gathered beside the
// vertices' bounds where every vertex is finite, or on its own from the finite ones at those places where one is
// not. Either way they are the sample's exact quantiles, on any number of threads: outliers placed on sampled
// vertices move the quantiles, and the vertices just inside and just past the ranges those give are told apart.
TEST(PrepareInput, TheOutlierSampleOfALargeScanIsEveryStrideThVertex) {
  constexpr std::size_t kSample = 16384;
  for (const bool with_nan : {false, true}) {
    std::mt19937 random(with_nan ? 8 : 7);
    std::uniform_real_distribution<float> uniform(0.0f, 10.0f);
    Scan scan;
    const std::size_t n = 100003;  // a stride of 6, and a last sample past a whole multiple of the slices'
    for (std::size_t i = 0; i < n; ++i) scan.vertices.push_back({uniform(random), uniform(random), uniform(random)});
    const std::size_t stride = n / kSample;
    ASSERT_EQ(stride, 6u);
    // Far values on 100 sampled vertices raise the upper quantile of x; on unsampled ones they are outliers.
    for (std::size_t j = 0; j < 100; ++j) scan.vertices[(50 + 97 * j) * stride].x = 40.0f + 0.1f * float(j);
    for (std::size_t j = 0; j < 50; ++j) scan.vertices[(60 + 97 * j) * stride + 1].x = 1000.0f;
    if (with_nan) scan.vertices[7 * stride].y = std::numeric_limits<float>::quiet_NaN();  // a sampled place
    // The ranges from the sample: the finite vertices at multiples of the stride.
    std::array<std::pair<float, float>, 3> ranges;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<float> v;
      for (std::size_t i = 0; i < n; i += stride)
        if (std::isfinite(scan.vertices[i].y)) v.push_back(scan.vertices[i][axis]);
      std::sort(v.begin(), v.end());
      const std::size_t k = std::size_t(double(v.size() - 1) * kOutlierQuantile);
      const float lo = v[k], hi = v[v.size() - 1 - k], margin = std::max(kOutlierMinMargin, hi - lo);
      ranges[std::size_t(axis)] = {lo - margin, hi + margin};
    }
    // Two unsampled vertices on x's upper end: one at it (kept), one a float's step past it (an outlier).
    scan.vertices[9 * stride + 2].x = ranges[0].second;
    scan.vertices[9 * stride + 3].x = std::nextafter(ranges[0].second, INFINITY);
    std::size_t outliers = 0;
    for (const glm::vec3& p : scan.vertices) {
      if (!std::isfinite(p.y)) continue;
      bool out = false;
      for (int axis = 0; axis < 3; ++axis)
        out = out || p[axis] < ranges[std::size_t(axis)].first || p[axis] > ranges[std::size_t(axis)].second;
      outliers += out;
    }
    ASSERT_GT(ranges[0].second, 20.0f);  // the sampled far values moved the quantile
    ASSERT_EQ(outliers, 51u);
    for (const unsigned threads : {1u, 2u, 3u}) {
      const detail::InputView view = detail::view_input(scan, true, nullptr, threads);
      EXPECT_EQ(view.checked.outlier_vertices, outliers) << with_nan << " " << threads;
      EXPECT_EQ(view.checked.skipped_vertices, with_nan ? 1u : 0u) << threads;
      EXPECT_EQ(view.checked.hi.x, ranges[0].second) << with_nan << " " << threads;
    }
  }
}

// An IncrementalAnalysis's input checks try the previous analysis's quantile bounds first (input_view.h): a guess
// that serves leaves the ranges those of a search afresh, and one that does not (past every value, inside the
// data, the wrong way round, from another scan) is replaced by the bounds sampled afresh, with the same ranges.
TEST(PrepareInput, QuantileGuessesChangeTheWorkNotTheRanges) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 10.0f);
    std::uniform_int_distribution<int> step(0, 20);
    Scan scan;
    for (std::size_t i = 0; i < 16000; ++i) {  // x continuous, y tied at the floor, z tied at the top
      const float y = i % 3 == 0 ? 0.0f : 0.5f * float(step(random));
      scan.vertices.push_back({uniform(random), y, i % 4 == 0 ? 10.0f : uniform(random)});
    }
    for (int i = 0; i < 3; ++i) scan.vertices.push_back({-100.0f, 300.0f, 1.0f});
    const PreparedInput expected = prepare_input(scan);
    ASSERT_EQ(expected.outlier_vertices, 3u);
    const auto same = [&](detail::QuantileGuess& guess) {
      const detail::InputView view = detail::view_input(scan, true, nullptr, 2, &guess);
      EXPECT_EQ(view.checked.outlier_vertices, expected.outlier_vertices) << seed;
      EXPECT_EQ(view.checked.lo, expected.lo) << seed;
      EXPECT_EQ(view.checked.hi, expected.hi) << seed;
    };
    detail::QuantileGuess sampled;
    same(sampled);
    for (const detail::QuantileBounds& axis : sampled.axes) ASSERT_TRUE(axis.has_value()) << seed;
    // On the continuous axis, bounds a little inside the sampled ones still leave few values past them: they
    // serve, and stay.
    detail::QuantileGuess near = sampled;
    near.axes[0] = std::pair(std::nextafter(near.axes[0]->first, INFINITY), std::nextafter(near.axes[0]->second, -INFINITY));
    const detail::QuantileGuess near_before = near;
    same(near);
    EXPECT_EQ(near.axes, near_before.axes) << seed;
    EXPECT_NE(near.axes, sampled.axes) << seed;
    // Guesses that cannot serve: each is replaced by the sampled bounds.
    const std::array<std::pair<float, float>, 5> bad = {std::pair(-1e30f, 1e30f), std::pair(4.0f, 6.0f),
                                                         std::pair(6.0f, 4.0f), std::pair(0.0f, 0.0f),
                                                         std::pair(9.9f, 10.0f)};
    for (const auto& bounds : bad) {
      detail::QuantileGuess guess;
      guess.axes.fill(bounds);
      same(guess);
      EXPECT_EQ(guess.axes, sampled.axes) << seed << " " << bounds.first << " " << bounds.second;
    }
  }
}

// An IncrementalAnalysis's input checks keep each chunk's share of the outlier sample (QuantileGuess::parts): where
// the bounds serve, a chunk's tails are read again only where it changed or moved to a new place in the sample. Parts
// grow, shrink, move and change under one guess, and a vertex at the upper range's end (kept) and a float's step past
// it (an outlier) are told apart as the whole scan's sample tells them, every step.
TEST(PrepareInput, PartSamplesKeptBetweenChecksGiveTheSameOutliers) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> uniform(0.0f, 10.0f);
  std::uniform_int_distribution<int> size_of(1500, 4500);
  // `high`: a part with many values past the rest on x, which moves the upper quantile past the bounds kept.
  const auto make_part = [&](int high = 12, std::size_t size = 0) {
    std::vector<glm::vec3> part(size != 0 ? size : std::size_t(size_of(random)));
    for (glm::vec3& v : part) v = {uniform(random), uniform(random), uniform(random)};
    // A few values past the rest on x, sampled or not by where the part lies: the upper quantile moves with them.
    const std::size_t n = std::min(part.size(), std::size_t(high));
    for (std::size_t j = 0; j < n; ++j) part[j * part.size() / n].x = 10.0f + 0.5f * uniform(random);
    return part;
  };
  std::vector<std::vector<glm::vec3>> parts(30);
  std::vector<detail::PartKey> keys(parts.size());
  std::uint64_t version = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) parts[p] = make_part(), keys[p] = {100 + p, ++version};
  detail::QuantileGuess kept;
  std::size_t tails_reused = 0, reused_across_strides = 0, served = 0, bounds_moved = 0;
  std::set<std::size_t> strides;  // the sample's: a part's tails are kept at each
  for (int step = 0; step < 24; ++step) {
    // A part in front, one in the middle or the last changes (its size too: the parts after it move in the sample).
    const std::size_t p = step % 3 == 0 ? 0 : step % 3 == 1 ? parts.size() / 2 : parts.size() - 1;
    if (step > 0) parts[p] = make_part(step == 12 ? 5000 : 12), keys[p].hash = ++version;
    // From step 16 the last part is large every other step: the sample's stride changes by turns.
    if (step >= 16) parts.back() = make_part(12, step % 2 == 0 ? 20000 : 2000), keys.back().hash = ++version;
    // Now and then a part is removed and another takes its place under a new id: the guess forgets the old one.
    if (step % 5 == 4) keys[parts.size() / 3].id = 1000 + std::uint64_t(step);
    std::size_t count = 0;
    for (const auto& part : parts) count += part.size();
    const std::size_t stride = count / 16384;
    ASSERT_GE(stride, 3u);
    strides.insert(stride);
    // The whole scan's ranges of x: its sample's quantiles.
    std::vector<float> v;
    std::size_t at = 0;
    for (const auto& part : parts)
      for (const glm::vec3& q : part) v.push_back(q.x), ++at;
    std::vector<float> sample;
    for (std::size_t i = 0; i < v.size(); i += stride) sample.push_back(v[i]);
    std::sort(sample.begin(), sample.end());
    const std::size_t k = std::max<std::size_t>(1, std::size_t(double(sample.size() - 1) * kOutlierQuantile));
    const float lo = sample[k], hi = sample[sample.size() - 1 - k];
    const float upper = hi + std::max(kOutlierMinMargin, hi - lo);
    // The probe: the last part's last vertex that the sample does not take, at the range's end or just past it.
    std::vector<glm::vec3>& last = parts.back();
    std::size_t probe = last.size() - 1;
    while ((count - last.size() + probe) % stride == 0) --probe;
    const glm::vec3 before = last[probe];
    for (const bool past : {false, true}) {
      last[probe].x = past ? std::nextafter(upper, INFINITY) : upper;
      keys.back().hash = ++version;
      std::vector<std::span<const glm::vec3>> spans;
      detail::KnownInput known;
      known.indices_in_range = true;
      for (const auto& part : parts) spans.emplace_back(part), known.runs.push_back(detail::summarize_vertices(part));
      const detail::QuantileGuess kept_before = kept;
      const std::optional<PreparedInput> with_parts = detail::check_parts(spans, 0, true, known, 2, &kept, keys);
      EXPECT_LE(kept.parts.size(), parts.size()) << step;  // no part's samples kept once it is gone
      detail::QuantileGuess fresh;
      const std::optional<PreparedInput> without = detail::check_parts(spans, 0, true, known, 2, &fresh);
      EXPECT_EQ(with_parts.has_value(), !past) << step;
      EXPECT_EQ(without.has_value(), !past) << step;
      // Where the bounds served, every part's tails of every axis were summed; those of a part that neither
      // changed nor moved were the kept ones (against the bounds kept: not after the bounds moved).
      bounds_moved += kept_before.axes != kept.axes && step > 0;
      if (kept_before.axes == kept.axes && step > 0) {
        ++served;
        ASSERT_EQ(kept.parts.size(), parts.size());
        for (std::size_t q = 0; q + 1 < parts.size(); ++q) {
          const detail::PartSample& now = kept.parts.at(keys[q].id).front();
          for (const auto& tails : now.tails) EXPECT_TRUE(tails.has_value()) << step << " " << q;
          if (!kept_before.parts.count(keys[q].id)) continue;
          const std::vector<detail::PartSample>& places = kept_before.parts.at(keys[q].id);
          for (std::size_t w = 0; w < places.size(); ++w) {
            const detail::PartSample& was = places[w];
            const bool reused = was.hash == now.hash && was.stride == now.stride && was.first == now.first &&
                                was.tails[0] && now.tails[0] && was.tails[0]->lower == now.tails[0]->lower &&
                                was.tails[0]->below == now.tails[0]->below;
            tails_reused += reused;
            // Kept from before the last check's stride (its first place is another stride's).
            reused_across_strides += reused && w > 0 && places.front().stride != now.stride;
          }
        }
      }
    }
    last[probe] = before;
  }
  EXPECT_GT(tails_reused, 200u);
  EXPECT_GT(served, 30u);
  EXPECT_GT(bounds_moved, 0u);
  EXPECT_GE(strides.size(), 2u);
  EXPECT_GT(reused_across_strides, 30u);
}

// A large scan's input checks run on slices side by side (analyze's threads): the first bad index still names
// the error, and the non-finite vertices and bounds are counted over every slice.
TEST(PrepareInput, ChecksOnSeveralThreadsNameTheFirstBadIndex) {
  Scan scan = synth::generate(synth::default_room());
  while (scan.vertices.size() < 300000) {  // copies of the room side by side, every slice holding some
    const std::size_t n = scan.vertices.size(), m = scan.indices.size();
    for (std::size_t i = 0; i < n; ++i) scan.vertices.push_back(scan.vertices[i]);
    for (std::size_t i = 0; i < m; ++i) scan.indices.push_back(scan.indices[i] + std::uint32_t(n));
  }
  const auto vertex_count = std::uint32_t(scan.vertices.size());
  Scan bad = scan;
  bad.indices[bad.indices.size() - 5] = vertex_count + 7;  // in the last slice
  bad.indices[bad.indices.size() / 2 + 1] = vertex_count;  // the first
  AnalysisOptions options;
  options.threads = 4;
  try {
    analyze(bad, options);
    ADD_FAILURE() << "no Error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadIndices);
    const std::string expected = "index " + std::to_string(vertex_count) + " of triangle " +
                                 std::to_string((bad.indices.size() / 2 + 1) / 3) + " is out of range";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Scan holes = scan;
  holes.vertices[10] = {nan, 0.0f, 0.0f};
  holes.vertices[holes.vertices.size() - 10] = {0.0f, INFINITY, 0.0f};
  AnalysisOptions one_thread;
  one_thread.threads = 1;
  const AnalysisResult one = analyze(holes, one_thread), four = analyze(holes, options);
  EXPECT_EQ(four.input.skipped_vertices, 2u);
  EXPECT_EQ(four.input.skipped_vertices, one.input.skipped_vertices);
  EXPECT_EQ(four.voxels.grid.spec, one.voxels.grid.spec);
  EXPECT_EQ(four.voxels.grid.cells, one.voxels.grid.cells);
}

// summarize_vertices reads four vertices at a time: its counts and bounds are a loop's over the vertices in
// order, zeros' signs included (the first of equal extremes, +0 or -0, is kept), with NaN and Inf anywhere.
TEST(PrepareInput, AVertexRunIsTheLoopsInOrder) {
  const auto in_order = [](const std::vector<glm::vec3>& vertices) {
    detail::VertexRun run;
    run.count = vertices.size();
    for (const glm::vec3& v : vertices) {
      if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) continue;
      ++run.finite;
      for (int axis = 0; axis < 3; ++axis) {
        if (v[axis] < run.lo[axis]) run.lo[axis] = v[axis];
        if (run.hi[axis] < v[axis]) run.hi[axis] = v[axis];
      }
    }
    return run;
  };
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  std::mt19937 random(7);
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<glm::vec3> vertices(random() % 40);
    for (glm::vec3& v : vertices)
      for (int axis = 0; axis < 3; ++axis) {
        const unsigned pick = random() % 12;
        v[axis] = pick == 0 ? 0.0f : pick == 1 ? -0.0f : pick == 2 && trial % 3 == 0 ? NAN
                : pick == 3 && trial % 5 == 0 ? -INFINITY : float(int(random() % 7) - 3) * 0.5f;
      }
    const detail::VertexRun got = detail::summarize_vertices(vertices), want = in_order(vertices);
    ASSERT_EQ(got.count, want.count) << "trial " << trial;
    ASSERT_EQ(got.finite, want.finite) << "trial " << trial;
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(bits(got.lo[axis]), bits(want.lo[axis])) << "trial " << trial << " axis " << axis;
      ASSERT_EQ(bits(got.hi[axis]), bits(want.hi[axis])) << "trial " << trial << " axis " << axis;
    }
  }
}

TEST(PrepareInput, AnAnalysisOfWhatIsLeftEqualsOneOfTheCleanScan) {
  // analyze() reads the scan in place where nothing is removed and the renumbered arrays where something is:
  // a NaN vertex and a stray one, with triangles on them, leave exactly the clean room's analysis.
  const Scan clean = synth::generate(synth::default_room());
  Scan dirty = clean;
  const auto n = std::uint32_t(dirty.vertices.size());
  dirty.vertices.push_back({std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f});
  dirty.vertices.push_back({1000.0f, 0.0f, 0.0f});
  dirty.indices.insert(dirty.indices.end(), {0, 1, n, n + 1, 2, 3});
  const AnalysisResult a = analyze(clean), b = analyze(dirty);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(b.input.skipped_vertices, 1u);
  EXPECT_EQ(b.input.outlier_vertices, 1u);
  EXPECT_EQ(b.input.dropped_triangles, 2u);
  EXPECT_EQ(a.voxels.grid.cells, b.voxels.grid.cells);
  EXPECT_EQ(a.floor_y, b.floor_y);
  ASSERT_EQ(a.areas.size(), b.areas.size());
  for (std::size_t i = 0; i < a.areas.size(); ++i) EXPECT_EQ(a.areas[i].center, b.areas[i].center) << i;
  EXPECT_EQ(a.bounds.vertices, b.bounds.vertices);
  EXPECT_EQ(a.bounds.indices, b.bounds.indices);
}

TEST(GridBudget, AbsurdExtentsAreRefusedNotAllocated) {
  // Too few vertices for the outlier test: the grid budget must catch it.
  Scan scan{{{0, 0, 0}, {5000, 10, 5000}, {1, 1, 1}}, {}};
  EXPECT_EQ(code_of([&] { analyze(scan); }), ErrorCode::GridTooLarge);
  EXPECT_EQ(code_of([&] { make_grid_spec({0, 0, 0}, {1, 1, 1}, 0.0f); }), ErrorCode::BadParameter);
  EXPECT_EQ(code_of([&] { make_grid_spec({0, 0, 0}, {1, 1, 1}, std::nanf("")); }), ErrorCode::BadParameter);
}

TEST(Frames, UnityUnrealAndZUpMapToOurFrame) {
  const auto converted = [](glm::vec3 p, SourceFrame f) {
    Scan s{{p}, {}};
    convert_to_roomsense_frame(s, f);
    return s.vertices[0];
  };
  // Unity: left-handed, Y up, forward +Z; ours: forward -Z.
  EXPECT_EQ(converted({1, 2, 3}, {UpAxis::Y, Units::Metres, true}), glm::vec3(1, 2, -3));
  // Unreal (Eq. 3.2): x = y_u / 100, y = z_u / 100, z = x_u / 100 (Unity frame), then Unity -> ours.
  const glm::vec3 unreal = converted({300, 100, 200}, {UpAxis::Z, Units::Centimetres, true});
  EXPECT_NEAR(unreal.x, 1.0f, 1e-6f);
  EXPECT_NEAR(unreal.y, 2.0f, 1e-6f);
  EXPECT_NEAR(unreal.z, -3.0f, 1e-6f);
  // Right-handed Z up (Blender): up becomes +Y, +Y (forward) becomes -Z.
  const glm::vec3 blender = converted({1000, 2000, 3000}, {UpAxis::Z, Units::Millimetres, false});
  EXPECT_NEAR(blender.x, 1.0f, 1e-6f);
  EXPECT_NEAR(blender.y, 3.0f, 1e-6f);
  EXPECT_NEAR(blender.z, -2.0f, 1e-6f);
}

TEST(Frames, AConvertedUnityRoomGivesTheSameLevels) {
  const Scan ours = synth::generate(synth::default_room());
  Scan unity = ours;
  for (glm::vec3& v : unity.vertices) v.z = -v.z;  // what a Unity export of the room holds
  convert_to_roomsense_frame(unity, {UpAxis::Y, Units::Metres, true});
  const AnalysisResult a = analyze(ours), b = analyze(unity);
  EXPECT_EQ(a.floor_y, b.floor_y);
  EXPECT_EQ(a.ceiling_y, b.ceiling_y);
  EXPECT_EQ(a.bounds.indices.size(), b.bounds.indices.size());
}

}  // namespace
}  // namespace roomsense
