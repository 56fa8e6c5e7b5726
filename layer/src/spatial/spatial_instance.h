// Per instance: which parts of the standard spatial-entity API the layer serves, and where the calls it does not
// answer itself go (a mesh source's hook when it watches the application's calls, else the next layer).
#pragma once
#include "spatial_declarations.h"

// Every XR_EXT_spatial_entity and XR_EXT_future function, one line each: the layer hooks them all when it serves
// any part of the API (spatial_api.cpp), answers for its own handles and passes the rest on.
#define ROOMSENSE_SPATIAL_FUNCTIONS(_)                                                                                  \
  _(xrEnumerateSpatialCapabilitiesEXT) _(xrEnumerateSpatialCapabilityComponentTypesEXT)                                \
  _(xrEnumerateSpatialCapabilityFeaturesEXT) _(xrCreateSpatialContextAsyncEXT) _(xrCreateSpatialContextCompleteEXT)   \
  _(xrDestroySpatialContextEXT) _(xrCreateSpatialDiscoverySnapshotAsyncEXT) _(xrCreateSpatialDiscoverySnapshotCompleteEXT) \
  _(xrQuerySpatialComponentDataEXT) _(xrDestroySpatialSnapshotEXT) _(xrCreateSpatialEntityFromIdEXT)                   \
  _(xrDestroySpatialEntityEXT) _(xrCreateSpatialUpdateSnapshotEXT) _(xrGetSpatialBufferStringEXT)                      \
  _(xrGetSpatialBufferUint8EXT) _(xrGetSpatialBufferUint16EXT) _(xrGetSpatialBufferUint32EXT)                          \
  _(xrGetSpatialBufferFloatEXT) _(xrGetSpatialBufferVector2fEXT) _(xrGetSpatialBufferVector3fEXT)                      \
  _(xrPollFutureEXT) _(xrCancelFutureEXT)

namespace roomsense::layer {

struct SpatialInstance {
  bool planes = false;            // the layer serves XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT: the runtime has none
  // The runtime's conversion of the OS's monotonic clock, when it has the extension (platform::clock_conversion():
  // XR_KHR_convert_timespec_time or XR_KHR_win32_convert_performance_counter_time); platform::xr_time_now calls it.
  PFN_xrVoidFunction convert_time = nullptr;
  struct Forward {
#define ROOMSENSE_FORWARD_MEMBER(name) PFN_##name name = nullptr;
    ROOMSENSE_SPATIAL_FUNCTIONS(ROOMSENSE_FORWARD_MEMBER)
#undef ROOMSENSE_FORWARD_MEMBER
  } forward;  // null where nothing below has the function: what is not the layer's goes there
};

}  // namespace roomsense::layer
