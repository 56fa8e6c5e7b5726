#include "surface_heights.h"

#include "../parallel.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace roomsense::detail {

BandLimits band_limits(const GridSpec& spec, int lo, int hi) {
  return {spec.origin.y + (float(lo) - kVoxelTestEpsilon) * spec.voxel_size,
          spec.origin.y + (float(hi + 1) - kVoxelTestEpsilon) * spec.voxel_size};
}

namespace {

bool in_band(float y, BandLimits band) { return y >= band.first && y < band.second; }

// Twice a triangle's area where it is near-horizontal (within ~25°, either way up: scans disagree on winding),
// else 0.
float horizontal_area2(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float area2 = glm::length(n);
  return area2 > 0.0f && std::fabs(n.y) >= 0.9f * area2 ? area2 : 0.0f;
}

// band_sums over `bands`: a std::array where their count is known (a storey's floor and ceiling: two), held in
// registers rather than read from memory at every triangle; else the caller's span.
template <class Bands>
void add_band_sums(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices, const Bands& bands,
                   std::vector<BandSum>& sums) {
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3 &a = vertices[indices[t]], &b = vertices[indices[t + 1]], &c = vertices[indices[t + 2]];
    const float cy = (a.y + b.y + c.y) / 3.0f;
    float area2 = -1.0f;  // most triangles lie in no band: no cross product for them
    for (std::size_t k = 0; k < bands.size(); ++k) {
      if (!in_band(cy, bands[k])) continue;
      if (area2 < 0.0f) area2 = horizontal_area2(a, b, c);
      if (area2 == 0.0f) break;
      sums[k].weighted.add(double(cy) * area2);  // a product of two floats: exact in a double
      sums[k].weight.add(area2);
    }
  }
}

}  // namespace

std::vector<BandSum> band_sums(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                               std::span<const BandLimits> bands) {
  std::vector<BandSum> sums(bands.size());
  if (bands.size() == 2) add_band_sums(vertices, indices, std::array{bands[0], bands[1]}, sums);
  else add_band_sums(vertices, indices, bands, sums);
  return sums;
}

std::vector<BandSum> band_sums(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                               std::span<const BandLimits> bands, unsigned threads) {
  // Blocks taken by whichever worker is free: a scan's floor and ceiling triangles lie in runs of its own order.
  constexpr std::size_t kBlock = 8192;
  const std::size_t triangles = indices.size() / 3, blocks = (triangles + kBlock - 1) / kBlock;
  std::vector<std::vector<BandSum>> parts(blocks);
  parallel_tasks(blocks, threads, [&](std::size_t b) {
    const std::size_t begin = b * kBlock, end = std::min(triangles, begin + kBlock);
    parts[b] = band_sums(vertices, indices.subspan(3 * begin, 3 * (end - begin)), bands);
  });
  std::vector<BandSum> sums(bands.size());
  for (const std::vector<BandSum>& part : parts)
    for (std::size_t k = 0; k < part.size(); ++k) sums[k] += part[k];
  return sums;
}

float band_height(const BandSum& sum, BandLimits limits) {
  const double weight = sum.weight.value();
  if (weight > 0.0) return float(sum.weighted.value() / weight);
  return 0.5f * (limits.first + limits.second);
}

float surface_height(const GridSpec& spec, std::span<const glm::vec3> vertices,
                     std::span<const std::uint32_t> indices, int lo, int hi) {
  const BandLimits limits = band_limits(spec, lo, hi);
  const float y_lo = limits.first, y_hi = limits.second;
  double weighted = 0.0, weight = 0.0;
  if (!indices.empty()) {
    const BandSum sum = band_sums(vertices, indices, std::span(&limits, 1)).front();
    if (sum.exact()) return band_height(sum, limits);
    // Terms past the fixed point's (a height times an area of 2^15 and more): summed in order.
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::vec3 &a = vertices[indices[t]], &b = vertices[indices[t + 1]], &c = vertices[indices[t + 2]];
      const float cy = (a.y + b.y + c.y) / 3.0f;
      if (!in_band(cy, limits)) continue;
      const float area2 = horizontal_area2(a, b, c);
      if (area2 == 0.0f) continue;
      weighted += double(cy) * area2;
      weight += area2;
    }
  } else {
    // A point cloud has no normals: wall points spread evenly over the band while the surface's pile up, so
    // take the fullest 1 cm bin and average the points within a bin of it.
    constexpr float kBin = 0.01f;
    std::vector<std::uint32_t> bins(std::size_t(std::max(1.0f, std::ceil((y_hi - y_lo) / kBin))), 0);
    const auto bin_of = [&](float y) { return std::min(bins.size() - 1, std::size_t((y - y_lo) / kBin)); };
    for (const glm::vec3& v : vertices)
      if (in_band(v.y, limits)) ++bins[bin_of(v.y)];
    const std::size_t peak = std::size_t(std::max_element(bins.begin(), bins.end()) - bins.begin());
    for (const glm::vec3& v : vertices)
      if (in_band(v.y, limits) && bin_of(v.y) + 1 >= peak && bin_of(v.y) <= peak + 1) {
        weighted += v.y;
        weight += 1.0;
      }
  }
  if (weight > 0.0) return float(weighted / weight);
  return 0.5f * (y_lo + y_hi);
}

