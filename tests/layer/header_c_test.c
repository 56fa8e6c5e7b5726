/* The public header compiles as C (C11, -Wall -Wextra -Wpedantic) and its values are what it documents. */
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <stdio.h>
#include <string.h>

int main(void) {
  XrRoomAnalyzerCreateInfoEXTX create = {XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, NULL, XR_NULL_HANDLE, 0.0f,
                                         XR_ROOM_COMPUTE_BACKEND_AUTO_EXTX};
  XrRoomAreaEXTX area;
  PFN_xrGetRoomAreasEXTX get_areas = NULL;
  memset(&area, 0, sizeof area);
  area.type = XR_TYPE_ROOM_AREA_EXTX;
  if ((long)create.type != 1099999000L || (long)XR_TYPE_ROOM_ANALYSIS_JSON_EXTX != 1099999006L) return 1;
  if (strcmp(XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, "XR_EXTX_room_understanding") != 0) return 1;
  if (XR_ROOM_AREA_TYPE_FURNITURE_EXTX != 4 || XR_ROOM_INTERACTION_NONE_EXTX != 3 || XR_ROOM_COMPUTE_STATE_FAILED_EXTX != 3)
    return 1;
  {
    /* Spec version 2: the queries' structures and values. */
    XrRoomPlacementQueryEXTX query;
    XrRoomPlacementsEXTX placements = {XR_TYPE_ROOM_PLACEMENTS_EXTX, NULL, 0, 0, NULL, XR_ROOM_PLACEMENT_SHORTFALL_NONE_EXTX};
    PFN_xrFindRoomPlacementsEXTX place = NULL;
    PFN_xrRaycastRoomEXTX raycast = NULL;
    PFN_xrGetRoomRandomPointEXTX random_point = NULL;
    PFN_xrLocateRoomPointEXTX locate = NULL;
    memset(&query, 0, sizeof query);
    query.type = XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX;
    query.surfaces = XR_ROOM_SURFACE_WALL_BIT_EXTX | XR_ROOM_SURFACE_FURNITURE_BIT_EXTX;
    if (query.surfaces != 9 || (long)query.type != 1099999009L ||
        (long)XR_TYPE_ROOM_POINT_LOCATION_EXTX != 1099999016L || XR_ROOM_PLACEMENT_SHORTFALL_TOO_FEW_EXTX != 5 ||
        XR_ROOM_REACH_FILTER_DISTANCE_EXTX != 2 || placements.placementCapacityInput != 0)
      return 1;
    (void)place, (void)raycast, (void)random_point, (void)locate;
  }
  {
    /* Spec version 3: storeys and rooms. */
    XrRoomStoreyEXTX storeys[2];
    XrRoomInfoEXTX rooms[4];
    XrRoomHomeLayoutEXTX home = {XR_TYPE_ROOM_HOME_LAYOUT_EXTX, NULL, 2, 0, storeys, 4, 0, rooms};
    XrRoomAreaLocationEXTX location = {XR_TYPE_ROOM_AREA_LOCATION_EXTX, NULL, 0, XR_ROOM_INDEX_NONE_EXTX};
    area.next = &location;
    if (XR_EXTX_room_understanding_SPEC_VERSION != 3 || (long)home.type != 1099999017L ||
        (long)location.type != 1099999018L || location.roomIndex != 0xFFFFFFFFu || home.rooms != rooms)
      return 1;
  }
  (void)get_areas;
  printf("XR_EXTX_room_understanding.h: C ok, %u-byte XrRoomAreaEXTX\n", (unsigned)sizeof area);
  return 0;
}
