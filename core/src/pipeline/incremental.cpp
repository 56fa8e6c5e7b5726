// IncrementalAnalysis (incremental.h): chunks by id, and a voxel stage that keeps each chunk's voxels.
//
// Why the kept voxels are exact: triangle mode marks, per triangle, the voxels its test cube touches, from the
// triangle's grid-unit corners alone (voxelize.h). The combined scan's grid-unit vertices are its world
// vertices mapped one by one (to_grid_units), so with the same GridSpec a chunk's triangles mark the same
// voxels whether alone or among the others, and the grid of the combined scan is the union of the chunks'.
// A chunk's marks are reused only under the GridSpec they were made with, and only while prepare_input kept
// every vertex and triangle (otherwise the combined indices are renumbered and the stage runs in full); then
// analyze() leaves the mapping to the stage, which maps the vertices of each chunk it voxelizes again, alone.
#include "roomsense/incremental.h"

#include "analysis_caches.h"
#include "../grid/voxelize_cpu.h"
#include "../parallel.h"

#include "roomsense/content_hash.h"
#include "roomsense/error.h"
#include "roomsense/voxelize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <optional>
#include <span>

namespace roomsense {
namespace {

std::uint64_t content_hash(const Scan& scan) {
  ContentHash h;
  h.add(std::span<const glm::vec3>(scan.vertices));
  h.add(std::span<const std::uint32_t>(scan.indices));
  h.add(std::span<const glm::vec3>(scan.labels.vertices));
  h.add(std::span<const std::uint32_t>(scan.labels.indices));
  h.add(std::span<const SurfaceLabel>(scan.labels.labels));
  return h.value();
}

}  // namespace

// Serves the voxel stage of analyze() from the chunks' kept voxels. Before each analysis the owner gives it the
// combined scan, which says where each chunk's triangles lie, and the previous analysis's stage result
// (set_chunks): where that is the grid of this stage's previous run, the level and column counts are those
// counted again only in the columns of the chunks voxelized again or dropped since.
class IncrementalAnalysis::ChunkVoxelStage final : public VoxelStage {
 public:
  explicit ChunkVoxelStage(unsigned threads) : threads_(threads) {}
  std::string name() const override { return CpuVoxelStage().name(); }

  void set_chunks(const detail::CombinedScan& combined, const VoxelStageResult* previous) {
    combined_ = &combined;
    previous_ = previous;
  }
  std::size_t revoxelized() const { return revoxelized_; }

  VoxelStageResult run(const VoxelizeRequest& request) override {
    revoxelized_ = 0;
    const detail::CombinedScan& c = *combined_;
    // The previous analysis's grid is the one the chunks in kept_ made where this stage's previous run made it
    // from them (an analysis that failed after the stage leaves no previous result).
    const VoxelStageResult* previous = std::exchange(previous_, nullptr);
    const bool from_previous = std::exchange(made_grid_, false) && previous != nullptr && previous->grid.spec == request.spec;
    // analyze() maps the vertices itself only where the input checks dropped or renumbered something, or there
    // are no triangles: the stage in full. Otherwise (grid_vertices empty: the combined scan as it is, in triangle
    // mode) each chunk voxelized again is mapped alone below.
    if (!request.grid_vertices.empty()) {
      kept_.clear();
      revoxelized_ = c.placed.size();
      return CpuVoxelStage(threads_).run(request);
    }
    if (request.spec != spec_) kept_.clear(), spec_ = request.spec;
    std::map<std::uint64_t, Kept> now;
    // The columns whose voxels may differ from the previous grid's: those of the chunks voxelized again, and of
    // the ones dropped or replaced (left in kept_ below).
    std::vector<std::uint8_t> touched(from_previous ? request.spec.column_count() : 0);
    const auto touch = [&](const Kept& kept) {
      for (const std::uint32_t v : kept.voxels) touched[v / std::uint32_t(request.spec.ny)] = 1;
    };
    try {
      for (std::size_t k = 0; k < c.placed.size(); ++k) {
        const detail::CombinedScan::Placed& chunk = c.placed[k];
        const auto it = kept_.find(chunk.id);
        if (it != kept_.end() && it->second.hash == chunk.hash) {
          now.emplace(chunk.id, std::move(it->second));
          kept_.erase(it);
          continue;
        }
        const auto placed = now.emplace(chunk.id, voxelize_chunk(request, chunk.hash, k)).first;
        if (from_previous) touch(placed->second);
        ++revoxelized_;
      }
    } catch (...) {
      kept_.clear();  // some were moved into `now`: keep nothing rather than an emptied entry
      scratch_ = VoxelGrid(GridSpec{});
      throw;
    }
    if (from_previous)
      for (const auto& [id, gone] : kept_) touch(gone);
    kept_ = std::move(now);
    scratch_ = VoxelGrid(GridSpec{});  // between analyses the stage holds no grid of its own

    VoxelStageResult r;
    r.grid = VoxelGrid(request.spec);
    for (const auto& [id, kept] : kept_) {
      for (const std::uint32_t v : kept.voxels) r.grid.cells[v] = 1;
      r.voxel_tests += kept.tests;
    }
    // The whole stage's budget, as voxelize_cpu counts it over all triangles.
    if (r.voxel_tests > request.test_budget)
      throw Error(ErrorCode::TooMuchWork, too_much_work_message(request.test_budget));
    count_from(from_previous ? previous : nullptr, touched, request.min_separation_levels, r);
    made_grid_ = true;
    return r;
  }

