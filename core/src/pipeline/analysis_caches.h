// What an IncrementalAnalysis keeps between its analyses besides each chunk's voxels: each storey's area
// searches by bands of rows (areas/search_cache.h).
#pragma once
#include "roomsense/analysis.h"
#include "../areas/search_cache.h"

#include <memory>
#include <vector>

namespace roomsense::detail {

struct AnalysisCaches {
  std::vector<std::unique_ptr<SearchCache>> storeys;  // storey i of the latest analysis
};

// analyze() (analysis.h), its area searches served by `caches`.
AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches);

}  // namespace roomsense::detail
