// The compute pipelines of the voxel stage, built once per device from the embedded SPIR-V. They share one
// descriptor set layout (shaders/common.glsl: four storage buffers) and one push-constant block.
#pragma once
#include "vulkan_context.h"
#include "vulkan_handle.h"

#include <cstdint>

namespace roomsense::compute {

// Mirrors `Params` in shaders/common.glsl (std430-free push constants: 4-byte members, no padding).
struct PushConstants {
  std::int32_t nx, ny, nz;
  std::uint32_t vertex_count;
  std::uint32_t work_count;
  std::uint32_t work_offset;
  std::uint32_t voxel_count;
  std::uint32_t column_count;
  std::int32_t min_separation;
  std::uint32_t grid_offset;
  std::uint32_t levels_offset;
  std::uint32_t select_offset;
  std::uint32_t columns_offset;
  std::uint32_t any_offset;
  std::uint32_t item_base;
  std::uint32_t triangle_count;
  std::uint32_t info_offset;
};
static_assert(sizeof(PushConstants) == 17 * 4);

enum class Kernel { Vertices, Triangles, ExpandGrid, CountLevels, SelectLevels, CountColumns, Count };

struct VoxelPipelines {
  explicit VoxelPipelines(const VulkanContext& ctx);

  DeviceChild<VkDescriptorSetLayout> set_layout;
  DeviceChild<VkPipelineLayout> layout;
  DeviceChild<VkPipeline> pipelines[std::size_t(Kernel::Count)];

  VkPipeline operator[](Kernel k) const { return pipelines[std::size_t(k)].get(); }
};

inline constexpr std::uint32_t kLocalSize = 64;  // LOCAL_SIZE in shaders/common.glsl
// The select pass scans H_Grid serially, twice: taller grids would exceed lavapipe's loop budget.
inline constexpr int kMaxLevels = 16384;

}  // namespace roomsense::compute
