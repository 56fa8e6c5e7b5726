// farther_than (core/src/queries/distance_transform.h, internal): the rooms' split takes its cores from it, and
// it must say exactly what comparing distance_to_unmasked with the limit says, on any raster and any limit.
#include "../../core/src/queries/distance_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using roomsense::detail::distance_to_unmasked;
using roomsense::detail::farther_than;

void expect_as_the_transform(int nx, int nz, const std::vector<std::uint8_t>& mask, float limit) {
  const std::vector<float> distance = distance_to_unmasked(nx, nz, mask);
  const std::vector<std::uint8_t> found = farther_than(nx, nz, mask, limit);
  ASSERT_EQ(found.size(), distance.size());
  for (std::size_t c = 0; c < found.size(); ++c)
    ASSERT_EQ(found[c], distance[c] > limit ? 1 : 0)
        << nx << " x " << nz << ", limit " << limit << ", cell " << c << " at distance " << distance[c];
}

TEST(FartherThan, SaysWhatTheTransformSaysOnRandomRasters) {
  std::mt19937 random(7);
  // Limits at and a float's step either side of every whole squared distance's root up to 40 cells, where the
  // threshold on squared distances must fall exactly as the transform's floats compare.
  std::vector<float> limits = {-3.0f, -0.0f, 0.0f, 0.5f, 1.0f, 63.9f, roomsense::detail::kFartherThanRows, 80.0f,
                               std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()};
  for (int d = 1; d <= 1600; d += 7) {
    const float root = float(std::sqrt(double(d)));
    limits.insert(limits.end(), {root, std::nextafter(root, 0.0f), std::nextafter(root, 100.0f)});
  }
  int tested = 0;
  for (const auto& [nx, nz] : {std::pair(1, 1), std::pair(1, 37), std::pair(41, 1), std::pair(23, 17), std::pair(90, 70)})
    for (const double density : {0.0, 0.02, 0.2, 0.7, 1.0}) {
      std::bernoulli_distribution free(1.0 - density);
      std::vector<std::uint8_t> mask(std::size_t(nx) * std::size_t(nz));
      for (std::uint8_t& m : mask) m = free(random) ? 1 : 0;
      for (const float limit : limits) {
        expect_as_the_transform(nx, nz, mask, limit);
        ++tested;
      }
    }
  EXPECT_GT(tested, 1000);
}

// A room-like raster: free inside walls, with a doorway; the limits a storey's split asks (half of a 0.8-1.2 m
// passage at 5-10 cm voxels, plus the split's 1e-3).
TEST(FartherThan, SaysWhatTheTransformSaysOnARoomsFreeSpace) {
  const int nx = 80, nz = 60;
  std::vector<std::uint8_t> mask(std::size_t(nx) * std::size_t(nz), 1);
  for (int z = 0; z < nz; ++z)
    for (int x = 0; x < nx; ++x)
      if (x == 0 || z == 0 || x == nx - 1 || z == nz - 1 || (x == 40 && (z < 25 || z > 33))) mask[std::size_t(z * nx + x)] = 0;
  for (const float cells : {4.0f, 4.5f, 5.0f, 6.0f, 8.0f, 10.0f, 12.0f})
    expect_as_the_transform(nx, nz, mask, cells + 1e-3f);
}

}  // namespace
