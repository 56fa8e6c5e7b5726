// Input hygiene before voxelization: non-finite vertices are skipped, far outliers rejected, triangles
// that touch either dropped, and indices validated. Every removal is counted so callers can report it.
#pragma once
#include "roomsense/scan.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomsense {

// A vertex is an outlier when it lies more than max(kOutlierMinMargin, the robust span) beyond the
// [0.5 %, 99.5 %] quantile range of its axis (the k-th smallest and largest value, k = max(1, floor((n - 1) q))).
// One stray vertex 1 km away would otherwise make the grid absurd; a corridor seen through a door (tens of percent
// of a room's span) stays.
inline constexpr float kOutlierMinMargin = 2.0f;  // metres
inline constexpr double kOutlierQuantile = 0.005;
inline constexpr std::size_t kOutlierMinVertices = 200;  // below this, quantiles mean little: keep all

struct PreparedInput {
  std::vector<glm::vec3> vertices;      // finite, not outliers
  std::vector<std::uint32_t> indices;   // remapped into `vertices`; triangles touching a removed vertex dropped
  std::size_t input_vertices = 0;
  std::size_t input_triangles = 0;
  std::size_t skipped_vertices = 0;     // NaN or Inf
  std::size_t outlier_vertices = 0;
  std::size_t dropped_triangles = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};         // bounds of `vertices` (Eq. 3.5)
};

// Throws Error: EmptyInput (no vertices), BadIndices (count not a multiple of 3, or an index out of range),
// NoValidVertices (nothing left).
PreparedInput prepare_input(const Scan& scan, bool reject_outliers = true);

}  // namespace roomsense
