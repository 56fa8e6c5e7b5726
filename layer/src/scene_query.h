// The layer's own scene query (active capture): an observer, a new scene of visual meshes (collider meshes
// when the runtime has no visual ones) around the base space's origin, every mesh read and located in
// the base space. Runs on an analyzer's worker thread; gives up when `stop` is requested.
#pragma once
#include "functions.h"
#include "mesh.h"

#include <cstdint>
#include <stop_token>
#include <vector>

namespace roomsense::layer {

struct RuntimeMesh {
  MeshPiece mesh;  // in the base space
  XrUuidMSFT component{};
  std::uint64_t hash = 0;  // content_hash of the buffers as served
};

inline constexpr float kQueryRadius = 100.0f;  // metres around the base space's origin: any room

// Throws std::runtime_error with one readable line when the runtime does not deliver.
// Returns empty when `stop` was requested.
std::vector<RuntimeMesh> query_runtime_meshes(const NextDispatch& next, XrInstance instance, XrSystemId system,
                                              XrSession session, XrSpace base, XrTime time, std::stop_token stop);

}  // namespace roomsense::layer