 private:
  struct Kept {
    std::uint64_t hash = 0;
    std::vector<std::uint32_t> voxels;  // GridSpec::index of each marked voxel
    std::uint64_t tests = 0;
  };

  // Chunk k's triangles alone on the grid, from its own arrays (its vertices mapped to grid units here); its marks
  // lie within its vertices' box (box_index per axis).
  Kept voxelize_chunk(const VoxelizeRequest& request, std::uint64_t hash, std::size_t k) {
    const Scan& chunk = *combined_->chunks[k];
    Kept kept;
    kept.hash = hash;
    if (chunk.indices.empty()) return kept;
    const std::vector<glm::vec3> vertices = to_grid_units(chunk.vertices, request.spec);
    VoxelizeRequest part = request;
    part.grid_vertices = vertices;
    part.indices = chunk.indices;
    // One scratch grid for every chunk, cleared over each chunk's box after use: a chunk costs its box, not the
    // grid (the first result of a room in a hundred chunks cleared the whole grid a hundred times).
    // A failure here reaches run(), which drops the scratch grid with whatever marks it holds.
    if (scratch_.spec != request.spec) scratch_ = VoxelGrid(request.spec);
    VoxelGrid& grid = scratch_;
    voxelize_cpu_into(part, grid, threads_, &kept.tests);
    const GridSpec& s = request.spec;
    // The marks lie in the cells of the box of the vertices the triangles use (box_index is monotone), so in those of
    // every vertex's box: one pass over the vertices, not a lookup per index. Where unused vertices make that box far
    // larger than the triangles need (a hostile chunk: a triangle and two far corners), the used vertices' box is
    // found instead. With the columns' scan below, a re-sent 13k-triangle block's marks took 127 -> 27 us, a
    // 1,960-triangle object's 18.5 -> 4.9 us (the voxel stage's serial part of an update).
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    std::array<glm::ivec2, 3> box;  // per axis, the first and last cell
    // The box of vertex(k) for k in [0, n): lo, hi and its cells; returns how many cells it holds.
    const auto box_of = [&](std::size_t n, const auto& vertex) {
      lo = glm::vec3(INFINITY), hi = glm::vec3(-INFINITY);
      for (std::size_t k = 0; k < n; ++k) lo = glm::min(lo, vertex(k)), hi = glm::max(hi, vertex(k));
      box = {glm::ivec2(box_index(lo.x, s.nx), box_index(hi.x, s.nx)),
             glm::ivec2(box_index(lo.y, s.ny), box_index(hi.y, s.ny)),
             glm::ivec2(box_index(lo.z, s.nz), box_index(hi.z, s.nz))};
      return double(box[0].y - box[0].x + 1) * double(box[1].y - box[1].x + 1) * double(box[2].y - box[2].x + 1);
    };
    constexpr double kCellsPerTriangle = 64.0;  // a fine mesh's box holds a few cells a triangle
    const std::span<const glm::vec3> at = part.grid_vertices;
    if (box_of(at.size(), [&](std::size_t k) { return at[k]; }) >
        std::max(4096.0, kCellsPerTriangle * double(part.indices.size() / 3)))
      box_of(part.indices.size(), [&](std::size_t k) { return at[part.indices[k]]; });
    // Each column's levels in the box: most hold no mark, found by one pass the compiler vectorizes.
    const auto levels = std::size_t(box[1].y - box[1].x + 1);
    for (int z = box[2].x; z <= box[2].y; ++z)
      for (int x = box[0].x; x <= box[0].y; ++x) {
        const std::size_t first = s.index(x, box[1].x, z);
        std::uint8_t* const column = grid.cells.data() + first;
        std::uint8_t any = 0;
        for (std::size_t y = 0; y < levels; ++y) any |= column[y];
        if (any == 0) continue;
        for (std::size_t y = 0; y < levels; ++y)
          if (column[y] != 0) kept.voxels.push_back(std::uint32_t(first + y)), column[y] = 0;
      }
    // prepare_input drops what is not finite, but a mark outside the box would stay for the next chunk.
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(lo) || !finite(hi)) std::fill(grid.cells.begin(), grid.cells.end(), std::uint8_t{0});
    return kept;
  }

