// Where the real room scans live (../shared/rooms beside the checkout) and what a test does without them:
// skip with a clear message on a user's fresh clone, fail when CI is set (CI always has the folder).
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace roomsense::test {

inline std::filesystem::path rooms_dir() {
  if (const char* env = std::getenv("ROOMSENSE_ROOMS_DIR"); env != nullptr && *env != '\0') return env;
  return ROOMSENSE_DEFAULT_ROOMS_DIR;
}

inline bool running_in_ci() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && *ci != '\0';
}

}  // namespace roomsense::test

// Resolves `relative` under rooms_dir() into `var`, or skips the test (fails under CI) when it is missing.
#define ROOMSENSE_REQUIRE_ROOM(var, relative)                                                             \
  const std::filesystem::path var = ::roomsense::test::rooms_dir() / (relative);                        \
  if (!std::filesystem::exists(var)) {                                                                   \
    if (::roomsense::test::running_in_ci()) FAIL() << "CI must have the room scans, missing: " << var;   \
    GTEST_SKIP() << "real room scans not found at " << var                                               \
                 << " (they live in ../shared/rooms beside the checkout; set ROOMSENSE_ROOMS_DIR)";      \
  }
