#include "environment.h"

#include "roomsense/platform.h"

#include <cstdlib>
#include <stdexcept>

namespace roomsense::demo {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLayerManifest = "openxr/1/api_layers/implicit.d/XR_APILAYER_ROOMSENSE_room_understanding.json";
constexpr const char* kRuntimeManifest = "openxr/1/roomsense_simruntime.json";

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr ? v : "";
}

}  // namespace

Setup prepare_environment(const std::string& runtime_override, const std::string& scene) {
  Setup s;
  const fs::path share = platform::executable_path().parent_path().parent_path() / "share";
  s.layer_search_dir = share;
  s.layer_manifest = share / kLayerManifest;
  if (!fs::exists(s.layer_manifest))
    throw std::runtime_error("the roomsense layer's manifest is missing: " + s.layer_manifest.string() +
                             " (build the roomsense-demo target, or install the project)");
  s.runtime_manifest = runtime_override.empty() ? share / kRuntimeManifest : fs::path(runtime_override);
  if (!fs::exists(s.runtime_manifest))
    throw std::runtime_error("the OpenXR runtime's manifest is missing: " + s.runtime_manifest.string());
  s.runtime_manifest = fs::absolute(s.runtime_manifest);

  // The runtime: this process only. A different XR_RUNTIME_JSON of the user's is named, not silently lost.
  const std::string old_runtime = env("XR_RUNTIME_JSON");
  if (!old_runtime.empty() && fs::path(old_runtime) != s.runtime_manifest)
    s.notes.push_back("XR_RUNTIME_JSON=" + old_runtime + " is replaced for this run (use --runtime MANIFEST to pick one)");
  platform::set_environment("XR_RUNTIME_JSON", s.runtime_manifest.string());

  // The layer: the tree's share/ goes first in XDG_DATA_DIRS, where the loader also looks for implicit layers.
  // XDG_DATA_HOME (the user's own layers) is left alone; the defaults of XDG_DATA_DIRS are kept behind ours.
  std::string dirs = env("XDG_DATA_DIRS");
  if (dirs.empty()) dirs = "/usr/local/share:/usr/share";
  platform::set_environment("XDG_DATA_DIRS", share.string() + ":" + dirs);

  if (!scene.empty()) platform::set_environment("ROOMSENSE_SIM_SCENE", scene);
  if (std::getenv("DISABLE_XR_APILAYER_ROOMSENSE") != nullptr)
    s.notes.push_back("DISABLE_XR_APILAYER_ROOMSENSE is set: the loader will leave the roomsense layer out");
  return s;
}

std::string loaded_layer_library() { return platform::loaded_module_path("libXrApiLayer_roomsense.so"); }

}  // namespace roomsense::demo
