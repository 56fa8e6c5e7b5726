#include "config.h"

#include "log.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace roomsense::layer {

Config read_config() {
  Config c;
  if (const char* dir = std::getenv("ROOMSENSE_EXPORT_DIR"); dir != nullptr) c.export_dir = dir;
  if (const char* env = std::getenv("ROOMSENSE_BACKEND"); env != nullptr && *env != '\0') {
    std::string v = env;
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (v == "auto") c.env_backend = BackendChoice::Auto;
    else if (v == "cpu") c.env_backend = BackendChoice::Cpu;
    else if (v == "vulkan") c.env_backend = BackendChoice::Vulkan;
    else log_warn(std::string("ROOMSENSE_BACKEND='") + env + "' ignored (auto, cpu or vulkan)");
  }
  return c;
}

}  // namespace roomsense::layer
