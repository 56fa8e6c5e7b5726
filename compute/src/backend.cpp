// The backend factory. Auto is conservative: Vulkan only on a real GPU and a grid past the crossover
// (kVulkanCrossoverVoxels, compute/README.md); lavapipe never wins against the CPU path.
#include "roomsense/backend.h"

#include "roomsense/error.h"
#include "roomsense/vulkan_voxel_stage.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace roomsense {
namespace {

std::string lower(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

void set(std::string* note, std::string text) {
  if (note != nullptr) *note = std::move(text);
}

}  // namespace

Backend parse_backend(std::string_view text) {
  const std::string s = lower(text);
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
    set(note, std::string("ROOMSENSE_BACKEND ignored: ") + e.what());
    return fallback;
  }
}

std::unique_ptr<VoxelStage> make_voxel_stage(Backend backend, std::size_t problem_size_hint, std::string* note) {
  if (backend == Backend::Cpu) {
    set(note, "cpu: requested");
    return std::make_unique<CpuVoxelStage>();
  }
  if (backend == Backend::Auto) {
    if (problem_size_hint < kVulkanCrossoverVoxels) {
      set(note, "cpu: auto, " + std::to_string(problem_size_hint) + " voxels is below the Vulkan crossover of " +
                    std::to_string(kVulkanCrossoverVoxels));
      return std::make_unique<CpuVoxelStage>();
    }
    // A grid past the default budget is refused before any voxel stage runs (make_grid_spec): starting a GPU
    // driver in the app's process for it would be work, and driver state, for nothing.
    if (problem_size_hint > kDefaultVoxelBudget) {
      set(note, "cpu: auto, " + std::to_string(problem_size_hint) + " voxels is past the grid budget of " +
                    std::to_string(kDefaultVoxelBudget) + ": no device probed");
      return std::make_unique<CpuVoxelStage>();
    }
    std::string why;
    const std::optional<VulkanDeviceInfo> device = probe_vulkan_device(&why);
    if (!device) {
      set(note, "cpu: auto, Vulkan unavailable: " + why);
      return std::make_unique<CpuVoxelStage>();
    }
    if (device->kind != GpuKind::Discrete && device->kind != GpuKind::Integrated) {
      set(note, "cpu: auto, the best Vulkan device (" + device->name + ", " + to_string(device->kind) +
                    ") is slower than the CPU path");
      return std::make_unique<CpuVoxelStage>();
    }
  }
  std::string why;
  std::unique_ptr<VulkanVoxelStage> stage = VulkanVoxelStage::create({}, &why);
  if (!stage) {
    set(note, "cpu: Vulkan unavailable: " + why);
    return std::make_unique<CpuVoxelStage>();
  }
  set(note, std::string("vulkan: ") + (backend == Backend::Auto ? "auto" : "requested") + ", on " + stage->device().name +
                " (" + to_string(stage->device().kind) + ")");
  return stage;
}

std::size_t estimated_voxel_count(const Scan& scan, float voxel_size) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : scan.vertices)
    if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  if (!(lo.x <= hi.x) || !(voxel_size > 0.0f)) return 0;
  const glm::dvec3 n = glm::dvec3(hi - lo) / double(voxel_size) + 1.0;
  return std::size_t(std::min(n.x * n.y * n.z, 1e18));
}

}  // namespace roomsense
