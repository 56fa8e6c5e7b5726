// roomsense-demo --spatial-entities: an OpenXR app that knows only the standard spatial-entity API
// (XR_EXT_spatial_entity, XR_EXT_spatial_plane_tracking, XR_EXT_future; not XR_EXTX_room_understanding). It reads
// the planes of a plane-tracking context (and, where the runtime or a layer lists it, the placement areas and the
// room mesh of XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX), prints them with two timings, and writes
// spatial_entities.json. Whatever serves the planes (the runtime itself, or the roomsense layer over its own room
// analysis) is invisible to it, as to any engine reading planes through XR_EXT_spatial_plane_tracking.
#pragma once
#include <filesystem>
#include <string>

namespace roomsense::demo {

// Runs the whole app through the loader (the environment already prepared: demo::prepare_environment), prints
// what it found, and writes `output/spatial_entities.json`. Throws std::runtime_error with one line naming the
// OpenXR function and its XrResult on any failure.
void run_spatial_entities(const std::string& room, const std::filesystem::path& output);

}  // namespace roomsense::demo
