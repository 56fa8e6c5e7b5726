#pragma once
#include "options.h"
#include "roomsense/analysis.h"
#include "roomsense/scan.h"

#include <string>
#include <vector>

namespace roomsense::cli {

// `roomsense analyze`: returns the process exit status.
int analyze_command(const std::vector<std::string>& args);

// What analyze and place share: the scan as the options read it (converted to roomsense's frame) and its analysis.
struct LoadedAnalysis {
  Scan scan;
  AnalysisResult result;
  double load_ms = 0.0;
};
// Throws Error for bad input and std::invalid_argument for a bad ROOMSENSE_BACKEND; `step` says what it was doing
// (for an out-of-memory line).
LoadedAnalysis load_and_analyze(const AnalyzeOptions& options, const char*& step);

// The plan's heading: the scan's file name, or the synthetic:NAME source as given.
std::string report_title(const std::string& source);

}  // namespace roomsense::cli
