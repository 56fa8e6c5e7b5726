#ifndef XR_EXTX_ROOM_UNDERSTANDING_H_
#define XR_EXTX_ROOM_UNDERSTANDING_H_ 1

/*
** XR_EXTX_room_understanding: placement areas and a simplified room-bounds mesh computed from the runtime's
** scene meshes, provided by the implicit API layer XR_APILAYER_ROOMSENSE_room_understanding (roomsense).
**
** Enable the extension in xrCreateInstance (the layer's manifest lists it, so the loader accepts it even though
** the runtime does not know it) and get its functions from xrGetInstanceProcAddr. Without the extension enabled,
** xrGetInstanceProcAddr answers XR_ERROR_FUNCTION_UNSUPPORTED for them.
**
** Usage:
**   1. xrCreateRoomAnalyzerEXTX(session, {baseSpace = a LOCAL or STAGE space}) -> analyzer.
**   2. Optionally xrSubmitRoomMeshEXTX(analyzer, mesh) for meshes the application has itself.
**   3. xrComputeRoomEXTX(analyzer, {time, includeRuntimeMeshes}) starts an asynchronous analysis. With
**      includeRuntimeMeshes the layer queries the runtime's scene meshes (XR_MSFT_scene_understanding) itself
**      and adds the scene meshes the application has read; it always adds the submitted meshes. When those
**      meshes (and the runtime's labels) are the ones the latest result was computed from, the compute
**      completes without a new analysis and that result stands, computeDuration included.
**   4. Poll xrGetRoomComputeStateEXTX until COMPLETED (or FAILED). Computing again while RUNNING returns
**      XR_ERROR_CALL_ORDER_INVALID.
**   5. xrGetRoomLayoutEXTX, xrGetRoomAreasEXTX (two-call idiom) and xrGetRoomBoundsMeshEXTX (two-call idiom on
**      both arrays) return the latest completed result; before any result exists they return
**      XR_ERROR_CALL_ORDER_INVALID. A failed compute leaves the previous result in place.
**   6. Spec version 2: queries on the latest result, each answered at once (well under a millisecond):
**      xrFindRoomPlacementsEXTX (where an object of a given size fits: poses best first, two-call idiom),
**      xrRaycastRoomEXTX, xrGetRoomRandomPointEXTX and xrLocateRoomPointEXTX. Each is deterministic for a given
**      query and seed. A query the room cannot satisfy succeeds with no result and says why.
**   7. Spec version 3: whole homes. Chain XrRoomHomeLayoutEXTX to XrRoomLayoutEXTX::next for every storey's
**      heights and the rooms (each storey's free space split at doorways and passages at most 1.2 m wide
**      between walls), XrRoomAreaLocationEXTX to an XrRoomAreaEXTX's next for that area's storey and room, and
**      XrRoomBoundsMeshRoomEXTX to XrRoomBoundsMeshEXTX::next for one room's own closed bounds mesh.
**   Destroying the session (or the instance) destroys its analyzers, also while an analysis runs. Once the
**   runtime answered one of the layer's calls in the session with XR_ERROR_SESSION_LOST (the compute then ends
**   FAILED), xrCreateRoomAnalyzerEXTX and xrComputeRoomEXTX return XR_ERROR_SESSION_LOST for that session.
**
** Everything is in the analyzer's baseSpace: right-handed, +Y up, metres.
**
** Structure type values: this extension has no number in the Khronos registry. Its values use the enum block of
** extension number 100000 (1000000000 + (100000 - 1) * 1000 = 1099999000), far above every registered
** extension (the registry is below number 1000), so they cannot collide with a registered structure type.
** XrStructureType cannot be extended in C, so they are defined as casts.
*/

#include <openxr/openxr.h>

