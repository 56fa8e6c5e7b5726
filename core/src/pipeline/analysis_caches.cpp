// ChunkBandSums (analysis_caches.h): the surface heights' sums kept chunk by chunk.
#include "analysis_caches.h"

#include <algorithm>

namespace roomsense::detail {

ChunkBandSums::Band ChunkBandSums::band(const CombinedScan& c, Limits limits) const {
  Band out{limits, {}};
  out.chunks.reserve(c.placed.size());
  for (std::size_t k = 0; k < c.placed.size(); ++k) {
    const CombinedScan::Placed& p = c.placed[k];
    if (const auto it = chunks_.find(p.id); it != chunks_.end() && it->second.hash == p.hash) {
      const auto& bands = it->second.bands;
      const auto known = std::find_if(bands.begin(), bands.end(), [&](const auto& b) { return b.first == limits; });
      if (known != bands.end()) {
        out.chunks.push_back(known->second);
        continue;
      }
    }
    const std::size_t end = k + 1 < c.placed.size() ? c.placed[k + 1].index : c.scan.indices.size();
    out.chunks.push_back(band_sum(c.scan.vertices, std::span(c.scan.indices).subspan(p.index, end - p.index), limits));
  }
  return out;
}

void ChunkBandSums::keep(const CombinedScan& c, const std::vector<Band>& bands) {
  chunks_.clear();
  for (std::size_t k = 0; k < c.placed.size(); ++k) {
    Kept& kept = chunks_[c.placed[k].id];
    kept.hash = c.placed[k].hash;
    for (const Band& band : bands)
      if (k < band.chunks.size()) kept.bands.push_back({band.limits, band.chunks[k]});
  }
}

}  // namespace roomsense::detail
