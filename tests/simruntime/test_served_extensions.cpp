// ROOMSENSE_SIM_EXTENSIONS: the runtime advertises the scene extensions it names and no other, so a test or an
// app developer can play one headset; a name it does not serve fails instance creation with one line.
#include "sim_env.h"
#include "xr_harness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using simtest::ScopedEnv;

std::vector<std::string> advertised() {
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> props(count, XrExtensionProperties{XR_TYPE_EXTENSION_PROPERTIES});
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()));
  std::vector<std::string> names;
  for (uint32_t i = 0; i < count; ++i) names.emplace_back(props[i].extensionName);
  return names;
}

bool has(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(ServedExtensions, AllSceneExtensionsByDefaultAndTheBaseOnesAlways) {
  const auto names = advertised();
  EXPECT_TRUE(has(names, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  EXPECT_TRUE(has(names, XR_MND_HEADLESS_EXTENSION_NAME));
  EXPECT_TRUE(has(names, "XR_EXT_future"));
}

TEST(ServedExtensions, TheVariableLimitsTheSceneExtensions) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(" XR_MSFT_scene_understanding "));
  const auto names = advertised();
  EXPECT_TRUE(has(names, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  EXPECT_TRUE(has(names, XR_MND_HEADLESS_EXTENSION_NAME));
  for (const char* other : {"XR_EXT_spatial_entity", "XR_META_spatial_entity_mesh", "XR_ANDROID_scene_meshing",
                            "XR_ML_world_mesh_detection"})
    EXPECT_FALSE(has(names, other)) << other;
}

TEST(ServedExtensions, AnExtensionBringsThoseItBuildsOn) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_META_spatial_entity_mesh"));
  const auto names = advertised();
  for (const char* quest : {"XR_META_spatial_entity_mesh", "XR_FB_spatial_entity", "XR_FB_spatial_entity_query", "XR_FB_scene"})
    EXPECT_TRUE(has(names, quest)) << quest;
  EXPECT_FALSE(has(names, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
}

TEST(ServedExtensions, AnUnknownNameFailsInstanceCreation) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_MSFT_scene_understanding,XR_FOO_bar"));
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_NE(simtest::create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME}), XR_SUCCESS);
  EXPECT_EQ(instance, XR_NULL_HANDLE);
}

TEST(ServedExtensions, AnExtensionLeftOutCannotBeEnabled) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_MSFT_scene_understanding"));
  XrInstance instance = XR_NULL_HANDLE;
  // The loader itself refuses an extension nobody offers.
  EXPECT_EQ(simtest::create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME, "XR_ANDROID_scene_meshing"}),
            XR_ERROR_EXTENSION_NOT_PRESENT);
}

}  // namespace
