/* roomsense.h: the handle-based C API of roomsense, for new code (C, C#, Rust, Python ctypes, ...).
 *
 * The same room pipeline as RoomCreatorLibrary.h (thesis chapter 3), in the same library, without its
 * globals:
 * - Every analyzer is independent. Any number may exist and compute at the same time.
 * - Every function is thread-safe on one analyzer, except rs_analyzer_destroy, which must not race any
 *   other call on that analyzer.
 * - The caller owns every buffer. Results are copied out with OpenXR's two-call idiom: call once with
 *   capacity 0 to learn the count, then again with a buffer of at least that many elements. A non-zero
 *   capacity below the count returns RS_ERROR_SIZE_INSUFFICIENT and sets the count.
 * - No function throws, aborts or keeps a pointer it was given after it returns.
 *
 *     rs_analyzer* a;
 *     rs_analyzer_create(NULL, &a);                          // default options
 *     rs_analyzer_compute(a, xyz, vertex_count, NULL, 0);    // a point cloud; or pass triangle indices
 *     rs_state state;
 *     rs_analyzer_wait(a, RS_WAIT_INFINITE, &state);         // or poll rs_analyzer_state once per frame
 *     uint32_t n = 0;
 *     rs_analyzer_get_areas(a, 0, &n, NULL);
 *     rs_area* areas = malloc(n * sizeof *areas);
 *     rs_analyzer_get_areas(a, n, &n, areas);
 *     rs_analyzer_destroy(a);
 *
 * After a compute, the analyzer also answers placement queries (API 1.1, at the end of this header): where an
 * object of a given size can go, random points on the surfaces and in free space, whether a point is inside
 * the room, and where a ray hits it.
 *
 * Frame: results are in roomsense's frame, right-handed, +Y up, metres (OpenXR's STAGE/LOCAL). Input in
 * another frame is converted first as rs_analyzer_options says (up axis, units, handedness); results are
 * not converted back. Triangles, input and output, are counter-clockwise seen from the front.
 */
#ifndef ROOMSENSE_ROOMSENSE_H_
#define ROOMSENSE_ROOMSENSE_H_

#include <stdint.h>

#if !defined(ROOMSENSE_CAPI_EXPORT)
#  if defined(_WIN32)
#    if defined(ROOMSENSE_CAPI_BUILDING)
#      define ROOMSENSE_CAPI_EXPORT __declspec(dllexport)
#    else
#      define ROOMSENSE_CAPI_EXPORT __declspec(dllimport)
#    endif
#  elif defined(__GNUC__)
#    define ROOMSENSE_CAPI_EXPORT __attribute__((visibility("default")))
#  else
#    define ROOMSENSE_CAPI_EXPORT
#  endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* (major << 22) | (minor << 12) | patch, like XR_MAKE_VERSION. rs_api_version() returns the library's;
 * a library with the same major version as the header is compatible. */
#define RS_MAKE_VERSION(major, minor, patch) \
  ((((uint32_t)(major)) << 22) | (((uint32_t)(minor)) << 12) | ((uint32_t)(patch)))
#define RS_API_VERSION RS_MAKE_VERSION(1, 3, 0)  /* 1.1: placement queries; 1.2: rooms; 1.3: chunks */

/* Every enum has a _MAX_ENUM member, as in OpenXR: it makes the enum 32 bits wide in every compiler and
 * lets C++ hold any 32-bit value a caller passes (options are checked, not trusted).
 * Results, as in OpenXR: zero and positive values are successes, negative values errors. */
typedef enum rs_result {
  RS_SUCCESS = 0,
  RS_ERROR_INVALID_ARGUMENT = -1,    /* a NULL pointer where one is required, an option out of range */
  RS_ERROR_HANDLE_INVALID = -2,      /* a NULL analyzer */
  RS_ERROR_SIZE_INSUFFICIENT = -3,   /* a capacity below the count; the count is set */
  RS_ERROR_BUSY = -4,                /* rs_analyzer_compute while a compute runs */
  RS_ERROR_NOT_READY = -5,           /* a getter while a compute runs */
  RS_ERROR_NO_RESULT = -6,           /* a getter before any compute */
  RS_ERROR_EMPTY_INPUT = -7,         /* no vertices (thesis code 1) */
  RS_ERROR_BAD_INDICES = -8,         /* an index count not a multiple of 3, or an index out of range */
  RS_ERROR_NO_VALID_VERTICES = -9,   /* every vertex was NaN/Inf or a far outlier */
  RS_ERROR_GRID_TOO_LARGE = -10,     /* the scan's extent needs more voxels than the memory budget */
  RS_ERROR_NO_ROOM = -11,            /* no floor and ceiling at least 1.5 m apart: nothing to analyse */
  RS_ERROR_OUT_OF_MEMORY = -12,
  RS_ERROR_INTERNAL = -13,           /* a bug; rs_analyzer_get_message says more */
  RS_ERROR_TOO_MUCH_WORK = -14,      /* the triangles need more voxel tests than the work budget: use larger voxels */
  RS_RESULT_MAX_ENUM = 0x7FFFFFFF
} rs_result;

