#include "capture.h"

#include "analyzer.h"
#include "guard.h"
#include "log.h"
#include "results.h"
#include "sources/source_support.h"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace roomsense::layer {

XrSpace capture_space(SessionState& session) {
  std::lock_guard lock(session.mutex);
  if (session.capture_space == XR_NULL_HANDLE && !session.capture_space_failed) {
    auto info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    info.poseInReferenceSpace.orientation.w = 1.0f;
    const XrResult r = session.instance->next.xrCreateReferenceSpace(session.handle, &info, &session.capture_space);
    if (XR_FAILED(r)) {
      session.capture_space = XR_NULL_HANDLE;
      session.capture_space_failed = true;
      log_warn("cannot create a LOCAL space for capturing scene meshes (" + xr::result_name(r) + ")");
    }
  }
  return session.capture_space;
}

std::optional<Rigid> locate_in_capture_space(SessionState& session, XrSpace space, XrTime time) {
  const XrSpace capture = capture_space(session);
  if (capture == XR_NULL_HANDLE) return std::nullopt;
  auto where = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
  if (XR_FAILED(session.instance->next.xrLocateSpace(space, capture, time, &where)) || !located(where.locationFlags))
    return std::nullopt;
  return to_rigid(where.pose);
}

void keep_capture(SessionState& session, const SourceInfo& source, SourceChunk chunk, std::uint64_t group,
                  std::uint64_t epoch) {
  const MeshPiece& m = chunk.mesh;
  chunk.mesh.indices.resize(chunk.mesh.indices.size() / 3 * 3);
  for (std::uint32_t i : m.indices)
    if (i >= m.vertices.size()) return;  // the runtime's business; nothing we can analyse
  auto mesh = std::make_shared<CapturedMesh>();
  mesh->source = &source;
  mesh->hash = content_hash(m);
  mesh->group = group;
  mesh->epoch = epoch;
  mesh->chunk = std::move(chunk);

  std::lock_guard lock(session.mutex);
  auto& kept = session.captured;
  const auto same_group = [&](const CapturedMesh& k) { return group != 0 && k.source == &source && k.group == group; };
  for (const auto& k : kept)
    if (same_group(*k) && k->epoch > epoch) return;
  std::erase_if(kept, [&](const std::shared_ptr<const CapturedMesh>& k) {
    return (same_group(*k) && k->epoch < epoch) ||
           (k->source == &source && (k->chunk.id == mesh->chunk.id || k->hash == mesh->hash));
  });
  kept.push_back(std::move(mesh));
  ++session.capture_generation;
  log_debug([&] { return std::string("captured a scene mesh the application read through ") + source.name + " (" +
                         std::to_string(kept.size()) + " kept)"; });
}

std::vector<std::shared_ptr<const CapturedMesh>> captures_of_best_source(
    const std::vector<std::shared_ptr<const CapturedMesh>>& captured) {
  for (const SourceInfo* info : mesh_sources()) {
    std::vector<std::shared_ptr<const CapturedMesh>> mine;
    for (const auto& c : captured)
      if (c->source == info) mine.push_back(c);
    if (!mine.empty()) {
      if (mine.size() < captured.size())
        log_debug([&] { return std::to_string(captured.size() - mine.size()) + " captured mesh(es) read through other "
                               "extensions left out: " + info->name + " has the same surfaces"; });
      return mine;
    }
  }
  return {};
}

void capture_read_done(const std::shared_ptr<SessionState>& session) {
  if (session->instance->extx || session->instance->config.export_dir.empty()) return;
  bool changed;
  {
    std::lock_guard lock(session->mutex);
    changed = session->capture_generation != session->exported_generation;
  }
  if (changed) request_export(session);
}

// ---- export-only analyses

void export_captured(SessionState& session, std::stop_token stop) {
  std::vector<std::shared_ptr<const CapturedMesh>> captured;
  std::uint64_t generation;
  {
    std::lock_guard lock(session.mutex);
    if (session.capture_generation == session.exported_generation) return;
    captured = session.captured;
    generation = session.capture_generation;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    std::vector<const MeshPiece*> pieces;
    LabelledTriangles labels;
    for (const auto& c : captures_of_best_source(captured)) {
      pieces.push_back(&c->chunk.mesh);
      add_labelled(labels, c->chunk.mesh, c->chunk.labels);
    }
    const auto analysis = std::make_shared<const AnalysisResult>(
        analyze_pieces(pieces, labels, kDefaultVoxelSize, session.instance->config.env_backend, stop));
    if (!analysis->ok()) {
      log_warn("export: the scene meshes the application read hold no room yet: " + analysis->status_message);
    } else {
      MeshSources sources;
      sources.base_space = "LOCAL";
      sources.app_read_meshes = pieces.size();
      const auto elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
      const RoomResult result = make_room_result(analysis, sources, elapsed.count());
      export_files(session.instance->config.export_dir, result, analysis->bounds);
    }
  } catch (const std::exception& e) {
    if (stop.stop_requested()) return;  // cancelled, not exported: the session's end exports it
    log_warn(std::string("export: analysis of the captured scene meshes failed: ") + e.what());
  }
  std::lock_guard lock(session.mutex);
  session.exported_generation = generation;
}

void request_export(const std::shared_ptr<SessionState>& session) {
  std::lock_guard lock(session->mutex);
  if (session->export_ending) return;  // the session's shut-down exports what is left
  session->export_pending = true;
  if (!session->export_worker.joinable()) {
    SessionState* s = session.get();  // the session outlives the worker: shut_down_session joins it
    session->export_worker = std::jthread([s](std::stop_token stop) {
      for (;;) {
        {
          std::unique_lock lock(s->mutex);
          s->export_wake.wait(lock, [s] { return s->export_ending || s->export_pending; });
          if (s->export_ending) return;
          s->export_pending = false;
        }
        export_captured(*s, stop);
      }
    });
  }
  session->export_wake.notify_all();
}

}  // namespace roomsense::layer
