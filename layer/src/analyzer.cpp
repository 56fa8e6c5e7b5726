#include "analyzer.h"

#include "guard.h"
#include "log.h"
#include "capture.h"
#include "sources/source_support.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_set>
#if ROOMSENSE_HAVE_COMPUTE
#include "roomsense/voxel_stage_choice.h"
#endif

namespace roomsense::layer {
namespace {


// The active query of the first source that delivers, best first; each failure is one line in the log.
std::vector<ServedChunk> query_best_source(const InstanceState& instance, const SessionState& session, XrSpace base,
                                           XrTime time, std::stop_token stop, MeshSources& report) {
  const QueryContext context{instance.handle, session.system, session.handle, base, time};
  std::string skipped;
  for (const EnabledSource& s : instance.sources) {
    if (stop.stop_requested()) return {};
    const auto start = std::chrono::steady_clock::now();
    try {
      MeshSource::Answer answer = s.source->query(context, stop);
      std::vector<ServedChunk>& chunks = answer.chunks;
      if (!chunks.empty()) {
        report.source = s.info->name;
        report.source_reason = skipped.empty() ? "the runtime's best mesh source (" + std::string(s.info->gives) + ")"
                                               : "the best that delivered (" + skipped + ")";
        report.query_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        log_info(std::string("runtime meshes from ") + s.info->name + ": " + std::to_string(chunks.size()) + " chunks (" +
                 std::to_string(answer.read) + " read, the others as served before) in " + std::to_string(report.query_ms) +
                 " ms; " + report.source_reason);
        return chunks;
      }
      skipped += std::string(skipped.empty() ? "" : "; ") + s.info->name + " served nothing";
    } catch (const std::exception& e) {
      log_warn(std::string(s.info->name) + " left out: " + e.what());
      skipped += std::string(skipped.empty() ? "" : "; ") + s.info->name + " failed: " + e.what();
    }
  }
  if (instance.sources.empty())
    log_warn("includeRuntimeMeshes: the runtime has no scene-mesh extension the layer knows, so only meshes read by the "
             "application and submitted ones are analysed");
  report.source_reason = skipped;
  return {};
}

}  // namespace

namespace {

// The voxel stage `backend` asks for on this scan, with its line in the log; null for the CPU stage. A Vulkan
// stage is kept in `kept` for later analyses where the choice stands: one costs 310-370 ms to start on an
// H100 (compute/README.md), more than a room's whole analysis.
VoxelStage* chosen_stage(const VoxelWorkload& workload, Backend backend, std::unique_ptr<VoxelStage>& kept) {
#if ROOMSENSE_HAVE_COMPUTE
  if (kept && (backend == Backend::Vulkan || (backend == Backend::Auto && auto_may_pick_vulkan(workload))))
    return kept.get();
  std::string note;
  std::unique_ptr<VoxelStage> stage = make_voxel_stage(backend, workload, &note);
  if (backend == Backend::Vulkan && stage->name() != "vulkan") log_warn("backend: " + note);
  else log_info("backend: " + note);
  if (stage->name() == CpuVoxelStage().name()) return nullptr;
  kept = std::move(stage);
  return kept.get();
#else
  (void)workload, (void)kept;
  if (backend == Backend::Vulkan) log_warn("backend: this build has no Vulkan backend; cpu used");
  return nullptr;
#endif
}

}  // namespace

AnalysisResult analyze_pieces(const std::vector<const MeshPiece*>& pieces, const LabelledTriangles& labels,
                              float voxel_size, Backend backend, std::stop_token stop) {
  Scan scan = merge(pieces);
  scan.labels = labels;
  AnalysisOptions options;
  options.voxel_size = voxel_size;
  options.stop = std::move(stop);
  std::unique_ptr<VoxelStage> stage;  // one analysis: nothing to keep it for
  options.voxel_stage = chosen_stage(estimate_voxel_workload(scan, voxel_size), backend, stage);
  return analyze(scan, options);
}

AnalysisResult analyze_pieces(IncrementalAnalysis& incremental, ChunkFeed& feed, std::span<const FedPiece> pieces,
                              std::span<const std::uint64_t> ids, float voxel_size, Backend backend,
                              std::unique_ptr<VoxelStage>& kept_stage, std::stop_token stop) {
  if (ids.size() != pieces.size() || !std::is_sorted(ids.begin(), ids.end()))
    throw std::logic_error("analyze_pieces: one ascending chunk id per piece");
  if (VoxelStage* const stage = chosen_stage(feed.workload(pieces, ids, voxel_size), backend, kept_stage)) {
    std::vector<const MeshPiece*> meshes;  // the scan whole
    for (const FedPiece& p : pieces) meshes.push_back(p.mesh);
    Scan merged = merge(meshes);
    for (const FedPiece& p : pieces)
      if (p.labels != nullptr) add_labelled(merged.labels, *p.mesh, *p.labels);
    AnalysisOptions options;
    options.voxel_size = voxel_size;
    options.stop = std::move(stop);
    options.voxel_stage = stage;
    return analyze(merged, options);
  }
  // Piece i is chunk ids[i]: the ids ascend, so the chunks combined in id order are merge() of the pieces, their
  // labels in the same order, and the result is analyze_pieces()'s; a piece unchanged since the last analysis is
  // not given again, and keeps its voxels.
  feed.feed(incremental, pieces, ids);
  incremental.set_stop(std::move(stop));
  const AnalysisResult& result = incremental.result();
  log_debug([&] {
    return std::to_string(feed.fed()) + " of " + std::to_string(pieces.size()) + " meshes changed; " +
           std::to_string(incremental.revoxelized_chunks()) + " voxelized again, the others' voxels kept";
  });
  return result;
}

Analyzer::Analyzer(std::shared_ptr<SessionState> session, Settings settings)
    : session_(std::move(session)), settings_(settings) {}

Analyzer::~Analyzer() {
  end_worker();  // the worker it returns ends here: ~jthread requests stop (a running compute returns) and joins
}

std::optional<std::jthread> Analyzer::end_worker() {
  std::jthread worker;
  {
    std::lock_guard lock(mutex_);
    if (shut_) return std::nullopt;
    shut_ = true;
    worker = std::move(worker_);
  }
  work_.notify_all();
  done_.notify_all();
  return worker;
}

XrResult Analyzer::submit(MeshPiece mesh) {
  auto piece = std::make_shared<const MeshPiece>(std::move(mesh));
  std::lock_guard lock(mutex_);
  if (shut_) return XR_ERROR_HANDLE_INVALID;
  submitted_.push_back(std::move(piece));
  return XR_SUCCESS;
}

XrRoomComputeStateEXTX Analyzer::wait() {
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return shut_ || state_ != XR_ROOM_COMPUTE_STATE_RUNNING_EXTX; });
  return state_;
}