#ifdef __cplusplus
extern "C" {
#endif

#define XR_EXTX_room_understanding 1
#define XR_EXTX_room_understanding_SPEC_VERSION 3
#define XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME "XR_EXTX_room_understanding"

XR_DEFINE_HANDLE(XrRoomAnalyzerEXTX)

/* The enum block of (unregistered) extension number 100000. */
#define XR_EXTX_ROOM_UNDERSTANDING_ENUM_BASE 1099999000

#define XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX ((XrStructureType)1099999000)
#define XR_TYPE_ROOM_MESH_EXTX ((XrStructureType)1099999001)
#define XR_TYPE_ROOM_COMPUTE_INFO_EXTX ((XrStructureType)1099999002)
#define XR_TYPE_ROOM_LAYOUT_EXTX ((XrStructureType)1099999003)
#define XR_TYPE_ROOM_AREA_EXTX ((XrStructureType)1099999004)
#define XR_TYPE_ROOM_BOUNDS_MESH_EXTX ((XrStructureType)1099999005)
/* roomsense's addition, chained to XrRoomLayoutEXTX::next: the analysis as JSON (see below). */
#define XR_TYPE_ROOM_ANALYSIS_JSON_EXTX ((XrStructureType)1099999006)
/* Spec version 2: the queries. */
#define XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX ((XrStructureType)1099999009)
#define XR_TYPE_ROOM_PLACEMENTS_EXTX ((XrStructureType)1099999010)
#define XR_TYPE_ROOM_PLACEMENT_EXTX ((XrStructureType)1099999011)
#define XR_TYPE_ROOM_RAYCAST_INFO_EXTX ((XrStructureType)1099999012)
#define XR_TYPE_ROOM_RAYCAST_HIT_EXTX ((XrStructureType)1099999013)
#define XR_TYPE_ROOM_RANDOM_POINT_INFO_EXTX ((XrStructureType)1099999014)
#define XR_TYPE_ROOM_POINT_EXTX ((XrStructureType)1099999015)
#define XR_TYPE_ROOM_POINT_LOCATION_EXTX ((XrStructureType)1099999016)
/* Spec version 3: storeys and rooms. */
#define XR_TYPE_ROOM_HOME_LAYOUT_EXTX ((XrStructureType)1099999017)
#define XR_TYPE_ROOM_AREA_LOCATION_EXTX ((XrStructureType)1099999018)
#define XR_TYPE_ROOM_BOUNDS_MESH_ROOM_EXTX ((XrStructureType)1099999019)

/* XrRoomAreaLocationEXTX::roomIndex of an area in no room. */
#define XR_ROOM_INDEX_NONE_EXTX 0xFFFFFFFFu

#define XR_OBJECT_TYPE_ROOM_ANALYZER_EXTX ((XrObjectType)1099999000)

typedef enum XrRoomAreaTypeEXTX {
    XR_ROOM_AREA_TYPE_WALL_EXTX = 1,
    XR_ROOM_AREA_TYPE_FLOOR_EXTX = 2,
    XR_ROOM_AREA_TYPE_CEILING_EXTX = 3,
    XR_ROOM_AREA_TYPE_FURNITURE_EXTX = 4,
    XR_ROOM_AREA_TYPE_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomAreaTypeEXTX;

/* The largest class an area holds: at least 2 x 2 m (walls 2 x 1 m), 1 x 1 m (1 x 0.5 m), 0.5 x 0.5 m
   (0.5 x 0.3 m), less 0.1 m. Areas grow past their class into the free surface around them: extents give
   their actual size. */
typedef enum XrRoomAreaSizeEXTX {
    XR_ROOM_AREA_SIZE_LARGE_EXTX = 1,
    XR_ROOM_AREA_SIZE_MEDIUM_EXTX = 2,
    XR_ROOM_AREA_SIZE_SMALL_EXTX = 3,
    XR_ROOM_AREA_SIZE_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomAreaSizeEXTX;

typedef enum XrRoomInteractionEXTX {
    XR_ROOM_INTERACTION_CLOSE_EXTX = 1,
    XR_ROOM_INTERACTION_DISTANCE_EXTX = 2,
    XR_ROOM_INTERACTION_NONE_EXTX = 3,
    XR_ROOM_INTERACTION_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomInteractionEXTX;

typedef enum XrRoomComputeStateEXTX {
    XR_ROOM_COMPUTE_STATE_NONE_EXTX = 0,
    XR_ROOM_COMPUTE_STATE_RUNNING_EXTX = 1,
    XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX = 2,
    XR_ROOM_COMPUTE_STATE_FAILED_EXTX = 3,
    XR_ROOM_COMPUTE_STATE_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomComputeStateEXTX;

typedef enum XrRoomComputeBackendEXTX {
    XR_ROOM_COMPUTE_BACKEND_AUTO_EXTX = 0,
    XR_ROOM_COMPUTE_BACKEND_CPU_EXTX = 1,
    XR_ROOM_COMPUTE_BACKEND_VULKAN_EXTX = 2,
    XR_ROOM_COMPUTE_BACKEND_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomComputeBackendEXTX;

/* Category bits of XrRoomAreaEXTX::categoryFlags (thesis Eq. 3.58): one bit of each group is set. */
#define XR_ROOM_AREA_CATEGORY_SIZE_LARGE_BIT_EXTX 0x00000001
#define XR_ROOM_AREA_CATEGORY_SIZE_MEDIUM_BIT_EXTX 0x00000002
#define XR_ROOM_AREA_CATEGORY_SIZE_SMALL_BIT_EXTX 0x00000004
#define XR_ROOM_AREA_CATEGORY_INTERACTION_CLOSE_BIT_EXTX 0x00000008
#define XR_ROOM_AREA_CATEGORY_INTERACTION_DISTANCE_BIT_EXTX 0x00000010
#define XR_ROOM_AREA_CATEGORY_INTERACTION_NONE_BIT_EXTX 0x00000020
#define XR_ROOM_AREA_CATEGORY_TYPE_WALL_BIT_EXTX 0x00000040
#define XR_ROOM_AREA_CATEGORY_TYPE_FLOOR_BIT_EXTX 0x00000080
#define XR_ROOM_AREA_CATEGORY_TYPE_FURNITURE_BIT_EXTX 0x00000100
#define XR_ROOM_AREA_CATEGORY_TYPE_CEILING_BIT_EXTX 0x00000200

typedef struct XrRoomAnalyzerCreateInfoEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace baseSpace; /* results are expressed in this space; it must be gravity-aligned (LOCAL or STAGE) */
    float voxelSize;   /* metres; 0 means 0.10; otherwise 0.01 to 1 */
    XrRoomComputeBackendEXTX backend; /* AUTO also follows the environment variable ROOMSENSE_BACKEND */
} XrRoomAnalyzerCreateInfoEXTX;

typedef struct XrRoomMeshEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrPosef pose; /* mesh space -> baseSpace */
    uint32_t vertexCount;
    const XrVector3f* vertices;
    uint32_t indexCount; /* a multiple of 3 (counter-clockwise triangles); 0 for a point cloud */
    const uint32_t* indices;
} XrRoomMeshEXTX;

typedef struct XrRoomComputeInfoEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrTime time; /* when the runtime's meshes are located in baseSpace */
    XrBool32 includeRuntimeMeshes;
} XrRoomComputeInfoEXTX;

typedef struct XrRoomLayoutEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    float floorHeight;   /* y of the main storey's scanned floor surface */
    float ceilingHeight; /* y of its ceiling surface */
    uint32_t storeyCount;
    XrVector3f boundsMin; /* axis-aligned box of the room-bounds mesh */
    XrVector3f boundsMax;
    uint32_t inputVertexCount;
    uint32_t inputTriangleCount;
    XrDuration computeDuration; /* from xrComputeRoomEXTX to the result, nanoseconds */
} XrRoomLayoutEXTX;

typedef struct XrRoomAreaEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrPosef pose;        /* centre; +Z = surface normal into free space; walls: +Y up */
    XrExtent2Df extents; /* full width (X) and height (Y), metres */
    float volumeHeight;  /* clear space checked in front of the surface, along +Z */
    XrRoomAreaTypeEXTX areaType;
    XrRoomAreaSizeEXTX size;
    XrRoomInteractionEXTX interaction;
    uint32_t categoryFlags; /* thesis Eq. 3.58 bits: XR_ROOM_AREA_CATEGORY_*_BIT_EXTX */
} XrRoomAreaEXTX;

typedef struct XrRoomBoundsMeshEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t vertexCapacityInput;
    uint32_t vertexCountOutput;
    XrVector3f* vertices;
    uint32_t indexCapacityInput;
    uint32_t indexCountOutput;
    uint32_t* indices; /* CCW triangles facing free space */
} XrRoomBoundsMeshEXTX;

