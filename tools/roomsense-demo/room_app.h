// The demo's OpenXR application: an instance with XR_EXTX_room_understanding and XR_MND_headless (the layer
// enables the runtime's scene extensions itself), a headless session running its frame loop, and one analysis
// of the runtime's scene meshes through the layer. Everything goes through the Khronos loader.
#pragma once
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <string>
#include <vector>

namespace roomsense::demo {

struct RoomReport {
  std::string runtime_name;
  std::string layer_library;  // the layer the loader loaded into this process
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  std::vector<XrRoomAreaEXTX> areas;
  std::vector<XrVector3f> bounds_vertices;
  std::vector<uint32_t> bounds_indices;
  XrRoomPlacementQueryEXTX placement_query{XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX, nullptr};  // the one query the demo asks
  std::vector<XrRoomPlacementEXTX> placements;
  XrRoomPlacementShortfallEXTX placement_shortfall = XR_ROOM_PLACEMENT_SHORTFALL_NONE_EXTX;
  std::string json;  // the analysis as the layer reports it (roomsense.analysis/1)
  int frames = 0;    // frames the app ran while the analysis was computed
};

// Throws std::runtime_error naming the call and its result on any failure.
RoomReport analyse_room_through_openxr();

}  // namespace roomsense::demo
