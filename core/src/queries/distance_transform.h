// The exact Euclidean distance transform of a raster (Felzenszwalb and Huttenlocher, "Distance Transforms of
// Sampled Functions", 2012): two passes of the lower envelope of parabolas, linear in the cell count.
#pragma once
#include <cstdint>
#include <vector>

namespace roomsense::detail {

// For each cell of an nx × nz raster (row-major, x fastest): the distance, in cells, from its centre to the
// nearest centre of a cell where `mask` is 0. Cells beyond the raster count as 0, so no distance exceeds the
// way out of it.
std::vector<float> distance_to_unmasked(int nx, int nz, const std::vector<std::uint8_t>& mask);

// 1 where distance_to_unmasked(nx, nz, mask) > `limit`, else 0: the same comparison of the same distances, as a
// threshold on squared distances (whole numbers) tested row by row within the limit, where the limit is at most
// kFartherThanRows cells; beyond it (or NaN) through the transform.
inline constexpr float kFartherThanRows = 64.0f;
std::vector<std::uint8_t> farther_than(int nx, int nz, const std::vector<std::uint8_t>& mask, float limit);

}  // namespace roomsense::detail