/* ---- Storeys and rooms (spec version 3) ---- */

typedef struct XrRoomStoreyEXTX {
    float floorHeight;   /* y of the storey's scanned floor surface */
    float ceilingHeight; /* y of its ceiling surface (under a pitched roof, its ridge) */
} XrRoomStoreyEXTX;

/* A room: a storey's free space up to doorways and passages at most 1.2 m wide between walls. */
typedef struct XrRoomInfoEXTX {
    uint32_t storeyIndex; /* into XrRoomHomeLayoutEXTX::storeys */
    float floorArea;      /* m² of free floor */
    XrVector3f center;    /* the centroid of its free floor, at its floor's height */
    float floorHeight;
    float ceilingHeight;
} XrRoomInfoEXTX;

/* Chained to XrRoomLayoutEXTX::next. Two-call idiom on both arrays (as XrRoomBoundsMeshEXTX): the counts are
** always written; an array with a non-zero capacity below its count makes the call return
** XR_ERROR_SIZE_INSUFFICIENT. Storeys come main storey first (its heights are XrRoomLayoutEXTX's), rooms storey by
** storey, each storey's largest first. */
typedef struct XrRoomHomeLayoutEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t storeyCapacityInput;
    uint32_t storeyCountOutput;   /* XrRoomLayoutEXTX::storeyCount */
    XrRoomStoreyEXTX* storeys;
    uint32_t roomCapacityInput;
    uint32_t roomCountOutput;
    XrRoomInfoEXTX* rooms;
} XrRoomHomeLayoutEXTX;

