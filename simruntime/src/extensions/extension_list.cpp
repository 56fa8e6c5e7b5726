// The extensions the simulated runtime serves. A new scene extension is one file pair in this folder and one
// line here.
#include "served_extension.h"

#include "../functions.h"
#include "android_scene_meshing.h"
#include "ext_future.h"
#include "ext_spatial_plane_tracking.h"
#include "meta_spatial_entity_mesh.h"
#include "ml_world_mesh_detection.h"
#include "msft_scene_understanding.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

namespace roomsense::sim {
namespace {

const ServedExtension& headless_extension() {
  static const ServedExtension e{XR_MND_HEADLESS_EXTENSION_NAME, XR_MND_headless_SPEC_VERSION, false, {}};
  return e;
}

const ServedExtension& timespec_extension() {
#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&sim::name)},
  static const ServedExtension e{XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME, XR_KHR_convert_timespec_time_SPEC_VERSION,
                                 false, {SIM_TIMESPEC_FUNCTIONS(SIM_SERVE)}};
#undef SIM_SERVE
  return e;
}

// A value as one short line of the message: control characters as '?', at most 64 characters.
std::string shown(std::string text) {
  constexpr std::size_t kMax = 64;
  if (text.size() > kMax) text = text.substr(0, kMax) + "...";
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return text;
}

}  // namespace

const std::vector<const ServedExtension*>& served_extensions() {
  static const std::vector<const ServedExtension*> list = {
      &headless_extension(),
      &timespec_extension(),
      &ext_future_extension(),
      &msft_scene_understanding_extension(),
      &android_scene_meshing_extension(),
      &ml_world_mesh_detection_extension(),
      &fb_spatial_entity_extension(),
      &fb_spatial_entity_query_extension(),
      &fb_scene_extension(),
      &fb_spatial_entity_container_extension(),
      &meta_spatial_entity_mesh_extension(),
      &ext_spatial_entity_extension(),
      &ext_spatial_plane_tracking_extension(),
  };
  return list;
}

const ServedExtension* served_extension(std::string_view name) {
  for (const ServedExtension* e : served_extensions())
    if (name == e->name) return e;
  return nullptr;
}

std::vector<const ServedExtension*> advertised_extensions() {
  const char* wanted = std::getenv("ROOMSENSE_SIM_EXTENSIONS");
  std::vector<const ServedExtension*> out;
  if (wanted == nullptr || *wanted == '\0') {
    out = served_extensions();
    return out;
  }
  std::vector<std::string> names;
  std::stringstream in(wanted);
  for (std::string item; std::getline(in, item, ',');) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    const ServedExtension* e = served_extension(item);
    if (e == nullptr || !e->scene)
      throw std::invalid_argument("ROOMSENSE_SIM_EXTENSIONS: '" + shown(item) +
                                  "' is not a scene extension this runtime serves");
    names.push_back(item);
  }
  for (std::size_t i = 0; i < names.size(); ++i)  // grows while it runs: requirements of requirements
    for (const char* r : served_extension(names[i])->builds_on)
      if (std::find(names.begin(), names.end(), r) == names.end()) names.emplace_back(r);
  for (const ServedExtension* e : served_extensions())
    if (!e->scene || std::find(names.begin(), names.end(), e->name) != names.end()) out.push_back(e);
  return out;
}

}  // namespace roomsense::sim