/* A constant, readable name for people: "RS_ERROR_BUSY". Never NULL; "RS_UNKNOWN_RESULT" for others. */
ROOMSENSE_CAPI_EXPORT const char* rs_result_string(rs_result result);
ROOMSENSE_CAPI_EXPORT uint32_t rs_api_version(void);

typedef enum rs_up_axis { RS_UP_AXIS_Y = 0, RS_UP_AXIS_Z = 1, RS_UP_AXIS_MAX_ENUM = 0x7FFFFFFF } rs_up_axis;
typedef enum rs_units {
  RS_UNITS_METRES = 0, RS_UNITS_CENTIMETRES = 1, RS_UNITS_MILLIMETRES = 2, RS_UNITS_MAX_ENUM = 0x7FFFFFFF
} rs_units;

/* What a compute produces; a run without areas or without bounds is faster. */
typedef enum rs_compute_flag_bits {
  RS_COMPUTE_AREAS = 1,   /* placement areas (thesis §3.3-3.5) */
  RS_COMPUTE_BOUNDS = 2,  /* the room-bounds mesh (thesis §3.6) */
  RS_COMPUTE_FLAG_BITS_MAX_ENUM = 0x7FFFFFFF
} rs_compute_flag_bits;

typedef struct rs_analyzer_options {
  uint32_t struct_size;    /* sizeof(rs_analyzer_options); rs_analyzer_options_init sets it */
  float voxel_size;        /* metres, in [0.01, 1]; 0 means the default 0.10 */
  uint32_t thread_count;   /* 0: one per hardware thread. Results do not depend on it. */
  uint32_t compute_flags;  /* rs_compute_flag_bits; 0 means both */
  rs_up_axis up_axis;      /* the input's up axis */
  rs_units units;          /* the input's units */
  int32_t left_handed;     /* non-zero: the input is left-handed (Unity with +Y up, Unreal with +Z up) */
} rs_analyzer_options;

/* Fills *options with the defaults: 0.10 m voxels, all threads, areas and bounds, right-handed +Y up
 * metres (no conversion). */
ROOMSENSE_CAPI_EXPORT void rs_analyzer_options_init(rs_analyzer_options* options);

typedef struct rs_analyzer rs_analyzer;

/* options may be NULL for the defaults. RS_ERROR_INVALID_ARGUMENT for a NULL `out`, a struct_size below
 * the first version's, or an option out of range. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_create(const rs_analyzer_options* options, rs_analyzer** out);

/* Frees the analyzer and its results. A running compute is stopped first; this returns within about
 * 100 ms whatever the compute is doing. NULL is ignored. */
ROOMSENSE_CAPI_EXPORT void rs_analyzer_destroy(rs_analyzer* analyzer);

