#include "roomsense/error.h"
#include "roomsense/input.h"
#include "input_view.h"
#include "../parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace roomsense {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The [q, 1-q] quantiles of one axis over the kept vertices (`keep` empty: all), widened by the outlier margin.
// Quantiles of an evenly strided sample of at most kQuantileSample vertices are as good for this and keep large
// scans cheap.
constexpr std::size_t kQuantileSample = 16384;
std::pair<float, float> robust_range(const std::vector<glm::vec3>& vertices, const std::vector<std::uint8_t>& keep, int axis) {
  std::vector<float> values;
  const std::size_t stride = std::max<std::size_t>(1, vertices.size() / kQuantileSample);
  values.reserve(vertices.size() / stride + 1);
  for (std::size_t i = 0; i < vertices.size(); i += stride)
    if (keep.empty() || keep[i]) values.push_back(vertices[i][axis]);
  if (values.empty()) return {-INFINITY, INFINITY};
  const std::size_t lo_k = std::size_t(double(values.size() - 1) * kOutlierQuantile);
  const std::size_t hi_k = values.size() - 1 - lo_k;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(lo_k), values.end());
  const float lo = values[lo_k];
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(hi_k), values.end());
  const float hi = values[hi_k];
  const float margin = std::max(kOutlierMinMargin, hi - lo);
  return {lo - margin, hi + margin};
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
// The three axes' outlier ranges are sampled on up to `threads` threads (the same ranges on any number).
bool check_input(const Scan& scan, bool reject_outliers, PreparedInput& out, const detail::KnownInput* known,
                 unsigned threads) {
  if (scan.vertices.empty()) throw Error(ErrorCode::EmptyInput, "the scan has no vertices");
  if (scan.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw Error(ErrorCode::BadIndices, "the scan has more vertices than 32-bit indices can address");
  if (scan.indices.size() % 3 != 0)
    throw Error(ErrorCode::BadIndices,
                "the index count " + std::to_string(scan.indices.size()) + " is not a multiple of 3");
  const std::uint32_t vertex_count = std::uint32_t(scan.vertices.size());
  if (known == nullptr || !known->indices_in_range)
    for (std::size_t i = 0; i < scan.indices.size(); ++i)
      if (scan.indices[i] >= vertex_count) [[unlikely]]
        throw Error(ErrorCode::BadIndices, "index " + std::to_string(scan.indices[i]) + " of triangle " +
                                               std::to_string(i / 3) + " is out of range (" +
                                               std::to_string(scan.vertices.size()) + " vertices)");
  out.input_vertices = scan.vertices.size();
  out.input_triangles = scan.indices.size() / 3;

  // The vertices by runs: the caller's, or one over them all.
  std::vector<detail::VertexRun> own;
  if (known == nullptr || !covers(known->runs, scan.vertices.size()))
    own.push_back(detail::summarize_vertices(scan.vertices));
  const std::span<const detail::VertexRun> runs =
      own.empty() ? std::span<const detail::VertexRun>(known->runs) : std::span<const detail::VertexRun>(own);
  std::size_t finite_count = 0;
  for (const detail::VertexRun& run : runs) finite_count += run.finite;
  out.skipped_vertices = scan.vertices.size() - finite_count;

  // Which vertices are kept: made only once one is removed (the usual scan removes none).
  std::vector<std::uint8_t> keep;
  const auto make_keep = [&] {
    if (!keep.empty()) return;
    keep.resize(scan.vertices.size());
    for (std::size_t i = 0; i < scan.vertices.size(); ++i) keep[i] = finite(scan.vertices[i]) ? 1 : 0;
  };
  if (out.skipped_vertices != 0) make_keep();

  if (reject_outliers && finite_count >= kOutlierMinVertices) {
    std::pair<float, float> range[3];
    detail::parallel_tasks(3, threads, [&](std::size_t axis) { range[axis] = robust_range(scan.vertices, keep, int(axis)); });
    std::size_t first = 0;
    for (const detail::VertexRun& run : runs) {
      // A run whose finite vertices' bounds lie within the ranges has no outlier.
      bool inside = true;
      for (int axis = 0; axis < 3; ++axis)
        inside = inside && run.lo[axis] >= range[axis].first && run.hi[axis] <= range[axis].second;
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
    out.lo = glm::vec3(INFINITY), out.hi = glm::vec3(-INFINITY);
    for (const detail::VertexRun& run : runs) {
      out.lo = glm::min(out.lo, run.lo);
      out.hi = glm::max(out.hi, run.hi);
    }
  }
  return renumbered;
}

}  // namespace

PreparedInput prepare_input(const Scan& scan, bool reject_outliers) {
  PreparedInput out;
  if (!check_input(scan, reject_outliers, out, nullptr, 1)) {
    out.vertices = scan.vertices;
    out.indices = scan.indices;
  }
  return out;
}

namespace detail {

VertexRun summarize_vertices(std::span<const glm::vec3> vertices) {
  VertexRun run;
  run.count = vertices.size();
  for (const glm::vec3& v : vertices) {
    if (!finite(v)) continue;
    ++run.finite;
    run.lo = glm::min(run.lo, v);
    run.hi = glm::max(run.hi, v);
  }
  return run;
}

InputView view_input(const Scan& scan, bool reject_outliers, const KnownInput* known, unsigned threads) {
  InputView view;
  const bool renumbered = check_input(scan, reject_outliers, view.checked, known, threads);
  view.vertices = renumbered ? std::span<const glm::vec3>(view.checked.vertices) : std::span<const glm::vec3>(scan.vertices);
  view.indices = renumbered ? std::span<const std::uint32_t>(view.checked.indices) : std::span<const std::uint32_t>(scan.indices);
  return view;
}

}  // namespace detail

}  // namespace roomsense