/* Chained to the next of any element of xrGetRoomAreasEXTX's array: where that area lies. */
typedef struct XrRoomAreaLocationEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t storeyIndex; /* 0: the main storey */
    uint32_t roomIndex;   /* into XrRoomHomeLayoutEXTX::rooms, or XR_ROOM_INDEX_NONE_EXTX */
} XrRoomAreaLocationEXTX;

/* Chained to XrRoomBoundsMeshEXTX::next: xrGetRoomBoundsMeshEXTX returns that room's bounds instead, a closed
** mesh around its free space, closed across its doorways where the next room begins (two-call idiom as usual).
** A roomIndex not below XrRoomHomeLayoutEXTX::roomCountOutput returns XR_ERROR_VALIDATION_FAILURE. */
typedef struct XrRoomBoundsMeshRoomEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t roomIndex;
} XrRoomBoundsMeshRoomEXTX;

/* ---- Queries (spec version 2) ----
** All positions and directions are in the analyzer's baseSpace. Invalid arguments (a wrong structure type, NULL,
** a length that is negative, not finite or over 100 m, a zero size or direction, unknown surface bits or enum
** values, maxPlacements 0 or over 1024) return XR_ERROR_VALIDATION_FAILURE; before the first result,
** XR_ERROR_CALL_ORDER_INVALID. */

/* Surfaces a query may use: walls, free floor, free ceiling, furniture tops. */
typedef XrFlags64 XrRoomSurfaceFlagsEXTX;
static const XrRoomSurfaceFlagsEXTX XR_ROOM_SURFACE_WALL_BIT_EXTX = 0x00000001;
static const XrRoomSurfaceFlagsEXTX XR_ROOM_SURFACE_FLOOR_BIT_EXTX = 0x00000002;
static const XrRoomSurfaceFlagsEXTX XR_ROOM_SURFACE_CEILING_BIT_EXTX = 0x00000004;
static const XrRoomSurfaceFlagsEXTX XR_ROOM_SURFACE_FURNITURE_BIT_EXTX = 0x00000008;