  // r's level counts, levels and column counts: the previous result's, counted again in the touched columns,
  // where there is one (its levels' column counts only where the levels are the same); else over the grid.
  static void count_from(const VoxelStageResult* previous, const std::vector<std::uint8_t>& touched,
                         int min_separation, VoxelStageResult& r) {
    const GridSpec& s = r.grid.spec;
    const auto column = [&](const VoxelGrid& g, std::size_t col) { return g.cells.data() + col * std::size_t(s.ny); };
    if (previous == nullptr) {
      r.level_counts = count_levels(r.grid);
    } else {
      r.level_counts = previous->level_counts;
      for (std::size_t col = 0; col < touched.size(); ++col) {
        if (!touched[col]) continue;
        const std::uint8_t *was = column(previous->grid, col), *is = column(r.grid, col);
        for (int y = 0; y < s.ny; ++y) r.level_counts[std::size_t(y)] += std::uint32_t(is[y]) - std::uint32_t(was[y]);
      }
    }
    r.levels = select_floor_ceiling(r.level_counts, min_separation);
    if (previous == nullptr || !r.levels || previous->levels != r.levels) {
      count_columns(r.grid, r.levels, r.column_counts, r.column_any);
      return;
    }
    r.column_counts = previous->column_counts;
    r.column_any = previous->column_any;
    detail::count_columns_again(r.grid, *r.levels, touched, r.column_counts, r.column_any);
  }

  unsigned threads_;
  const detail::CombinedScan* combined_ = nullptr;  // the owner's, set before each analysis
  const VoxelStageResult* previous_ = nullptr;      // the previous result's, for one run
  bool made_grid_ = false;                          // the previous run made its grid from kept_'s chunks
  GridSpec spec_{};
  std::map<std::uint64_t, Kept> kept_;
  std::size_t revoxelized_ = 0;
  VoxelGrid scratch_{GridSpec{}};  // within one run, the chunks' grid: all zero between chunks
};

IncrementalAnalysis::IncrementalAnalysis(AnalysisOptions options)
    : options_(std::move(options)),
      stage_(std::make_unique<ChunkVoxelStage>(options_.threads)),
      caches_(std::make_unique<detail::AnalysisCaches>()) {
  options_.voxel_stage = stage_.get();
  caches_->chunk_stage = stage_.get();
}
IncrementalAnalysis::~IncrementalAnalysis() = default;
IncrementalAnalysis::IncrementalAnalysis(IncrementalAnalysis&&) noexcept = default;
IncrementalAnalysis& IncrementalAnalysis::operator=(IncrementalAnalysis&&) noexcept = default;

