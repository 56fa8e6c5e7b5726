// ring_offsets (core/src/areas/ring_offsets.h, internal): each square offset's core box, the box of whole covered
// columns a search tests first, is the first largest box that trying every pair of runs finds. ring_offsets skips
// the pairs that cannot beat the best so far; this is the plain search, over many sizes and voxels.
#include "../../core/src/areas/ring_offsets.h"

#include <gtest/gtest.h>

namespace {

using namespace roomsense::detail;

struct CoreBox {
  glm::ivec2 lo{1, 0}, hi{0, 0};
};

CoreBox first_largest_box(const std::vector<CellRun>& runs) {
  CoreBox box;
  long best = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    int lo = runs[i].dz_lo, hi = runs[i].dz_hi;
    for (std::size_t j = i; j < runs.size(); ++j) {
      lo = std::max(lo, runs[j].dz_lo), hi = std::min(hi, runs[j].dz_hi);
      if (lo > hi) break;
      const long area = long(j - i + 1) * long(hi - lo + 1);
      if (area > best) best = area, box.lo = {runs[i].dx, lo}, box.hi = {runs[j].dx, hi};
    }
  }
  return box;
}

TEST(RingOffsets, ASquaresCoreBoxIsTheFirstLargestBoxOfItsRuns) {
  std::size_t squares = 0;
  for (const float voxel : {0.02f, 0.05f, 0.07f, 0.1f, 0.13f, 0.25f})
    for (const float width : {0.3f, 0.5f, 0.77f, 1.0f, 2.0f})
      for (const float tolerance : {0.0f, 0.1f}) {
        if (width / voxel > 60.0f) continue;  // the largest rings take a while; their shapes repeat the smaller
        for (const RingOffset& o : ring_offsets(size_range(width, width, tolerance, voxel), Shape::Square)) {
          const CoreBox expected = first_largest_box(o.runs);
          ASSERT_EQ(o.core_lo, expected.lo) << "offset (" << o.dx << ", " << o.dz << ") at " << voxel << " m";
          ASSERT_EQ(o.core_hi, expected.hi) << "offset (" << o.dx << ", " << o.dz << ") at " << voxel << " m";
          ++squares;
        }
      }
  EXPECT_GT(squares, 1000u);
}

}  // namespace
