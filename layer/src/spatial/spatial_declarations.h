// The registry's declarations of XR_EXT_future, XR_EXT_spatial_entity and XR_EXT_spatial_plane_tracking
// (roomsense/xr/ext: Debian's headers predate them), then the spatial block of our public header.
#pragma once
#include <openxr/openxr.h>

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <openxr/XR_EXTX_room_understanding.h>
