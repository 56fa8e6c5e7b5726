// An analysis's JSON without its timings: what two analyses of the same chunks agree on byte for byte.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/export.h"

#include <nlohmann/json.hpp>

#include <string>

namespace roomsense::test {

inline std::string json_without_timings(const AnalysisResult& r) {
  nlohmann::json j = nlohmann::json::parse(analysis_json(r, {}));
  j.erase("timings_ms");
  return j.dump();
}

}  // namespace roomsense::test