typedef enum XrRoomReachFilterEXTX {
    XR_ROOM_REACH_FILTER_ANY_EXTX = 0,
    XR_ROOM_REACH_FILTER_CLOSE_EXTX = 1,    /* interaction CLOSE */
    XR_ROOM_REACH_FILTER_DISTANCE_EXTX = 2, /* interaction DISTANCE */
    XR_ROOM_REACH_FILTER_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomReachFilterEXTX;

/* Why fewer placements than maxPlacements were found. */
typedef enum XrRoomPlacementShortfallEXTX {
    XR_ROOM_PLACEMENT_SHORTFALL_NONE_EXTX = 0,
    XR_ROOM_PLACEMENT_SHORTFALL_NO_SURFACE_EXTX = 1,  /* the room has no free surface of the asked kinds */
    XR_ROOM_PLACEMENT_SHORTFALL_NO_SPACE_EXTX = 2,    /* none holds the footprint with its clearance and edge distance */
    XR_ROOM_PLACEMENT_SHORTFALL_NO_HEADROOM_EXTX = 3, /* spots hold the footprint, not its height and clearance above */
    XR_ROOM_PLACEMENT_SHORTFALL_NO_REACH_EXTX = 4,    /* spots fit, none with the asked reach */
    XR_ROOM_PLACEMENT_SHORTFALL_TOO_FEW_EXTX = 5,     /* fewer than asked without overlapping */
    XR_ROOM_PLACEMENT_SHORTFALL_MAX_ENUM_EXTX = 0x7FFFFFFF
} XrRoomPlacementShortfallEXTX;

/* An object to place, as a box in the frame of the pose a placement returns (the areas' convention): objectSize.x
** (width) and .y (depth) are its footprint on the surface, .z its height along the surface's normal. On a wall, x
** runs along the wall, y up it, and z is how far the object stands out. The clear box (footprint grown by
** clearance on every side, height plus clearanceAbove) holds no scanned surface and stays in the room. */
typedef struct XrRoomPlacementQueryEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrVector3f objectSize;
    XrRoomSurfaceFlagsEXTX surfaces; /* at least one bit */
    float clearance;
    float clearanceAbove;
    float edgeDistance;              /* the footprint stays this far inside the free surface's edge */
    XrRoomReachFilterEXTX reach;
    XrBool32 hasUserPosition;        /* reach from userPosition; else from any free floor (thesis §3.5.1) */
    XrVector3f userPosition;
    float userReach;                 /* metres; 0 means 0.7 */
    XrBool32 hasNearPoint;           /* best first: nearest nearPoint; else the most free space around */
    XrVector3f nearPoint;
    XrVector3f faceDirection;        /* non-zero: horizontal footprints turn +Y along it; walls facing it rank higher */
    uint32_t maxPlacements;          /* 1 to 1024 */
    XrBool32 allowOverlap;           /* false: no placement lies in another's clear box */
    uint64_t seed;                   /* breaks ties between equally good spots */
} XrRoomPlacementQueryEXTX;

typedef struct XrRoomPlacementEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrPosef pose;        /* footprint centre on the surface; +Z the normal into free space; walls: +Y up */
    XrExtent2Df extents; /* the footprint: objectSize.x, objectSize.y */
    XrRoomAreaTypeEXTX surfaceType;
    XrRoomInteractionEXTX interaction;
    uint32_t storeyIndex;
    float margin;        /* free surface beyond the footprint and its clearance, metres (an estimate, at most 0.5) */
} XrRoomPlacementEXTX;

/* Two-call idiom on placements: the count is how many the query finds (the same on every call). */
typedef struct XrRoomPlacementsEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t placementCapacityInput;
    uint32_t placementCountOutput;
    XrRoomPlacementEXTX* placements; /* each element's type must be XR_TYPE_ROOM_PLACEMENT_EXTX */
    XrRoomPlacementShortfallEXTX shortfall;
} XrRoomPlacementsEXTX;

typedef struct XrRoomRaycastInfoEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrVector3f origin;
    XrVector3f direction; /* any length but zero */
    float maxDistance;    /* metres; 0 means unlimited */
} XrRoomRaycastInfoEXTX;

/* The first scanned surface or room edge along the ray. */
typedef struct XrRoomRaycastHitEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrBool32 hit;
    XrVector3f position;
    XrVector3f normal;   /* unit, against the ray */
    float distance;
    XrRoomAreaTypeEXTX surfaceType;
    XrBool32 scanned;    /* false: the ray left the room where the scan has no surface (a hole, an open door) */
} XrRoomRaycastHitEXTX;

typedef struct XrRoomRandomPointInfoEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrRoomSurfaceFlagsEXTX surfaces; /* 0: a point in the room's free space */
    float distance;                  /* from the surface's edge; in free space, from every surface */
    uint64_t seed;
} XrRoomRandomPointInfoEXTX;

typedef struct XrRoomPointEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrBool32 found;
    XrVector3f position;
    XrVector3f normal;              /* the surface's; zero for a point in free space */
    XrRoomAreaTypeEXTX surfaceType; /* 0 for a point in free space */
} XrRoomPointEXTX;

typedef struct XrRoomPointLocationEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrBool32 insideRoom;  /* within its walls, between its floor and its ceiling */
    XrBool32 inFreeSpace; /* inside, and in no scanned surface */
    uint32_t storeyIndex;
} XrRoomPointLocationEXTX;

/* roomsense's addition (chain it to XrRoomLayoutEXTX::next): the whole analysis as JSON, the schema
** "roomsense.analysis/1" of the roomsense command line, with stage timings and grid. Two-call idiom:
** jsonCountOutput counts the terminating zero; with jsonCapacityInput 0 only the count is written. */
typedef struct XrRoomAnalysisJsonEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t jsonCapacityInput;
    uint32_t jsonCountOutput;
    char* json;
} XrRoomAnalysisJsonEXTX;

/* ---- Through the standard spatial-entity API (XR_EXT_spatial_entity) ----
** Applications that speak XR_EXT_spatial_entity need none of the functions above: the layer serves
** XR_EXT_spatial_plane_tracking itself over its analysis where the runtime has none (floor, ceiling, each
** wall segment and table tops, with BOUNDED_2D, PLANE_ALIGNMENT, POLYGON_2D, MESH_2D and PLANE_SEMANTIC_LABEL),
** and adds one capability of its own, whatever the runtime has:
**   XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX, configured with
**   XrSpatialCapabilityConfigurationPlacementAreasEXTX. Its entities are
**   - one per placement area: BOUNDED_2D (pose as XrRoomAreaEXTX::pose, extents) and
**     XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX (read with XrSpatialComponentPlacementAreaListEXTX);
**   - one room entity: MESH_3D, the closed room-bounds mesh (VECTOR3F vertices, UINT32 indices, CCW triangles
**     facing free space).
** Spec version 3: XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX, the storey and room of a plane or a placement
** area (read with XrSpatialComponentRoomLocationListEXTX). Enable it in the placement-areas configuration, or in
** a plane-tracking configuration, which the layer then serves itself (a runtime's planes do not have it).
** A context of this capability cannot also hold the runtime's own capabilities: create two contexts.
** The structures below need the XR_EXT_spatial_entity types: they are declared once a header that has them
** (<openxr/openxr.h> of OpenXR 1.1.49 or later) came first, or when this header is included again after it. */
#define XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX ((XrSpatialCapabilityEXT)1099999000)
#define XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX ((XrSpatialComponentTypeEXT)1099999000)
#define XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLACEMENT_AREAS_EXTX ((XrStructureType)1099999007)
#define XR_TYPE_SPATIAL_COMPONENT_PLACEMENT_AREA_LIST_EXTX ((XrStructureType)1099999008)
#define XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX ((XrSpatialComponentTypeEXT)1099999001)
#define XR_TYPE_SPATIAL_COMPONENT_ROOM_LOCATION_LIST_EXTX ((XrStructureType)1099999020)