/* Starts analysing a scan on the analyzer's worker thread (started at its first compute and kept until
 * rs_analyzer_destroy) and returns at once. The scan is copied before the call
 * returns. xyz: vertex_count vertices, 3 floats each. indices: index_count triangle indices, 3 per
 * triangle, or NULL with index_count 0 for a point cloud (the thesis's input). NaN/Inf vertices are
 * skipped, far outliers rejected. A new compute replaces the previous result.
 * Returns RS_SUCCESS (started), RS_ERROR_BUSY, RS_ERROR_EMPTY_INPUT (xyz NULL or vertex_count 0),
 * RS_ERROR_BAD_INDICES, RS_ERROR_OUT_OF_MEMORY, RS_ERROR_HANDLE_INVALID. Errors found while computing
 * (RS_ERROR_NO_ROOM, ...) make the state RS_STATE_FAILED and are returned by the getters. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_compute(rs_analyzer* analyzer, const float* xyz, uint32_t vertex_count,
                                                    const uint32_t* indices, uint32_t index_count);

/* ---- A room in chunks (API 1.3) ----
 * As headsets deliver a room: mesh blocks by id, added, re-sent and removed while the user looks around.
 * rs_analyzer_set_chunk adds the chunk of that id or replaces it (vertices and indices as for
 * rs_analyzer_compute, indices into the chunk's own vertices; copied, converted to roomsense's frame);
 * rs_analyzer_remove_chunk removes it (RS_ERROR_INVALID_ARGUMENT when there is none). Both may be called while a
 * compute runs: the change waits for the next rs_analyzer_compute_chunks, which analyses every chunk held,
 * in id order, as one scan, and gives the same result as rs_analyzer_compute on that scan. It voxelizes only
 * the chunks changed since the last one (while the grid's extent stays), derives again only what the change
 * can reach (the area searches near it; features when the voxels changed; the bounds meshes through the voxel
 * layers that changed; the input checks and surface heights of the changed chunks), and when nothing changed
 * it keeps the previous result, already in C form, at once. rs_analyzer_compute does not touch the chunks. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_set_chunk(rs_analyzer* analyzer, uint64_t chunk_id, const float* xyz,
                                                      uint32_t vertex_count, const uint32_t* indices,
                                                      uint32_t index_count);
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_remove_chunk(rs_analyzer* analyzer, uint64_t chunk_id);
/* Returns as rs_analyzer_compute does; RS_ERROR_EMPTY_INPUT when no chunk is held. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_compute_chunks(rs_analyzer* analyzer);

typedef enum rs_state {
  RS_STATE_IDLE = 0,     /* no compute yet */
  RS_STATE_RUNNING = 1,
  RS_STATE_READY = 2,    /* results can be read */
  RS_STATE_FAILED = 3,   /* the getters return why; rs_analyzer_get_message says it in words */
  RS_STATE_MAX_ENUM = 0x7FFFFFFF
} rs_state;

/* Never blocks (beyond a short lock). */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_state(rs_analyzer* analyzer, rs_state* out);

#define RS_WAIT_INFINITE UINT32_MAX
/* Blocks until no compute runs or timeout_ms passes; `out` (nullable) receives the state then, which is
 * RS_STATE_RUNNING after a timeout. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_wait(rs_analyzer* analyzer, uint32_t timeout_ms, rs_state* out);

/* The getters below return RS_ERROR_NOT_READY while a compute runs, RS_ERROR_NO_RESULT before the first,
 * and the failure's code after a failed one. */

typedef struct rs_vec3 { float x, y, z; } rs_vec3;
typedef struct rs_quat { float x, y, z, w; } rs_quat;  /* as XrQuaternionf */

typedef struct rs_timings {  /* milliseconds, per stage of the pipeline; areas and bounds overlap: total is the
                                * analysis's own time, not the stages' sum */
  double prepare, voxelize, features, areas, reduce, classify, bounds, total;
} rs_timings;

typedef struct rs_layout {
  float floor_y;                  /* metres: the scanned floor surface of the main storey */
  float ceiling_y;                /* the ceiling surface of the main storey */
  uint32_t storey_count;          /* at least 1; see rs_analyzer_get_storeys */
  uint32_t area_count;            /* what rs_analyzer_get_areas returns */
  uint32_t bounds_vertex_count;   /* what rs_analyzer_get_bounds returns */
  uint32_t bounds_index_count;
  uint32_t input_vertex_count;    /* as given */
  uint32_t input_triangle_count;
  uint32_t skipped_vertex_count;  /* NaN / Inf */
  uint32_t outlier_vertex_count;  /* far from the room, rejected */
  float voxel_size;               /* metres */
  rs_vec3 grid_origin;            /* minimum corner of voxel (0,0,0) */
  uint32_t grid_dims[3];          /* voxels along x, y, z */
  rs_timings timings;
} rs_layout;

ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_layout(rs_analyzer* analyzer, rs_layout* out);

typedef struct rs_storey { float floor_y, ceiling_y; } rs_storey;

/* The storeys found, main storey first (two-call idiom). */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_storeys(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count,
                                                        rs_storey* storeys);

