// ROOMSENSE_SIM_SCAN_SECONDS: a user scanning the room. Over that many seconds from the instance's creation the
// room's chunks (cubes of ROOMSENSE_SIM_CHUNK_SIZE, scene_data.h) appear nearest the head first: in the first half
// each appears coarse (every second of its triangles), in the second half each is refined to its whole mesh, in
// the same order. The live-meshing extensions (XR_MSFT_scene_understanding, XR_ANDROID_scene_meshing,
// XR_ML_world_mesh_detection) serve the room as scanned at each query, each chunk's update time the time it last
// changed, as a headset meshing the room while the user looks around does; Quest's captured scene and the plane
// extensions serve the whole room, as a scene captured beforehand. 0 (the default) serves the whole room at once.
#pragma once
#include "room_source.h"
#include "scene_data.h"

#include <openxr/openxr.h>

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace roomsense::sim {

using SharedChunk = std::shared_ptr<const Chunk>;

// The room as scanned at one time: what the live-meshing extensions serve. A chunk shown in several steps is the
// same object in each, so what an extension builds from it can be kept by its address (while it is held).
struct ScanStep {
  std::shared_ptr<const Room> room;    // the whole room: its source, objects and labels
  std::vector<SharedChunk> chunks;     // the chunks shown, each coarse or whole, in the order of their cells
  std::map<ChunkCell, XrTime> changed; // when each chunk shown last changed; empty where the room never changes
  // A chunk's update time: when it last changed, or `otherwise` where the room never changes.
  XrTime update_time(const ChunkCell& cell, XrTime otherwise) const;
};

// The whole room in chunks of `chunk_size`, never changing: split at the first ask, and shared by every instance
// of the room while one holds it.
std::shared_ptr<const ScanStep> whole_room(const std::shared_ptr<const Room>& room, double chunk_size);

// What an extension builds from the room as scanned: a scene per step and a piece per chunk (a submesh, blocks),
// each kept while something else holds the step or the chunk it came from, since a step of a scan changes a chunk
// or two. Not thread-safe: call under the runtime's lock.
template <class Scene, class Piece>
class BuiltPerStep {
 public:
  // The step's scene: the one kept, or make_scene() (the scenes and pieces no one else holds let go first).
  template <class MakeScene>
  std::shared_ptr<const Scene> scene(const std::shared_ptr<const ScanStep>& step, MakeScene make_scene) {
    std::erase_if(scenes_, unheld);
    auto& entry = scenes_[step.get()];
    if (!entry.second) {
      std::erase_if(pieces_, unheld);
      entry = {step, std::make_shared<const Scene>(make_scene())};
    }
    return entry.second;
  }
  // The chunk's piece: the one kept, or make_piece().
  template <class MakePiece>
  const Piece& piece(const SharedChunk& chunk, MakePiece make_piece) {
    auto& entry = pieces_[chunk.get()];
    if (!entry.second) entry = {chunk, std::make_shared<const Piece>(make_piece())};
    return *entry.second;
  }
  void clear() {
    scenes_.clear();
    pieces_.clear();
  }

 private:
  static constexpr auto unheld = [](const auto& entry) { return entry.second.first.use_count() == 1; };
  std::map<const ScanStep*, std::pair<std::shared_ptr<const ScanStep>, std::shared_ptr<const Scene>>> scenes_;
  std::map<const Chunk*, std::pair<SharedChunk, std::shared_ptr<const Piece>>> pieces_;
};

class ScanProgress {
 public:
  // `head`: where the user stands (ROOMSENSE_SIM_HEAD_POSE); `start`: the scan's first moment.
  ScanProgress(std::shared_ptr<const Room> room, double chunk_size, const glm::dvec3& head, double seconds, XrTime start);
  // The room as scanned at `now`: the same object for every time within one step of the scan. Thread-safe.
  std::shared_ptr<const ScanStep> at(XrTime now);
  std::size_t chunks() const { return order_.size(); }
  // Steps are 0 (nothing shown) to 2 * chunks() (every chunk whole): one more at each chunk shown or refined.
  std::size_t step_at(XrTime now) const;

 private:
  std::shared_ptr<const ScanStep> build(std::size_t step) const;

  std::shared_ptr<const ScanStep> whole_room_;
  std::vector<ChunkCell> order_;           // the chunks' cells, nearest the head first
  std::vector<std::size_t> by_cell_;       // ranks in the order of their cells
  std::vector<SharedChunk> coarse_, whole_chunks_;  // per rank
  std::vector<XrTime> shown_, whole_;      // per rank: when the chunk appears coarse, and whole
  std::mutex mutex_;
  std::size_t cached_step_ = 0;
  std::shared_ptr<const ScanStep> cached_;
};

}  // namespace roomsense::sim
