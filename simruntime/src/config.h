// Runtime options from the environment, read once per xrCreateInstance.
#pragma once
#include <openxr/openxr.h>

#include <string>

namespace roomsense::sim {

struct Config {
  std::string scene_path;           // ROOMSENSE_SIM_SCENE; empty when unset
  double chunk_size = 2.0;          // ROOMSENSE_SIM_CHUNK_SIZE, metres: edge of the cubes the mesh is split into
  XrPosef head_pose{{0, 0, 0, 1}, {0.0f, 1.6f, 0.0f}};  // ROOMSENSE_SIM_HEAD_POSE, VIEW in LOCAL/STAGE
  int compute_delay_ms = 20;        // ROOMSENSE_SIM_COMPUTE_DELAY_MS: how long a scene compute stays UPDATING
  double scan_seconds = 0.0;        // ROOMSENSE_SIM_SCAN_SECONDS: how long the room takes to be scanned (scan.h)
};

// Throws std::invalid_argument with a message naming the variable when a value cannot be parsed. Also parses
// ROOMSENSE_SIM_FAULTS and installs it (faults.h) for every call until the next instance.
Config config_from_environment();

}  // namespace roomsense::sim
