/* The C APIs of libRoomCreatorLibrary.so from plain C11, linked against nothing else.
 * The thesis API is used the way a Unity script uses it (thesis §3.8.1): start, poll once per "frame"
 * until the code is not -1, copy the floats out, clean up. The handle API is checked for its two-call
 * idiom, its argument checks, destroying an analyzer while it computes, and its placement queries.
 * Usage: capi_c_test CASE (one ctest per case; see main). */
#define _POSIX_C_SOURCE 199309L
#include "roomsense/RoomCreatorLibrary.h"
#include "roomsense/roomsense.h"

#include "box_room.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int failures = 0;

#define CHECK(cond)                                                       \
  do {                                                                    \
    if (!(cond)) {                                                        \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                         \
    }                                                                     \
  } while (0)
#define CHECK_MSG(cond, ...)                                              \
  do {                                                                    \
    if (!(cond)) {                                                        \
      fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                       \
      fputc('\n', stderr);                                                \
      ++failures;                                                         \
    }                                                                     \
  } while (0)
#define CHECK_RS(expr, expected)                                                                     \
  do {                                                                                               \
    const rs_result r_ = (expr);                                                                     \
    if (r_ != (expected)) {                                                                          \
      fprintf(stderr, "%s:%d: %s returned %s, expected %s\n", __FILE__, __LINE__, #expr,           \
              rs_result_string(r_), rs_result_string(expected));                                     \
      ++failures;                                                                                    \
    }                                                                                                \
  } while (0)

static const double kTimeoutSeconds = 120.0; /* generous: sanitizers and a shared 2-core machine */

static double now_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void sleep_frame(void) { /* about one 90 Hz frame */
  const struct timespec t = {0, 11 * 1000 * 1000};
  nanosleep(&t, NULL);
}

static int popcount(unsigned v) {
  int n = 0;
  for (; v; v &= v - 1) ++n;
  return n;
}

static float length3(float x, float y, float z) { return sqrtf(x * x + y * y + z * z); }

/* ---------------------------------------------------------------------------------------------------- */
/* Thesis API                                                                                             */

typedef float* (*retrieve_fn)(int*, int*, int*);

static float* retrieve_understanding3(int* code, int* size, int* unused) {
  (void)unused;
  return RetrieveRoomUnderstanding(code, size);
}

/* Polls like an engine's update loop until the code is not -1. */
static float* poll(retrieve_fn retrieve, int* code, int* a, int* b) {
  const double start = now_seconds();
  float* data;
  for (;;) {
    data = retrieve(code, a, b);
    if (*code != -1) return data;
    if (now_seconds() - start > kTimeoutSeconds) {
      fprintf(stderr, "timed out after %.0f s waiting for a result\n", kTimeoutSeconds);
      ++failures;
      return NULL;
    }
    sleep_frame();
  }
}

/* Counts per type bit: [0] walls, [1] floors, [2] furniture, [3] ceilings. */
static void check_thesis_areas(const float* f, int size, int counts[4]) {
  int i;
  const float tol = 0.1f; /* one voxel */
  memset(counts, 0, 4 * sizeof(int));
  for (i = 0; i + 11 <= size; i += 11) {
    const float* a = f + i;
    const float cx = a[0], cy = a[1], cz = a[2], nx = a[3], ny = a[4], nz = a[5];
    const unsigned flags = (unsigned)a[10];
    const int k = i / 11;
    CHECK_MSG((float)flags == a[10], "area %d: flags %g not an integer", k, (double)a[10]);
    CHECK_MSG((flags & ~1023u) == 0, "area %d: flags %u", k, flags);
    CHECK_MSG(popcount(flags & (1 | 2 | 4)) == 1, "area %d: flags %u: size group", k, flags);
    CHECK_MSG(popcount(flags & (8 | 16 | 32)) == 1, "area %d: flags %u: interaction group", k, flags);
    CHECK_MSG(popcount(flags & (64 | 128 | 256 | 512)) == 1, "area %d: flags %u: type group", k, flags);
    CHECK_MSG(fabsf(length3(nx, ny, nz) - 1.0f) < 1e-4f, "area %d: normal length %g", k,
              (double)length3(nx, ny, nz));
    CHECK_MSG(a[6] > 0.0f && a[7] > 0.0f && a[9] > 0.0f, "area %d: height %g width %g volume %g", k, (double)a[6],
              (double)a[7], (double)a[9]);
    CHECK_MSG(fabsf(cx - BOX_CX) <= BOX_HALF_X + tol && fabsf(cz - BOX_CZ) <= BOX_HALF_Z + tol &&
                  cy >= BOX_FLOOR - tol && cy <= BOX_CEILING + tol,
              "area %d: centre (%g, %g, %g) outside the room", k, (double)cx, (double)cy, (double)cz);
    if (flags & 64) { /* wall: horizontal normal into the room, centre on a wall plane */
      const float to_centre_x = BOX_CX - cx, to_centre_z = BOX_CZ - cz;
      const float dx = BOX_HALF_X - fabsf(cx - BOX_CX), dz = BOX_HALF_Z - fabsf(cz - BOX_CZ);
      ++counts[0];
      CHECK_MSG(fabsf(ny) < 1e-4f, "wall %d: normal y %g", k, (double)ny);
      CHECK_MSG(nx * to_centre_x + nz * to_centre_z > 0.0f, "wall %d at (%g, %g, %g): normal (%g, %g, %g) points out",
                k, (double)cx, (double)cy, (double)cz, (double)nx, (double)ny, (double)nz);
      CHECK_MSG(fminf(fabsf(dx), fabsf(dz)) <= 1.5f * tol, "wall %d: centre (%g, %g) off the walls", k, (double)cx,
                (double)cz);
      CHECK_MSG(a[8] == 0.0f, "wall %d: rotation %g", k, (double)a[8]);
    } else if (flags & 128) { /* floor */
      ++counts[1];
      CHECK_MSG(nx == 0.0f && ny == 1.0f && nz == 0.0f, "floor %d: normal (%g, %g, %g)", k, (double)nx, (double)ny,
                (double)nz);
      CHECK_MSG(fabsf(cy - BOX_FLOOR) <= tol, "floor %d: centre y %g, floor %g", k, (double)cy, (double)BOX_FLOOR);
      CHECK_MSG(!(fabsf(cx - TABLE_CX) < TABLE_HALF_X && fabsf(cz - TABLE_CZ) < TABLE_HALF_Z),
                "floor %d centred at (%g, %g), under the table", k, (double)cx, (double)cz);
    } else if (flags & 256) { /* furniture: the table top */
      ++counts[2];
      CHECK_MSG(nx == 0.0f && ny == 1.0f && nz == 0.0f, "furniture %d: normal (%g, %g, %g)", k, (double)nx,
                (double)ny, (double)nz);
      CHECK_MSG(fabsf(cy - (BOX_FLOOR + TABLE_HEIGHT)) <= tol, "furniture %d: centre y %g", k, (double)cy);
      CHECK_MSG(fabsf(cx - TABLE_CX) <= TABLE_HALF_X && fabsf(cz - TABLE_CZ) <= TABLE_HALF_Z,
                "furniture %d: centre (%g, %g) off the table", k, (double)cx, (double)cz);
    } else if (flags & 512) { /* ceiling */
      ++counts[3];
      CHECK_MSG(nx == 0.0f && ny == -1.0f && nz == 0.0f, "ceiling %d: normal (%g, %g, %g)", k, (double)nx,
                (double)ny, (double)nz);
      CHECK_MSG(fabsf(cy - BOX_CEILING) <= tol, "ceiling %d: centre y %g", k, (double)cy);
    }
  }
}

