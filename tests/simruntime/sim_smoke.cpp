// A whole headless app run as one process: instance, session state machine, a scene with every mesh read,
// input (actions, all inactive) and a few frames, exit. ctest runs it plain and with the core validation layer stacked (which must stay
// silent); --provoke makes one invalid call so that the layer's reporting can be seen to work.
// --skip-mesh-buffers leaves out xrGetSceneMeshBuffersMSFT: Debian's core validation 1.0.20 rejects every
// XrSceneMeshBuffersMSFT whose next chain holds the vertex or index structs the spec requires there
// (VUID-XrSceneMeshBuffersMSFT-next-next, a false positive on the app's input before the runtime is called),
// so that one call cannot be run under the layer. The plain smoke run and the gtest suite cover it.
#include "input_harness.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace {

using namespace simtest;

bool layer_available(const std::string& name) {
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateApiLayerProperties(0, &count, nullptr));
  std::vector<XrApiLayerProperties> layers(count, {XR_TYPE_API_LAYER_PROPERTIES});
  SIM_CHECK(xrEnumerateApiLayerProperties(count, &count, layers.data()));
  for (const auto& l : layers)
    if (name == l.layerName) return true;
  return false;
}

// Drains events, returns the last session state seen.
XrSessionState drain(App& app, XrSessionState state) {
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(app.instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
      state = reinterpret_cast<XrEventDataSessionStateChanged&>(event).state;
    event = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  return state;
}

int run(int argc, char** argv) {
  bool provoke = false, read_buffers = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--provoke") == 0) provoke = true;
    else if (std::strcmp(argv[i], "--skip-mesh-buffers") == 0) read_buffers = false;
    else if (std::strcmp(argv[i], "--expect-layer") == 0 && i + 1 < argc) {
      if (!layer_available(argv[++i])) {
        std::fprintf(stderr, "simruntime_smoke: the loader does not find layer %s\n", argv[i]);
        return 2;
      }
    }
  }
  App app;
  const Input input(app);
  if (drain(app, XR_SESSION_STATE_UNKNOWN) != XR_SESSION_STATE_READY) throw std::runtime_error("session not READY");
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  SIM_CHECK(xrBeginSession(app.session, &begin));
  if (drain(app, XR_SESSION_STATE_READY) != XR_SESSION_STATE_FOCUSED) throw std::runtime_error("session not FOCUSED");

  uint32_t formats = 1;
  SIM_CHECK(xrEnumerateSwapchainFormats(app.session, 0, &formats, nullptr));
  if (formats != 0) throw std::runtime_error("a headless session with swapchain formats");

  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT observer_info{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
  SIM_CHECK(app.msft.createObserver(app.session, &observer_info, &observer));
  XrSceneMSFT scene = compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT, XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT});
  std::size_t vertices = 0, components = 0;
  for (auto type : {XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT, XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT})
    for (const auto& m : read_meshes(app, scene, type, type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT, read_buffers)) {
      vertices += m.vertices.size();
      ++components;
    }
  if (components == 0) throw std::runtime_error("no mesh components");

  XrSpace view = XR_NULL_HANDLE;
  XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  view_info.poseInReferenceSpace.orientation.w = 1;
  SIM_CHECK(xrCreateReferenceSpace(app.session, &view_info, &view));
  for (int frame = 0; frame < 3; ++frame) {
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState state{XR_TYPE_FRAME_STATE};
    SIM_CHECK(xrWaitFrame(app.session, &wait, &state));
    XrFrameBeginInfo frame_begin{XR_TYPE_FRAME_BEGIN_INFO};
    SIM_CHECK(xrBeginFrame(app.session, &frame_begin));
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    SIM_CHECK(xrLocateSpace(view, app.local, state.predictedDisplayTime, &location));
    SIM_CHECK(sync(app.session, input.set));
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = input.select;
    XrActionStateBoolean select{XR_TYPE_ACTION_STATE_BOOLEAN};
    SIM_CHECK(xrGetActionStateBoolean(app.session, &get, &select));
    SIM_CHECK(xrLocateSpace(input.grip_space, app.local, state.predictedDisplayTime, &location));
    if (select.isActive || location.locationFlags != 0) throw std::runtime_error("input from a headset with no controllers");
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    SIM_CHECK(xrEndFrame(app.session, &end));
  }
  if (provoke) {
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    const XrResult r = xrLocateSpace(reinterpret_cast<XrSpace>(uintptr_t{0xdead}), app.local, 1, &location);
    std::printf("provoked xrLocateSpace with a bad handle: %d\n", static_cast<int>(r));
  }

  SIM_CHECK(app.msft.destroyScene(scene));
  SIM_CHECK(app.msft.destroyObserver(observer));
  SIM_CHECK(xrDestroySpace(view));
  SIM_CHECK(xrDestroySpace(input.grip_space));
  SIM_CHECK(xrDestroyActionSet(input.set));
  SIM_CHECK(xrRequestExitSession(app.session));
  if (drain(app, XR_SESSION_STATE_FOCUSED) != XR_SESSION_STATE_STOPPING) throw std::runtime_error("session not STOPPING");
  SIM_CHECK(xrEndSession(app.session));
  if (drain(app, XR_SESSION_STATE_STOPPING) != XR_SESSION_STATE_EXITING) throw std::runtime_error("session not EXITING");
  SIM_CHECK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  std::printf("simruntime_smoke: %zu mesh components, %zu vertices, session ended cleanly\n", components, vertices);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simruntime_smoke failed: %s\n", e.what());
    return 1;
  }
}