void IncrementalAnalysis::set_chunk(std::uint64_t id, Scan chunk) {
  const std::uint64_t hash = content_hash(chunk);
  const auto it = chunks_.find(id);
  if (it != chunks_.end() && it->second.hash == hash) return;  // re-sent unchanged
  chunks_[id] = {std::move(chunk), hash};
  dirty_ = true;
}

bool IncrementalAnalysis::remove_chunk(std::uint64_t id) {
  if (chunks_.erase(id) == 0) return false;
  dirty_ = true;
  return true;
}

namespace {

// Throws BadIndices for an index of chunk `id` past its own vertices. Such an index, moved past the vertices
// before the chunk, would stay past them (so analyze() would refuse it as it would the chunk alone) unless it
// landed in a later chunk: checked here instead.
void check_indices(std::uint64_t id, const Scan& s) {
  const auto worst = std::max_element(s.indices.begin(), s.indices.end());
  if (worst != s.indices.end() && *worst >= s.vertices.size())
    throw Error(ErrorCode::BadIndices, "chunk " + std::to_string(id) + ": index " + std::to_string(*worst) +
                                           " is out of range (" + std::to_string(s.vertices.size()) + " vertices)");
}

// Where the arrays of a scan placed at `at` end.
detail::CombinedScan::Placed end_of(detail::CombinedScan::Placed at, const Scan& s) {
  at.vertex += s.vertices.size(), at.index += s.indices.size(), at.label_vertex += s.labels.vertices.size();
  at.label_index += s.labels.indices.size(), at.label += s.labels.labels.size();
  return at;
}

// The arrays of `chunks` in order, placed from `start` on: where each goes.
std::vector<detail::CombinedScan::Placed> place_from(detail::CombinedScan::Placed start,
                                                     std::span<const std::pair<std::uint64_t, const Scan*>> chunks,
                                                     std::span<const std::uint64_t> hashes) {
  std::vector<detail::CombinedScan::Placed> placed;
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    start.id = chunks[k].first, start.hash = hashes.empty() ? 0 : hashes[k];
    placed.push_back(start);
    start = end_of(start, *chunks[k].second);
  }
  return placed;
}

// Whether `s`'s labelled triangles are its own: one label each, and each indexing its own label vertices. (In a
// combined scan, a chunk's index past its own may land in a later chunk's label vertices, and a chunk's labels
// past its triangles label the next chunk's.)
bool labels_own(const Scan& s) {
  const LabelledTriangles& l = s.labels;
  const auto worst = std::max_element(l.indices.begin(), l.indices.end());
  return l.indices.size() == 3 * l.labels.size() && (worst == l.indices.end() || *worst < l.vertices.size());
}

}  // namespace

std::vector<std::uint64_t> IncrementalAnalysis::chunk_ids() const {
  std::vector<std::uint64_t> ids;
  ids.reserve(chunks_.size());
  for (const auto& [id, chunk] : chunks_) ids.push_back(id);
  return ids;
}

Scan IncrementalAnalysis::combined_scan() const {
  std::vector<std::pair<std::uint64_t, const Scan*>> chunks;
  detail::CombinedScan c;
  for (const auto& [id, chunk] : chunks_) {
    check_indices(id, chunk.scan);
    chunks.push_back({id, &chunk.scan});
    c.chunks.push_back(&chunk.scan);
  }
  c.placed = place_from({}, chunks, {});
  if (!c.placed.empty()) c.end = end_of(c.placed.back(), *chunks.back().second);
  return c.take_whole(1);
}

