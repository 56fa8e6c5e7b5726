// The seam between the simulated runtime's core and the scene extensions it serves: one ServedExtension per
// extension, one file pair each under extensions/, and one line in extension_list.cpp. ROOMSENSE_SIM_EXTENSIONS
// picks which scene extensions an instance advertises, so a test (or an app developer) can reproduce a Quest,
// an Android XR device, a Magic Leap 2 or a HoloLens.
#pragma once
#include <openxr/openxr.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace roomsense::sim {

struct ServedFunction {
  const char* name;
  PFN_xrVoidFunction function;
};

struct ServedExtension {
  const char* name;
  std::uint32_t version = 1;
  // A scene extension: advertised unless ROOMSENSE_SIM_EXTENSIONS leaves it out. Others (headless, timespec,
  // the EXT_future an EXT scene extension needs) are always there.
  bool scene = false;
  std::vector<ServedFunction> functions;
  // Objects of a session or instance going away: forget them (called without the runtime's lock).
  void (*forget_session)(std::uint64_t session) = nullptr;
  void (*forget_instance)(std::uint64_t instance) = nullptr;
  // Extensions it builds on: naming it in ROOMSENSE_SIM_EXTENSIONS advertises them too, as the device would.
  std::vector<const char*> builds_on = {};
};

// Every extension the runtime can serve.
const std::vector<const ServedExtension*>& served_extensions();

// The extension served under `name`, or null.
const ServedExtension* served_extension(std::string_view name);

// The extensions an instance advertises: the base ones, and the scene extensions ROOMSENSE_SIM_EXTENSIONS names
// with those they require (all of them when unset). Throws std::invalid_argument
// naming the variable for a name that is not one of them.
std::vector<const ServedExtension*> advertised_extensions();

}  // namespace roomsense::sim