static int test_thesis_understanding(void) {
  int n, code = 99, size = -5, counts[4];
  float* room = box_room(&n, 1);
  float* areas;
  float* copy;
  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
  free(room); /* the library copied it */
  areas = poll(retrieve_understanding3, &code, &size, NULL);
  CHECK_MSG(code == 0, "code %d", code);
  CHECK(areas != NULL);
  CHECK_MSG(size > 0 && size % 11 == 0, "size %d", size);
  if (code != 0 || areas == NULL || size <= 0) {
    CleanUpRoomUnderstanding();
    return failures;
  }
  /* What a Unity script does: Marshal.Copy into its own array. */
  copy = (float*)malloc((size_t)size * sizeof(float));
  memcpy(copy, areas, (size_t)size * sizeof(float));
  check_thesis_areas(copy, size, counts);
  printf("%d areas: %d walls, %d floors, %d furniture, %d ceilings\n", size / 11, counts[0], counts[1], counts[2],
         counts[3]);
  CHECK(counts[0] > 0 && counts[1] > 0 && counts[2] > 0 && counts[3] > 0);
  {
    /* Retrieve again before CleanUp: the same array. */
    int code2 = 99, size2 = 0;
    float* again = RetrieveRoomUnderstanding(&code2, &size2);
    CHECK(code2 == 0 && size2 == size && again == areas);
    CHECK(memcmp(again, copy, (size_t)size * sizeof(float)) == 0);
  }
  CHECK(CleanUpRoomUnderstanding() == 0);
  {
    int code3 = 99, size3 = 99;
    CHECK(RetrieveRoomUnderstanding(&code3, &size3) == NULL);
    CHECK(code3 == 1 && size3 == 0);
  }
  free(copy);
  return failures;
}

/* Directed edges as (from << 32 | to), sorted: a closed, consistently wound mesh has each directed edge
 * once and its reverse once. */
static int compare_u64(const void* a, const void* b) {
  const uint64_t x = *(const uint64_t*)a, y = *(const uint64_t*)b;
  return x < y ? -1 : x > y ? 1 : 0;
}

static void check_closed_mesh(const float* xyz, unsigned vertices, const uint32_t* indices, unsigned index_count) {
  uint64_t* edges = (uint64_t*)malloc((index_count + 1) * sizeof(uint64_t));
  unsigned t, e, duplicates = 0, unmatched = 0, degenerate = 0;
  double volume = 0.0;
  for (t = 0; t + 3 <= index_count; t += 3) {
    int c;
    for (c = 0; c < 3; ++c) {
      const uint32_t a = indices[t + c], b = indices[t + (c + 1) % 3];
      edges[t + c] = ((uint64_t)a << 32) | b;
      if (a == b) ++degenerate;
    }
    {
      /* Signed volume of the tetrahedron (origin, v0, v1, v2), in the numbers' own (right-handed) reading. */
      const float* p = xyz + 3 * indices[t];
      const float* q = xyz + 3 * indices[t + 1];
      const float* r = xyz + 3 * indices[t + 2];
      volume += ((double)p[0] * ((double)q[1] * r[2] - (double)q[2] * r[1]) -
                 (double)p[1] * ((double)q[0] * r[2] - (double)q[2] * r[0]) +
                 (double)p[2] * ((double)q[0] * r[1] - (double)q[1] * r[0])) /
                6.0;
    }
  }
  qsort(edges, index_count, sizeof(uint64_t), compare_u64);
  for (e = 0; e < index_count; ++e) {
    const uint64_t reverse = (edges[e] << 32) | (edges[e] >> 32);
    if (e > 0 && edges[e] == edges[e - 1]) ++duplicates;
    if (!bsearch(&reverse, edges, index_count, sizeof(uint64_t), compare_u64)) ++unmatched;
  }
  CHECK_MSG(duplicates == 0 && unmatched == 0 && degenerate == 0,
            "mesh not closed: %u duplicate directed edges, %u without their reverse, %u degenerate", duplicates,
            unmatched, degenerate);
  /* The mesh is the surface of the solid bounds volume (walls, floor, ceiling), its front faces towards
   * free space: counter-clockwise in the numbers' right-handed reading (clockwise in Unity's left-handed
   * one), so the signed volume is that of the solid, positive and below the room's. */
  {
    const double room = 4.0 * BOX_HALF_X * BOX_HALF_Z * (BOX_CEILING - BOX_FLOOR);
    CHECK_MSG(volume > 0.0 && volume < room, "signed volume %g, room %g", volume, room);
  }
  /* Seen from the middle of the room, the nearest surface below faces up and the nearest above faces down. */
  {
    const float px = BOX_CX, py = 0.0f, pz = BOX_CZ;
    float below = -1e9f, above = 1e9f, below_ny = 0.0f, above_ny = 0.0f;
    for (t = 0; t + 3 <= index_count; t += 3) {
      const float* p = xyz + 3 * indices[t];
      const float* q = xyz + 3 * indices[t + 1];
      const float* r = xyz + 3 * indices[t + 2];
      const float ux = q[0] - p[0], uy = q[1] - p[1], uz = q[2] - p[2];
      const float wx = r[0] - p[0], wy = r[1] - p[1], wz = r[2] - p[2];
      const float ny = uz * wx - ux * wz; /* y of (q - p) x (r - p) */
      float d, s1, s2, y;
      if (fabsf(ny) < 1e-6f) continue;   /* vertical */
      /* barycentrics of (px, pz) in the triangle projected onto the x-z plane */
      d = ux * wz - uz * wx;
      s1 = ((px - p[0]) * wz - (pz - p[2]) * wx) / d;
      s2 = (ux * (pz - p[2]) - uz * (px - p[0])) / d;
      if (s1 < 0.0f || s2 < 0.0f || s1 + s2 > 1.0f) continue;
      y = p[1] + s1 * uy + s2 * wy;
      if (y < py && y > below) { below = y; below_ny = ny; }
      if (y > py && y < above) { above = y; above_ny = ny; }
    }
    CHECK_MSG(below_ny > 0.0f && above_ny < 0.0f,
              "faces seen from the room: below at y %g with normal y %g, above at y %g with normal y %g",
              (double)below, (double)below_ny, (double)above, (double)above_ny);
  }
  (void)vertices;
  free(edges);
}

