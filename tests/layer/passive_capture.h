// Helpers of the passive-capture tests: a fresh folder per test process for ROOMSENSE_EXPORT_DIR, and what an
// application received from the runtime, to compare a run with the layer against one without it.
#pragma once
#include "test_process.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace layertest {

// An empty folder of this test process (parallel ctest runs do not share it), removed as the process exits.
inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = roomsense::test::scratch_dir() / name;
  std::filesystem::remove_all(dir);
  return dir;
}

// What the application received: counts, and FNV-1a over every byte in the order received.
struct Received {
  std::size_t meshes = 0, vertices = 0, indices = 0, labels = 0;
  std::uint64_t checksum = 1469598103934665603ull;

  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) checksum = (checksum ^ p[i]) * 1099511628211ull;
  }
  template <typename T>
  void add(const std::vector<T>& v) {
    add(v.data(), v.size() * sizeof(T));
  }
  bool operator==(const Received&) const = default;
};

inline std::ostream& operator<<(std::ostream& out, const Received& r) {
  return out << r.meshes << " meshes, " << r.vertices << " vertices, " << r.indices << " indices, " << r.labels
             << " labels, checksum " << r.checksum;
}

}  // namespace layertest
