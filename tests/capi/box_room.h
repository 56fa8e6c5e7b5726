/* A simple box room as a dense point cloud, generated in plain C the way an engine script would gather
 * scan vertices: floor, ceiling, four walls, and a table with open space below. Coordinates are in the
 * frame the caller gives the library (for the thesis API, Unity's: +Y up, metres). */
#ifndef ROOMSENSE_TESTS_CAPI_BOX_ROOM_H_
#define ROOMSENSE_TESTS_CAPI_BOX_ROOM_H_

#include <stdlib.h>

/* The room: x in [BOX_CX - 2.5, BOX_CX + 2.5], z in [BOX_CZ - 2, BOX_CZ + 2], y in [BOX_FLOOR, BOX_CEILING].
 * Off the origin on purpose, with the floor below y = 0 as in a LOCAL space around the head. */
#define BOX_CX 0.7f
#define BOX_CZ (-0.4f)
#define BOX_HALF_X 2.5f
#define BOX_HALF_Z 2.0f
#define BOX_FLOOR (-1.3f)
#define BOX_CEILING 1.3f
/* The table: a 1.2 x 0.8 m top, 0.75 m above the floor, centred here. */
#define TABLE_CX (BOX_CX + 1.1f)
#define TABLE_CZ (BOX_CZ + 0.9f)
#define TABLE_HALF_X 0.6f
#define TABLE_HALF_Z 0.4f
#define TABLE_HEIGHT 0.75f
#define BOX_SPACING 0.04f

typedef struct box_points {
  float* xyz;
  int count; /* points */
  int capacity;
} box_points;

static void box_add(box_points* p, float x, float y, float z) {
  if (p->count == p->capacity) {
    p->capacity = p->capacity ? 2 * p->capacity : 4096;
    p->xyz = (float*)realloc(p->xyz, (size_t)p->capacity * 3 * sizeof(float));
    if (!p->xyz) abort();
  }
  p->xyz[3 * p->count + 0] = x;
  p->xyz[3 * p->count + 1] = y;
  p->xyz[3 * p->count + 2] = z;
  ++p->count;
}

static int box_steps(float length) { return (int)(length / BOX_SPACING + 0.5f); }

/* A rectangle spanned from `o` along `u` and `v` (lengths lu, lv), sampled every BOX_SPACING. */
static void box_rect(box_points* p, const float o[3], const float u[3], float lu, const float v[3], float lv) {
  const int nu = box_steps(lu), nv = box_steps(lv);
  int i, j;
  for (i = 0; i <= nu; ++i)
    for (j = 0; j <= nv; ++j) {
      const float a = lu * (float)i / (float)nu, b = lv * (float)j / (float)nv;
      box_add(p, o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]);
    }
}

/* Returns the points; *count receives the number of points (floats = 3 * count). Free with free(). */
static float* box_room(int* count, int with_table) {
  box_points p = {0, 0, 0};
  const float x0 = BOX_CX - BOX_HALF_X, x1 = BOX_CX + BOX_HALF_X;
  const float z0 = BOX_CZ - BOX_HALF_Z, z1 = BOX_CZ + BOX_HALF_Z;
  const float h = BOX_CEILING - BOX_FLOOR;
  const float ux[3] = {1, 0, 0}, uy[3] = {0, 1, 0}, uz[3] = {0, 0, 1};
  {
    const float floor_o[3] = {x0, BOX_FLOOR, z0}, ceiling_o[3] = {x0, BOX_CEILING, z0};
    box_rect(&p, floor_o, ux, x1 - x0, uz, z1 - z0);
    box_rect(&p, ceiling_o, ux, x1 - x0, uz, z1 - z0);
  }
  {
    const float south[3] = {x0, BOX_FLOOR, z0}, north[3] = {x0, BOX_FLOOR, z1};
    const float west[3] = {x0, BOX_FLOOR, z0}, east[3] = {x1, BOX_FLOOR, z0};
    box_rect(&p, south, ux, x1 - x0, uy, h);
    box_rect(&p, north, ux, x1 - x0, uy, h);
    box_rect(&p, west, uz, z1 - z0, uy, h);
    box_rect(&p, east, uz, z1 - z0, uy, h);
  }
  if (with_table) {
    const float ty = BOX_FLOOR + TABLE_HEIGHT;
    const float top[3] = {TABLE_CX - TABLE_HALF_X, ty, TABLE_CZ - TABLE_HALF_Z};
    const float under[3] = {TABLE_CX - TABLE_HALF_X, ty - 0.03f, TABLE_CZ - TABLE_HALF_Z};
    int corner;
    box_rect(&p, top, ux, 2 * TABLE_HALF_X, uz, 2 * TABLE_HALF_Z);
    box_rect(&p, under, ux, 2 * TABLE_HALF_X, uz, 2 * TABLE_HALF_Z);
    for (corner = 0; corner < 4; ++corner) { /* legs: thin vertical strips */
      const float lx = TABLE_CX + ((corner & 1) ? 1.0f : -1.0f) * (TABLE_HALF_X - 0.05f);
      const float lz = TABLE_CZ + ((corner & 2) ? 1.0f : -1.0f) * (TABLE_HALF_Z - 0.05f);
      const float leg[3] = {lx, BOX_FLOOR, lz};
      box_rect(&p, leg, ux, 0.04f, uy, TABLE_HEIGHT - 0.03f);
    }
  }
  *count = p.count;
  return p.xyz;
}

#endif /* ROOMSENSE_TESTS_CAPI_BOX_ROOM_H_ */
