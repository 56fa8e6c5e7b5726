// One line per message on stderr, prefixed so it stands out in an app's log. The runtime has no other output.
#pragma once
#include <cstdio>
#include <string>

namespace roomsense::sim {

inline void log_error(const std::string& message) {
  std::fprintf(stderr, "[roomsense-simruntime] error: %s\n", message.c_str());
  std::fflush(stderr);
}

inline void log_info(const std::string& message) {
  std::fprintf(stderr, "[roomsense-simruntime] %s\n", message.c_str());
  std::fflush(stderr);
}

}  // namespace roomsense::sim
