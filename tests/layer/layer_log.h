// The layer's info log of a test (ROOMSENSE_LOG=info into ROOMSENSE_LOG_FILE), and what it says of the queries.
#pragma once
#include "passive_capture.h"
#include "sim_env.h"

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace layertest {

struct QueryCount {
  std::size_t chunks = 0, read = 0;
};

// Each active query's "N chunks (K read, ...)" from the layer's info log, in order.
inline std::vector<QueryCount> query_counts(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::vector<QueryCount> counts;
  for (std::string s; std::getline(in, s);) {
    const std::size_t from = s.find("runtime meshes from ");
    const std::size_t colon = from == std::string::npos ? from : s.find(": ", from);
    const std::size_t open = colon == std::string::npos ? colon : s.find(" chunks (", colon);
    if (open == std::string::npos) continue;
    counts.push_back({std::stoul(s.substr(colon + 2)), std::stoul(s.substr(open + 9))});
  }
  return counts;
}

// While it lives, the layer logs at info level into a fresh file of the test's own folder `name`.
class LayerLog {
 public:
  explicit LayerLog(const std::string& name)
      : path_(fresh(name)), file_("ROOMSENSE_LOG_FILE", path_.string()), level_("ROOMSENSE_LOG", std::string("info")) {}
  const std::filesystem::path& path() const { return path_; }
  std::vector<QueryCount> query_counts() const { return layertest::query_counts(path_); }

 private:
  static std::filesystem::path fresh(const std::string& name) {
    const std::filesystem::path dir = temp_dir(name);
    std::filesystem::create_directories(dir);
    return dir / "layer.log";
  }
  std::filesystem::path path_;
  simtest::ScopedEnv file_, level_;
};

}  // namespace layertest
