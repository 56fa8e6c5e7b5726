// ChunkBandSums and ChunkLabelVoxels (analysis_caches.h): the surface heights' sums and the labels' voxels kept
// chunk by chunk.
#include "analysis_caches.h"

#include "../parallel.h"

#include <algorithm>
#include <limits>

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


namespace {

bool same_spec(const GridSpec& a, const GridSpec& b) {
  return a.origin == b.origin && a.voxel_size == b.voxel_size && a.nx == b.nx && a.ny == b.ny && a.nz == b.nz;
}

}  // namespace

LabelGrid ChunkLabelVoxels::grid(const CombinedScan& c, const GridSpec& spec, std::uint64_t test_budget,
                                 std::vector<std::string>& warnings) {
  LabelGrid out;
  const LabelledTriangles& labels = c.scan.labels;
  if (!labels_usable(labels, warnings)) return out;
  // Chunk k's labelled triangles: its indices (into the scan's label vertices) and labels, one per triangle (the
  // scan has one label per triangle, and no chunk fewer: IncrementalAnalysis refuses those).
  const auto label_end = [&](std::size_t k) { return k + 1 < c.placed.size() ? c.placed[k + 1].label : labels.labels.size(); };
  std::map<std::uint64_t, Kept> now;
  std::vector<std::pair<std::size_t, LabelBoxes>> fresh;  // chunk, its boxes
  std::uint64_t tests = 0;
  for (std::size_t k = 0; k < c.placed.size(); ++k) {
    const CombinedScan::Placed& p = c.placed[k];
    const auto it = chunks_.find(p.id);
    if (it != chunks_.end() && it->second.hash == p.hash && same_spec(it->second.spec, spec)) {
      tests += it->second.tests;
      now.emplace(p.id, std::move(it->second));
      continue;
    }
    const std::size_t count = label_end(k) - p.label;
    fresh.emplace_back(k, label_boxes(spec, labels.vertices, std::span(labels.indices).subspan(p.label_index, 3 * count),
                                      std::span(labels.labels).subspan(p.label, count)));
    tests += fresh.back().second.tests;
  }
  chunks_ = std::move(now);  // the fresh ones join below, within the budget
  if (tests > test_budget) {
    warnings.push_back(over_budget_warning(test_budget));
    return out;
  }
  // The entries kept (8 bytes each) stay within the grid's voxel count: past it the chunks' labelled triangles
  // overlap a lot, and the labels are voxelized whole, as a full analysis does, with nothing kept.
  const auto whole = [&] {
    chunks_.clear();
    return voxelize_labels(spec, labels, test_budget, warnings);
  };
  if (spec.voxel_count() > std::numeric_limits<std::uint32_t>::max()) return whole();
  std::uint64_t entries = 0;
  for (const auto& [id, kept] : chunks_) entries += kept.voxels.size();
  try {
    if (!fresh.empty()) scratch_.resize(spec.voxel_count(), 0);  // all zero: touched_voxels leaves it so
    for (auto& [k, boxes] : fresh) {
      Kept kept{c.placed[k].hash, spec, boxes.tests, boxes.dropped, 0, !boxes.boxes.empty(), touched_voxels(spec, boxes, scratch_)};
      entries += kept.voxels.size();
      if (entries > spec.voxel_count()) return whole();
      for (const LabelBoxes::Box& b : boxes.boxes) kept.present = LabelMask(kept.present | label_bit(b.label));
      chunks_[c.placed[k].id] = std::move(kept);
    }
  } catch (...) {  // out of memory halfway: nothing kept may be half made, and the scratch must be zero again
    scratch_ = {};
    chunks_.clear();
    throw;
  }
  std::size_t dropped = 0;
  bool any_box = false;
  for (const auto& [id, kept] : chunks_) dropped += kept.dropped, any_box = any_box || kept.any_box;
  add_dropped_warning(dropped, warnings);
  if (!any_box) return out;
  out.masks.assign(spec.voxel_count(), 0);
  for (const auto& [id, kept] : chunks_) {
    out.present = LabelMask(out.present | kept.present);
    for (const auto& [voxel, mask] : kept.voxels) out.masks[voxel] |= mask;
  }
  return out;
}

}  // namespace roomsense::detail
