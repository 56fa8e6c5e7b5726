// Passive capture, for every source: the scene meshes an application reads are copied and kept in the
// session's capture space (a LOCAL space of the layer's). Analyzers add them with includeRuntimeMeshes; with
// ROOMSENSE_EXPORT_DIR and no extension, the layer analyses them on its own (whenever the application is done
// reading, and when the session ends) and exports the result.
#pragma once
#include "state.h"

#include <memory>
#include <optional>

namespace roomsense::layer {

// The session's capture space, created on first use; XR_NULL_HANDLE when the runtime refuses one.
XrSpace capture_space(SessionState& session);

// Where `space` is in the session's capture space at `time` (created on first use); nothing when either cannot
// be located. The pose that moves what an application read in `space` into the capture space.
std::optional<Rigid> locate_in_capture_space(SessionState& session, XrSpace space, XrTime time);

// Keeps a chunk the application read (in the capture space). It replaces a kept chunk of the same source with
// the same id or content, and every chunk of an earlier epoch of the same group; a chunk of an earlier epoch
// than one kept is dropped (an old scene read late).
void keep_capture(SessionState& session, const SourceInfo& source, SourceChunk chunk, std::uint64_t group = 0,
                  std::uint64_t epoch = 0);

// The captures of one source only: the best (first in mesh_sources()) that has any. The same surfaces read
// through two extensions would otherwise count twice.
std::vector<std::shared_ptr<const CapturedMesh>> captures_of_best_source(
    const std::vector<std::shared_ptr<const CapturedMesh>>& captured);

// The application is done reading for now (e.g. it destroyed a scene or a snapshot): in export-only mode,
// analyse and export what changed.
void capture_read_done(const std::shared_ptr<SessionState>& session);

// Wakes the session's export worker (export-only mode), starting it on first use.
void request_export(const std::shared_ptr<SessionState>& session);

// Analyses and exports what was captured since the last export-only analysis, on the calling thread.
// A stop request abandons the analysis (the export worker's shutdown).
void export_captured(SessionState& session, std::stop_token stop = {});

}  // namespace roomsense::layer
