// The human-readable summary `roomsense analyze` prints without --json.
#pragma once
#include "roomsense/analysis.h"

#include <string>

namespace roomsense::cli {

std::string summary(const AnalysisResult& result, const std::string& source, double load_ms);

}  // namespace roomsense::cli
