#include "roomsense/error.h"
#include "roomsense/grid.h"
#include "roomsense/voxelize.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace roomsense {
namespace {

// %g: a scan 1e30 m wide or an infinite voxel size must not print as forty digits.
std::string compact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace

GridSpec make_grid_spec(const glm::vec3& lo, const glm::vec3& hi, float voxel_size, std::size_t voxel_budget) {
  if (!(voxel_size >= kMinVoxelSize && voxel_size <= kMaxVoxelSize))
    throw Error(ErrorCode::BadParameter, "voxel size " + compact(voxel_size) + " m is outside [" +
                                             compact(kMinVoxelSize) + ", " + compact(kMaxVoxelSize) + "] m");
  // Eq. 3.4, in double so that a huge extent cannot overflow before it is compared with the budget. The
  // 2 eps make room for triangle mode's test cubes, which sit eps below the voxels (voxelize.h): a face at
  // the very top of the scan, e.g. a ceiling at 2.6 m over a floor at 0 with 0.1 m voxels (25.9999996 in
  // float grid units), belongs to level 26, so the grid needs it.
  const auto dim = [&](float a, float b) {
    return std::floor((double(b) - double(a)) / double(voxel_size) + 2.0 * double(kVoxelTestEpsilon)) + 1.0;
  };
  const double dx = dim(lo.x, hi.x), dy = dim(lo.y, hi.y), dz = dim(lo.z, hi.z);
  const double voxels = dx * dy * dz;
  if (!(voxels <= double(voxel_budget)))
    throw Error(ErrorCode::GridTooLarge,
                "the scan spans " + compact(double(hi.x) - lo.x) + " x " + compact(double(hi.y) - lo.y) + " x " +
                    compact(double(hi.z) - lo.z) + " m, which needs " + compact(voxels) +
                    " voxels; the budget is " + std::to_string(voxel_budget) + " (use a larger voxel size)");
  GridSpec spec;
  spec.origin = lo;
  spec.voxel_size = voxel_size;
  spec.nx = int(dx);
  spec.ny = int(dy);
  spec.nz = int(dz);
  return spec;
}

}  // namespace roomsense