typedef XrResult(XRAPI_PTR* PFN_xrCreateRoomAnalyzerEXTX)(XrSession session, const XrRoomAnalyzerCreateInfoEXTX* createInfo,
                                                          XrRoomAnalyzerEXTX* analyzer);
typedef XrResult(XRAPI_PTR* PFN_xrDestroyRoomAnalyzerEXTX)(XrRoomAnalyzerEXTX analyzer);
typedef XrResult(XRAPI_PTR* PFN_xrSubmitRoomMeshEXTX)(XrRoomAnalyzerEXTX analyzer, const XrRoomMeshEXTX* mesh);
typedef XrResult(XRAPI_PTR* PFN_xrComputeRoomEXTX)(XrRoomAnalyzerEXTX analyzer, const XrRoomComputeInfoEXTX* computeInfo);
typedef XrResult(XRAPI_PTR* PFN_xrGetRoomComputeStateEXTX)(XrRoomAnalyzerEXTX analyzer, XrRoomComputeStateEXTX* state);
typedef XrResult(XRAPI_PTR* PFN_xrGetRoomLayoutEXTX)(XrRoomAnalyzerEXTX analyzer, XrRoomLayoutEXTX* layout);
typedef XrResult(XRAPI_PTR* PFN_xrGetRoomAreasEXTX)(XrRoomAnalyzerEXTX analyzer, uint32_t areaCapacityInput,
                                                    uint32_t* areaCountOutput, XrRoomAreaEXTX* areas);
typedef XrResult(XRAPI_PTR* PFN_xrGetRoomBoundsMeshEXTX)(XrRoomAnalyzerEXTX analyzer, XrRoomBoundsMeshEXTX* mesh);
typedef XrResult(XRAPI_PTR* PFN_xrFindRoomPlacementsEXTX)(XrRoomAnalyzerEXTX analyzer, const XrRoomPlacementQueryEXTX* query,
                                                          XrRoomPlacementsEXTX* placements);
typedef XrResult(XRAPI_PTR* PFN_xrRaycastRoomEXTX)(XrRoomAnalyzerEXTX analyzer, const XrRoomRaycastInfoEXTX* info,
                                                   XrRoomRaycastHitEXTX* hit);
typedef XrResult(XRAPI_PTR* PFN_xrGetRoomRandomPointEXTX)(XrRoomAnalyzerEXTX analyzer, const XrRoomRandomPointInfoEXTX* info,
                                                          XrRoomPointEXTX* point);
typedef XrResult(XRAPI_PTR* PFN_xrLocateRoomPointEXTX)(XrRoomAnalyzerEXTX analyzer, const XrVector3f* point,
                                                       XrRoomPointLocationEXTX* location);

#ifndef XR_NO_PROTOTYPES
#ifdef XR_EXTENSION_PROTOTYPES
/* The layer exports none of these: get them from xrGetInstanceProcAddr. */
XRAPI_ATTR XrResult XRAPI_CALL xrCreateRoomAnalyzerEXTX(XrSession session, const XrRoomAnalyzerCreateInfoEXTX* createInfo,
                                                        XrRoomAnalyzerEXTX* analyzer);
XRAPI_ATTR XrResult XRAPI_CALL xrDestroyRoomAnalyzerEXTX(XrRoomAnalyzerEXTX analyzer);
XRAPI_ATTR XrResult XRAPI_CALL xrSubmitRoomMeshEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomMeshEXTX* mesh);
XRAPI_ATTR XrResult XRAPI_CALL xrComputeRoomEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomComputeInfoEXTX* computeInfo);
XRAPI_ATTR XrResult XRAPI_CALL xrGetRoomComputeStateEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomComputeStateEXTX* state);
XRAPI_ATTR XrResult XRAPI_CALL xrGetRoomLayoutEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomLayoutEXTX* layout);
XRAPI_ATTR XrResult XRAPI_CALL xrGetRoomAreasEXTX(XrRoomAnalyzerEXTX analyzer, uint32_t areaCapacityInput,
                                                  uint32_t* areaCountOutput, XrRoomAreaEXTX* areas);