void IncrementalAnalysis::update_combined() {
  detail::CombinedScan& c = caches_->combined;
  // The chunks placed as before, from the first: kept; the rest placed again.
  std::size_t same = 0;
  auto it = chunks_.begin();
  for (; same < c.placed.size() && it != chunks_.end(); ++same, ++it)
    if (c.placed[same].id != it->first || c.placed[same].hash != it->second.hash) break;
  // What is known of the chunks after those (their vertex runs, whether their labels are their own), by id, kept
  // for the ones that come back unchanged (their indices were checked when they were placed).
  struct Known {
    detail::CombinedScan::Placed at;
    detail::VertexRun run;
    std::uint8_t own_labels;
  };
  std::vector<Known> later;
  for (std::size_t k = same; k < c.placed.size(); ++k) later.push_back({c.placed[k], c.known.runs[k], c.own_labels[k]});
  // The chunks placed again, each changed one's indices checked before anything changes: a chunk refused here
  // leaves the combined scan as the last result had it.
  std::vector<std::pair<std::uint64_t, const Scan*>> rest;
  std::vector<std::uint64_t> hashes;
  std::vector<const Known*> kept;  // per chunk of `rest`: what was known of it, or null where it changed
  auto was = later.begin();
  for (; it != chunks_.end(); ++it) {
    while (was != later.end() && was->at.id < it->first) ++was;
    const bool unchanged = was != later.end() && was->at.id == it->first && was->at.hash == it->second.hash;
    if (!unchanged) check_indices(it->first, it->second.scan);
    rest.push_back({it->first, &it->second.scan});
    hashes.push_back(it->second.hash);
    kept.push_back(unchanged ? &*was : nullptr);
  }
  try {
    // Where the chunks placed again begin: after the kept ones.
    const detail::CombinedScan::Placed start = same < c.placed.size() ? c.placed[same] : c.end;
    const std::vector<detail::CombinedScan::Placed> placed = place_from(start, rest, hashes);
    // The changed chunks' runs and labels, side by side.
    std::vector<detail::VertexRun> runs(rest.size());
    std::vector<std::uint8_t> own(rest.size());
    detail::parallel_for(rest.size(), options_.threads, 1, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t k = begin; k < end; ++k) {
        runs[k] = kept[k] ? kept[k]->run : detail::summarize_vertices(rest[k].second->vertices);
        own[k] = kept[k] ? kept[k]->own_labels : std::uint8_t(labels_own(*rest[k].second));
      }
    });
    c.placed.resize(same), c.known.runs.resize(same), c.own_labels.resize(same), c.chunks.resize(same);
    c.placed.insert(c.placed.end(), placed.begin(), placed.end());
    c.known.runs.insert(c.known.runs.end(), runs.begin(), runs.end());
    c.own_labels.insert(c.own_labels.end(), own.begin(), own.end());
    // Every chunk's arrays, a kept one's looked up again: removed and set again as it was, it is another node.
    for (std::size_t k = 0; k < same; ++k) c.chunks[k] = &chunks_.at(c.placed[k].id).scan;
    for (const auto& [id, scan] : rest) c.chunks.push_back(scan);
    c.end = placed.empty() ? start : end_of(placed.back(), *rest.back().second);
    c.moved_from(same);
  } catch (...) {
    c.clear();  // lists half made: the next result places every chunk again
    throw;
  }
  c.known.indices_in_range = true;
}

const AnalysisResult& IncrementalAnalysis::result() {
  reused_ = !dirty_ && result_.has_value();
  if (reused_) return *result_;
  // The analysis's threads (analyze() makes the same pool current), for the copies too.
  const detail::PoolScope scope(detail::pool_for(caches_->workers, options_.threads));
  update_combined();
  // The previous result, alive through the analysis, which may take its features and bounds (a chunk refined
  // within its voxels) and compares against it; gone once the analysis ends, or fails.
  const std::optional<AnalysisResult> previous = std::exchange(result_, std::nullopt);
  stage_->set_chunks(caches_->combined, previous ? &previous->voxels : nullptr);
  caches_->previous = previous ? &*previous : nullptr;
  struct Forget {
    detail::AnalysisCaches& caches;
    ~Forget() { caches.previous = nullptr; }
  } forget{*caches_};
  result_ = detail::analyze(caches_->combined.handle(), options_, caches_.get());
  dirty_ = false;
  return *result_;
}

