/* roomsense: declarations for XR_FB_spatial_entity (spaces with components,
 * async request ids) and XR_FB_spatial_entity_query (finding spaces by uuid or
 * component). Used only where the system <openxr/openxr.h> lacks them. */
#ifndef ROOMSENSE_XR_EXT_XR_FB_SPATIAL_ENTITY_H
#define ROOMSENSE_XR_EXT_XR_FB_SPATIAL_ENTITY_H

#include <openxr/openxr.h>

#include "base_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- XR_FB_spatial_entity (registry extension 114, revision 3) ---- */
#ifndef XR_FB_spatial_entity
#define XR_FB_spatial_entity 1
#define XR_FB_spatial_entity_SPEC_VERSION 3
#define XR_FB_SPATIAL_ENTITY_EXTENSION_NAME "XR_FB_spatial_entity"

XR_DEFINE_ATOM(XrAsyncRequestIdFB)

/* Values this extension adds to core enums. */
#define XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB ((XrResult)-1000113000)
#define XR_ERROR_SPACE_COMPONENT_NOT_ENABLED_FB ((XrResult)-1000113001)
#define XR_ERROR_SPACE_COMPONENT_STATUS_PENDING_FB ((XrResult)-1000113002)
#define XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB ((XrResult)-1000113003)

#define XR_TYPE_SPACE_COMPONENT_STATUS_FB ((XrStructureType)1000113001)
#define XR_TYPE_SPATIAL_ANCHOR_CREATE_INFO_FB ((XrStructureType)1000113003)
#define XR_TYPE_SYSTEM_SPATIAL_ENTITY_PROPERTIES_FB ((XrStructureType)1000113004)
#define XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB ((XrStructureType)1000113005)
#define XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB ((XrStructureType)1000113006)
#define XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB ((XrStructureType)1000113007)

/* Component types. Later extensions add values (XR_META_spatial_entity_mesh
 * adds one, declared as a macro in its own header). */
typedef enum XrSpaceComponentTypeFB {
    XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB = 0,
    XR_SPACE_COMPONENT_TYPE_STORABLE_FB = 1,
    XR_SPACE_COMPONENT_TYPE_SHARABLE_FB = 2,
    XR_SPACE_COMPONENT_TYPE_BOUNDED_2D_FB = 3,
    XR_SPACE_COMPONENT_TYPE_BOUNDED_3D_FB = 4,
    XR_SPACE_COMPONENT_TYPE_SEMANTIC_LABELS_FB = 5,
    XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB = 6,
    XR_SPACE_COMPONENT_TYPE_SPACE_CONTAINER_FB = 7,
    XR_SPACE_COMPONENT_TYPE_MAX_ENUM_FB = 0x7FFFFFFF
} XrSpaceComponentTypeFB;

/* Chained to XrSystemProperties. */
typedef struct XrSystemSpatialEntityPropertiesFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrBool32 supportsSpatialEntity;
} XrSystemSpatialEntityPropertiesFB;

typedef struct XrSpatialAnchorCreateInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace space;
    XrPosef poseInSpace;
    XrTime time;
} XrSpatialAnchorCreateInfoFB;

typedef struct XrSpaceComponentStatusSetInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpaceComponentTypeFB componentType;
    XrBool32 enabled;
    XrDuration timeout;
} XrSpaceComponentStatusSetInfoFB;

typedef struct XrSpaceComponentStatusFB {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrBool32 enabled;
    XrBool32 changePending;
} XrSpaceComponentStatusFB;

typedef struct XrEventDataSpatialAnchorCreateCompleteFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
    XrResult result;
    XrSpace space;
    XrUuidEXT uuid;
} XrEventDataSpatialAnchorCreateCompleteFB;

typedef struct XrEventDataSpaceSetStatusCompleteFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
    XrResult result;
    XrSpace space;
    XrUuidEXT uuid;
    XrSpaceComponentTypeFB componentType;
    XrBool32 enabled;
} XrEventDataSpaceSetStatusCompleteFB;

typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialAnchorFB)(
    XrSession session, const XrSpatialAnchorCreateInfoFB* info, XrAsyncRequestIdFB* requestId);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceUuidFB)(XrSpace space, XrUuidEXT* uuid);
typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSpaceSupportedComponentsFB)(
    XrSpace space, uint32_t componentTypeCapacityInput, uint32_t* componentTypeCountOutput,
    XrSpaceComponentTypeFB* componentTypes);
