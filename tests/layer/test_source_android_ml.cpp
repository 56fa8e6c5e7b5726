// The XR_ANDROID_scene_meshing and XR_ML_world_mesh_detection sources, each on a simulated headset that serves
// only that scene extension (ROOMSENSE_SIM_EXTENSIONS): what they hide from the application. Their rooms
// against the CLI's are in test_sources_rooms.cpp.
#include "compare.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace {

using namespace layertest;

// The layer enabled the headset's extension below itself: an application that did not must not see its functions.
TEST(LayerSourceAndroidMlDefaultRoom, LayerEnabledFunctionsStayHidden) {
  const std::pair<const char*, std::vector<const char*>> hidden[] = {
      {"XR_ANDROID_scene_meshing", {"xrCreateSceneMeshingTrackerANDROID", "xrGetSubmeshDataANDROID"}},
      {"XR_ML_world_mesh_detection", {"xrCreateWorldMeshDetectorML", "xrRequestWorldMeshAsyncML", "xrPollFutureEXT"}},
  };
  for (const auto& [extension, functions] : hidden) {
    ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(extension));
    ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
    App app;
    for (const char* name : functions) {
      PFN_xrVoidFunction f = nullptr;
      EXPECT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
      EXPECT_EQ(f, nullptr) << name;
    }
  }
}

}  // namespace
