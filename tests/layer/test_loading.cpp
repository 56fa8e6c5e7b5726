// How the loader finds and stacks the layer: listed as an implicit layer offering the extension, switched off
// by DISABLE_XR_APILAYER_ROOMSENSE, invisible to an application that does not enable the extension, and safe
// when the same manifest is found twice.
#include "layer_harness.h"
#include "roomsense/xr/loader_interface.h"
#include "test_process.h"

#include <dlfcn.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

using namespace layertest;

std::string library_of(PFN_xrVoidFunction f) {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(f), &info) == 0 || info.dli_fname == nullptr) return "?";
  return std::filesystem::path(info.dli_fname).filename().string();
}

TEST(LayerLoading, FoundAsAnImplicitLayerThatOffersTheExtension) {
  EXPECT_EQ(layer_listed(kLayerName), 1);
  EXPECT_TRUE(has_extension(nullptr, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME));
  EXPECT_TRUE(has_extension(kLayerName, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME));
  // The manifest's version (what the loader reports) is the header's: apps test it before using newer calls.
  EXPECT_EQ(extension_version(kLayerName, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME),
            uint32_t(XR_EXTX_room_understanding_SPEC_VERSION));
  App app;
  EXPECT_TRUE(layer_library_loaded());
}

TEST(LayerLoading, DisabledByTheEnvironmentVariable) {
  for (const char* value : {"1", ""}) {  // any value, even an empty one, switches the layer off
    ScopedEnv disable("DISABLE_XR_APILAYER_ROOMSENSE", std::string(value));
    EXPECT_EQ(layer_listed(kLayerName), 0);
    EXPECT_FALSE(has_extension(nullptr, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME));
    XrInstance instance = XR_NULL_HANDLE;
    EXPECT_EQ(create_instance(&instance, {XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME}),
              XR_ERROR_EXTENSION_NOT_PRESENT);
    ASSERT_EQ(create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME}), XR_SUCCESS);
    EXPECT_FALSE(layer_library_loaded()) << "the loader loaded the layer although it is disabled";
    PFN_xrVoidFunction f = nullptr;
    EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrCreateRoomAnalyzerEXTX", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
    EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);
  }
}

// An application that does not enable the extension gets the runtime's own functions: the layer only keeps
// an eye on instance creation and destruction.
TEST(LayerLoading, AnApplicationWithoutTheExtensionIsUntouched) {
  ScopedEnv no_export("ROOMSENSE_EXPORT_DIR", std::nullopt);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app({XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME});
  EXPECT_TRUE(layer_library_loaded());
  PFN_xrVoidFunction f = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(app.instance, "xrCreateRoomAnalyzerEXTX", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(f, nullptr);
  for (const char* name : {"xrCreateSceneObserverMSFT", "xrGetSceneMeshBuffersMSFT", "xrGetSceneComponentsMSFT",
                           "xrLocateSceneComponentsMSFT", "xrComputeNewSceneMSFT"}) {
    ASSERT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_SUCCESS) << name;
    EXPECT_EQ(library_of(f), "libroomsense_simruntime.so") << name << " is not the runtime's own function";
  }
  // And it reads the room as it would without the layer.
  EXPECT_GT(read_scene_meshes(app), 0u);
}

