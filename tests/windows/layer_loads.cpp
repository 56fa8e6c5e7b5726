// What the Windows OpenXR loader does with an implicit layer, step by step, for the manifest a registry value
// names: parse the manifest, load the DLL at its library_path (relative to the manifest's folder), find
// xrNegotiateLoaderApiLayerInterface, and negotiate interface version 1 under the manifest's layer name. Bad
// negotiations are refused, not crashed on. Prints each step; exit status 0 when all hold.
//   layer_loads MANIFEST
#include "roomsense/platform.h"
#include "roomsense/xr/loader_interface.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using Negotiate = XrResult(XRAPI_PTR*)(const XrNegotiateLoaderInfo*, const char*, XrNegotiateApiLayerRequest*);

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok) ++failures;
}

XrNegotiateLoaderInfo loader_info() {
  XrNegotiateLoaderInfo info{};
  info.structType = XR_LOADER_INTERFACE_STRUCT_LOADER_INFO;
  info.structVersion = XR_LOADER_INFO_STRUCT_VERSION;
  info.structSize = sizeof(info);
  info.minInterfaceVersion = 1;
  info.maxInterfaceVersion = XR_CURRENT_LOADER_API_LAYER_VERSION;
  info.minApiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.maxApiVersion = XR_MAKE_VERSION(1, 0x3ff, 0xfff);
  return info;
}

XrNegotiateApiLayerRequest layer_request() {
  XrNegotiateApiLayerRequest request{};
  request.structType = XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST;
  request.structVersion = XR_API_LAYER_INFO_STRUCT_VERSION;
  request.structSize = sizeof(request);
  return request;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: layer_loads MANIFEST\n");
    return 2;
  }
  const std::filesystem::path manifest_path = argv[1];
  std::ifstream in(manifest_path);
  check(in.good(), "the manifest " + manifest_path.string() + " opens");
  if (!in) return 1;
  const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  check(!manifest.is_discarded() && manifest.contains("api_layer"), "it is an API layer manifest");
  if (failures != 0) return 1;
  const nlohmann::json& layer = manifest["api_layer"];
  const std::string name = layer.value("name", ""), library_path = layer.value("library_path", "");
  check(layer.value("disable_environment", "") == "DISABLE_XR_APILAYER_ROOMSENSE",
        "an implicit layer with disable_environment DISABLE_XR_APILAYER_ROOMSENSE");

  const std::filesystem::path library = manifest_path.parent_path() / library_path;
  const roomsense::platform::SharedLibrary dll(library.string());
  check(dll.loaded(), "library_path " + library_path + " loads (" + (dll.loaded() ? library.string() : dll.error()) + ")");
  if (!dll.loaded()) return 1;
  const auto negotiate = reinterpret_cast<Negotiate>(dll.symbol("xrNegotiateLoaderApiLayerInterface"));
  check(negotiate != nullptr, "it exports xrNegotiateLoaderApiLayerInterface");
  if (negotiate == nullptr) return 1;

  const XrNegotiateLoaderInfo info = loader_info();
  XrNegotiateApiLayerRequest request = layer_request();
  const XrResult result = negotiate(&info, name.c_str(), &request);
  check(result == XR_SUCCESS && request.layerInterfaceVersion == 1 && request.getInstanceProcAddr != nullptr &&
            request.createApiLayerInstance != nullptr,
        "negotiation as " + name + ": interface 1, xrGetInstanceProcAddr and xrCreateApiLayerInstance");
  check(XR_VERSION_MAJOR(request.layerApiVersion) == 1, "OpenXR 1.x");

  XrNegotiateApiLayerRequest other = layer_request();
  check(negotiate(&info, "XR_APILAYER_SOMEONE_else", &other) == XR_ERROR_INITIALIZATION_FAILED,
        "another layer's name is refused");
  check(negotiate(&info, name.c_str(), nullptr) == XR_ERROR_INITIALIZATION_FAILED, "a null request is refused");
  XrNegotiateLoaderInfo future = info;
  future.minInterfaceVersion = future.maxInterfaceVersion = 2;
  check(negotiate(&future, name.c_str(), &other) == XR_ERROR_INITIALIZATION_FAILED, "interface version 2 alone is refused");
  return failures == 0 ? 0 : 1;
}