static int test_thesis_bounds(void) {
  int n, code = 99, vsize = -1, tsize = -1, i;
  float* room = box_room(&n, 1);
  float* mesh;
  CHECK(StartRoomBounds(room, 3 * n) == 0);
  free(room);
  mesh = poll(RetrieveRoomBounds, &code, &vsize, &tsize);
  CHECK_MSG(code == 0, "code %d", code);
  CHECK(mesh != NULL);
  CHECK_MSG(vsize > 0 && vsize % 3 == 0 && tsize > 0 && tsize % 3 == 0, "vertex size %d, triangle size %d", vsize,
            tsize);
  if (code == 0 && mesh != NULL && vsize > 0 && tsize > 0) {
    const unsigned vertices = (unsigned)vsize / 3;
    uint32_t* indices = (uint32_t*)malloc((size_t)tsize * sizeof(uint32_t));
    int bad_index = 0, outside = 0;
    for (i = 0; i < tsize; ++i) {
      const float f = mesh[vsize + i];
      if (!(f >= 0.0f && f < (float)vertices && f == floorf(f))) ++bad_index;
      indices[i] = f >= 0.0f && f < (float)vertices ? (uint32_t)f : 0;
    }
    CHECK_MSG(bad_index == 0, "%d indices not integers below %u", bad_index, vertices);
    for (i = 0; i < vsize; i += 3)
      if (fabsf(mesh[i] - BOX_CX) > BOX_HALF_X + 0.25f || fabsf(mesh[i + 2] - BOX_CZ) > BOX_HALF_Z + 0.25f ||
          mesh[i + 1] < BOX_FLOOR - 0.25f || mesh[i + 1] > BOX_CEILING + 0.25f)
        ++outside;
    CHECK_MSG(outside == 0, "%d vertices outside the room", outside);
    if (bad_index == 0) check_closed_mesh(mesh, vertices, indices, (unsigned)tsize);
    printf("bounds: %u vertices, %d triangles\n", vertices, tsize / 3);
    free(indices);
  }
  CHECK(CleanUpRoomBounds() == 0);
  return failures;
}

static int test_thesis_errors(void) {
  float nine[9] = {0};
  int n, code = 99, size = 99, vsize = 99, tsize = 99;
  float* room = box_room(&n, 0);

  /* Nothing started: "no result". Null outputs are skipped, never written. */
  CHECK(RetrieveRoomUnderstanding(&code, &size) == NULL && code == 1 && size == 0);
  CHECK(RetrieveRoomBounds(&code, &vsize, &tsize) == NULL && code == 1 && vsize == 0 && tsize == 0);
  CHECK(RetrieveRoomUnderstanding(NULL, NULL) == NULL);
  CHECK(RetrieveRoomBounds(NULL, NULL, NULL) == NULL);
  size = 99;
  CHECK(RetrieveRoomUnderstandingPlaces(&code, &size) == NULL && code == 1 && size == 0);
  CHECK(RetrieveRoomUnderstandingPlaces(NULL, NULL) == NULL);
  CHECK(CleanUpRoomUnderstanding() == 0 && CleanUpRoomBounds() == 0);

  /* Code 1: no array or a size below 1; code 2: a size not divisible by 3. */
  CHECK(StartRoomUnderstanding(NULL, 0) == 1);
  CHECK(StartRoomUnderstanding(NULL, 9) == 1);
  CHECK(StartRoomUnderstanding(nine, 0) == 1);
  CHECK(StartRoomUnderstanding(nine, -3) == 1);
  CHECK(StartRoomUnderstanding(nine, 10) == 2);
  CHECK(StartRoomUnderstanding(nine, 1) == 2);
  CHECK(StartRoomBounds(NULL, 0) == 1);
  CHECK(StartRoomBounds(nine, -1) == 1);
  CHECK(StartRoomBounds(nine, 10) == 2);
  CHECK(RetrieveRoomUnderstanding(&code, &size) == NULL && code == 1); /* bad input started nothing */

  /* Code 4: busy from Start until CleanUp, running or finished. */
  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
  CHECK(StartRoomUnderstanding(room, 3 * n) == 4);
  CHECK(StartRoomUnderstanding(room, 10) == 2); /* input checks come first */
  poll(retrieve_understanding3, &code, &size, NULL);
  CHECK_MSG(code == 0, "code %d", code);
  CHECK(StartRoomUnderstanding(room, 3 * n) == 4); /* finished, not cleaned up: still busy */
  CHECK(CleanUpRoomUnderstanding() == 0);
  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);

  /* CleanUp while the worker runs waits for it and discards the result. */
  CHECK(CleanUpRoomUnderstanding() == 0);
  CHECK(RetrieveRoomUnderstanding(&code, &size) == NULL && code == 1 && size == 0);
  CHECK(CleanUpRoomUnderstanding() == 0); /* twice is harmless */

  CHECK(StartRoomBounds(room, 3 * n) == 0);
  CHECK(StartRoomBounds(room, 3 * n) == 4);
  CHECK(CleanUpRoomBounds() == 0);
  CHECK(StartRoomBounds(room, 3 * n) == 0);
  CHECK(CleanUpRoomBounds() == 0);

  /* Code 1 from Retrieve: finished without a result. A floor alone has no ceiling. */
  {
    int i;
    for (i = 0; i < n; ++i) room[3 * i + 1] = BOX_FLOOR; /* flatten everything onto the floor */
    CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
    CHECK(poll(retrieve_understanding3, &code, &size, NULL) == NULL);
    CHECK_MSG(code == 1 && size == 0, "flat scan: code %d size %d", code, size);
    CHECK(CleanUpRoomUnderstanding() == 0);
    CHECK(StartRoomBounds(room, 3 * n) == 0);
    CHECK(poll(RetrieveRoomBounds, &code, &vsize, &tsize) == NULL);
    CHECK_MSG(code == 1 && vsize == 0 && tsize == 0, "flat scan bounds: code %d", code);
    CHECK(CleanUpRoomBounds() == 0);
  }
  /* Every vertex NaN: no valid vertex, code 1, no crash. One vertex: code 1. */
  {
    int i;
    for (i = 0; i < 3 * n; ++i) room[i] = NAN;
    CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
    poll(retrieve_understanding3, &code, &size, NULL);
    CHECK_MSG(code == 1, "all NaN: code %d", code);
    CHECK(CleanUpRoomUnderstanding() == 0);
    CHECK(StartRoomBounds(nine, 3) == 0);
    poll(RetrieveRoomBounds, &code, &vsize, &tsize);
    CHECK_MSG(code == 1, "one vertex: code %d", code);
    CHECK(CleanUpRoomBounds() == 0);
  }
  free(room);
  return failures;
}

/* Both jobs at once, as the thesis allows, and their results the same as when run alone. */
static int test_thesis_parallel(void) {
  int n, c1 = 99, c2 = 99, size = 0, vsize = 0, tsize = 0, alone_size = 0, alone_code = 99;
  float* room = box_room(&n, 1);
  float *areas, *mesh, *alone;
  float* kept;
  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
  alone = poll(retrieve_understanding3, &alone_code, &alone_size, NULL);
  CHECK(alone_code == 0);
  kept = (float*)malloc((size_t)(alone_size + 1) * sizeof(float));
  if (alone) memcpy(kept, alone, (size_t)alone_size * sizeof(float));
  CHECK(CleanUpRoomUnderstanding() == 0);

  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
  CHECK(StartRoomBounds(room, 3 * n) == 0);
  areas = poll(retrieve_understanding3, &c1, &size, NULL);
  mesh = poll(RetrieveRoomBounds, &c2, &vsize, &tsize);
  CHECK(c1 == 0 && c2 == 0 && areas != NULL && mesh != NULL && vsize > 0);
  CHECK_MSG(size == alone_size, "%d floats in parallel, %d alone", size, alone_size);
  if (areas && size == alone_size) CHECK(memcmp(areas, kept, (size_t)size * sizeof(float)) == 0);
  CHECK(CleanUpRoomUnderstanding() == 0);
  CHECK(CleanUpRoomBounds() == 0);
  free(kept);
  free(room);
  return failures;
}