XRAPI_ATTR XrResult XRAPI_CALL xrGetRoomBoundsMeshEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomBoundsMeshEXTX* mesh);
XRAPI_ATTR XrResult XRAPI_CALL xrFindRoomPlacementsEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomPlacementQueryEXTX* query,
                                                        XrRoomPlacementsEXTX* placements);
XRAPI_ATTR XrResult XRAPI_CALL xrRaycastRoomEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomRaycastInfoEXTX* info,
                                                 XrRoomRaycastHitEXTX* hit);
XRAPI_ATTR XrResult XRAPI_CALL xrGetRoomRandomPointEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomRandomPointInfoEXTX* info,
                                                        XrRoomPointEXTX* point);
XRAPI_ATTR XrResult XRAPI_CALL xrLocateRoomPointEXTX(XrRoomAnalyzerEXTX analyzer, const XrVector3f* point,
                                                     XrRoomPointLocationEXTX* location);
#endif /* XR_EXTENSION_PROTOTYPES */
#endif /* !XR_NO_PROTOTYPES */

#ifdef __cplusplus
}
#endif

#endif /* XR_EXTX_ROOM_UNDERSTANDING_H_ */

/* Outside the include guard: a second inclusion, after the XR_EXT_spatial_entity declarations, adds these. */
#if defined(XR_EXT_spatial_entity) && !defined(XR_EXTX_ROOM_UNDERSTANDING_SPATIAL_H_)
#define XR_EXTX_ROOM_UNDERSTANDING_SPATIAL_H_ 1
#ifdef __cplusplus
extern "C" {
#endif
/* Same layout as XrSpatialCapabilityConfigurationBaseHeaderEXT; capability is
** XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX; components: BOUNDED_2D, PLACEMENT_AREA_EXTX, MESH_3D. */
typedef struct XrSpatialCapabilityConfigurationPlacementAreasEXTX {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialCapabilityEXT capability;
    uint32_t enabledComponentCount;
    const XrSpatialComponentTypeEXT* enabledComponents;
} XrSpatialCapabilityConfigurationPlacementAreasEXTX;

/* One placement area: what XrRoomAreaEXTX says besides its pose. */
typedef struct XrSpatialPlacementAreaDataEXTX {
    XrRoomAreaTypeEXTX areaType;
    XrRoomAreaSizeEXTX size;
    XrRoomInteractionEXTX interaction;
    XrExtent2Df extents;    /* full width (X) and height (Y), metres */
    float volumeHeight;     /* clear space checked in front of the surface, along +Z */
    uint32_t categoryFlags; /* thesis Eq. 3.58 bits: XR_ROOM_AREA_CATEGORY_*_BIT_EXTX */
} XrSpatialPlacementAreaDataEXTX;

/* Where a plane or placement area lies (spec version 3): as XrRoomAreaLocationEXTX. */
typedef struct XrSpatialRoomLocationDataEXTX {
    uint32_t storeyIndex; /* 0: the main storey */
    uint32_t roomIndex;   /* into XrRoomHomeLayoutEXTX::rooms, or XR_ROOM_INDEX_NONE_EXTX */
} XrSpatialRoomLocationDataEXTX;

/* Chained to XrSpatialComponentDataQueryResultEXT::next, one element per entity id of the query. */
typedef struct XrSpatialComponentRoomLocationListEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t locationCount;
    XrSpatialRoomLocationDataEXTX* locations;
} XrSpatialComponentRoomLocationListEXTX;

/* Chained to XrSpatialComponentDataQueryResultEXT::next, one element per entity id of the query. */
typedef struct XrSpatialComponentPlacementAreaListEXTX {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t placementAreaCount;
    XrSpatialPlacementAreaDataEXTX* placementAreas;
} XrSpatialComponentPlacementAreaListEXTX;
#ifdef __cplusplus
}
#endif
#endif /* XR_EXT_spatial_entity && !XR_EXTX_ROOM_UNDERSTANDING_SPATIAL_H_ */
