// Backend choice: parsing, the environment, the factory's fallbacks, and the device ranking.
#include "device_choice.h"
#include "roomsense/voxel_stage_choice.h"
#include "roomsense/error.h"
#include "vulkan_test_env.h"

#include <cstdlib>
#include <iostream>

namespace roomsense {
namespace {

TEST(Backend, ParsesTheThreeNames) {
  EXPECT_EQ(parse_backend("auto"), Backend::Auto);
  EXPECT_EQ(parse_backend("CPU"), Backend::Cpu);
  EXPECT_EQ(parse_backend("Vulkan"), Backend::Vulkan);
  EXPECT_THROW(parse_backend("cuda"), Error);
  EXPECT_THROW(parse_backend(""), Error);
  EXPECT_STREQ(to_string(Backend::Vulkan), "vulkan");
}

TEST(Backend, ReadsTheEnvironment) {
  std::string note;
  ::setenv("ROOMSENSE_BACKEND", "cpu", 1);
  EXPECT_EQ(backend_from_environment(Backend::Vulkan, &note), Backend::Cpu);
  ::setenv("ROOMSENSE_BACKEND", "gpu please", 1);
  EXPECT_EQ(backend_from_environment(Backend::Auto, &note), Backend::Auto);
  EXPECT_NE(note.find("ROOMSENSE_BACKEND ignored"), std::string::npos) << note;
  ::unsetenv("ROOMSENSE_BACKEND");
  EXPECT_EQ(backend_from_environment(Backend::Vulkan), Backend::Vulkan);
}

TEST(Backend, CpuAndSmallAutoNeverTouchVulkan) {
  std::string note;
  EXPECT_EQ(make_voxel_stage(Backend::Cpu, {1u << 30, 1u << 30}, &note)->name(), "cpu");
  EXPECT_EQ(make_voxel_stage(Backend::Auto, {1000, 1000}, &note)->name(), "cpu");
  EXPECT_NE(note.find("below the Vulkan crossover"), std::string::npos) << note;
}

// A big grid of few triangles (vertex mode, or a coarse scan of a hall) is cheap on the CPU: a Vulkan
// stage's start (310-370 ms on an H100) would cost more than the whole CPU voxel stage.
TEST(Backend, AutoWeighsTrianglesNotTheGrid) {
  std::string note;
  EXPECT_EQ(make_voxel_stage(Backend::Auto, {kDefaultVoxelBudget, 0}, &note)->name(), "cpu");
  EXPECT_NE(note.find("0 triangles is below the Vulkan crossover"), std::string::npos) << note;
  EXPECT_EQ(make_voxel_stage(Backend::Auto, {kDefaultVoxelBudget, kVulkanCrossoverTriangles - 1}, &note)->name(), "cpu");
}

TEST(Backend, AutoProbesNoDeviceForAGridTheAnalysisRefuses) {
  std::string note;
  EXPECT_EQ(make_voxel_stage(Backend::Auto, {kDefaultVoxelBudget + 1, kVulkanCrossoverTriangles}, &note)->name(), "cpu");
  EXPECT_NE(note.find("no device probed"), std::string::npos) << note;
}

TEST(Backend, AutoAvoidsLavapipe) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  std::string note;
  const auto chosen = make_voxel_stage(Backend::Auto, {std::size_t{1} << 22, kVulkanCrossoverTriangles}, &note);
  const GpuKind kind = stage->device().kind;
  const bool gpu = kind == GpuKind::Discrete || kind == GpuKind::Integrated;
  EXPECT_EQ(chosen->name(), gpu ? "vulkan" : "cpu") << note;
}

TEST(Backend, VulkanRequestGivesVulkanOrSaysWhyNot) {
  std::string note;
  const auto chosen = make_voxel_stage(Backend::Vulkan, {}, &note);
  ASSERT_NE(chosen, nullptr);
  if (chosen->name() == "cpu") {
    EXPECT_NE(note.find("Vulkan unavailable"), std::string::npos) << note;
    if (test::running_in_ci()) ADD_FAILURE() << "CI must have lavapipe: " << note;
  } else {
    EXPECT_EQ(note.rfind("vulkan: requested, on ", 0), 0u) << note;
  }
}

TEST(DeviceChoice, DiscreteThenIntegratedThenCpu) {
  using compute::DeviceCandidate;
  const DeviceCandidate cpu{VK_PHYSICAL_DEVICE_TYPE_CPU, VK_API_VERSION_1_3, true, 16};
  const DeviceCandidate integrated{VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, VK_API_VERSION_1_2, true, 16};
  const DeviceCandidate discrete{VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_1, true, 16};
  DeviceCandidate old_discrete = discrete;
  old_discrete.api_version = VK_API_VERSION_1_0;
  DeviceCandidate no_compute = discrete;
  no_compute.has_compute_queue = false;
  DeviceCandidate few_buffers = discrete;
  few_buffers.max_storage_buffers_per_stage = 3;

  const DeviceCandidate a[] = {cpu, integrated, discrete};
  EXPECT_EQ(compute::choose_device(a), 2);
  const DeviceCandidate b[] = {cpu, integrated};
  EXPECT_EQ(compute::choose_device(b), 1);
  const DeviceCandidate c[] = {old_discrete, no_compute, few_buffers, cpu};
  EXPECT_EQ(compute::choose_device(c), 3);
  const DeviceCandidate d[] = {integrated, integrated};
  EXPECT_EQ(compute::choose_device(d), 0);  // the loader's order among equals
  EXPECT_EQ(compute::choose_device(std::span<const DeviceCandidate>{}), -1);
}

}  // namespace
}  // namespace roomsense

namespace roomsense {
namespace {

TEST(VulkanStage, ReportsDeviceAndValidation) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  std::cout << "[ device   ] " << stage->device().name << " (" << to_string(stage->device().kind) << "), validation "
            << (stage->validation_enabled() ? "on" : "off (VK_LAYER_KHRONOS_validation not installed)") << '\n';
  if (test::running_in_ci()) {
    EXPECT_TRUE(stage->validation_enabled());
  }
  EXPECT_EQ(stage->name(), "vulkan");
}

}  // namespace
}  // namespace roomsense
