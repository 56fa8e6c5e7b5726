// Parsing of the ROOMSENSE_SIM_* environment variables (documented in ../README.md).
#include "config.h"

#include "faults.h"
#include "pose_math.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace roomsense::sim {
namespace {

const char* env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : nullptr;
}

std::vector<double> numbers(const char* name, const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < item.size() && item[used] == ' ') ++used;
    if (used == 0 || used != item.size() || !std::isfinite(value))
      throw std::invalid_argument(std::string(name) + "='" + text + "' is not a comma-separated list of numbers");
    out.push_back(value);
  }
  return out;
}

}  // namespace

Config config_from_environment() {
  Config config;
  if (const char* scene = env("ROOMSENSE_SIM_SCENE")) config.scene_path = scene;
  if (const char* chunk = env("ROOMSENSE_SIM_CHUNK_SIZE")) {
    const auto v = numbers("ROOMSENSE_SIM_CHUNK_SIZE", chunk);
    if (v.size() != 1 || v[0] < 0.05 || v[0] > 1000.0)
      throw std::invalid_argument(std::string("ROOMSENSE_SIM_CHUNK_SIZE='") + chunk + "' must be one number in [0.05, 1000] metres");
    config.chunk_size = v[0];
  }
  if (const char* scan = env("ROOMSENSE_SIM_SCAN_SECONDS")) {
    const auto v = numbers("ROOMSENSE_SIM_SCAN_SECONDS", scan);
    if (v.size() != 1 || !(v[0] >= 0.0 && v[0] <= 3600.0))
      throw std::invalid_argument(std::string("ROOMSENSE_SIM_SCAN_SECONDS='") + scan + "' must be one number in [0, 3600] seconds");
    config.scan_seconds = v[0];
  }
  if (const char* head = env("ROOMSENSE_SIM_HEAD_POSE")) {
    const auto v = numbers("ROOMSENSE_SIM_HEAD_POSE", head);
    if (v.size() != 3 && v.size() != 7)
      throw std::invalid_argument(std::string("ROOMSENSE_SIM_HEAD_POSE='") + head + "' must be x,y,z or x,y,z,qx,qy,qz,qw");
    config.head_pose.position = {float(v[0]), float(v[1]), float(v[2])};
    if (v.size() == 7) {
      const double n = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
      if (n < 1e-6) throw std::invalid_argument(std::string("ROOMSENSE_SIM_HEAD_POSE='") + head + "' has a zero quaternion");
      config.head_pose.orientation = {float(v[3] / n), float(v[4] / n), float(v[5] / n), float(v[6] / n)};
    }
  }
  if (const char* delay = env("ROOMSENSE_SIM_COMPUTE_DELAY_MS")) {
    const auto v = numbers("ROOMSENSE_SIM_COMPUTE_DELAY_MS", delay);
    if (v.size() != 1 || v[0] < 0 || v[0] > 60000)
      throw std::invalid_argument(std::string("ROOMSENSE_SIM_COMPUTE_DELAY_MS='") + delay + "' must be in [0, 60000]");
    config.compute_delay_ms = static_cast<int>(v[0]);
  }
  // Parsed before anything is installed: a bad value leaves the previous instance's plan (and fails this one).
  const char* fault_spec = env("ROOMSENSE_SIM_FAULTS");
  faults::install(std::make_shared<const faults::Plan>(faults::parse(fault_spec != nullptr ? fault_spec : "")));
  return config;
}

}  // namespace roomsense::sim
