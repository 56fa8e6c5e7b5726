#include "config.h"

#include "log.h"
#include "sources/source_support.h"

#include <cstdlib>

namespace roomsense::layer {
namespace {

// A whole number of milliseconds in [lo, hi] from the environment; anything else is logged and ignored.
void read_milliseconds(const char* name, long long lo, long long hi, std::chrono::milliseconds& out) {
  const char* env = std::getenv(name);
  if (env == nullptr || *env == '\0') return;
  char* end = nullptr;
  const long long ms = std::strtoll(env, &end, 10);
  if (*end == '\0' && ms >= lo && ms <= hi) out = std::chrono::milliseconds(ms);
  else log_warn(std::string(name) + "='" + env + "' ignored (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
}

}  // namespace

Config read_config() {
  Config c;
  if (const char* dir = std::getenv("ROOMSENSE_EXPORT_DIR"); dir != nullptr) c.export_dir = dir;
  std::string note;
  c.env_backend = backend_from_environment(Backend::Auto, &note);
  if (!note.empty()) log_warn(note);
  read_milliseconds("ROOMSENSE_RUNTIME_TIMEOUT_MS", 1, 600000, c.runtime_timeout);
  read_milliseconds("ROOMSENSE_SPATIAL_INTERVAL_MS", 100, 3600000, c.spatial_interval);
  set_runtime_timeout(c.runtime_timeout);  // the sources' waits (one instance at a time: the loader's limit)
  return c;
}

}  // namespace roomsense::layer
