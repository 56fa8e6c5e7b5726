// The backend choice's parsing, its environment variable, and the grid-size estimate Auto uses.
#include "roomsense/backend.h"

#include "roomsense/error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace roomsense {

Backend parse_backend(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (s == "auto") return Backend::Auto;
  if (s == "cpu") return Backend::Cpu;
  if (s == "vulkan") return Backend::Vulkan;
  throw Error(ErrorCode::BadParameter, "unknown backend '" + std::string(text) + "' (expected auto, cpu or vulkan)");
}

const char* to_string(Backend backend) {
  switch (backend) {
    case Backend::Cpu: return "cpu";
    case Backend::Vulkan: return "vulkan";
    default: return "auto";
  }
}

Backend backend_from_environment(Backend fallback, std::string* note) {
  const char* env = std::getenv("ROOMSENSE_BACKEND");
  if (env == nullptr || *env == '\0') return fallback;
  try {
    return parse_backend(env);
  } catch (const Error& e) {
    if (note != nullptr) *note = std::string("ROOMSENSE_BACKEND ignored: ") + e.what();
    return fallback;
  }
}

VoxelWorkload estimate_voxel_workload(const Scan& scan, float voxel_size) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : scan.vertices)
    if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  return voxel_workload(lo, hi, scan.indices.size() / 3, voxel_size);
}

VoxelWorkload voxel_workload(const glm::vec3& lo, const glm::vec3& hi, std::size_t triangles, float voxel_size) {
  VoxelWorkload w;
  w.triangles = triangles;
  if (!(lo.x <= hi.x) || !(voxel_size > 0.0f)) return w;
  const glm::dvec3 n = glm::dvec3(hi - lo) / double(voxel_size) + 1.0;
  w.voxels = std::size_t(std::min(n.x * n.y * n.z, 1e18));
  return w;
}

}  // namespace roomsense
