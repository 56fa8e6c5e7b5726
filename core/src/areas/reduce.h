// Result reduction of §3.4: centre deduplication (Eq. 3.42-3.44), then overlap reduction for walls
// (Eq. 3.45-3.48) and for horizontal surfaces (Eq. 3.49-3.53).
#pragma once
#include "candidate.h"

namespace roomsense::detail {

struct Sized {
  Candidate c;
  AreaSize size = AreaSize::Large;
};

// Eq. 3.44: large, then medium, then small; a rectangle is kept when none of its centre voxels (Eq. 3.43) is
// already marked by a kept one.
std::vector<Sized> deduplicate_centres(const std::array<Candidates, 3>& by_size);

// Eq. 3.45-3.47 on V_Wall in order: kept unless a test point lies in the box of a kept rectangle, widened by
// `offset` voxels in X and Z. Returns the indices kept.
std::vector<std::size_t> reduce_wall_overlaps(const std::vector<Sized>& walls, int offset);

// Eq. 3.50-3.52 on V_Floor, V_Ceiling or V_Furniture in order: kept unless a test point lies strictly inside a
// kept square; for furniture only squares within `offset` levels count (Eq. 3.49). Returns the indices kept.
std::vector<std::size_t> reduce_square_overlaps(const std::vector<Sized>& squares, int offset, bool furniture);

}  // namespace roomsense::detail
