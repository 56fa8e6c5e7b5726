// The XR_EXT_spatial_plane_tracking source on a simulated OpenXR 1.1 device (ROOMSENSE_SIM_EXTENSIONS names only
// XR_EXT_spatial_entity and XR_EXT_spatial_plane_tracking): the layer analyses the room from planes alone, and
// comes close to the CLI's analysis of the full mesh.
#include "compare.h"
#include "roomsense/synthetic.h"
#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <gtest/gtest.h>

#include <iostream>
#include <map>

namespace {

using namespace layertest;

const std::string kPlanesOnly = "XR_EXT_spatial_entity,XR_EXT_spatial_plane_tracking";

std::map<std::string, int> area_counts(const nlohmann::json& analysis) {
  std::map<std::string, int> counts;
  for (const auto& area : analysis.at("areas")) ++counts[area.at("type").get<std::string>()];
  return counts;
}

std::string describe(const std::map<std::string, int>& counts) {
  std::string s;
  for (const auto& [type, n] : counts) s += type + "=" + std::to_string(n) + " ";
  return s;
}

TEST(LayerSourceExtPlanes, DefaultRoomFromPlanesComesCloseToTheCli) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const nlohmann::json got = nlohmann::json::parse(read_result(app.extx, a).json);
  EXPECT_EQ(got.at("openxr").at("mesh_source"), XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME);
  const nlohmann::json cli = run_cli("synthetic:default");
  const roomsense::synth::RoomSpec truth = roomsense::synth::default_room();
  ASSERT_TRUE(got.at("floor_y").is_number()) << got.dump();
  ASSERT_TRUE(got.at("ceiling_y").is_number()) << got.dump();
  EXPECT_NEAR(got.at("floor_y").get<double>(), cli.at("floor_y").get<double>(), 0.05);
  EXPECT_NEAR(got.at("ceiling_y").get<double>(), cli.at("ceiling_y").get<double>(), 0.05);
  EXPECT_NEAR(got.at("floor_y").get<double>(), truth.floor_y, 0.1);
  EXPECT_NEAR(got.at("ceiling_y").get<double>(), truth.ceiling_y, 0.1);
  const auto planes = area_counts(got), mesh = area_counts(cli);
  for (const char* type : {"wall", "floor", "ceiling", "furniture"}) EXPECT_GT(planes.count(type), 0u) << type << " areas missing";
  std::cout << "planes only: floor_y " << got.at("floor_y") << " ceiling_y " << got.at("ceiling_y") << " areas " << describe(planes)
            << "\nfull mesh (CLI): floor_y " << cli.at("floor_y") << " ceiling_y " << cli.at("ceiling_y") << " areas "
            << describe(mesh) << "\n";
}

// The layer enabled the extensions below itself: an application that did not must not see their functions, nor
// the discovery events of the layer's own contexts.
TEST(LayerSourceExtPlanes, LayerEnabledFunctionsAndEventsStayHidden) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  PFN_xrVoidFunction f = nullptr;
  for (const char* name : {"xrCreateSpatialContextAsyncEXT", "xrQuerySpatialComponentDataEXT", "xrGetSpatialBufferVector2fEXT"}) {
    EXPECT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
    EXPECT_EQ(f, nullptr) << name;
  }
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  for (;;) {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
    const XrResult r = xrPollEvent(app.instance, &e);
    if (r == XR_EVENT_UNAVAILABLE) break;
    LT_CHECK(r);
    EXPECT_NE(e.type, XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT);
  }
}

// An application of its own on such a device: its spatial queries work beside the layer's.
TEST(LayerSourceExtPlanes, AnApplicationKeepsItsOwnContexts) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME,
           XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME, XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME});
  const auto capabilities = proc<PFN_xrEnumerateSpatialCapabilitiesEXT>(app.instance, "xrEnumerateSpatialCapabilitiesEXT");
  const auto create = proc<PFN_xrCreateSpatialContextAsyncEXT>(app.instance, "xrCreateSpatialContextAsyncEXT");
  const auto complete = proc<PFN_xrCreateSpatialContextCompleteEXT>(app.instance, "xrCreateSpatialContextCompleteEXT");
  const auto destroy = proc<PFN_xrDestroySpatialContextEXT>(app.instance, "xrDestroySpatialContextEXT");
  const auto poll = proc<PFN_xrPollFutureEXT>(app.instance, "xrPollFutureEXT");
  uint32_t count = 0;
  LT_CHECK(capabilities(app.instance, app.system, 0, &count, nullptr));
  std::vector<XrSpatialCapabilityEXT> listed(count);
  LT_CHECK(capabilities(app.instance, app.system, count, &count, listed.data()));
  // The runtime's plane tracking, and the layer's placement areas beside it.
  EXPECT_EQ(listed, (std::vector<XrSpatialCapabilityEXT>{XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT,
                                                         XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX}));
  const XrSpatialComponentTypeEXT bounded = XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT;
  XrSpatialCapabilityConfigurationPlaneTrackingEXT config{XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT, nullptr,
                                                          XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, 1, &bounded};
  const auto* header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
  XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT, nullptr, 1, &header};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  LT_CHECK(create(app.session, &info, &future));

  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(nlohmann::json::parse(read_result(app.extx, a).json).at("openxr").at("mesh_source"),
            XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME);

  XrFuturePollInfoEXT poll_info{XR_TYPE_FUTURE_POLL_INFO_EXT, nullptr, future};
  XrFuturePollResultEXT state{XR_TYPE_FUTURE_POLL_RESULT_EXT, nullptr, XR_FUTURE_STATE_PENDING_EXT};
  for (int i = 0; i < 5000 && state.state != XR_FUTURE_STATE_READY_EXT; ++i) {
    LT_CHECK(poll(app.instance, &poll_info, &state));
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  XrCreateSpatialContextCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT, nullptr};
  LT_CHECK(complete(app.session, future, &completion));
  LT_CHECK(completion.futureResult);
  LT_CHECK(destroy(completion.spatialContext));
}

}  // namespace
