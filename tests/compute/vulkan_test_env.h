// Shared by the compute tests: one Vulkan stage per test binary (instance and pipeline creation dominate
// a run on lavapipe), created with VK_LAYER_KHRONOS_validation, and the bit-for-bit comparison of results.
#pragma once
#include "roomsense/vulkan_voxel_stage.h"
#include "rooms.h"  // tests/support, from roomsense_test_support

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "sanitizers.h"  // tests/support

#if ROOMSENSE_TEST_ASAN
#include <dlfcn.h>
#endif

namespace roomsense::test {

struct SharedVulkan {
  std::unique_ptr<VulkanVoxelStage> stage;
  std::string why_not;
};

// Under AddressSanitizer: keep the driver libraries mapped after the Vulkan loader dlcloses them, so that
// LeakSanitizer can name them and lsan_vulkan_drivers.supp (driver libraries only) applies. The handles are
// left open on purpose (RTLD_NODELETE).
inline void pin_vulkan_drivers_for_leak_reports() {
#if ROOMSENSE_TEST_ASAN
  for (const char* lib : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"}) (void)dlopen(lib, RTLD_NOW | RTLD_NODELETE);
#endif
}

// Validation is required under CI (vulkan-validationlayers is installed there) and optional elsewhere.
inline SharedVulkan& shared_vulkan() {
  static SharedVulkan shared = [] {
    SharedVulkan s;
    pin_vulkan_drivers_for_leak_reports();
    VulkanStageOptions options;
    options.validation = true;
    options.require_validation = running_in_ci();
    s.stage = VulkanVoxelStage::create(options, &s.why_not);
    return s;
  }();
  return shared;
}

// Fails (GTest) when the two results differ anywhere, naming the first difference.
void expect_identical(const VoxelStageResult& cpu, const VoxelStageResult& gpu);

}  // namespace roomsense::test

// `var` is the shared stage; skips when there is no Vulkan device, fails under CI=1 (CI installs lavapipe).
#define ROOMSENSE_REQUIRE_VULKAN(var)                                                                       \
  ::roomsense::VulkanVoxelStage* var = ::roomsense::test::shared_vulkan().stage.get();                      \
  if (var == nullptr) {                                                                                     \
    if (::roomsense::test::running_in_ci())                                                                 \
      FAIL() << "CI must have a Vulkan device (mesa-vulkan-drivers): " << ::roomsense::test::shared_vulkan().why_not; \
    GTEST_SKIP() << "no usable Vulkan (" << ::roomsense::test::shared_vulkan().why_not                      \
                 << "); install mesa-vulkan-drivers for lavapipe";                                          \
  }

// Checks that a block issued no validation warnings or errors.
class ValidationScope {
 public:
  explicit ValidationScope(const roomsense::VulkanVoxelStage& stage) : stage_(stage), before_(stage.validation_messages()) {}
  ~ValidationScope() { EXPECT_EQ(stage_.validation_messages(), before_) << "Vulkan validation messages (see the log above)"; }

 private:
  const roomsense::VulkanVoxelStage& stage_;
  std::uint64_t before_;
};
