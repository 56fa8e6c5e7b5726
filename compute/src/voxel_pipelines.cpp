#include "voxel_pipelines.h"

#include "vulkan_error.h"

// Generated at build time from shaders/*.comp (compute/CMakeLists.txt, cmake/embed_spirv.cmake).
#include "spirv/count_columns.h"
#include "spirv/count_levels.h"
#include "spirv/expand_grid.h"
#include "spirv/select_levels.h"
#include "spirv/voxelize_triangles.h"
#include "spirv/voxelize_vertices.h"

#include <span>

namespace roomsense::compute {
namespace {

std::span<const std::uint32_t> spirv_of(Kernel k) {
  switch (k) {
    case Kernel::Vertices: return spirv::kVoxelizeVertices;
    case Kernel::Triangles: return spirv::kVoxelizeTriangles;
    case Kernel::ExpandGrid: return spirv::kExpandGrid;
    case Kernel::CountLevels: return spirv::kCountLevels;
    case Kernel::SelectLevels: return spirv::kSelectLevels;
    default: return spirv::kCountColumns;
  }
}

}  // namespace

VoxelPipelines::VoxelPipelines(const VulkanContext& ctx) {
  const DeviceFunctions& vk = ctx.vk();
  const VkDevice device = ctx.device();

  VkDescriptorSetLayoutBinding bindings[4]{};
  for (std::uint32_t i = 0; i < 4; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo dsli{};
  dsli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dsli.bindingCount = 4;
  dsli.pBindings = bindings;
  VkDescriptorSetLayout dsl = VK_NULL_HANDLE;
  check(vk.vkCreateDescriptorSetLayout(device, &dsli, nullptr, &dsl), "vkCreateDescriptorSetLayout");
  set_layout = DeviceChild<VkDescriptorSetLayout>(device, dsl, vk.vkDestroyDescriptorSetLayout);

  VkPushConstantRange range{};
  range.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  range.size = sizeof(PushConstants);
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &dsl;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &range;
  VkPipelineLayout pl = VK_NULL_HANDLE;
  check(vk.vkCreatePipelineLayout(device, &pli, nullptr, &pl), "vkCreatePipelineLayout");
  layout = DeviceChild<VkPipelineLayout>(device, pl, vk.vkDestroyPipelineLayout);

  for (std::size_t k = 0; k < std::size_t(Kernel::Count); ++k) {
    const std::span<const std::uint32_t> code = spirv_of(Kernel(k));
    VkShaderModuleCreateInfo smi{};
    smi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    smi.codeSize = code.size_bytes();
    smi.pCode = code.data();
    VkShaderModule sm = VK_NULL_HANDLE;
    check(vk.vkCreateShaderModule(device, &smi, nullptr, &sm), "vkCreateShaderModule");
    const DeviceChild<VkShaderModule> module(device, sm, vk.vkDestroyShaderModule);  // only needed while creating

    VkComputePipelineCreateInfo cpi{};
    cpi.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpi.stage.module = sm;
    cpi.stage.pName = "main";
    cpi.layout = pl;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vk.vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cpi, nullptr, &pipeline), "vkCreateComputePipelines");
    pipelines[k] = DeviceChild<VkPipeline>(device, pipeline, vk.vkDestroyPipeline);
  }
}

}  // namespace roomsense::compute
