// One chunk of a runtime's scene as a source serves it, and the chunks a source served at its last query.
// Kept so that the next query need not read again a chunk whose change marker and placement are the same: on a
// headset that refines a few meshes at a time, a query then costs the runtime's listing and the changed meshes,
// not the whole room, and the analysis is given the same chunk, already checked and keyed (issue 19, item 2).
#pragma once
#include "../mesh.h"
#include "roomsense/surface_label.h"

#include <openxr/openxr.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace roomsense::layer {

// One chunk of the runtime's scene: a mesh block, a submesh, a plane.
struct SourceChunk {
  std::string id;            // stable across queries: the source's prefix and the runtime's uuid or buffer id
  std::uint64_t change = 0;  // changes when the content does: lastUpdatedTime, a version, or a content hash
  XrPosef placed{{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};  // what moved the runtime's vertices into `mesh`
  MeshPiece mesh;            // in the base space (active query) or the session's capture space (passive)
  std::vector<SurfaceLabel> labels;  // one per triangle, or empty when the runtime gives none
  std::uint64_t key = 0;     // an active query's: piece_key of the mesh and its labels, set by query()
  // Set, instead of the content, by a source's run_query for a chunk it served before with the same change marker
  // and placement (MeshSource::served_before): query() serves that one, not read from the runtime again.
  std::shared_ptr<const SourceChunk> same_as;
};
using ServedChunk = std::shared_ptr<const SourceChunk>;

class ServedChunks {
 public:
  // The chunk served last as `id` in `session`, when it came with this change marker and placement; else null.
  ServedChunk find(XrSession session, const std::string& id, std::uint64_t change, const XrPosef& placed) const;
  // One query's chunks replace the last one's: a chunk not served again is forgotten, so what is kept is at most
  // one query's chunks, shared with the analysis that reads them.
  void keep(XrSession session, const std::vector<ServedChunk>& served);
  // The session ended: its chunks are not kept past it.
  void forget(XrSession session);

 private:
  mutable std::mutex mutex_;  // the analyzers of a session query from their own threads
  XrSession session_ = XR_NULL_HANDLE;
  std::unordered_map<std::string, ServedChunk> by_id_;
};

}  // namespace roomsense::layer
