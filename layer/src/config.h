// The layer's configuration, read from the environment at each xrCreateInstance (DESIGN.md's table):
// ROOMSENSE_EXPORT_DIR, ROOMSENSE_BACKEND, ROOMSENSE_RUNTIME_TIMEOUT_MS and ROOMSENSE_SPATIAL_INTERVAL_MS here; ROOMSENSE_LOG and
// ROOMSENSE_LOG_FILE in log.h.
// DISABLE_XR_APILAYER_ROOMSENSE is the loader's business (the manifest's disable_environment).
#pragma once
#include "roomsense/backend.h"

#include <chrono>
#include <string>

namespace roomsense::layer {

struct Config {
  std::string export_dir;                          // empty: no export
  Backend env_backend = Backend::Auto;  // ROOMSENSE_BACKEND; applies where the app asks for AUTO
  // ROOMSENSE_RUNTIME_TIMEOUT_MS: how long a mesh source waits for a future or query that never completes.
  std::chrono::milliseconds runtime_timeout = std::chrono::seconds(10);
  // ROOMSENSE_SPATIAL_INTERVAL_MS: how often the layer looks at the runtime's meshes again while an application
  // has a spatial context of the layer's (the analysis runs again only when they changed).
  std::chrono::milliseconds spatial_interval = std::chrono::seconds(5);
};

Config read_config();

}  // namespace roomsense::layer
