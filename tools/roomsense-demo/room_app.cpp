#include "room_app.h"

#include "checked_calls.h"
#include "environment.h"
#include "instance.h"

#include <cstring>
#include <stdexcept>

namespace roomsense::demo {
namespace {


struct Extx {
  PFN_xrCreateRoomAnalyzerEXTX create = nullptr;
  PFN_xrDestroyRoomAnalyzerEXTX destroy = nullptr;
  PFN_xrComputeRoomEXTX compute = nullptr;
  PFN_xrGetRoomComputeStateEXTX state = nullptr;
  PFN_xrGetRoomLayoutEXTX layout = nullptr;
  PFN_xrGetRoomAreasEXTX areas = nullptr;
  PFN_xrGetRoomBoundsMeshEXTX bounds = nullptr;
  PFN_xrFindRoomPlacementsEXTX place = nullptr;
};

bool runtime_offers(const char* extension) {
  uint32_t count = 0;
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr))) return false;
  std::vector<XrExtensionProperties> props(count, {XR_TYPE_EXTENSION_PROPERTIES, nullptr});
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()))) return false;
  for (const auto& p : props)
    if (std::strcmp(p.extensionName, extension) == 0) return true;
  return false;
}

XrSessionState poll_session_state(XrInstance instance, XrSessionState state) {
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
  while (xrPollEvent(instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
      state = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
    event = {XR_TYPE_EVENT_DATA_BUFFER, nullptr};
  }
  return state;
}

}  // namespace

