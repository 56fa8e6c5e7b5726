// ChunkBandSums (analysis_caches.h): the surface heights' sums kept chunk by chunk.
#include "analysis_caches.h"

#include "../parallel.h"

#include <algorithm>

namespace roomsense::detail {

std::vector<BandSum> ChunkBandSums::sums(const CombinedScan& c, std::span<const BandLimits> bands, unsigned threads) {
  const std::vector<BandLimits> wanted(bands.begin(), bands.end());
  std::map<std::uint64_t, Kept> now;
  std::vector<std::size_t> missing;  // chunks whose sums are not kept
  for (std::size_t k = 0; k < c.placed.size(); ++k) {
    const CombinedScan::Placed& p = c.placed[k];
    const auto it = chunks_.find(p.id);
    // Moved out: should this analysis fail, an entry left behind has no bands, and is never taken for kept.
    if (it != chunks_.end() && it->second.hash == p.hash && it->second.bands == wanted) now.emplace(p.id, std::move(it->second));
    else missing.push_back(k);
  }
  std::vector<std::vector<BandSum>> found(missing.size());
  parallel_tasks(missing.size(), threads, [&](std::size_t i) {
    const std::size_t k = missing[i];
    const std::size_t first = c.placed[k].index;
    found[i] = band_sums(c.scan.vertices, std::span(c.scan.indices).subspan(first, c.index_end(k) - first), bands);
  });
  for (std::size_t i = 0; i < missing.size(); ++i) {
    const CombinedScan::Placed& p = c.placed[missing[i]];
    now[p.id] = {p.hash, wanted, std::move(found[i])};
  }
  chunks_ = std::move(now);
  std::vector<BandSum> out(bands.size());
  for (const auto& [id, kept] : chunks_)
    for (std::size_t b = 0; b < out.size(); ++b) out[b] += kept.sums[b];
  return out;
}

}  // namespace roomsense::detail