/* The numeric values are those of the OpenXR extension XR_EXTX_room_understanding. */
typedef enum rs_area_type {
  RS_AREA_TYPE_NONE = 0,  /* no surface: a ray that hit nothing, a point in free space */
  RS_AREA_TYPE_WALL = 1, RS_AREA_TYPE_FLOOR = 2, RS_AREA_TYPE_CEILING = 3, RS_AREA_TYPE_FURNITURE = 4,
  RS_AREA_TYPE_MAX_ENUM = 0x7FFFFFFF
} rs_area_type;
typedef enum rs_area_size {
  RS_AREA_SIZE_LARGE = 1, RS_AREA_SIZE_MEDIUM = 2, RS_AREA_SIZE_SMALL = 3, RS_AREA_SIZE_MAX_ENUM = 0x7FFFFFFF
} rs_area_size;
typedef enum rs_reach {
  RS_REACH_CLOSE = 1, RS_REACH_DISTANCE = 2, RS_REACH_NONE = 3, RS_REACH_MAX_ENUM = 0x7FFFFFFF
} rs_reach;

/* Category bits of thesis Eq. 3.58; exactly one of each group is set. */
enum {
  RS_FLAG_SIZE_LARGE = 1, RS_FLAG_SIZE_MEDIUM = 2, RS_FLAG_SIZE_SMALL = 4,
  RS_FLAG_REACH_CLOSE = 8, RS_FLAG_REACH_DISTANCE = 16, RS_FLAG_REACH_NONE = 32,
  RS_FLAG_TYPE_WALL = 64, RS_FLAG_TYPE_FLOOR = 128, RS_FLAG_TYPE_FURNITURE = 256, RS_FLAG_TYPE_CEILING = 512
};

/* One classified placement area (thesis §3.5), a rectangle on a surface.
 * Pose: +Z is the normal, into free space; for walls +Y is world up. corners go counter-clockwise seen
 * from the front: corners[0] -> corners[1] is the width (+X), corners[1] -> corners[2] the height (+Y). */
typedef struct rs_area {
  rs_area_type type;
  rs_area_size size;
  rs_reach reach;
  uint32_t flags;          /* Eq. 3.58 */
  rs_vec3 center;
  rs_vec3 normal;          /* unit */
  rs_quat orientation;     /* rotates (X, Y, Z) onto (width axis, height axis, normal): the OpenXR pose */
  rs_vec3 corners[4];
  float half_width;        /* centre to the right edge, metres */
  float half_height;       /* centre to the upper edge, metres */
  float rotation_deg;      /* about the normal, right-handed; 0 for walls */
  float volume_height;     /* clear space checked in front of the surface, along the normal, metres */
} rs_area;

/* The areas: walls, floors, ceilings, furniture; large before medium before small (two-call idiom). */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_areas(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count,
                                                      rs_area* areas);

/* ---- Rooms (API 1.2) ----
 * Each storey's free space split into rooms at doorways and passages at most 1.2 m wide between walls. */
#define RS_NO_ROOM (-1)

/* A room: its storey (an index into rs_analyzer_get_storeys), its free floor and where it is. */
typedef struct rs_room {
  uint32_t storey;
  float floor_area;        /* m² of free floor columns */
  rs_vec3 center;          /* the centroid of its free floor, at its floor's height */
  float floor_y, ceiling_y;
} rs_room;

/* The rooms, storey by storey, each storey's largest first (two-call idiom). */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_rooms(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count,
                                                      rs_room* rooms);

/* Where an area lies: element i belongs to element i of rs_analyzer_get_areas (the same count). */
typedef struct rs_area_place {
  uint32_t storey;         /* index into rs_analyzer_get_storeys; 0: the main storey */
  int32_t room;            /* index into rs_analyzer_get_rooms, or RS_NO_ROOM */
} rs_area_place;

ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_area_places(rs_analyzer* analyzer, uint32_t capacity,
                                                            uint32_t* count, rs_area_place* places);