/* An application that exits without cleaning up: the thesis API's understanding finished (its worker idle), its
 * bounds still computing, and a handle API analyzer computing, never destroyed. The process must end at once;
 * check_exit_without_cleanup.cmake runs it many times, as exit's races are rare. Named only: it leaves the work
 * running for main's return. */
static int test_exit_without_cleanup(void) {
  static rs_analyzer* left = NULL; /* static: LeakSanitizer sees it reachable */
  int n, code = 99, size = 0;
  float* room = box_room(&n, 1);
  CHECK(StartRoomUnderstanding(room, 3 * n) == 0);
  CHECK(poll(retrieve_understanding3, &code, &size, NULL) != NULL && code == 0);
  CHECK(StartRoomBounds(room, 3 * n) == 0);
  CHECK_RS(rs_analyzer_create(NULL, &left), RS_SUCCESS);
  if (left) CHECK_RS(rs_analyzer_compute(left, room, (uint32_t)n, NULL, 0), RS_SUCCESS);
  free(room);
  return failures;
}

/* ---------------------------------------------------------------------------------------------------- */
/* Handle API                                                                                             */

static rs_analyzer* computed(const rs_analyzer_options* options, const float* xyz, uint32_t n) {
  rs_analyzer* a = NULL;
  rs_state state = RS_STATE_IDLE;
  CHECK_RS(rs_analyzer_create(options, &a), RS_SUCCESS);
  if (!a) return NULL;
  CHECK_RS(rs_analyzer_compute(a, xyz, n, NULL, 0), RS_SUCCESS);
  CHECK_RS(rs_analyzer_wait(a, (uint32_t)(kTimeoutSeconds * 1000), &state), RS_SUCCESS);
  CHECK_MSG(state == RS_STATE_READY, "state %d", (int)state);
  return a;
}

static void check_rs_area(const rs_area* a, int k) {
  static const unsigned size_bit[] = {0, 1, 2, 4}, reach_bit[] = {0, 8, 16, 32}, type_bit[] = {0, 64, 128, 512, 256};
  const rs_quat q = a->orientation;
  float ex, ey, ez;
  CHECK_MSG(a->type >= 1 && a->type <= 4 && a->size >= 1 && a->size <= 3 && a->reach >= 1 && a->reach <= 3,
            "area %d: type %d size %d reach %d", k, (int)a->type, (int)a->size, (int)a->reach);
  if (!(a->type >= 1 && a->type <= 4 && a->size >= 1 && a->size <= 3 && a->reach >= 1 && a->reach <= 3)) return;
  CHECK_MSG(a->flags == (size_bit[a->size] | reach_bit[a->reach] | type_bit[a->type]), "area %d: flags %u", k,
            a->flags);
  CHECK_MSG(fabsf(length3(a->normal.x, a->normal.y, a->normal.z) - 1.0f) < 1e-4f, "area %d: normal", k);
  CHECK_MSG(fabsf(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w - 1.0f) < 1e-4f, "area %d: quaternion", k);
  /* The orientation rotates +Z onto the normal: third column of the rotation matrix. */
  ex = 2.0f * (q.x * q.z + q.w * q.y);
  ey = 2.0f * (q.y * q.z - q.w * q.x);
  ez = 1.0f - 2.0f * (q.x * q.x + q.y * q.y);
  CHECK_MSG(fabsf(ex - a->normal.x) < 1e-3f && fabsf(ey - a->normal.y) < 1e-3f && fabsf(ez - a->normal.z) < 1e-3f,
            "area %d: orientation * Z = (%g, %g, %g), normal (%g, %g, %g)", k, (double)ex, (double)ey, (double)ez,
            (double)a->normal.x, (double)a->normal.y, (double)a->normal.z);
  {
    const rs_vec3* c = a->corners;
    const float mx = (c[0].x + c[1].x + c[2].x + c[3].x) / 4, my = (c[0].y + c[1].y + c[2].y + c[3].y) / 4,
                mz = (c[0].z + c[1].z + c[2].z + c[3].z) / 4;
    const float w = length3(c[1].x - c[0].x, c[1].y - c[0].y, c[1].z - c[0].z);
    const float h = length3(c[2].x - c[1].x, c[2].y - c[1].y, c[2].z - c[1].z);
    CHECK_MSG(length3(mx - a->center.x, my - a->center.y, mz - a->center.z) < 1e-3f, "area %d: corners' centre", k);
    CHECK_MSG(fabsf(w - 2 * a->half_width) < 1e-3f && fabsf(h - 2 * a->half_height) < 1e-3f,
              "area %d: corners %g x %g, half extents %g x %g", k, (double)w, (double)h, (double)a->half_width,
              (double)a->half_height);
  }
}

