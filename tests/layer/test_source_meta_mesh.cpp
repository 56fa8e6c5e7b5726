// The XR_META_spatial_entity_mesh source on a simulated Quest (ROOMSENSE_SIM_EXTENSIONS names only the Quest's
// scene extensions): what it hides from and leaves to the application. Its rooms against the CLI's are in
// test_sources_rooms.cpp.
#include "compare.h"
#include "rooms.h"
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace layertest;

const std::string kQuest = "XR_FB_spatial_entity,XR_FB_spatial_entity_query,XR_FB_scene,XR_FB_spatial_entity_container,"
                           "XR_META_spatial_entity_mesh";

// The layer enabled the Quest extensions below itself: an application that did not must not see their functions.
TEST(LayerSourceMetaMesh, LayerEnabledQuestFunctionsStayHidden) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kQuest);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  PFN_xrVoidFunction f = nullptr;
  for (const char* name : {"xrQuerySpacesFB", "xrRetrieveSpaceQueryResultsFB", "xrGetSpaceTriangleMeshMETA",
                           "xrSetSpaceComponentStatusFB", "xrGetSpaceSemanticLabelsFB"}) {
    EXPECT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
    EXPECT_EQ(f, nullptr) << name;
  }
}

// An application of its own on a Quest: the layer's query leaves the application's spaces, requests and
// results alone, and the application's query still finds the global mesh afterwards.
TEST(LayerSourceMetaMesh, AQuestApplicationKeepsItsOwnQueries) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kQuest);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_EXTENSION_NAME,
           XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME, XR_FB_SCENE_EXTENSION_NAME, XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME});
  PFN_xrVoidFunction f = nullptr;
  LT_CHECK(xrGetInstanceProcAddr(app.instance, "xrQuerySpacesFB", &f));
  const auto query = reinterpret_cast<PFN_xrQuerySpacesFB>(f);
  LT_CHECK(xrGetInstanceProcAddr(app.instance, "xrRetrieveSpaceQueryResultsFB", &f));
  const auto retrieve = reinterpret_cast<PFN_xrRetrieveSpaceQueryResultsFB>(f);

  XrSpaceComponentFilterInfoFB filter{XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB, nullptr};
  filter.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  XrSpaceQueryInfoFB info{XR_TYPE_SPACE_QUERY_INFO_FB, nullptr};
  info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
  info.filter = reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&filter);
  XrAsyncRequestIdFB mine = 0;
  LT_CHECK(query(app.session, reinterpret_cast<const XrSpaceQueryInfoBaseHeaderFB*>(&info), &mine));

  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(nlohmann::json::parse(read_result(app.extx, a).json).at("openxr").at("mesh_source"),
            XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME);

  // The application's request, made before the layer's, still holds its one result.
  XrSpaceQueryResultsFB results{XR_TYPE_SPACE_QUERY_RESULTS_FB, nullptr};
  LT_CHECK(retrieve(app.session, mine, &results));
  EXPECT_EQ(results.resultCountOutput, 1u);
}

}  // namespace