RoomReport analyse_room_through_openxr() {
  Checker check;
  if (!runtime_offers(XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME))
    throw std::runtime_error("the loader offers no " XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME
                             ": the roomsense layer was not found or is disabled");
  // No scene extension of its own: the layer enables whichever the runtime has (its mesh sources).
  std::vector<const char*> extensions = {XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME};

  Instance instance;
  XrInstanceCreateInfo create{XR_TYPE_INSTANCE_CREATE_INFO, nullptr};
  std::strncpy(create.applicationInfo.applicationName, "roomsense-demo", XR_MAX_APPLICATION_NAME_SIZE - 1);
  create.applicationInfo.applicationVersion = 1;
  create.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);  // Debian's 1.0.20 loader refuses 1.1
  create.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  create.enabledExtensionNames = extensions.data();
  check(xrCreateInstance(&create, &instance.handle), "xrCreateInstance");
  check.instance = instance.handle;

  RoomReport report;
  XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES, nullptr};
  check(xrGetInstanceProperties(instance.handle, &properties), "xrGetInstanceProperties");
  report.runtime_name = properties.runtimeName;
  report.layer_library = loaded_layer_library();

  Extx extx;
  extx.create = proc<PFN_xrCreateRoomAnalyzerEXTX>(check, instance.handle, "xrCreateRoomAnalyzerEXTX");
  extx.destroy = proc<PFN_xrDestroyRoomAnalyzerEXTX>(check, instance.handle, "xrDestroyRoomAnalyzerEXTX");
  extx.compute = proc<PFN_xrComputeRoomEXTX>(check, instance.handle, "xrComputeRoomEXTX");
  extx.state = proc<PFN_xrGetRoomComputeStateEXTX>(check, instance.handle, "xrGetRoomComputeStateEXTX");
  extx.layout = proc<PFN_xrGetRoomLayoutEXTX>(check, instance.handle, "xrGetRoomLayoutEXTX");
  extx.areas = proc<PFN_xrGetRoomAreasEXTX>(check, instance.handle, "xrGetRoomAreasEXTX");
  extx.bounds = proc<PFN_xrGetRoomBoundsMeshEXTX>(check, instance.handle, "xrGetRoomBoundsMeshEXTX");
  extx.place = proc<PFN_xrFindRoomPlacementsEXTX>(check, instance.handle, "xrFindRoomPlacementsEXTX");

  XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO, nullptr};
  system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  check(xrGetSystem(instance.handle, &system_info, &system), "xrGetSystem");
  XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO, nullptr};  // headless: no graphics binding
  session_info.systemId = system;
  XrSession session = XR_NULL_HANDLE;
  check(xrCreateSession(instance.handle, &session_info, &session), "xrCreateSession");
  XrSessionState state = poll_session_state(instance.handle, XR_SESSION_STATE_UNKNOWN);
  if (state != XR_SESSION_STATE_READY) throw std::runtime_error("the session did not become READY");
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO, nullptr};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  check(xrBeginSession(session, &begin), "xrBeginSession");

  XrReferenceSpaceCreateInfo space_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO, nullptr};
  space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  space_info.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace local = XR_NULL_HANDLE;
  check(xrCreateReferenceSpace(session, &space_info, &local), "xrCreateReferenceSpace");

  XrRoomAnalyzerCreateInfoEXTX analyzer_info{XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, nullptr};
  analyzer_info.baseSpace = local;
  analyzer_info.voxelSize = 0.0f;  // the default, 0.10 m
  analyzer_info.backend = XR_ROOM_COMPUTE_BACKEND_AUTO_EXTX;
  XrRoomAnalyzerEXTX analyzer = XR_NULL_HANDLE;
  check(extx.create(session, &analyzer_info, &analyzer), "xrCreateRoomAnalyzerEXTX");

  // The frame loop runs on while the layer computes, as in any app.
  bool started = false;
  XrRoomComputeStateEXTX compute_state = XR_ROOM_COMPUTE_STATE_NONE_EXTX;
  for (int frame = 0; frame < 90 * 120; ++frame) {
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO, nullptr};
    XrFrameState frame_state{XR_TYPE_FRAME_STATE, nullptr};
    check(xrWaitFrame(session, &wait, &frame_state), "xrWaitFrame");
    XrFrameBeginInfo frame_begin{XR_TYPE_FRAME_BEGIN_INFO, nullptr};
    check(xrBeginFrame(session, &frame_begin), "xrBeginFrame");
    if (!started) {
      XrRoomComputeInfoEXTX compute{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
      compute.time = frame_state.predictedDisplayTime;
      compute.includeRuntimeMeshes = XR_TRUE;
      check(extx.compute(analyzer, &compute), "xrComputeRoomEXTX");
      started = true;
    }
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO, nullptr};
    end.displayTime = frame_state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    check(xrEndFrame(session, &end), "xrEndFrame");
    ++report.frames;
    check(extx.state(analyzer, &compute_state), "xrGetRoomComputeStateEXTX");
    if (compute_state != XR_ROOM_COMPUTE_STATE_RUNNING_EXTX) break;
  }
  if (compute_state != XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX)
    throw std::runtime_error(compute_state == XR_ROOM_COMPUTE_STATE_FAILED_EXTX
                                 ? "the room analysis failed (ROOMSENSE_LOG=info says why)"
                                 : "the room analysis did not finish in two minutes");

  // The results: the layout with the analysis JSON chained, then the two-call getters.
  XrRoomAnalysisJsonEXTX json{XR_TYPE_ROOM_ANALYSIS_JSON_EXTX, nullptr};
  report.layout.next = &json;
  check(extx.layout(analyzer, &report.layout), "xrGetRoomLayoutEXTX");
  std::vector<char> text(json.jsonCountOutput);
  json.jsonCapacityInput = json.jsonCountOutput;
  json.json = text.data();
  check(extx.layout(analyzer, &report.layout), "xrGetRoomLayoutEXTX");
  report.layout.next = nullptr;
  report.json.assign(text.data(), json.jsonCountOutput > 0 ? json.jsonCountOutput - 1 : 0);

  uint32_t count = 0;
  check(extx.areas(analyzer, 0, &count, nullptr), "xrGetRoomAreasEXTX");
  report.areas.assign(count, {XR_TYPE_ROOM_AREA_EXTX, nullptr});
  check(extx.areas(analyzer, count, &count, report.areas.data()), "xrGetRoomAreasEXTX");

  XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, nullptr};
  check(extx.bounds(analyzer, &bounds), "xrGetRoomBoundsMeshEXTX");
  report.bounds_vertices.resize(bounds.vertexCountOutput);
  report.bounds_indices.resize(bounds.indexCountOutput);
  bounds.vertexCapacityInput = bounds.vertexCountOutput;
  bounds.vertices = report.bounds_vertices.data();
  bounds.indexCapacityInput = bounds.indexCountOutput;
  bounds.indices = report.bounds_indices.data();
  check(extx.bounds(analyzer, &bounds), "xrGetRoomBoundsMeshEXTX");

  // One placement query: where three 30 cm cubes go on furniture tops (two-call idiom).
  report.placement_query = {XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX, nullptr};
  report.placement_query.objectSize = {0.3f, 0.3f, 0.3f};
  report.placement_query.surfaces = XR_ROOM_SURFACE_FURNITURE_BIT_EXTX;
  report.placement_query.maxPlacements = 3;
  XrRoomPlacementsEXTX placements{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
  check(extx.place(analyzer, &report.placement_query, &placements), "xrFindRoomPlacementsEXTX");
  report.placements.assign(placements.placementCountOutput, {XR_TYPE_ROOM_PLACEMENT_EXTX, nullptr});
  placements.placementCapacityInput = placements.placementCountOutput;
  placements.placements = report.placements.data();
  check(extx.place(analyzer, &report.placement_query, &placements), "xrFindRoomPlacementsEXTX");
  report.placement_shortfall = placements.shortfall;

  check(extx.destroy(analyzer), "xrDestroyRoomAnalyzerEXTX");
  check(xrDestroySpace(local), "xrDestroySpace");
  check(xrRequestExitSession(session), "xrRequestExitSession");
  state = poll_session_state(instance.handle, state);
  check(xrEndSession(session), "xrEndSession");
  check(xrDestroySession(session), "xrDestroySession");
  return report;
}

}  // namespace roomsense::demo