XrResult Analyzer::compute(const XrRoomComputeInfoEXTX& info) {
  Job job;
  job.include_runtime = info.includeRuntimeMeshes != XR_FALSE;
  job.time = info.time;
  job.started = std::chrono::steady_clock::now();
  if (job.include_runtime) {
    std::lock_guard lock(session_->mutex);
    job.captured = session_->captured;
    job.capture_space = session_->capture_space;
  }
  std::lock_guard lock(mutex_);
  if (shut_) return XR_ERROR_HANDLE_INVALID;
  if (state_ == XR_ROOM_COMPUTE_STATE_RUNNING_EXTX) return XR_ERROR_CALL_ORDER_INVALID;
  job.submitted = submitted_;
  if (latest_) job.skip_hash = latest_->input_hash;
  // Started before anything changes: a thread that cannot start leaves the analyzer as it was (the error goes to
  // the application), not RUNNING with no worker. It takes the job once this lock is released.
  if (!worker_.joinable()) worker_ = std::jthread([this](std::stop_token stop) { serve(stop); });
  pending_ = std::move(job);
  state_ = XR_ROOM_COMPUTE_STATE_RUNNING_EXTX;  // the worker publishes under this lock, so only after this
  work_.notify_one();
  return XR_SUCCESS;
}

void Analyzer::serve(std::stop_token stop) {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      work_.wait(lock, [&] { return shut_ || pending_.has_value(); });
      if (shut_) return;
      job = std::move(*pending_);
      pending_.reset();
    }
    run(stop, std::move(job));
  }
}

XrRoomComputeStateEXTX Analyzer::state() {
  std::lock_guard lock(mutex_);
  return state_;
}

std::shared_ptr<const RoomResult> Analyzer::latest() {
  std::lock_guard lock(mutex_);
  return latest_;
}

void Analyzer::shut_down() {
  std::optional<std::jthread> worker = end_worker();
  if (!worker) return;
  worker.reset();  // requests stop and joins
  if (settings_.base_space != XR_NULL_HANDLE) {
    session_->instance->next.xrDestroySpace(settings_.base_space);
    settings_.base_space = XR_NULL_HANDLE;
  }
}