typedef XrResult(XRAPI_PTR* PFN_xrSetSpaceComponentStatusFB)(
    XrSpace space, const XrSpaceComponentStatusSetInfoFB* info, XrAsyncRequestIdFB* requestId);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceComponentStatusFB)(
    XrSpace space, XrSpaceComponentTypeFB componentType, XrSpaceComponentStatusFB* status);
#endif /* XR_FB_spatial_entity */

/* ---- XR_FB_spatial_entity_query (registry extension 157, revision 1) ----
 * XrSpaceStorageLocationFB belongs to this extension in the registry
 * (XR_FB_spatial_entity_storage uses it too). */
#ifndef XR_FB_spatial_entity_query
#define XR_FB_spatial_entity_query 1
#define XR_FB_spatial_entity_query_SPEC_VERSION 1
#define XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME "XR_FB_spatial_entity_query"

#define XR_TYPE_SPACE_QUERY_INFO_FB ((XrStructureType)1000156001)
#define XR_TYPE_SPACE_QUERY_RESULTS_FB ((XrStructureType)1000156002)
#define XR_TYPE_SPACE_STORAGE_LOCATION_FILTER_INFO_FB ((XrStructureType)1000156003)
#define XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB ((XrStructureType)1000156052)
#define XR_TYPE_SPACE_UUID_FILTER_INFO_FB ((XrStructureType)1000156054)
#define XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB ((XrStructureType)1000156103)
#define XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB ((XrStructureType)1000156104)

typedef enum XrSpaceQueryActionFB {
    XR_SPACE_QUERY_ACTION_LOAD_FB = 0,
    XR_SPACE_QUERY_ACTION_MAX_ENUM_FB = 0x7FFFFFFF
} XrSpaceQueryActionFB;

typedef enum XrSpaceStorageLocationFB {
    XR_SPACE_STORAGE_LOCATION_INVALID_FB = 0,
    XR_SPACE_STORAGE_LOCATION_LOCAL_FB = 1,
    XR_SPACE_STORAGE_LOCATION_CLOUD_FB = 2,
    XR_SPACE_STORAGE_LOCATION_MAX_ENUM_FB = 0x7FFFFFFF
} XrSpaceStorageLocationFB;

/* Base headers: xrQuerySpacesFB takes a query info, whose filter members
 * point at any of the filter structs below. */
typedef struct XR_MAY_ALIAS XrSpaceQueryInfoBaseHeaderFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
} XrSpaceQueryInfoBaseHeaderFB;

typedef struct XR_MAY_ALIAS XrSpaceFilterInfoBaseHeaderFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
} XrSpaceFilterInfoBaseHeaderFB;

typedef struct XrSpaceQueryInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpaceQueryActionFB queryAction;
    uint32_t maxResultCount;
    XrDuration timeout;
    const XrSpaceFilterInfoBaseHeaderFB* filter;
    const XrSpaceFilterInfoBaseHeaderFB* excludeFilter;
} XrSpaceQueryInfoFB;

/* Chained to a filter struct. */
typedef struct XrSpaceStorageLocationFilterInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpaceStorageLocationFB location;
} XrSpaceStorageLocationFilterInfoFB;

typedef struct XrSpaceUuidFilterInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t uuidCount;
    XrUuidEXT* uuids;
} XrSpaceUuidFilterInfoFB;

typedef struct XrSpaceComponentFilterInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpaceComponentTypeFB componentType;
} XrSpaceComponentFilterInfoFB;

typedef struct XrSpaceQueryResultFB {
    XrSpace space;
    XrUuidEXT uuid;
} XrSpaceQueryResultFB;

typedef struct XrSpaceQueryResultsFB {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t resultCapacityInput;
    uint32_t resultCountOutput;
    XrSpaceQueryResultFB* results;
} XrSpaceQueryResultsFB;

typedef struct XrEventDataSpaceQueryResultsAvailableFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
} XrEventDataSpaceQueryResultsAvailableFB;

typedef struct XrEventDataSpaceQueryCompleteFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
    XrResult result;
} XrEventDataSpaceQueryCompleteFB;

typedef XrResult(XRAPI_PTR* PFN_xrQuerySpacesFB)(
    XrSession session, const XrSpaceQueryInfoBaseHeaderFB* info, XrAsyncRequestIdFB* requestId);
typedef XrResult(XRAPI_PTR* PFN_xrRetrieveSpaceQueryResultsFB)(
    XrSession session, XrAsyncRequestIdFB requestId, XrSpaceQueryResultsFB* results);
#endif /* XR_FB_spatial_entity_query */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_FB_SPATIAL_ENTITY_H */