// The layer enables XR_MSFT_scene_understanding below itself for its own queries; the application, which did
// not enable it, must still be told its functions are unsupported.
TEST(LayerLoading, SceneFunctionsTheLayerEnabledStayHiddenFromTheApplication) {
  App app;  // XR_EXTX_room_understanding and XR_MND_headless only
  PFN_xrVoidFunction f = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(app.instance, "xrCreateSceneObserverMSFT", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(xrGetInstanceProcAddr(app.instance, "xrGetSceneMeshBuffersMSFT", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(xrGetInstanceProcAddr(app.instance, "xrCreateRoomAnalyzerEXTX", &f), XR_SUCCESS);
  EXPECT_EQ(library_of(f), "libXrApiLayer_roomsense.so");
}

// What the layer's own xrGetInstanceProcAddr hands to the loader (found through the one exported symbol, in
// the copy the loader already loaded): for everything it does not hook, the runtime's function itself.
PFN_xrGetInstanceProcAddr layers_get_instance_proc_addr() {
  void* lib = dlopen("libXrApiLayer_roomsense.so", RTLD_NOW | RTLD_NOLOAD);
  if (lib == nullptr) return nullptr;
  auto negotiate = reinterpret_cast<PFN_xrNegotiateLoaderApiLayerInterface>(dlsym(lib, "xrNegotiateLoaderApiLayerInterface"));
  dlclose(lib);  // the loader's reference keeps it loaded
  XrNegotiateLoaderInfo loader{XR_LOADER_INTERFACE_STRUCT_LOADER_INFO, XR_LOADER_INFO_STRUCT_VERSION, sizeof(XrNegotiateLoaderInfo),
                               1, 1, XR_MAKE_VERSION(1, 0, 0), XR_MAKE_VERSION(1, 0xffff, 0xffff)};
  XrNegotiateApiLayerRequest request{XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST, XR_API_LAYER_INFO_STRUCT_VERSION,
                                     sizeof(XrNegotiateApiLayerRequest)};
  if (negotiate == nullptr || negotiate(&loader, kLayerName, &request) != XR_SUCCESS) return nullptr;
  return request.getInstanceProcAddr;
}

TEST(LayerLoading, TheFrameLoopAndSpacesGoStraightToTheRuntime) {
  // A HoloLens-like runtime: the application enables the one scene extension itself, so the layer adds none and
  // has no events of its own to keep from the application (LayerEvents below covers the other case).
  ScopedEnv hololens("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  for (bool extension : {true, false}) {
    std::vector<const char*> extensions = {XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME};
    if (extension) extensions.push_back(XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME);
    App app(extensions);
    const PFN_xrGetInstanceProcAddr gipa = layers_get_instance_proc_addr();
    ASSERT_NE(gipa, nullptr);
    PFN_xrVoidFunction f = nullptr;
    for (const char* name : {"xrWaitFrame", "xrBeginFrame", "xrEndFrame", "xrLocateSpace", "xrLocateViews", "xrPollEvent",
                             "xrDestroySpace", "xrBeginSession", "xrLocateSceneComponentsMSFT"}) {
      ASSERT_EQ(gipa(app.instance, name, &f), XR_SUCCESS) << name;
      EXPECT_EQ(library_of(f), "libroomsense_simruntime.so") << name << (extension ? " (extension enabled)" : "");
    }
    // Session bookkeeping is the layer's only with the extension (or ROOMSENSE_EXPORT_DIR).
    ASSERT_EQ(gipa(app.instance, "xrCreateSession", &f), XR_SUCCESS);
    EXPECT_EQ(library_of(f), extension ? "libXrApiLayer_roomsense.so" : "libroomsense_simruntime.so");
  }
}

// The same manifest in two search directories puts the layer into the chain twice; the copy nearest the
// application works and the other is skipped, so nothing recurses and every result arrives once.
TEST(LayerLoading, TheSameManifestInTwoSearchDirectories) {
  const std::filesystem::path log = roomsense::test::scratch_dir() / "layer_dup.log";
  ScopedEnv dirs("XDG_DATA_DIRS", std::string(ROOMSENSE_DUPLICATE_LAYER_DIR));
  ScopedEnv level("ROOMSENSE_LOG", std::string("info"));
  ScopedEnv file("ROOMSENSE_LOG_FILE", log.string());
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  EXPECT_EQ(layer_listed(kLayerName), 2) << "the test setup should show the layer in both directories";
  for (int round = 0; round < 2; ++round) {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    const Result r = read_result(app.extx, a);
    EXPECT_GT(r.indices.size(), 0u);
  }
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("1 more copy of the layer skipped"), std::string::npos) << text;
  std::filesystem::remove(log);
}

TEST(LayerLoading, LogGoesToTheFileAtTheChosenLevel) {
  const std::filesystem::path log = roomsense::test::scratch_dir() / "layer_log.log";
  {
    ScopedEnv level("ROOMSENSE_LOG", std::string("debug"));
    ScopedEnv file("ROOMSENSE_LOG_FILE", log.string());
    App app;
  }
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("[roomsense-layer] info: instance created: XR_EXTX_room_understanding enabled"), std::string::npos) << text;
  std::filesystem::remove(log);
  {
    ScopedEnv level("ROOMSENSE_LOG", std::string("error"));
    ScopedEnv file("ROOMSENSE_LOG_FILE", log.string());
    App app;
  }
  EXPECT_FALSE(std::filesystem::exists(log) && std::filesystem::file_size(log) > 0) << "info lines at level error";
  std::filesystem::remove(log);
}

}  // namespace