/* The room-bounds mesh: the surface of the solid bounds volume (thesis §3.6), closed, each vertex once,
 * counter-clockwise front faces towards free space (inside the room, towards the room). Capacities and counts are in vertices (xyz holds 3 floats per vertex) and in indices (3 per
 * triangle). With both capacities 0 only the counts are set; otherwise both buffers must be large enough,
 * or nothing is written and RS_ERROR_SIZE_INSUFFICIENT returned. Needs RS_COMPUTE_BOUNDS. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_bounds(rs_analyzer* analyzer, uint32_t vertex_capacity,
                                                       uint32_t* vertex_count, float* xyz, uint32_t index_capacity,
                                                       uint32_t* index_count, uint32_t* indices);

/* API 1.2: one room's own bounds (room: an index into rs_analyzer_get_rooms), closed across its doorways where
 * the next room begins; otherwise as rs_analyzer_get_bounds. A room index out of range is
 * RS_ERROR_INVALID_ARGUMENT. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_room_bounds(rs_analyzer* analyzer, uint32_t room,
                                                            uint32_t vertex_capacity, uint32_t* vertex_count,
                                                            float* xyz, uint32_t index_capacity,
                                                            uint32_t* index_count, uint32_t* indices);

/* A line for people about the last compute, NUL-terminated (two-call idiom; count includes the NUL):
 * "ok" and any warnings (skipped vertices, ...), or why it failed. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_get_message(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count,
                                                        char* buffer);

/* ---- Placement queries (API 1.1) ----
 * Questions about the room of the last successful compute, answered in microseconds to a millisecond without
 * copying the room, from any thread, at the same time as the getters. Each answer is deterministic for the
 * same query and seed. Like the getters they return RS_ERROR_NOT_READY while a compute runs, RS_ERROR_NO_RESULT
 * before the first and the failure's code after a failed one. A query the room cannot satisfy is not an error:
 * it finds nothing and says why. The first query of a result builds the room's index for them (about 0.5 ms
 * on a 78k-vertex room), on the thread that asks; queries asked meanwhile wait for that one build. */

/* The surfaces a query may use. The values are those of the extension's XrRoomSurfaceFlagsEXTX. */
typedef enum rs_surface_bits {
  RS_SURFACE_WALL = 1, RS_SURFACE_FLOOR = 2, RS_SURFACE_CEILING = 4, RS_SURFACE_FURNITURE = 8,
  RS_SURFACE_ANY = 15, RS_SURFACE_BITS_MAX_ENUM = 0x7FFFFFFF
} rs_surface_bits;

/* The reach a placement must have (thesis §3.5.1); 0 accepts any. */
typedef enum rs_reach_filter {
  RS_REACH_FILTER_ANY = 0, RS_REACH_FILTER_CLOSE = 1, RS_REACH_FILTER_DISTANCE = 2, RS_REACH_FILTER_MAX_ENUM = 0x7FFFFFFF
} rs_reach_filter;

/* Why fewer placements than max_count were found. */
typedef enum rs_placement_shortfall {
  RS_SHORTFALL_NONE = 0,
  RS_SHORTFALL_NO_SURFACE = 1,   /* the room has no free surface of the asked kinds */
  RS_SHORTFALL_NO_SPACE = 2,     /* no spot holds the footprint with its clearance and edge distance */
  RS_SHORTFALL_NO_HEADROOM = 3,  /* spots hold the footprint, not the object's height and clearance above */
  RS_SHORTFALL_NO_REACH = 4,     /* spots fit, none with the asked reach */
  RS_SHORTFALL_TOO_FEW = 5,      /* some found, not max_count without overlapping */
  RS_SHORTFALL_MAX_ENUM = 0x7FFFFFFF
} rs_placement_shortfall;

/* An object to place: a box in the frame of the pose a placement returns. size.x (width) and size.y (depth)
 * span its footprint on the surface, size.z is its height along the surface's normal; on a wall x runs along
 * the wall, y up it. Lengths are metres, finite, at most 100 m. */
typedef struct rs_placement_query {
  uint32_t struct_size;      /* sizeof(rs_placement_query); rs_placement_query_init sets it */
  rs_vec3 size;              /* each > 0 */
  uint32_t surfaces;         /* rs_surface_bits, at least one */
  float clearance;           /* free space around the footprint on every side */
  float clearance_above;     /* free space above the object's height */
  float edge_distance;       /* the footprint stays this far inside its free surface's edge */
  rs_reach_filter reach;
  int32_t has_user_position; /* non-zero: reach is judged from user_position (close: within user_reach of it) */
  rs_vec3 user_position;     /* otherwise close means next to free floor, as the thesis's areas */
  float user_reach;          /* metres; 0 means 0.7 */
  int32_t has_near_point;    /* non-zero: best first means nearest near_point; else the most free space */
  rs_vec3 near_point;
  rs_vec3 face_direction;    /* non-zero: the footprint's +Y points this way on horizontal surfaces */
  uint32_t max_count;        /* 1 to 1024 */
  int32_t allow_overlap;     /* zero: no two placements' clear boxes overlap */
  uint32_t reserved;         /* 0; keeps seed 8-byte aligned without implicit padding */
  uint64_t seed;             /* breaks ties between equally good spots */
} rs_placement_query;

