// The layer's log: one line per message, "[roomsense-layer] LEVEL: text", on stderr or in ROOMSENSE_LOG_FILE.
// ROOMSENSE_LOG picks the level (error, warn, info, debug; default warn). Both are read at each
// xrCreateInstance, so a test can change them between instances.
#pragma once
#include <string>

namespace roomsense::layer {

enum class LogLevel { Error = 0, Warn = 1, Info = 2, Debug = 3 };

// Reads ROOMSENSE_LOG and ROOMSENSE_LOG_FILE. A bad value is reported once and the default kept.
void configure_log();

bool log_enabled(LogLevel level);
void log_line(LogLevel level, const std::string& message);

inline void log_error(const std::string& message) { log_line(LogLevel::Error, message); }
inline void log_warn(const std::string& message) { log_line(LogLevel::Warn, message); }
inline void log_info(const std::string& message) {
  if (log_enabled(LogLevel::Info)) log_line(LogLevel::Info, message);
}
// Takes a callable so that the message is only built when it is printed.
template <typename Text>
void log_debug(Text&& text) {
  if (log_enabled(LogLevel::Debug)) log_line(LogLevel::Debug, text());
}

}  // namespace roomsense::layer
