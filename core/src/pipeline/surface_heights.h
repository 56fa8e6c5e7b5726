// Metric heights of the floor and ceiling levels (internal to the pipeline).
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/features.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace roomsense::detail {

// A sum of doubles kept in fixed point, in units of 2^-48 in 128 bits, so that it comes out the same however its
// terms are grouped: the surface heights of an IncrementalAnalysis add up each chunk's sums, and must equal one
// pass over the combined scan. Each term is truncated to whole units (at most 3.6e-15 off); a term of 2^15 or
// more (or not finite) makes the sum inexact, and the caller then sums in one pass, in order. That too is a
// property of the terms, not of their grouping, and 2^64 terms of 2^63 units fit.
class ExactSum {
 public:
  void add(double term) {
    if (!(std::fabs(term) < 0x1p15)) {
      in_range_ = false;
      return;
    }
    sum_ += Wide(std::int64_t(term * 0x1p48));  // scaling by 2^48 is exact; the cast truncates
  }
  ExactSum& operator+=(const ExactSum& other) {
    sum_ += other.sum_, in_range_ = in_range_ && other.in_range_;
    return *this;
  }
  double value() const { return std::ldexp(double(sum_), -48); }
  bool exact() const { return in_range_; }

 private:
  __extension__ typedef __int128 Wide;
  Wide sum_ = 0;
  bool in_range_ = true;
};

// surface_height's sums over some triangles of a scan in one band of levels.
struct BandSum {
  ExactSum weighted, weight;
  bool exact() const { return weighted.exact() && weight.exact(); }
  BandSum& operator+=(const BandSum& other) {
    weighted += other.weighted, weight += other.weight;
    return *this;
  }
};
// The band [lo, hi]'s limits in metres, as triangle mode sees the levels (test cubes sit kVoxelTestEpsilon below
// the voxels).
using BandLimits = std::pair<float, float>;
BandLimits band_limits(const GridSpec& spec, int lo, int hi);
// Each band's sums over `indices` (some of a scan's triangles, in `vertices`), in one pass over them.
std::vector<BandSum> band_sums(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                               std::span<const BandLimits> bands);
// The same, the triangles split among `threads` workers (the sums do not depend on how).
std::vector<BandSum> band_sums(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                               std::span<const BandLimits> bands, unsigned threads);
// surface_height from the band's sums over all the scan's triangles, where they are exact.
float band_height(const BandSum& sum, BandLimits limits);

// The height of the scanned surface in the levels [lo, hi]: the area-weighted mean height of near-horizontal
// triangles there, or of the vertices there for a point cloud; the middle of the band if neither exists.
float surface_height(const GridSpec& spec, std::span<const glm::vec3> vertices,
                     std::span<const std::uint32_t> indices, int lo, int hi);

// The highest vertex in the levels [lo, hi]: the ridge of a roof that raised_ceiling raised I_Ceiling to; the
// middle of the band without one.
float surface_top(const GridSpec& spec, std::span<const glm::vec3> vertices, int lo, int hi);

// Per facet of `features` but the first (SurfaceLevels::ceiling_planes): the plane y = p.x x + p.y z + p.z
// fitted (least squares, by area) to the scan's triangles that are not walls (points, for a point cloud)
// above the facet's tiles within a level of its ceiling; the facet's fitted levels where fewer than three
// such samples span a plane.
std::vector<glm::vec3> ceiling_planes(const GridSpec& spec, std::span<const glm::vec3> vertices,
                                      std::span<const std::uint32_t> indices, const RoomFeatures& features);

}  // namespace roomsense::detail
