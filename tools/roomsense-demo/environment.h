// Where the demo finds the simulated runtime and the layer: beside its own executable, in a build tree or an
// installed tree (both have bin/, lib/ and share/openxr/1/). The demo points the Khronos loader at them through
// the environment of its own process, before the first OpenXR call, so nobody has to set anything.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace roomsense::demo {

struct Setup {
  std::filesystem::path runtime_manifest;  // what XR_RUNTIME_JSON now names
  std::filesystem::path layer_manifest;    // the tree's implicit-layer manifest
  std::filesystem::path layer_search_dir;  // the tree's share/, prepended to XDG_DATA_DIRS
  std::vector<std::string> notes;          // what was changed in the environment, for the user
};

// `runtime_override`: --runtime MANIFEST (empty: the tree's simulated runtime). `scene`: the room for the
// simulated runtime (ROOMSENSE_SIM_SCENE). Throws std::runtime_error with one line when the tree is incomplete.
Setup prepare_environment(const std::string& runtime_override, const std::string& scene);

// The path of the layer library the loader actually loaded into this process, or "".
std::string loaded_layer_library();

}  // namespace roomsense::demo
