/* A program from outside the roomsense tree, built against the installed roomsense-dev package twice:
 * with find_package(roomsense) (CMakeLists.txt here) and with pkg-config (scripts/package.sh). It uses
 * both C APIs on the C box room and checks what they find, so a wrong header, library or link fails. */
#include <roomsense/RoomCreatorLibrary.h>
#include <roomsense/roomsense.h>

#include <math.h>
#include <stdio.h>

#include "../capi/box_room.h"

static int fail(const char* what) {
  fprintf(stderr, "consumer: FAILED: %s\n", what);
  return 1;
}

int main(void) {
  int n = 0, code = -1, size = 0;
  float* room = box_room(&n, 1);
  rs_analyzer* a = NULL;
  rs_state state = RS_STATE_IDLE;
  rs_layout layout;
  const uint32_t version = rs_api_version();

  if (version >> 22 != RS_API_VERSION >> 22) return fail("the library's major version differs from the header's");
  if (rs_analyzer_create(NULL, &a) != RS_SUCCESS) return fail("rs_analyzer_create");
  if (rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0) != RS_SUCCESS) return fail("rs_analyzer_compute");
  if (rs_analyzer_wait(a, RS_WAIT_INFINITE, &state) != RS_SUCCESS || state != RS_STATE_READY)
    return fail("the analysis did not succeed");
  if (rs_analyzer_get_layout(a, &layout) != RS_SUCCESS) return fail("rs_analyzer_get_layout");
  if (fabsf(layout.floor_y - BOX_FLOOR) > 0.1f || fabsf(layout.ceiling_y - BOX_CEILING) > 0.1f || layout.area_count == 0)
    return fail("wrong floor, ceiling or no areas");
  rs_analyzer_destroy(a);

  /* The thesis API: start, poll, retrieve, clean up. */
  if (StartRoomUnderstanding(room, 3 * n) != 0) return fail("StartRoomUnderstanding");
  do {
    (void)RetrieveRoomUnderstanding(&code, &size);
  } while (code == -1);
  if (code != 0 || size <= 0 || size % 11 != 0) return fail("RetrieveRoomUnderstanding");
  CleanUpRoomUnderstanding();

  printf("consumer: roomsense C API %u.%u.%u, floor %.2f m, ceiling %.2f m, %u areas (handle API), %d (thesis API)\n",
         (unsigned)(version >> 22), (unsigned)((version >> 12) & 0x3FF), (unsigned)(version & 0xFFF),
         (double)layout.floor_y, (double)layout.ceiling_y, (unsigned)layout.area_count, size / 11);
  free(room);
  return 0;
}