float surface_top(const GridSpec& spec, std::span<const glm::vec3> vertices, int lo, int hi) {
  const float y_lo = spec.origin.y + (float(lo) - kVoxelTestEpsilon) * spec.voxel_size;
  const float y_hi = spec.origin.y + (float(hi + 1) - kVoxelTestEpsilon) * spec.voxel_size;
  float top = -INFINITY;
  for (const glm::vec3& v : vertices)
    if (v.y >= y_lo && v.y < y_hi) top = std::max(top, v.y);
  return std::isfinite(top) ? top : 0.5f * (y_lo + y_hi);
}

std::vector<glm::vec3> ceiling_planes(const GridSpec& spec, std::span<const glm::vec3> vertices,
                                      std::span<const std::uint32_t> indices, const RoomFeatures& features) {
  const std::size_t n = features.facets.size() > 1 ? features.facets.size() - 1 : 0;
  std::vector<glm::dmat3> m(n, glm::dmat3(0.0));
  std::vector<glm::dvec3> r(n, glm::dvec3(0.0));
  const float s = spec.voxel_size;
  const auto add = [&](const glm::vec3& p, double weight) {
    const float fx = std::floor((p.x - spec.origin.x) / s), fz = std::floor((p.z - spec.origin.z) / s);
    if (!(fx >= 0.0f && fz >= 0.0f && fx < float(spec.nx) && fz < float(spec.nz))) return;
    const std::size_t col = spec.column(int(fx), int(fz));
    const int facet = features.ceiling_facet[col];
    const float level = (p.y - spec.origin.y) / s - float(features.ceiling[col]);
    if (facet <= 0 || level < -1.0f || level > 2.0f) return;
    const glm::dvec3 q(p.x, p.z, 1.0);
    m[std::size_t(facet - 1)] += weight * glm::outerProduct(q, q);
    r[std::size_t(facet - 1)] += weight * double(p.y) * q;
  };
  if (n > 0 && !indices.empty()) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::vec3 &a = vertices[indices[t]], &b = vertices[indices[t + 1]], &c = vertices[indices[t + 2]];
      const glm::vec3 normal = glm::cross(b - a, c - a);
      const float area2 = glm::length(normal);
      if (area2 > 0.0f && std::fabs(normal.y) >= 0.3f * area2) add((a + b + c) / 3.0f, double(area2));
    }
  } else if (n > 0) {
    for (const glm::vec3& v : vertices) add(v, 1.0);
  }
  std::vector<glm::vec3> out;
  for (std::size_t k = 0; k < n; ++k) {
    const CeilingFacet& f = features.facets[k + 1];
    // The fitted levels, in metres: the level's lower face, where the surface enters the voxel.
    glm::vec3 plane(f.slope_x, f.slope_z,
                    spec.origin.y + s * f.offset - f.slope_x * spec.origin.x - f.slope_z * spec.origin.z);
    if (std::fabs(glm::determinant(m[k])) > 1e-12) {
      const glm::dvec3 fit = glm::inverse(m[k]) * r[k];
      if (std::isfinite(fit.x) && std::isfinite(fit.y) && std::isfinite(fit.z)) plane = glm::vec3(fit);
    }
    out.push_back(plane);
  }
  return out;
}

}  // namespace roomsense::detail
