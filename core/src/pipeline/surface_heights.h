// Metric heights of the floor and ceiling levels (internal to the pipeline).
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/features.h"

#include <cstdint>
#include <span>

namespace roomsense::detail {

// A sum of doubles kept in fixed point, in units of 2^-64, so that it comes out the same however its terms are
// grouped: the surface heights of an IncrementalAnalysis add up each chunk's sums, and must equal one pass over
// the combined scan. A term's bits below 2^-64 are dropped. A term of 2^40 or more, or terms whose magnitudes
// add up past 2^61, make the sum inexact (the caller then sums in one pass, in order); that too is a property of
// the terms, not of their grouping.
class ExactSum {
 public:
  void add(double term);
  ExactSum& operator+=(const ExactSum& other);
  double value() const;
  bool exact() const { return magnitude_ <= kMaxMagnitude; }

 private:
  static constexpr std::uint64_t kMaxMagnitude = std::uint64_t{1} << 61;
  void carry_in(std::int64_t whole, std::uint64_t fraction, std::uint64_t magnitude);
  std::int64_t whole_ = 0;      // the sum's integer part (floor)
  std::uint64_t fraction_ = 0;  // and its fraction, in units of 2^-64
  std::uint64_t magnitude_ = 0;  // a bound on |whole_| over any grouping: the terms' |floor| + 1, summed
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
std::pair<float, float> band_limits(const GridSpec& spec, int lo, int hi);
// The sums over `indices` (some of a scan's triangles, in `vertices`) in the band `limits`.
BandSum band_sum(std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                 std::pair<float, float> limits);
// surface_height from the band's sums over all the scan's triangles, where they are exact.
float band_height(const BandSum& sum, std::pair<float, float> limits);

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
