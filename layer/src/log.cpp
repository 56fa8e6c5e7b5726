#include "log.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace roomsense::layer {
namespace {

struct Sink {
  std::mutex mutex;
  std::atomic<int> level{static_cast<int>(LogLevel::Warn)};
  std::FILE* file = nullptr;  // owned; null: stderr

  ~Sink() {
    if (file != nullptr) std::fclose(file);
  }
};

Sink& sink() {
  static Sink s;
  return s;
}

const char* name(LogLevel level) {
  switch (level) {
    case LogLevel::Error: return "error";
    case LogLevel::Warn: return "warn";
    case LogLevel::Info: return "info";
    default: return "debug";
  }
}

}  // namespace

void configure_log() {
  Sink& s = sink();
  std::string problem;
  {
    std::lock_guard lock(s.mutex);
    int level = static_cast<int>(LogLevel::Warn);
    if (const char* env = std::getenv("ROOMSENSE_LOG"); env != nullptr && *env != '\0') {
      bool known = false;
      for (LogLevel l : {LogLevel::Error, LogLevel::Warn, LogLevel::Info, LogLevel::Debug})
        if (std::strcmp(env, name(l)) == 0) level = static_cast<int>(l), known = true;
      if (!known) problem = std::string("ROOMSENSE_LOG='") + env + "' ignored (error, warn, info or debug)";
    }
    s.level = level;
    // Reopened at every instance: the file may have been moved or removed since.
    const char* file = std::getenv("ROOMSENSE_LOG_FILE");
    if (s.file != nullptr) std::fclose(s.file);
    s.file = nullptr;
    if (file != nullptr && *file != '\0') {
      s.file = std::fopen(file, "a");
      if (s.file == nullptr) problem = std::string("cannot open ROOMSENSE_LOG_FILE '") + file + "': logging to stderr";
    }
  }
  if (!problem.empty()) log_warn(problem);
}

bool log_enabled(LogLevel level) { return static_cast<int>(level) <= sink().level.load(std::memory_order_relaxed); }

void log_line(LogLevel level, const std::string& message) {
  if (!log_enabled(level)) return;
  Sink& s = sink();
  std::lock_guard lock(s.mutex);
  std::FILE* out = s.file != nullptr ? s.file : stderr;
  std::fprintf(out, "[roomsense-layer] %s: %s\n", name(level), message.c_str());
  std::fflush(out);
}

}  // namespace roomsense::layer