static int test_handle_basic(void) {
  int n;
  float* room = box_room(&n, 1);
  rs_analyzer* a = computed(NULL, room, (uint32_t)n);
  rs_layout layout;
  uint32_t count = 0, i;
  rs_area* areas;
  if (!a) return failures;

  CHECK_RS(rs_analyzer_get_layout(a, &layout), RS_SUCCESS);
  /* one voxel: in vertex mode the levels average every point of their band, wall points included */
  CHECK_MSG(fabsf(layout.floor_y - BOX_FLOOR) <= 0.1f && fabsf(layout.ceiling_y - BOX_CEILING) <= 0.1f,
            "floor %g ceiling %g", (double)layout.floor_y, (double)layout.ceiling_y);
  CHECK(layout.storey_count == 1 && layout.input_vertex_count == (uint32_t)n && layout.voxel_size == 0.1f);
  CHECK(layout.grid_dims[0] > 0 && layout.grid_dims[1] > 0 && layout.grid_dims[2] > 0);
  {
    rs_storey storeys[2] = {{0, 0}, {0, 0}};
    CHECK_RS(rs_analyzer_get_storeys(a, 0, &count, NULL), RS_SUCCESS);
    CHECK(count == 1);
    CHECK_RS(rs_analyzer_get_storeys(a, 2, &count, storeys), RS_SUCCESS);
    CHECK(count == 1 && storeys[0].floor_y == layout.floor_y && storeys[0].ceiling_y == layout.ceiling_y);
  }

  /* Areas, two calls. */
  CHECK_RS(rs_analyzer_get_areas(a, 0, &count, NULL), RS_SUCCESS);
  CHECK_MSG(count > 0 && count == layout.area_count, "%u areas, layout %u", count, layout.area_count);
  areas = (rs_area*)calloc(count + 2, sizeof(rs_area));
  if (count > 1) {
    uint32_t c = 0;
    CHECK_RS(rs_analyzer_get_areas(a, count - 1, &c, areas), RS_ERROR_SIZE_INSUFFICIENT);
    CHECK(c == count);
  }
  CHECK_RS(rs_analyzer_get_areas(a, 1, &count, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_get_areas(a, 1, NULL, areas), RS_ERROR_INVALID_ARGUMENT);
  memset(&areas[count], 0xAB, sizeof(rs_area));
  {
    uint32_t c = 0;
    unsigned char sentinel[sizeof(rs_area)];
    memset(sentinel, 0xAB, sizeof sentinel);
    CHECK_RS(rs_analyzer_get_areas(a, count + 2, &c, areas), RS_SUCCESS);
    CHECK(c == count);
    CHECK(memcmp(&areas[count], sentinel, sizeof sentinel) == 0); /* nothing written past the count */
  }
  for (i = 0; i < count; ++i) check_rs_area(&areas[i], (int)i);

  /* Bounds, two calls. */
  {
    uint32_t vc = 0, ic = 0, v, bad = 0;
    float* xyz;
    uint32_t* idx;
    CHECK_RS(rs_analyzer_get_bounds(a, 0, &vc, NULL, 0, &ic, NULL), RS_SUCCESS);
    CHECK(vc == layout.bounds_vertex_count && ic == layout.bounds_index_count && vc > 0 && ic > 0 && ic % 3 == 0);
    xyz = (float*)malloc(3 * (size_t)vc * sizeof(float));
    idx = (uint32_t*)malloc((size_t)ic * sizeof(uint32_t));
    {
      uint32_t vc2 = 0, ic2 = 0;
      CHECK_RS(rs_analyzer_get_bounds(a, vc - 1, &vc2, xyz, ic, &ic2, idx), RS_ERROR_SIZE_INSUFFICIENT);
      CHECK(vc2 == vc && ic2 == ic);
      CHECK_RS(rs_analyzer_get_bounds(a, vc, &vc2, xyz, ic - 1, &ic2, idx), RS_ERROR_SIZE_INSUFFICIENT);
      CHECK_RS(rs_analyzer_get_bounds(a, vc, &vc2, NULL, ic, &ic2, idx), RS_ERROR_INVALID_ARGUMENT);
      CHECK_RS(rs_analyzer_get_bounds(a, vc, &vc2, xyz, ic, NULL, idx), RS_ERROR_INVALID_ARGUMENT);
    }
    CHECK_RS(rs_analyzer_get_bounds(a, vc, &vc, xyz, ic, &ic, idx), RS_SUCCESS);
    for (v = 0; v < ic; ++v)
      if (idx[v] >= vc) ++bad;
    CHECK(bad == 0);
    if (bad == 0) check_closed_mesh(xyz, vc, idx, ic);
    free(xyz);
    free(idx);
  }

  /* The message: "ok", NUL-terminated, two calls. */
  {
    char buffer[256];
    uint32_t c = 0;
    CHECK_RS(rs_analyzer_get_message(a, 0, &c, NULL), RS_SUCCESS);
    CHECK(c >= 3 && c <= sizeof buffer);
    CHECK_RS(rs_analyzer_get_message(a, 1, &c, buffer), RS_ERROR_SIZE_INSUFFICIENT);
    CHECK_RS(rs_analyzer_get_message(a, sizeof buffer, &c, buffer), RS_SUCCESS);
    CHECK(strlen(buffer) + 1 == c && strncmp(buffer, "ok", 2) == 0);
  }

  /* A second compute replaces the result with an identical one (determinism). */
  {
    rs_area* again = (rs_area*)calloc(count + 1, sizeof(rs_area));
    uint32_t c = 0;
    rs_state state;
    CHECK_RS(rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0), RS_SUCCESS);
    CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, &state), RS_SUCCESS);
    CHECK(state == RS_STATE_READY);
    CHECK_RS(rs_analyzer_get_areas(a, count + 1, &c, again), RS_SUCCESS);
    CHECK(c == count && memcmp(again, areas, count * sizeof(rs_area)) == 0);
    free(again);
  }
  free(areas);
  rs_analyzer_destroy(a);
  free(room);
  return failures;
}

