// The voxel stage on Vulkan compute (thesis §3.1-3.2, Eq. 3.6-3.12): the same VoxelStage interface as
// CpuVoxelStage, with bit-identical results. Vulkan is loaded at run time; where it is missing, create()
// says why and nothing else happens. See compute/README.md.
#pragma once
#include "roomsense/voxelize.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace roomsense {

enum class GpuKind { Discrete, Integrated, Virtual, Cpu, Other };
const char* to_string(GpuKind kind);

struct VulkanDeviceInfo {
  std::string name;
  GpuKind kind = GpuKind::Other;
};

struct VulkanStageOptions {
  // VK_LAYER_KHRONOS_validation plus a debug-utils messenger that counts and logs every warning and error.
  // ROOMSENSE_VULKAN_VALIDATION=1 in the environment turns it on too.
  bool validation = false;
  // With validation: fail create() when the layer is not installed (otherwise log and go on without it).
  bool require_validation = false;
  // The bound on one submission. Past it, or on VK_ERROR_DEVICE_LOST, run() logs a line and computes on the
  // CPU, and so do all later runs (the device may still own the buffers). ROOMSENSE_VULKAN_TIMEOUT_MS
  // overrides it.
  std::chrono::milliseconds fence_timeout{30000};
  // Where log lines go; stderr ("roomsense: vulkan: ...") when empty.
  std::function<void(std::string_view)> log;
};

// Where the time of the last run went. GPU times come from timestamp queries (0 when the queue has none);
// host times from a steady clock.
struct VulkanRunTimings {
  double host_work_list_ms = 0; // between the submissions: the big boxes' further chunks listed and copied
  double host_upload_ms = 0;    // copying vertices and indices into mapped memory
  double submit_wait_ms = 0;    // record, submit and wait for the fence (both submissions)
  double host_readback_ms = 0;  // copying the results out of mapped memory
  double gpu_upload_ms = 0;     // staging copies and clears on the GPU (0 copies on unified memory)
  double gpu_vertices_ms = 0;   // Eq. 3.6/3.7, vertex voxels
  double gpu_triangles_ms = 0;  // triangle mode
  double gpu_levels_ms = 0;     // byte-grid expansion and |V_y| (Eq. 3.8)
  double gpu_select_ms = 0;     // Eq. 3.9/3.10
  double gpu_columns_ms = 0;    // |V_xz| and the any-mask (Eq. 3.11/3.12)
  double gpu_readback_ms = 0;   // staging copy back (0 on unified memory)
  bool gpu_timestamps = false;
  bool fell_back = false;       // this run was computed by the CPU path
};

class VulkanVoxelStage final : public VoxelStage {
 public:
  // The stage on the best device (discrete, integrated, virtual, then CPU), or nullptr with the reason in
  // *why_not. Never throws for a missing or broken Vulkan.
  static std::unique_ptr<VulkanVoxelStage> create(const VulkanStageOptions& options = {},
                                                  std::string* why_not = nullptr);
  ~VulkanVoxelStage() override;
  VulkanVoxelStage(const VulkanVoxelStage&) = delete;
  VulkanVoxelStage& operator=(const VulkanVoxelStage&) = delete;

  std::string name() const override { return "vulkan"; }
  // One queue submission, two in triangle mode (the device sizes the work of big triangles). Falls back to CpuVoxelStage (with a log line) on timeout, device loss, or a grid
  // the device cannot hold.
  VoxelStageResult run(const VoxelizeRequest& request) override;

  const VulkanDeviceInfo& device() const;
  bool validation_enabled() const;
  std::uint64_t validation_messages() const;  // warnings and errors seen by the messenger
  const VulkanRunTimings& last_timings() const;
  std::uint64_t fallbacks() const;            // runs done by the CPU path

  class Impl;

 private:
  explicit VulkanVoxelStage(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The device create() would pick, without creating it (an instance only), or nothing with *why_not.
std::optional<VulkanDeviceInfo> probe_vulkan_device(std::string* why_not = nullptr);

}  // namespace roomsense
