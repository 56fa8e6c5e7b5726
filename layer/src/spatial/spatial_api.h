// What the rest of the layer needs of the spatial-entity API it serves (spatial_api.cpp).
#pragma once
#include <openxr/openxr.h>

#include <string_view>

namespace roomsense::layer {

// The layer's implementation of an XR_EXT_spatial_entity or XR_EXT_future function, or null.
PFN_xrVoidFunction spatial_hook(std::string_view name);

// A discovery recommended to one of the layer's contexts of `instance` since the last time (one per
// published analysis and context): true with `event` filled in (its next kept).
bool next_spatial_event(XrInstance instance, XrEventDataBuffer& event);

// The session is going away: its contexts, snapshots, entities and futures go with it. Without locks held.
void forget_spatial_session(XrSession session);

}  // namespace roomsense::layer