static int test_handle_errors(void) {
  rs_analyzer* a = NULL;
  rs_analyzer_options o;
  rs_state state = RS_STATE_READY;
  rs_layout layout;
  uint32_t count = 7;
  float nine[9] = {0};
  const uint32_t tri[3] = {0, 1, 2}, bad_tri[3] = {0, 1, 3};

  CHECK(strcmp(rs_result_string(RS_ERROR_BUSY), "RS_ERROR_BUSY") == 0);
  CHECK(strcmp(rs_result_string(RS_SUCCESS), "RS_SUCCESS") == 0);
  CHECK(strcmp(rs_result_string((rs_result)12345), "RS_UNKNOWN_RESULT") == 0);
  CHECK(rs_api_version() == RS_API_VERSION);

  /* NULL handles and outputs. */
  CHECK_RS(rs_analyzer_create(NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_compute(NULL, nine, 3, NULL, 0), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_state(NULL, &state), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_wait(NULL, 0, &state), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_layout(NULL, &layout), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_areas(NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_storeys(NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_bounds(NULL, 0, &count, NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_rooms(NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_area_places(NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_room_bounds(NULL, 0, 0, &count, NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_get_message(NULL, 0, &count, NULL), RS_ERROR_HANDLE_INVALID);
  rs_analyzer_destroy(NULL);
  rs_analyzer_options_init(NULL);

  /* Options out of range. */
  rs_analyzer_options_init(&o);
  CHECK(o.struct_size == sizeof o && o.voxel_size == 0.1f && o.compute_flags == 3u);
  o.voxel_size = 5.0f;
  CHECK_RS(rs_analyzer_create(&o, &a), RS_ERROR_INVALID_ARGUMENT);
  CHECK(a == NULL);
  o.voxel_size = NAN;
  CHECK_RS(rs_analyzer_create(&o, &a), RS_ERROR_INVALID_ARGUMENT);
  rs_analyzer_options_init(&o);
  o.struct_size = 4;
  CHECK_RS(rs_analyzer_create(&o, &a), RS_ERROR_INVALID_ARGUMENT);
  rs_analyzer_options_init(&o);
  o.compute_flags = 8;
  CHECK_RS(rs_analyzer_create(&o, &a), RS_ERROR_INVALID_ARGUMENT);
  rs_analyzer_options_init(&o);
  o.up_axis = (rs_up_axis)7;
  CHECK_RS(rs_analyzer_create(&o, &a), RS_ERROR_INVALID_ARGUMENT);

  /* Before any compute. */
  CHECK_RS(rs_analyzer_create(NULL, &a), RS_SUCCESS);
  if (!a) return failures;
  CHECK_RS(rs_analyzer_state(a, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_state(a, &state), RS_SUCCESS);
  CHECK(state == RS_STATE_IDLE);
  CHECK_RS(rs_analyzer_wait(a, 0, &state), RS_SUCCESS);
  CHECK(state == RS_STATE_IDLE);
  CHECK_RS(rs_analyzer_get_layout(a, &layout), RS_ERROR_NO_RESULT);
  CHECK_RS(rs_analyzer_get_layout(a, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_get_areas(a, 0, &count, NULL), RS_ERROR_NO_RESULT);
  CHECK_RS(rs_analyzer_get_message(a, 0, &count, NULL), RS_ERROR_NO_RESULT);

  /* Bad input, rejected before anything starts. */
  CHECK_RS(rs_analyzer_compute(a, NULL, 3, NULL, 0), RS_ERROR_EMPTY_INPUT);
  CHECK_RS(rs_analyzer_compute(a, nine, 0, NULL, 0), RS_ERROR_EMPTY_INPUT);
  CHECK_RS(rs_analyzer_compute(a, nine, 3, tri, 2), RS_ERROR_BAD_INDICES);
  CHECK_RS(rs_analyzer_compute(a, nine, 3, NULL, 3), RS_ERROR_BAD_INDICES);
  CHECK_RS(rs_analyzer_compute(a, nine, 3, bad_tri, 3), RS_ERROR_BAD_INDICES);
  CHECK_RS(rs_analyzer_state(a, &state), RS_SUCCESS);
  CHECK(state == RS_STATE_IDLE);

  /* A scan without a room: FAILED, the getters say why, the message in words. */
  CHECK_RS(rs_analyzer_compute(a, nine, 3, tri, 3), RS_SUCCESS);
  CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, &state), RS_SUCCESS);
  CHECK(state == RS_STATE_FAILED);
  CHECK_RS(rs_analyzer_get_layout(a, &layout), RS_ERROR_NO_ROOM);
  CHECK_RS(rs_analyzer_get_areas(a, 0, &count, NULL), RS_ERROR_NO_ROOM);
  {
    char message[512];
    CHECK_RS(rs_analyzer_get_message(a, sizeof message, &count, message), RS_SUCCESS);
    CHECK(count > 1 && strlen(message) + 1 == count);
    printf("no-room message: %s\n", message);
  }
  /* Every vertex NaN. */
  {
    float nans[9];
    int i;
    for (i = 0; i < 9; ++i) nans[i] = NAN;
    CHECK_RS(rs_analyzer_compute(a, nans, 3, tri, 3), RS_SUCCESS);
    CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, &state), RS_SUCCESS);
    CHECK(state == RS_STATE_FAILED);
    CHECK_RS(rs_analyzer_get_areas(a, 0, &count, NULL), RS_ERROR_NO_VALID_VERTICES);
  }

  /* Busy while running; the getters are not ready. The second compute races the first one's end, so a
   * few tries: a room takes far longer to analyse than returning from a call. */
  {
    int n, tries, busy = 0;
    float* room = box_room(&n, 0);
    for (tries = 0; tries < 5 && !busy; ++tries) {
      rs_result r, g;
      CHECK_RS(rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0), RS_SUCCESS);
      r = rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0);
      g = rs_analyzer_get_areas(a, 0, &count, NULL);
      CHECK(r == RS_ERROR_BUSY || r == RS_SUCCESS);
      CHECK(g == RS_ERROR_NOT_READY || g == RS_SUCCESS);
      busy = r == RS_ERROR_BUSY && g == RS_ERROR_NOT_READY;
      CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, &state), RS_SUCCESS);
      CHECK(state == RS_STATE_READY);
    }
    CHECK_MSG(busy, "never saw RS_ERROR_BUSY in %d tries", tries);
    free(room);
  }
  rs_analyzer_destroy(a);
  return failures;
}

/* The placement queries (API 1.1) on the box room, against its known geometry: cubes on the table's top, boards
 * on the walls, footprints on free floor clear of the table; rays to the floor and a wall; inside and outside;
 * random points; the two-call idiom; every argument check, before and after a compute. */
static int inside_table(float x, float z, float grow) {
  return fabsf(x - TABLE_CX) < TABLE_HALF_X + grow && fabsf(z - TABLE_CZ) < TABLE_HALF_Z + grow;
}

static int test_handle_queries(void) {
  int n;
  uint32_t count = 0, i;
  float* room = box_room(&n, 1);
  rs_analyzer* a = NULL;
  rs_placement_query q;
  rs_placement placements[16];
  rs_placement_shortfall shortfall = RS_SHORTFALL_MAX_ENUM;
  const rs_vec3 middle = {BOX_CX - 1.0f, 0.0f, BOX_CZ}, down = {0, -1, 0}, east = {1, 0, 0}, zero = {0, 0, 0};
  const rs_vec3 outside = {BOX_CX + BOX_HALF_X + 1.0f, 0.0f, BOX_CZ};
  rs_ray_hit hit;
  rs_location where;
  rs_surface_point point;

  rs_placement_query_init(&q);
  CHECK(q.struct_size == sizeof q && q.size.x == 0.3f && q.surfaces == RS_SURFACE_ANY && q.max_count == 1);
  rs_placement_query_init(NULL);
  CHECK(rs_api_version() >= RS_MAKE_VERSION(1, 1, 0));

  /* Before a compute: NULL handle, then the arguments, then the state. */
  CHECK_RS(rs_analyzer_find_placements(NULL, &q, 0, &count, NULL, NULL), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_raycast(NULL, &middle, &down, 0, &hit), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_locate(NULL, &middle, &where), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_random_point_on_surface(NULL, RS_SURFACE_FLOOR, 0, 0, &point), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_random_point_in_room(NULL, 0, 0, &point), RS_ERROR_HANDLE_INVALID);
  CHECK_RS(rs_analyzer_create(NULL, &a), RS_SUCCESS);
  if (!a) return failures;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 0, &count, NULL, NULL), RS_ERROR_NO_RESULT);
  q.max_count = 0;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_raycast(a, &middle, &down, 0, &hit), RS_ERROR_NO_RESULT);
  CHECK_RS(rs_analyzer_raycast(a, &middle, &zero, 0, &hit), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_locate(a, &middle, &where), RS_ERROR_NO_RESULT);
  CHECK_RS(rs_analyzer_random_point_in_room(a, -1.0f, 0, &point), RS_ERROR_INVALID_ARGUMENT);

  CHECK_RS(rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0), RS_SUCCESS);
  CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, NULL), RS_SUCCESS);

  /* Three 0.3 m cubes on the table's top, two calls; nothing written past the count. */
  rs_placement_query_init(&q);
  q.surfaces = RS_SURFACE_FURNITURE;
  q.max_count = 3;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 0, &count, NULL, &shortfall), RS_SUCCESS);
  CHECK_MSG(count == 3 && shortfall == RS_SHORTFALL_NONE, "%u placements, shortfall %d", count, (int)shortfall);
  if (count >= 2) {
    uint32_t c = 0;
    CHECK_RS(rs_analyzer_find_placements(a, &q, count - 1, &c, placements, NULL), RS_ERROR_SIZE_INSUFFICIENT);
    CHECK(c == count);
  }
  memset(placements, 0xAB, sizeof placements);
  CHECK_RS(rs_analyzer_find_placements(a, &q, 16, &count, placements, NULL), RS_SUCCESS);
  {
    unsigned char sentinel[sizeof(rs_placement)];
    memset(sentinel, 0xAB, sizeof sentinel);
    CHECK(count <= 3 && memcmp(&placements[count], sentinel, sizeof sentinel) == 0);
  }
  for (i = 0; i < count && i < 3; ++i) {
    const rs_placement* p = &placements[i];
    int k;
    CHECK_MSG(p->surface == RS_AREA_TYPE_FURNITURE && p->normal.y > 0.999f && p->width == 0.3f && p->depth == 0.3f,
              "placement %u: surface %d", i, (int)p->surface);
    CHECK_MSG(fabsf(p->center.y - (BOX_FLOOR + TABLE_HEIGHT)) < 0.1f, "placement %u at y %g", i, (double)p->center.y);
    for (k = 0; k < 4; ++k)
      CHECK_MSG(inside_table(p->corners[k].x, p->corners[k].z, 0.1f), "placement %u corner %d off the table", i, k);
  }

  /* Floor: 0.6 m squares with 0.2 m clearance never touch the table or leave the room. */
  rs_placement_query_init(&q);
  q.size.x = q.size.y = 0.6f;
  q.size.z = 1.0f;
  q.clearance = 0.2f;
  q.surfaces = RS_SURFACE_FLOOR;
  q.max_count = 6;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 16, &count, placements, &shortfall), RS_SUCCESS);
  CHECK_MSG(count == 6, "%u floor placements", count);
  for (i = 0; i < count && i < 16; ++i) {
    const rs_placement* p = &placements[i];
    int k;
    CHECK(p->surface == RS_AREA_TYPE_FLOOR && fabsf(p->center.y - BOX_FLOOR) < 0.1f);
    for (k = 0; k < 4; ++k) {
      CHECK_MSG(!inside_table(p->corners[k].x, p->corners[k].z, 0.1f), "floor placement %u on the table", i);
      CHECK(fabsf(p->corners[k].x - BOX_CX) < BOX_HALF_X && fabsf(p->corners[k].z - BOX_CZ) < BOX_HALF_Z);
    }
  }

  /* Walls: a 0.6 x 0.4 m board, within a voxel of one of the four walls, facing into the room, +Y up. */
  rs_placement_query_init(&q);
  q.size.x = 0.6f;
  q.size.y = 0.4f;
  q.size.z = 0.05f;
  q.surfaces = RS_SURFACE_WALL;
  q.max_count = 4;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 16, &count, placements, NULL), RS_SUCCESS);
  CHECK(count == 4);
  for (i = 0; i < count && i < 16; ++i) {
    const rs_placement* p = &placements[i];
    const float dx = BOX_HALF_X - fabsf(p->center.x - BOX_CX), dz = BOX_HALF_Z - fabsf(p->center.z - BOX_CZ);
    CHECK_MSG(p->surface == RS_AREA_TYPE_WALL && fabsf(p->normal.y) < 1e-5f && (dx < 0.15f || dz < 0.15f),
              "wall placement %u at (%g, %g)", i, (double)p->center.x, (double)p->center.z);
    CHECK(fabsf(p->corners[2].y - p->corners[1].y - 0.4f) < 1e-4f); /* +Y up the wall */
  }

  /* Impossible: a 9 m square. Zero results and why, not an error. */
  rs_placement_query_init(&q);
  q.size.x = q.size.y = 9.0f;
  q.surfaces = RS_SURFACE_FLOOR;
  CHECK_RS(rs_analyzer_find_placements(a, &q, 16, &count, placements, &shortfall), RS_SUCCESS);
  CHECK(count == 0 && shortfall == RS_SHORTFALL_NO_SPACE);

  /* Bad queries. */
  rs_placement_query_init(&q);
  CHECK_RS(rs_analyzer_find_placements(a, NULL, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_find_placements(a, &q, 0, NULL, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_find_placements(a, &q, 1, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  {
    rs_placement_query bad = q;
    bad.struct_size = 8;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.surfaces = 0;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad.surfaces = 16;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.reach = (rs_reach_filter)3;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.size.y = -0.1f;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.clearance = NAN;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.edge_distance = 1e9f;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.max_count = 1025;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.has_near_point = 1;
    bad.near_point.x = INFINITY;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
    bad = q;
    bad.reserved = 1;
    CHECK_RS(rs_analyzer_find_placements(a, &bad, 0, &count, NULL, NULL), RS_ERROR_INVALID_ARGUMENT);
  }

  /* Rays: down onto the floor (the measured one: the layout's), east onto the wall, none past max_distance. */
  {
    rs_layout layout;
    CHECK_RS(rs_analyzer_get_layout(a, &layout), RS_SUCCESS);
    CHECK_RS(rs_analyzer_raycast(a, &middle, &down, 0, &hit), RS_SUCCESS);
    CHECK_MSG(hit.hit && hit.scanned && hit.surface == RS_AREA_TYPE_FLOOR &&
                  fabsf(hit.position.y - layout.floor_y) < 1e-4f && hit.normal.y > 0.99f,
              "floor hit %d at y %g, floor %g", hit.hit, (double)hit.position.y, (double)layout.floor_y);
  }
  CHECK_RS(rs_analyzer_raycast(a, &middle, &east, 0, &hit), RS_SUCCESS);
  CHECK_MSG(hit.hit && hit.surface == RS_AREA_TYPE_WALL && fabsf(hit.position.x - (BOX_CX + BOX_HALF_X)) < 0.15f &&
                hit.normal.x < -0.99f,
            "wall hit %d at x %g", hit.hit, (double)hit.position.x);
  {
    /* Any length of direction but a vanishing one: the same hit. */
    const rs_vec3 east_short = {1e-3f, 0, 0}, east_long = {1e6f, 0, 0}, tiny = {1e-13f, 0, 0};
    rs_ray_hit other;
    CHECK_RS(rs_analyzer_raycast(a, &middle, &east_short, 0, &other), RS_SUCCESS);
    CHECK(other.hit && fabsf(other.distance - hit.distance) < 1e-5f);
    CHECK_RS(rs_analyzer_raycast(a, &middle, &east_long, 0, &other), RS_SUCCESS);
    CHECK(other.hit && fabsf(other.distance - hit.distance) < 1e-5f);
    CHECK_RS(rs_analyzer_raycast(a, &middle, &tiny, 0, &other), RS_ERROR_INVALID_ARGUMENT);
  }
  CHECK_RS(rs_analyzer_raycast(a, &middle, &east, 0.5f, &hit), RS_SUCCESS);
  CHECK(!hit.hit && hit.distance == 0.0f && hit.surface == RS_AREA_TYPE_NONE);
  CHECK_RS(rs_analyzer_raycast(a, &middle, &east, -1.0f, &hit), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_raycast(a, &middle, &east, NAN, &hit), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_raycast(a, NULL, &east, 0, &hit), RS_ERROR_INVALID_ARGUMENT);
  CHECK_RS(rs_analyzer_raycast(a, &middle, &east, 0, NULL), RS_ERROR_INVALID_ARGUMENT);

  /* Inside and outside. */
  CHECK_RS(rs_analyzer_locate(a, &middle, &where), RS_SUCCESS);
  CHECK(where.inside && where.free && where.storey == 0);
  CHECK_RS(rs_analyzer_locate(a, &outside, &where), RS_SUCCESS);
  CHECK(!where.inside && !where.free);
  CHECK_RS(rs_analyzer_locate(a, NULL, &where), RS_ERROR_INVALID_ARGUMENT);

  /* Random points: on the floor, in free space, the same for the same seed. */
  {
    rs_surface_point again;
    uint64_t seed;
    for (seed = 1; seed <= 8; ++seed) {
      CHECK_RS(rs_analyzer_random_point_on_surface(a, RS_SURFACE_FLOOR, 0.1f, seed, &point), RS_SUCCESS);
      CHECK(point.found && point.surface == RS_AREA_TYPE_FLOOR && fabsf(point.position.y - BOX_FLOOR) < 0.1f);
      CHECK(!inside_table(point.position.x, point.position.z, 0.0f));
      CHECK_RS(rs_analyzer_random_point_on_surface(a, RS_SURFACE_FLOOR, 0.1f, seed, &again), RS_SUCCESS);
      CHECK(memcmp(&point, &again, sizeof point) == 0);
      CHECK_RS(rs_analyzer_random_point_in_room(a, 0.2f, seed, &point), RS_SUCCESS);
      CHECK(point.found && point.surface == RS_AREA_TYPE_NONE && point.position.y > BOX_FLOOR + 0.2f &&
            point.position.y < BOX_CEILING - 0.2f && fabsf(point.position.x - BOX_CX) < BOX_HALF_X - 0.2f);
    }
    CHECK_RS(rs_analyzer_random_point_on_surface(a, 0, 0, 0, &point), RS_ERROR_INVALID_ARGUMENT);
    CHECK_RS(rs_analyzer_random_point_on_surface(a, RS_SURFACE_FLOOR, 0, 0, NULL), RS_ERROR_INVALID_ARGUMENT);
    /* Clearances the room cannot hold: nothing, at once (no walk over a 100 m ball's voxels). */
    CHECK_RS(rs_analyzer_random_point_in_room(a, 50.0f, 0, &point), RS_SUCCESS);
    CHECK(!point.found);
    CHECK_RS(rs_analyzer_random_point_in_room(a, 100.0f, 0, &point), RS_SUCCESS);
    CHECK(!point.found);
    CHECK_RS(rs_analyzer_random_point_in_room(a, 100.5f, 0, &point), RS_ERROR_INVALID_ARGUMENT);
    CHECK_RS(rs_analyzer_random_point_on_surface(a, RS_SURFACE_FLOOR, NAN, 0, &point), RS_ERROR_INVALID_ARGUMENT);
  }

  /* While a compute runs the queries are not ready (a few tries: the compute may end first); after a failed
   * compute they give its code, as the getters do. */
  {
    int tries, not_ready = 0;
    for (tries = 0; tries < 5 && !not_ready; ++tries) {
      rs_result r;
      CHECK_RS(rs_analyzer_compute(a, room, (uint32_t)n, NULL, 0), RS_SUCCESS);
      r = rs_analyzer_find_placements(a, &q, 0, &count, NULL, NULL);
      CHECK(r == RS_ERROR_NOT_READY || r == RS_SUCCESS);
      not_ready = r == RS_ERROR_NOT_READY;
      if (not_ready) {
        CHECK_RS(rs_analyzer_raycast(a, &middle, &down, 0, &hit), RS_ERROR_NOT_READY);
        CHECK_RS(rs_analyzer_random_point_in_room(a, 0.2f, 0, &point), RS_ERROR_NOT_READY);
      }
      CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, NULL), RS_SUCCESS);
    }
    CHECK_MSG(not_ready, "never saw RS_ERROR_NOT_READY in %d tries", tries);
  }
  {
    static const float nine[9] = {0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const uint32_t tri[3] = {0, 1, 2};
    CHECK_RS(rs_analyzer_compute(a, nine, 3, tri, 3), RS_SUCCESS);
    CHECK_RS(rs_analyzer_wait(a, RS_WAIT_INFINITE, NULL), RS_SUCCESS);
    CHECK_RS(rs_analyzer_find_placements(a, &q, 0, &count, NULL, NULL), RS_ERROR_NO_ROOM);
    CHECK_RS(rs_analyzer_raycast(a, &middle, &down, 0, &hit), RS_ERROR_NO_ROOM);
    CHECK_RS(rs_analyzer_locate(a, &middle, &where), RS_ERROR_NO_ROOM);
    CHECK_RS(rs_analyzer_random_point_on_surface(a, RS_SURFACE_FLOOR, 0, 0, &point), RS_ERROR_NO_ROOM);
    CHECK_RS(rs_analyzer_random_point_in_room(a, 0, 0, &point), RS_ERROR_NO_ROOM);
  }
  rs_analyzer_destroy(a);
  free(room);
  return failures;
}

/* Destroying analyzers while they compute, several at once: no crash, no leak, no race (ASan/TSan). */
static int test_handle_destroy_running(void) {
  int n, i;
  float* room = box_room(&n, 1);
  rs_analyzer* many[4];
  for (i = 0; i < 4; ++i) {
    many[i] = NULL;
    CHECK_RS(rs_analyzer_create(NULL, &many[i]), RS_SUCCESS);
    if (many[i]) CHECK_RS(rs_analyzer_compute(many[i], room, (uint32_t)n, NULL, 0), RS_SUCCESS);
  }
  for (i = 0; i < 4; ++i) {
    rs_state state = RS_STATE_IDLE;
    if (!many[i]) continue;
    if (i % 2 == 0) CHECK_RS(rs_analyzer_state(many[i], &state), RS_SUCCESS);
    rs_analyzer_destroy(many[i]); /* waits for the worker */
  }
  free(room);
  return failures;
}

/* Input in another frame: Z up, centimetres, right-handed. A point (x, y, z) of our frame is
 * (x, -z, y) there (roomsense maps right-handed Z-up (x, y, z) to (x, z, -y)). */
static int test_handle_frames(void) {
  int n, i;
  float* room = box_room(&n, 1);
  float* zup = (float*)malloc(3 * (size_t)n * sizeof(float));
  rs_analyzer_options o;
  rs_analyzer* a;
  rs_layout layout;
  for (i = 0; i < n; ++i) {
    zup[3 * i + 0] = 100.0f * room[3 * i + 0];
    zup[3 * i + 1] = -100.0f * room[3 * i + 2];
    zup[3 * i + 2] = 100.0f * room[3 * i + 1];
  }
  rs_analyzer_options_init(&o);
  o.up_axis = RS_UP_AXIS_Z;
  o.units = RS_UNITS_CENTIMETRES;
  o.compute_flags = RS_COMPUTE_AREAS; /* no bounds */
  o.thread_count = 1;
  a = computed(&o, zup, (uint32_t)n);
  if (a) {
    uint32_t vc = 9, ic = 9, count = 0;
    CHECK_RS(rs_analyzer_get_layout(a, &layout), RS_SUCCESS);
    /* one voxel: in vertex mode the levels average every point of their band, wall points included */
  CHECK_MSG(fabsf(layout.floor_y - BOX_FLOOR) <= 0.1f && fabsf(layout.ceiling_y - BOX_CEILING) <= 0.1f,
              "floor %g ceiling %g", (double)layout.floor_y, (double)layout.ceiling_y);
    CHECK_RS(rs_analyzer_get_bounds(a, 0, &vc, NULL, 0, &ic, NULL), RS_SUCCESS);
    CHECK(vc == 0 && ic == 0);
    CHECK_RS(rs_analyzer_get_areas(a, 0, &count, NULL), RS_SUCCESS);
    CHECK(count > 0);
    rs_analyzer_destroy(a);
  }
  free(zup);
  free(room);
  return failures;
}

int main(int argc, char** argv) {
  static const struct {
    const char* name;
    int (*run)(void);
    int named_only; /* not run by a call that names no case */
  } cases[] = {
      {"thesis_understanding", test_thesis_understanding, 0},
      {"thesis_bounds", test_thesis_bounds, 0},
      {"thesis_errors", test_thesis_errors, 0},
      {"thesis_parallel", test_thesis_parallel, 0},
      {"handle_basic", test_handle_basic, 0},
      {"handle_errors", test_handle_errors, 0},
      {"handle_destroy_running", test_handle_destroy_running, 0},
      {"handle_frames", test_handle_frames, 0},
      {"handle_queries", test_handle_queries, 0},
      {"exit_without_cleanup", test_exit_without_cleanup, 1},
  };
  size_t i;
  int ran = 0;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i)
    if (argc < 2 ? !cases[i].named_only : strcmp(argv[1], cases[i].name) == 0) {
      const int before = failures;
      printf("== %s\n", cases[i].name);
      cases[i].run();
      printf("%s: %s\n", cases[i].name, failures == before ? "passed" : "FAILED");
      ++ran;
    }
  if (ran == 0) {
    fprintf(stderr, "unknown case '%s'\n", argv[1]);
    return 2;
  }
  return failures == 0 ? 0 : 1;
}
