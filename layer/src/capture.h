// Passive capture: the scene meshes an application reads through XR_MSFT_scene_understanding are copied
// and placed in the session's capture space (a LOCAL space of the layer's). Analyzers add them with
// includeRuntimeMeshes; with ROOMSENSE_EXPORT_DIR and no extension, the layer analyses them on its own
// (after each scene the application is done with, and when the session ends) and exports the result.
#pragma once
#include "state.h"

#include <memory>

namespace roomsense::layer {

// Wakes the session's export worker (export-only mode), starting it on first use.
void request_export(const std::shared_ptr<SessionState>& session);

// Analyses and exports what was captured since the last export-only analysis, on the calling thread.
void export_captured(SessionState& session);

}  // namespace roomsense::layer