/* Fills *query with the defaults: a 0.3 m cube on any surface, no clearance, any reach, one placement, seed 0. */
ROOMSENSE_CAPI_EXPORT void rs_placement_query_init(rs_placement_query* query);

/* One place for the object. Pose as rs_area's: +Z the normal into free space, walls +Y up; corners are the
 * footprint's, counter-clockwise seen from the front. */
typedef struct rs_placement {
  rs_area_type surface;
  rs_reach reach;
  uint32_t storey;          /* 0: the main storey */
  rs_vec3 center;           /* the footprint's centre, on the surface */
  rs_vec3 normal;
  rs_quat orientation;      /* rotates (X, Y, Z) onto (width axis, depth axis, normal) */
  rs_vec3 corners[4];
  float width, depth;       /* the query's size.x and size.y */
  float margin;             /* free surface beyond the footprint, its clearance and edge distance, metres */
} rs_placement;

/* Up to query->max_count placements, best first (two-call idiom: the count and *shortfall are set by both
 * calls). shortfall may be NULL. RS_ERROR_INVALID_ARGUMENT for a NULL query or count, a struct_size below
 * this version's, a non-zero reserved, or a value out of range. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_find_placements(rs_analyzer* analyzer, const rs_placement_query* query,
                                                            uint32_t capacity, uint32_t* count,
                                                            rs_placement* placements,
                                                            rs_placement_shortfall* shortfall);

typedef struct rs_ray_hit {
  int32_t hit;              /* zero: nothing within max_distance; the other members are zero */
  int32_t scanned;          /* zero: the ray left through an unscanned part (a hole, an open door); the hit
                               lies on the room's bounds there */
  rs_area_type surface;
  float distance;           /* from the origin along the unit direction, metres */
  rs_vec3 position;
  rs_vec3 normal;           /* unit, against the ray */
} rs_ray_hit;

/* The first scanned surface or room edge along the ray, within a voxel. max_distance 0 means unlimited.
 * direction need not be unit length; it is normalized. RS_ERROR_INVALID_ARGUMENT for NULL pointers, a
 * non-finite origin, a non-finite direction or one of length 1e-12 or less (or too long to normalize in
 * float), or a negative or non-finite max_distance. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_raycast(rs_analyzer* analyzer, const rs_vec3* origin,
                                                    const rs_vec3* direction, float max_distance, rs_ray_hit* out);

typedef struct rs_location {
  int32_t inside;           /* within the room's walls, between its floor and its ceiling */
  int32_t free;             /* inside, and in no voxel of the scan */
  uint32_t storey;
} rs_location;

/* Where a point lies. RS_ERROR_INVALID_ARGUMENT for NULL pointers or a non-finite point. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_locate(rs_analyzer* analyzer, const rs_vec3* point, rs_location* out);

typedef struct rs_surface_point {
  int32_t found;            /* zero: no such surface, or no free space with that clearance */
  rs_area_type surface;     /* RS_AREA_TYPE_NONE for a point in free space */
  rs_vec3 position;
  rs_vec3 normal;           /* zero for a point in free space */
} rs_surface_point;

/* A point on free surface of the asked kinds (rs_surface_bits, at least one), at least edge_distance inside
 * its edge, uniform over their area. RS_ERROR_INVALID_ARGUMENT for a NULL out, surfaces 0 or with bits
 * outside RS_SURFACE_ANY, or an edge_distance outside 0 to 100 m (or not finite). */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_random_point_on_surface(rs_analyzer* analyzer, uint32_t surfaces,
                                                                    float edge_distance, uint64_t seed,
                                                                    rs_surface_point* out);

/* A point inside the room with no scanned voxel and no room edge within `clearance` metres, uniform over
 * such points. RS_ERROR_INVALID_ARGUMENT for a NULL out or a clearance outside 0 to 100 m (or not finite);
 * a clearance the room cannot hold finds nothing at once. */
ROOMSENSE_CAPI_EXPORT rs_result rs_analyzer_random_point_in_room(rs_analyzer* analyzer, float clearance, uint64_t seed,
                                                                 rs_surface_point* out);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif /* ROOMSENSE_ROOMSENSE_H_ */
