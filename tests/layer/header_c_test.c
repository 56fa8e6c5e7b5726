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
  (void)get_areas;
  printf("XR_EXTX_room_understanding.h: C ok, %u-byte XrRoomAreaEXTX\n", (unsigned)sizeof area);
  return 0;
}