void Analyzer::run(std::stop_token stop, Job job) {
  const InstanceState& instance = *session_->instance;
  MeshSources sources;
  sources.base_space = space_name(settings_.base_type);
  std::shared_ptr<RoomResult> result;
  std::string problem;
  try {
    std::vector<ServedChunk> runtime;
    std::vector<MeshPiece> app_read;
    std::vector<std::string> app_read_ids;  // the source's id of each
    if (job.include_runtime) {
      runtime = query_best_source(instance, *session_, settings_.base_space, job.time, stop, sources);
      if (stop.stop_requested()) return;
      // The application's reads of one extension only (captures_of_best_source); of the source the layer
      // queried, only what that query did not serve too.
      const auto captured = captures_of_best_source(job.captured);
      const bool same_source = !captured.empty() && captured.front()->source->name == sources.source;
      if (!captured.empty() && !runtime.empty() && !same_source) {
        log_debug([&] { return std::to_string(captured.size()) + " mesh(es) the application read through " +
                               captured.front()->source->name + " left out: " + sources.source + " served the same room"; });
      } else if (!captured.empty()) {
        std::unordered_set<std::uint64_t> hashes;
        std::unordered_set<std::string> ids;
        for (const ServedChunk& m : runtime) hashes.insert(content_hash(m->mesh)), ids.insert(m->id);
        auto where = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
        const XrResult result = instance.next.xrLocateSpace(job.capture_space, settings_.base_space, job.time, &where);
        if (XR_FAILED(result) || !located(where.locationFlags)) {
          log_warn("the scene meshes the application read cannot be located in the base space; left out");
        } else {
          const Rigid capture_to_base = to_rigid(where.pose);
          for (const auto& c : captured) {
            if (ids.count(c->chunk.id) > 0) continue;
            MeshPiece piece = c->chunk.mesh;
            transform_in_place(piece.vertices, capture_to_base);
            if (hashes.count(content_hash(piece)) > 0) continue;
            app_read.push_back(std::move(piece));
            app_read_ids.push_back(c->chunk.id);
          }
          if (sources.source.empty() && !app_read.empty()) sources.source = captured.front()->source->name;
        }
      }
    }
    // Each piece's chunk (ChunkIds), by the source's id of a runtime or application-read mesh and by the order of
    // submission of a submitted one; the pieces are analysed in chunk order.
    std::vector<std::string> keys;
    std::vector<const MeshPiece*> listed;  // as `keys`
    for (const ServedChunk& m : runtime) keys.push_back("runtime:" + m->id), listed.push_back(&m->mesh);
    for (std::size_t i = 0; i < app_read.size(); ++i) keys.push_back("read:" + app_read_ids[i]), listed.push_back(&app_read[i]);
    for (std::size_t i = 0; i < job.submitted.size(); ++i)
      keys.push_back("submitted:" + std::to_string(i)), listed.push_back(job.submitted[i].get());
    const std::vector<std::uint64_t> chunk_of = chunk_ids_.assign(keys);
    std::vector<std::size_t> order(keys.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return chunk_of[a] < chunk_of[b]; });
    // Each piece with the runtime's labels of its triangles, where its source gives any, and its key.
    std::vector<FedPiece> pieces;
    std::vector<std::uint64_t> ids;
    for (const std::size_t i : order) {
      if (i < runtime.size()) {  // keyed when it was served (checked_chunks)
        pieces.push_back({listed[i], runtime[i]->labels.empty() ? nullptr : &runtime[i]->labels, runtime[i]->key});
      } else {
        pieces.push_back({listed[i], nullptr, piece_key(*listed[i], nullptr)});
      }
      ids.push_back(chunk_of[i]);
    }
    sources.runtime_meshes = runtime.size();
    sources.app_read_meshes = app_read.size();
    sources.submitted_meshes = job.submitted.size();
    if (pieces.empty())
      throw std::runtime_error(job.include_runtime ? "no meshes to analyse: the runtime served none and none were submitted"
                                                   : "no meshes to analyse: none were submitted");
    // FNV-1a over the pieces' keys (their content and the runtime's labels), in the order the analysis reads them.
    std::uint64_t input_hash = 0xcbf29ce484222325ull;
    for (const FedPiece& piece : pieces) input_hash = (input_hash ^ piece.key) * 0x100000001b3ull;
    if (job.skip_hash == input_hash) {
      log_debug([] { return std::string("the meshes and labels are unchanged: the latest result stands"); });
      std::lock_guard lock(mutex_);
      state_ = XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX;
      done_.notify_all();
      return;
    }
    if (!incremental_) {
      AnalysisOptions options;
      options.voxel_size = settings_.voxel_size;
      incremental_.emplace(options);
    }
    const auto analysis = std::make_shared<const AnalysisResult>(
        analyze_pieces(*incremental_, feed_, pieces, ids, settings_.voxel_size, settings_.backend, stage_, stop));
    if (!analysis->ok()) throw std::runtime_error(analysis->status_message);
    if (stop.stop_requested()) return;
    const auto elapsed = std::chrono::steady_clock::now() - job.started;
    result = std::make_shared<RoomResult>(
        make_room_result(analysis, sources, std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count()));
    result->input_hash = input_hash;
    log_info("analysis completed: " + std::to_string(sources.runtime_meshes) + " runtime, " +
             std::to_string(sources.app_read_meshes) + " app-read and " + std::to_string(sources.submitted_meshes) +
             " submitted meshes; " + std::to_string(analysis->areas.size()) + " areas; pipeline " +
             std::to_string(analysis->timings.total) + " ms, compute " + std::to_string(double(result->duration) / 1e6) + " ms");
    if (!instance.config.export_dir.empty()) export_files(instance.config.export_dir, *result, analysis->bounds);
  } catch (const std::exception& e) {
    if (stop.stop_requested()) return;  // the analyzer is being destroyed: nothing failed
    problem = e.what();
  }
  if (!result) log_warn("room analysis failed: " + problem);
  std::lock_guard lock(mutex_);
  if (result) latest_ = std::move(result);
  state_ = latest_ && problem.empty() ? XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX : XR_ROOM_COMPUTE_STATE_FAILED_EXTX;
  done_.notify_all();
}

}  // namespace roomsense::layer
