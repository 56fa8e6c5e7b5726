// The mesh-source seam: which runtime extension the layer's meshes came through, and why, as an app and
// analysis.json see it; ROOMSENSE_SIM_EXTENSIONS playing one headset at a time.
#include "compare.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

using namespace layertest;

nlohmann::json analyse_runtime_room(const char* room) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string(room));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  EXPECT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  return nlohmann::json::parse(read_result(app.extx, a).json);
}

TEST(LayerSources, AnalysisJsonNamesTheSourceItsMeshesCameThrough) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  const nlohmann::json doc = analyse_runtime_room("synthetic:default");
  const nlohmann::json& openxr = doc.at("openxr");
  EXPECT_EQ(openxr.at("mesh_source"), XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME);
  EXPECT_NE(openxr.at("mesh_source_reason").get<std::string>(), "");
  EXPECT_GT(openxr.at("runtime_meshes").get<int>(), 1);  // the room comes in chunks
  EXPECT_GT(openxr.at("mesh_query_ms").get<double>(), 0.0);
}

TEST(LayerSources, LayerEnabledExtensionsStayHiddenFromTheApplication) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;  // enables only XR_EXTX_room_understanding and XR_MND_headless
  PFN_xrVoidFunction f = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(app.instance, "xrComputeNewSceneMSFT", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(f, nullptr);
}

TEST(LayerSources, NoSceneExtensionMeansSubmittedMeshesOnlyAndOneClearReason) {
  // A runtime with only the base extensions cannot be asked for (the variable needs one scene extension), so
  // ask for a room where the runtime has no room at all: the query delivers nothing and the compute fails
  // cleanly instead of guessing.
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string(""));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  EXPECT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_FAILED_EXTX);
}

}  // namespace

namespace {

// The layer's own requests through an extension only it enabled (Quest's space queries) answer with events; they
// are the layer's, of types the application never asked for, and must not reach the application's queue.
TEST(LayerEvents, EventsOfExtensionsOnlyTheLayerEnabledStayWithTheLayer) {
  ScopedEnv quest("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_FB_spatial_entity,XR_FB_spatial_entity_query,XR_FB_scene,"
                                                          "XR_FB_spatial_entity_container,XR_META_spatial_entity_mesh"));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(nlohmann::json::parse(read_result(app.extx, a).json).at("openxr").at("mesh_source"), "XR_META_spatial_entity_mesh");
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
  while (xrPollEvent(app.instance, &event) == XR_SUCCESS) {
    EXPECT_LT(event.type, 1000000000) << "an extension's event reached the application: type " << event.type;
    event = {XR_TYPE_EVENT_DATA_BUFFER, nullptr};
  }
}

}  // namespace

namespace {

// The same surfaces through two extensions count once: an app that reads the room through
// XR_MSFT_scene_understanding on a runtime that also has Quest's global mesh gets a room from the global mesh
// alone, equal to the CLI's, not the room twice over.
TEST(LayerSources, TheSameRoomReadThroughTwoExtensionsCountsOnce) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME});
  EXPECT_GT(read_scene_meshes(app), 1u);  // captured by the layer as the app reads them
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result got = read_result(app.extx, a);
  const nlohmann::json layer = nlohmann::json::parse(got.json);
  EXPECT_EQ(layer.at("openxr").at("mesh_source"), "XR_META_spatial_entity_mesh");
  EXPECT_EQ(layer.at("openxr").at("app_read_meshes"), 0);
  const nlohmann::json cli = run_cli("synthetic:default");
  EXPECT_EQ(layer.at("input").at("triangles"), cli.at("input").at("triangles"));
  EXPECT_EQ(layer.at("areas").size(), cli.at("areas").size());
}

// The app's reads through the very extension the layer queried add nothing twice (the same chunk ids).
TEST(LayerSources, ReadsOfTheQueriedSourceAddNothingTwice) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME});
  EXPECT_GT(read_scene_meshes(app), 1u);
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const nlohmann::json layer = nlohmann::json::parse(read_result(app.extx, a).json);
  EXPECT_EQ(layer.at("openxr").at("app_read_meshes"), 0);
  EXPECT_EQ(layer.at("input").at("triangles"), run_cli("synthetic:default").at("input").at("triangles"));
}

}  // namespace