std::map<std::uint64_t, Scan> split_into_blocks(const Scan& scan, float tile) {
  if (!(tile > 0.0f)) throw Error(ErrorCode::BadParameter, "the tile size must be positive");
  const auto check = [](const std::vector<glm::vec3>& vertices, const std::vector<std::uint32_t>& indices) {
    for (const std::uint32_t i : indices)
      if (i >= vertices.size())
        throw Error(ErrorCode::BadIndices, "index " + std::to_string(i) + " is out of range (" +
                                               std::to_string(vertices.size()) + " vertices)");
  };
  check(scan.vertices, scan.indices);
  check(scan.labels.vertices, scan.labels.indices);
  if (scan.labels.labels.size() < scan.labels.indices.size() / 3)
    throw Error(ErrorCode::BadIndices, "fewer labels than labelled triangles");
  std::map<std::uint64_t, Scan> out;
  // A NaN centroid goes to tile 0; absurd coordinates to the outermost tiles.
  const auto cell = [&](float v) {
    const double q = std::floor(double(v) / double(tile));
    return std::uint64_t(std::int64_t(std::isfinite(q) ? std::clamp(q, -1e9, 1e9) : 0.0) + (std::int64_t{1} << 31));
  };
  const auto key = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 m = (a + b + c) / 3.0f;
    return (cell(m.x) << 32) | cell(m.z);
  };
  const auto add = [&](std::vector<glm::vec3>& vertices, std::vector<std::uint32_t>& indices,
                       std::map<std::uint32_t, std::uint32_t>& remap, const std::vector<glm::vec3>& from,
                       const std::uint32_t* t) {
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = remap.try_emplace(t[k], std::uint32_t(vertices.size()));
      if (added) vertices.push_back(from[t[k]]);
      indices.push_back(it->second);
    }
  };
  std::map<std::uint64_t, std::map<std::uint32_t, std::uint32_t>> mesh_remap, label_remap;
  for (std::size_t t = 0; t + 2 < scan.indices.size(); t += 3) {
    const std::uint32_t* i = &scan.indices[t];
    const std::uint64_t k = key(scan.vertices[i[0]], scan.vertices[i[1]], scan.vertices[i[2]]);
    add(out[k].vertices, out[k].indices, mesh_remap[k], scan.vertices, i);
  }
  if (scan.indices.empty())  // a point cloud: each vertex to its own tile
    for (const glm::vec3& v : scan.vertices) out[key(v, v, v)].vertices.push_back(v);
  const LabelledTriangles& l = scan.labels;
  for (std::size_t t = 0; t + 2 < l.indices.size(); t += 3) {
    const std::uint32_t* i = &l.indices[t];
    const std::uint64_t k = key(l.vertices[i[0]], l.vertices[i[1]], l.vertices[i[2]]);
    add(out[k].labels.vertices, out[k].labels.indices, label_remap[k], l.vertices, i);
    out[k].labels.labels.push_back(l.labels[t / 3]);
  }
  return out;
}

std::size_t IncrementalAnalysis::revoxelized_chunks() const { return reused_ ? 0 : stage_->revoxelized(); }

namespace {

// The area searches' caches of the latest result's storeys: one of a storey that result no longer has keeps the
// counts of the result before. None where it failed.
std::span<const std::unique_ptr<detail::SearchCache>> searched_storeys(const detail::AnalysisCaches& caches,
                                                                        const std::optional<AnalysisResult>& result) {
  const std::size_t storeys = result ? std::min(result->storeys.size(), caches.storeys.size()) : 0;
  return std::span(caches.storeys).first(storeys);
}

}  // namespace

std::size_t IncrementalAnalysis::area_bands_searched() const {
  if (reused_) return 0;
  std::size_t n = 0;
  for (const auto& cache : searched_storeys(*caches_, result_)) n += cache->bands_searched();
  return n;
}

std::size_t IncrementalAnalysis::area_bands_total() const {
  std::size_t n = 0;
  for (const auto& cache : searched_storeys(*caches_, result_)) n += cache->bands_total();
  return n;
}

}  // namespace roomsense
