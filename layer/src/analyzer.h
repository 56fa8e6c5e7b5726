// One XrRoomAnalyzerEXTX: the meshes submitted to it, its compute state, the latest completed result, and
// the worker thread that runs its computes one after another (the runtime query, then the core pipeline),
// started at the first compute and kept until the analyzer shuts down. Getters never wait for the worker: they
// read the latest result, which the worker swaps in whole.
#pragma once
#include "chunk_feed.h"
#include "chunk_ids.h"
#include "config.h"
#include "results.h"
#include "state.h"
#include "roomsense/incremental.h"

#include <openxr/XR_EXTX_room_understanding.h>

#include <chrono>
#include <memory>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <span>
#include <stop_token>
#include <thread>
#include <vector>

namespace roomsense::layer {

class Analyzer {
 public:
  struct Settings {
    XrSpace base_space = XR_NULL_HANDLE;  // the layer's own copy of the application's baseSpace
    XrReferenceSpaceType base_type = XR_REFERENCE_SPACE_TYPE_LOCAL;
    float voxel_size = 0.1f;
    Backend backend = Backend::Auto;  // already resolved against ROOMSENSE_BACKEND
  };

  Analyzer(std::shared_ptr<SessionState> session, Settings settings);
  ~Analyzer();  // stops and joins the worker; releases no OpenXR handle (see shut_down)
  Analyzer(const Analyzer&) = delete;
  Analyzer& operator=(const Analyzer&) = delete;

  const std::shared_ptr<SessionState>& session() const { return session_; }

  // Both return XR_ERROR_HANDLE_INVALID once the analyzer is shut down. Arguments are already validated.
  XrResult submit(MeshPiece mesh);
  // When the meshes and the runtime's labels are those of the latest result (RoomResult::input_hash), the
  // compute ends COMPLETED without an analysis and keeps that result: an application computing every few
  // frames, and the layer's own periodic analyses (spatial/), then cost the runtime's query and a hash.
  XrResult compute(const XrRoomComputeInfoEXTX& info);

  // Waits until no compute runs or the analyzer shuts down; the state it ends in.
  XrRoomComputeStateEXTX wait();

  XrRoomComputeStateEXTX state();
  std::shared_ptr<const RoomResult> latest();  // null before the first completed compute

  // Stops a running compute, waits for the worker, destroys the layer's base space. Idempotent. Call before
  // the session is destroyed down the chain, and without the registry lock.
  void shut_down();
  // The same without calling down the chain (the base space is left to the session): at exit (~Registry).
  void end() { end_worker(); }

 private:
  struct Job {
    bool include_runtime = false;
    XrTime time = 0;
    std::vector<std::shared_ptr<const MeshPiece>> submitted;
    std::vector<std::shared_ptr<const CapturedMesh>> captured;
    XrSpace capture_space = XR_NULL_HANDLE;
    std::chrono::steady_clock::time_point started;
    std::optional<std::uint64_t> skip_hash;  // the latest result's input_hash
  };
  void run(std::stop_token stop, Job job);
  // Sets shut_ and wakes the worker and wait(); returns the worker to join (none when already shut).
  std::optional<std::jthread> end_worker();
  // The worker: each job compute() leaves in pending_, until the analyzer shuts down.
  void serve(std::stop_token stop);

  std::shared_ptr<SessionState> session_;
  Settings settings_;

  // The worker and wait() block on std::condition_variable, never on a stop token: a wait on one registers a
  // std::stop_callback, whose removal can hang in the MinGW-w64 GCC 12 libstdc++ of the Windows DLL (it waits on
  // an atomic, and that wait can lose its wake-up without a futex). shut_ wakes them instead.
  std::mutex mutex_;  // guards everything below
  std::condition_variable done_;  // notified when a compute ends, and at the shut-down
  std::condition_variable work_;  // notified when compute() leaves a job, and at the shut-down
  std::optional<Job> pending_;    // the compute the worker has yet to take
  bool shut_ = false;             // set by shut_down() and the destructor: the worker ends, wait() returns
  XrRoomComputeStateEXTX state_ = XR_ROOM_COMPUTE_STATE_NONE_EXTX;
  std::vector<std::shared_ptr<const MeshPiece>> submitted_;
  std::shared_ptr<const RoomResult> latest_;
  // The analyses' chunks and each mesh's chunk id, touched only by the worker.
  std::optional<IncrementalAnalysis> incremental_;
  ChunkIds chunk_ids_;
  ChunkFeed feed_;  // what incremental_ was given under each chunk id
  std::unique_ptr<VoxelStage> stage_;  // a Vulkan stage, kept for the next analyses (worker only, as above)
  // One thread for every compute, not one each: starting a thread took some 75 us on this project's VM, half of
  // an unchanged room's compute as an application sees it (bench/README.md).
  std::jthread worker_;
};

// The analyzer behind a handle of the registry (state.h), or null.
std::shared_ptr<Analyzer> find_analyzer(XrRoomAnalyzerEXTX handle);

// Runs the core pipeline on `pieces`, with the runtime's `labels`, with the given settings; the stage note
// (which backend) goes to the log. A stop request ends it with Error(Cancelled) within about 100 ms.
AnalysisResult analyze_pieces(const std::vector<const MeshPiece*>& pieces, const LabelledTriangles& labels,
                              float voxel_size, Backend backend, std::stop_token stop = {});
// The same analysis (with each piece's runtime labels), on the CPU backend through `incremental`, whose chunks
// become the pieces: piece i is chunk ids[i] (ascending: ChunkIds), and a chunk of another id is removed. `feed`
// gives it only the pieces that changed since its last call (chunk_feed.h); the others keep their voxels. Other
// backends analyse whole, on the stage in `kept_stage` where it is still the choice; a stage started here is
// left there for the next call.
AnalysisResult analyze_pieces(IncrementalAnalysis& incremental, ChunkFeed& feed, std::span<const FedPiece> pieces,
                              std::span<const std::uint64_t> ids, float voxel_size, Backend backend,
                              std::unique_ptr<VoxelStage>& kept_stage, std::stop_token stop = {});

}  // namespace roomsense::layer
