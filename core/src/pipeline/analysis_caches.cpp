// ChunkBandSums and ChunkLabelVoxels (analysis_caches.h): the surface heights' sums and the labels' voxels kept
// chunk by chunk.
#include "analysis_caches.h"

#include "../parallel.h"

#include <algorithm>
#include <limits>

namespace roomsense::detail {
namespace {

// Writes `from` at `to`, each index moved by `base`.
void copy_indices(std::uint32_t* to, std::span<const std::uint32_t> from, std::uint32_t base) {
  for (std::size_t k = 0; k < from.size(); ++k) to[k] = base + from[k];
}

// Writes chunk `s`'s arrays into `out` where `at` places them, its indices moved past the vertices before it.
void place_chunk(Scan& out, const CombinedScan::Placed& at, const Scan& s) {
  std::copy(s.vertices.begin(), s.vertices.end(), out.vertices.begin() + std::ptrdiff_t(at.vertex));
  copy_indices(out.indices.data() + at.index, s.indices, std::uint32_t(at.vertex));
  std::copy(s.labels.vertices.begin(), s.labels.vertices.end(), out.labels.vertices.begin() + std::ptrdiff_t(at.label_vertex));
  copy_indices(out.labels.indices.data() + at.label_index, s.labels.indices, std::uint32_t(at.label_vertex));
  std::copy(s.labels.labels.begin(), s.labels.labels.end(), out.labels.labels.begin() + std::ptrdiff_t(at.label));
}

// `v` resized to n, of which the first `keep` elements matter (place_chunk writes over the rest). Past its
// capacity it takes exactly n, copying only those: vector's own growth would double a whole scan's arrays.
template <class T>
void resize_keeping(std::vector<T>& v, std::size_t keep, std::size_t n) {
  if (n > v.capacity()) {
    v.resize(std::min(keep, v.size()));
    v.reserve(n);
  }
  v.resize(n);
}

}  // namespace

const Scan& CombinedScan::whole(unsigned threads) {
  const std::size_t from = std::min(in_place, placed.size());
  const bool sized = scan.vertices.size() == end.vertex && scan.indices.size() == end.index &&
                     scan.labels.vertices.size() == end.label_vertex && scan.labels.indices.size() == end.label_index &&
                     scan.labels.labels.size() == end.label;
  if (from == placed.size() && sized) return scan;
  // The arrays ending where `end` says, the parts before chunk `from` kept; then each chunk's own part, the workers
  // copying chunks side by side. A failure leaves in_place as it was: those chunks are still in place.
  const Placed start = from < placed.size() ? placed[from] : end;
  resize_keeping(scan.vertices, start.vertex, end.vertex);
  resize_keeping(scan.indices, start.index, end.index);
  resize_keeping(scan.labels.vertices, start.label_vertex, end.label_vertex);
  resize_keeping(scan.labels.indices, start.label_index, end.label_index);
  resize_keeping(scan.labels.labels, start.label, end.label);
  parallel_for(placed.size() - from, threads, 1, [&](std::size_t begin, std::size_t stop, std::size_t) {
    for (std::size_t k = from + begin; k < from + stop; ++k) place_chunk(scan, placed[k], *chunks[k]);
  });
  in_place = placed.size();
  return scan;
}

Scan CombinedScan::take_whole(unsigned threads) {
  whole(threads);
  in_place = 0;
  return std::move(scan);
}

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
    const Scan& chunk = *c.chunks[missing[i]];
    found[i] = band_sums(chunk.vertices, chunk.indices, bands);
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

LabelGrid ChunkLabelVoxels::grid(CombinedScan& c, const GridSpec& spec, std::uint64_t test_budget,
                                 std::vector<std::string>& warnings, unsigned threads) {
  LabelGrid out;
  if (!labels_usable(c.end.label_index, c.end.label, warnings)) return out;
  // Chunk k's labelled triangles: its own arrays where every chunk's are its own (CombinedScan::own_labels), else
  // its part of the whole scan's, its indices into all the label vertices (where one may land in a later chunk's)
  // and its labels as placed (labels_usable: as many in all as labelled triangles).
  const LabelledTriangles* all = c.labels_own() ? nullptr : &c.whole(threads).labels;
  const auto label_end = [&](std::size_t k) { return k + 1 < c.placed.size() ? c.placed[k + 1].label : c.end.label; };
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
    const LabelledTriangles& own = c.chunks[k]->labels;
    fresh.emplace_back(k, all ? label_boxes(spec, all->vertices, std::span(all->indices).subspan(p.label_index, 3 * count),
                                            std::span(all->labels).subspan(p.label, count))
                              : label_boxes(spec, own.vertices, std::span(own.indices).first(3 * count),
                                            std::span(own.labels).first(count)));
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
    return voxelize_labels(spec, c.whole(threads).labels, test_budget, warnings);
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
