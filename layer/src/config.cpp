#include "config.h"

#include "log.h"
#include "sources/source_support.h"

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
  if (const char* env = std::getenv("ROOMSENSE_RUNTIME_TIMEOUT_MS"); env != nullptr && *env != '\0') {
    char* end = nullptr;
    const long long ms = std::strtoll(env, &end, 10);
    if (*end == '\0' && ms >= 1 && ms <= 600000) c.runtime_timeout = std::chrono::milliseconds(ms);
    else log_warn(std::string("ROOMSENSE_RUNTIME_TIMEOUT_MS='") + env + "' ignored (1 to 600000)");
  }
  set_runtime_timeout(c.runtime_timeout);  // the sources' waits (one instance at a time: the loader's limit)
  return c;
}

}  // namespace roomsense::layer
