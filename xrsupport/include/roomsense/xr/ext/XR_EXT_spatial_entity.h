/* roomsense: declarations for XR_EXT_spatial_entity (spatial contexts,
 * discovery/update snapshots, component queries, spatial buffers), as
 * ratified in OpenXR 1.1.49. Used only when the system <openxr/openxr.h>
 * lacks the extension; a header that has it wins. */
#ifndef ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_ENTITY_H
#define ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_ENTITY_H

#include <openxr/openxr.h>

#include "XR_EXT_future.h"
#include "base_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef XR_EXT_spatial_entity
#define XR_EXT_spatial_entity 1
#define XR_EXT_spatial_entity_SPEC_VERSION 1
#define XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME "XR_EXT_spatial_entity"
#define XR_NULL_SPATIAL_ENTITY_ID_EXT 0
#define XR_NULL_SPATIAL_BUFFER_ID_EXT 0

/* Ids are plain 64-bit atoms; entities, contexts and snapshots are handles. */
XR_DEFINE_ATOM(XrSpatialEntityIdEXT)
XR_DEFINE_ATOM(XrSpatialBufferIdEXT)
XR_DEFINE_HANDLE(XrSpatialEntityEXT)
XR_DEFINE_HANDLE(XrSpatialContextEXT)
XR_DEFINE_HANDLE(XrSpatialSnapshotEXT)

/* Values this extension adds to core enums. */
#define XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT ((XrResult)-1000740001)
#define XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT ((XrResult)-1000740002)
#define XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT ((XrResult)-1000740003)
#define XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT ((XrResult)-1000740004)
#define XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT ((XrResult)-1000740005)
#define XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT ((XrResult)-1000740006)

#define XR_OBJECT_TYPE_SPATIAL_ENTITY_EXT ((XrObjectType)1000740000)
#define XR_OBJECT_TYPE_SPATIAL_CONTEXT_EXT ((XrObjectType)1000740001)
#define XR_OBJECT_TYPE_SPATIAL_SNAPSHOT_EXT ((XrObjectType)1000740002)

#define XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT ((XrStructureType)1000740000)
#define XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT ((XrStructureType)1000740001)
#define XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT ((XrStructureType)1000740002)
#define XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT ((XrStructureType)1000740003)
#define XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT ((XrStructureType)1000740004)
#define XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT ((XrStructureType)1000740005)
#define XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT ((XrStructureType)1000740006)
#define XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT ((XrStructureType)1000740007)
#define XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT ((XrStructureType)1000740008)
#define XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT ((XrStructureType)1000740009)
#define XR_TYPE_SPATIAL_COMPONENT_BOUNDED_3D_LIST_EXT ((XrStructureType)1000740010)
#define XR_TYPE_SPATIAL_COMPONENT_PARENT_LIST_EXT ((XrStructureType)1000740011)
#define XR_TYPE_SPATIAL_COMPONENT_MESH_3D_LIST_EXT ((XrStructureType)1000740012)
#define XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT ((XrStructureType)1000740013)
#define XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT ((XrStructureType)1000740014)
#define XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT ((XrStructureType)1000740015)
#define XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT ((XrStructureType)1000740016)

/* The enums below are new types, so they carry the values that later
 * extensions (plane, marker tracking, anchors, persistence) add to them. */
typedef enum XrSpatialCapabilityEXT {
    XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT = 1000741000,
    XR_SPATIAL_CAPABILITY_MARKER_TRACKING_QR_CODE_EXT = 1000743000,
    XR_SPATIAL_CAPABILITY_MARKER_TRACKING_MICRO_QR_CODE_EXT = 1000743001,
    XR_SPATIAL_CAPABILITY_MARKER_TRACKING_ARUCO_MARKER_EXT = 1000743002,
    XR_SPATIAL_CAPABILITY_MARKER_TRACKING_APRIL_TAG_EXT = 1000743003,
    XR_SPATIAL_CAPABILITY_ANCHOR_EXT = 1000762000,
    XR_SPATIAL_CAPABILITY_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialCapabilityEXT;

typedef enum XrSpatialCapabilityFeatureEXT {
    XR_SPATIAL_CAPABILITY_FEATURE_MARKER_TRACKING_FIXED_SIZE_MARKERS_EXT = 1000743000,
    XR_SPATIAL_CAPABILITY_FEATURE_MARKER_TRACKING_STATIC_MARKERS_EXT = 1000743001,
    XR_SPATIAL_CAPABILITY_FEATURE_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialCapabilityFeatureEXT;

typedef enum XrSpatialComponentTypeEXT {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT = 1,
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_3D_EXT = 2,
    XR_SPATIAL_COMPONENT_TYPE_PARENT_EXT = 3,
    XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT = 4,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT = 1000741000,
    XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT = 1000741001,
    XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT = 1000741002,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT = 1000741003,
    XR_SPATIAL_COMPONENT_TYPE_MARKER_EXT = 1000743000,
    XR_SPATIAL_COMPONENT_TYPE_ANCHOR_EXT = 1000762000,
    XR_SPATIAL_COMPONENT_TYPE_PERSISTENCE_EXT = 1000763000,
    XR_SPATIAL_COMPONENT_TYPE_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialComponentTypeEXT;

typedef enum XrSpatialEntityTrackingStateEXT {
    XR_SPATIAL_ENTITY_TRACKING_STATE_STOPPED_EXT = 1,
    XR_SPATIAL_ENTITY_TRACKING_STATE_PAUSED_EXT = 2,
    XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT = 3,
    XR_SPATIAL_ENTITY_TRACKING_STATE_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialEntityTrackingStateEXT;

typedef enum XrSpatialBufferTypeEXT {
    XR_SPATIAL_BUFFER_TYPE_UNKNOWN_EXT = 0,
    XR_SPATIAL_BUFFER_TYPE_STRING_EXT = 1,
    XR_SPATIAL_BUFFER_TYPE_UINT8_EXT = 2,
    XR_SPATIAL_BUFFER_TYPE_UINT16_EXT = 3,
    XR_SPATIAL_BUFFER_TYPE_UINT32_EXT = 4,
    XR_SPATIAL_BUFFER_TYPE_FLOAT_EXT = 5,
    XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT = 6,
    XR_SPATIAL_BUFFER_TYPE_VECTOR3F_EXT = 7,
    XR_SPATIAL_BUFFER_TYPE_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialBufferTypeEXT;

/* --- Capabilities and contexts --- */

/* Two-call idiom output of xrEnumerateSpatialCapabilityComponentTypesEXT. */
typedef struct XrSpatialCapabilityComponentTypesEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t componentTypeCapacityInput;
    uint32_t componentTypeCountOutput;
    XrSpatialComponentTypeEXT* componentTypes;
} XrSpatialCapabilityComponentTypesEXT;

/* Common head of the per-capability configuration structs. */
typedef struct XR_MAY_ALIAS XrSpatialCapabilityConfigurationBaseHeaderEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialCapabilityEXT capability;
    uint32_t enabledComponentCount;
    const XrSpatialComponentTypeEXT* enabledComponents;
} XrSpatialCapabilityConfigurationBaseHeaderEXT;

typedef struct XrSpatialContextCreateInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t capabilityConfigCount;
    const XrSpatialCapabilityConfigurationBaseHeaderEXT* const* capabilityConfigs;
} XrSpatialContextCreateInfoEXT;

typedef struct XrCreateSpatialContextCompletionEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
    XrSpatialContextEXT spatialContext;
} XrCreateSpatialContextCompletionEXT;

/* --- Snapshots --- */

typedef struct XrSpatialDiscoverySnapshotCreateInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t componentTypeCount;
    const XrSpatialComponentTypeEXT* componentTypes;
} XrSpatialDiscoverySnapshotCreateInfoEXT;

typedef struct XrCreateSpatialDiscoverySnapshotCompletionInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace baseSpace;
    XrTime time;
    XrFutureEXT future;
} XrCreateSpatialDiscoverySnapshotCompletionInfoEXT;

typedef struct XrCreateSpatialDiscoverySnapshotCompletionEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
    XrSpatialSnapshotEXT snapshot;
} XrCreateSpatialDiscoverySnapshotCompletionEXT;

typedef struct XrSpatialComponentDataQueryConditionEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t componentTypeCount;
    const XrSpatialComponentTypeEXT* componentTypes;
} XrSpatialComponentDataQueryConditionEXT;

/* Entity ids and states; the per-component lists hang off next. */
typedef struct XrSpatialComponentDataQueryResultEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t entityIdCapacityInput;
    uint32_t entityIdCountOutput;
    XrSpatialEntityIdEXT* entityIds;
    uint32_t entityStateCapacityInput;
    uint32_t entityStateCountOutput;
    XrSpatialEntityTrackingStateEXT* entityStates;
} XrSpatialComponentDataQueryResultEXT;

/* A buffer inside a snapshot, read with xrGetSpatialBuffer*EXT. */
typedef struct XrSpatialBufferEXT {
    XrSpatialBufferIdEXT bufferId;
    XrSpatialBufferTypeEXT bufferType;
} XrSpatialBufferEXT;

typedef struct XrSpatialBufferGetInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialBufferIdEXT bufferId;
} XrSpatialBufferGetInfoEXT;

/* --- Component data (chained to XrSpatialComponentDataQueryResultEXT) --- */

typedef struct XrSpatialBounded2DDataEXT {
    XrPosef center;
    XrExtent2Df extents;
} XrSpatialBounded2DDataEXT;

typedef struct XrSpatialComponentBounded2DListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t boundCount;
    XrSpatialBounded2DDataEXT* bounds;
} XrSpatialComponentBounded2DListEXT;

typedef struct XrSpatialComponentBounded3DListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t boundCount;
    XrBoxf* bounds;
} XrSpatialComponentBounded3DListEXT;

typedef struct XrSpatialComponentParentListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t parentCount;
    XrSpatialEntityIdEXT* parents;
} XrSpatialComponentParentListEXT;

/* Mesh in its own origin frame; vertices and indices are spatial buffers. */
typedef struct XrSpatialMeshDataEXT {
    XrPosef origin;
    XrSpatialBufferEXT vertexBuffer;
    XrSpatialBufferEXT indexBuffer;
} XrSpatialMeshDataEXT;

typedef struct XrSpatialComponentMesh3DListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t meshCount;
    XrSpatialMeshDataEXT* meshes;
} XrSpatialComponentMesh3DListEXT;

/* --- Entities, update snapshots, events, filters --- */

typedef struct XrSpatialEntityFromIdCreateInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialEntityIdEXT entityId;
} XrSpatialEntityFromIdCreateInfoEXT;

typedef struct XrSpatialUpdateSnapshotCreateInfoEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t entityCount;
    const XrSpatialEntityEXT* entities;
    uint32_t componentTypeCount;
    const XrSpatialComponentTypeEXT* componentTypes;
    XrSpace baseSpace;
    XrTime time;
} XrSpatialUpdateSnapshotCreateInfoEXT;

typedef struct XrEventDataSpatialDiscoveryRecommendedEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialContextEXT spatialContext;
} XrEventDataSpatialDiscoveryRecommendedEXT;

/* Chains to a discovery snapshot create info or a query condition. */
typedef struct XrSpatialFilterTrackingStateEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialEntityTrackingStateEXT trackingState;
} XrSpatialFilterTrackingStateEXT;

/* --- Function pointer types --- */

typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSpatialCapabilitiesEXT)(XrInstance instance, XrSystemId systemId,
                                                                   uint32_t capabilityCapacityInput,
                                                                   uint32_t* capabilityCountOutput,
                                                                   XrSpatialCapabilityEXT* capabilities);
typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSpatialCapabilityComponentTypesEXT)(
    XrInstance instance, XrSystemId systemId, XrSpatialCapabilityEXT capability,
    XrSpatialCapabilityComponentTypesEXT* capabilityComponents);
typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSpatialCapabilityFeaturesEXT)(
    XrInstance instance, XrSystemId systemId, XrSpatialCapabilityEXT capability,
    uint32_t capabilityFeatureCapacityInput, uint32_t* capabilityFeatureCountOutput,
    XrSpatialCapabilityFeatureEXT* capabilityFeatures);

typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialContextAsyncEXT)(XrSession session,
                                                                const XrSpatialContextCreateInfoEXT* createInfo,
                                                                XrFutureEXT* future);
typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialContextCompleteEXT)(XrSession session, XrFutureEXT future,
                                                                   XrCreateSpatialContextCompletionEXT* completion);
typedef XrResult(XRAPI_PTR* PFN_xrDestroySpatialContextEXT)(XrSpatialContextEXT spatialContext);

typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT)(
    XrSpatialContextEXT spatialContext, const XrSpatialDiscoverySnapshotCreateInfoEXT* createInfo,
    XrFutureEXT* future);
typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT)(
    XrSpatialContextEXT spatialContext,
    const XrCreateSpatialDiscoverySnapshotCompletionInfoEXT* createSnapshotCompletionInfo,
    XrCreateSpatialDiscoverySnapshotCompletionEXT* completion);
typedef XrResult(XRAPI_PTR* PFN_xrQuerySpatialComponentDataEXT)(
    XrSpatialSnapshotEXT snapshot, const XrSpatialComponentDataQueryConditionEXT* queryCondition,
    XrSpatialComponentDataQueryResultEXT* queryResult);
typedef XrResult(XRAPI_PTR* PFN_xrDestroySpatialSnapshotEXT)(XrSpatialSnapshotEXT snapshot);

typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialEntityFromIdEXT)(XrSpatialContextEXT spatialContext,
                                                                const XrSpatialEntityFromIdCreateInfoEXT* createInfo,
                                                                XrSpatialEntityEXT* spatialEntity);
typedef XrResult(XRAPI_PTR* PFN_xrDestroySpatialEntityEXT)(XrSpatialEntityEXT spatialEntity);
typedef XrResult(XRAPI_PTR* PFN_xrCreateSpatialUpdateSnapshotEXT)(
    XrSpatialContextEXT spatialContext, const XrSpatialUpdateSnapshotCreateInfoEXT* createInfo,
    XrSpatialSnapshotEXT* snapshot);

/* Buffer readers, two-call idiom; the element type is in the name. */
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferStringEXT)(XrSpatialSnapshotEXT snapshot,
                                                             const XrSpatialBufferGetInfoEXT* info,
                                                             uint32_t bufferCapacityInput,
                                                             uint32_t* bufferCountOutput, char* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferUint8EXT)(XrSpatialSnapshotEXT snapshot,
                                                            const XrSpatialBufferGetInfoEXT* info,
                                                            uint32_t bufferCapacityInput,
                                                            uint32_t* bufferCountOutput, uint8_t* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferUint16EXT)(XrSpatialSnapshotEXT snapshot,
                                                             const XrSpatialBufferGetInfoEXT* info,
                                                             uint32_t bufferCapacityInput,
                                                             uint32_t* bufferCountOutput, uint16_t* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferUint32EXT)(XrSpatialSnapshotEXT snapshot,
                                                             const XrSpatialBufferGetInfoEXT* info,
                                                             uint32_t bufferCapacityInput,
                                                             uint32_t* bufferCountOutput, uint32_t* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferFloatEXT)(XrSpatialSnapshotEXT snapshot,
                                                            const XrSpatialBufferGetInfoEXT* info,
                                                            uint32_t bufferCapacityInput,
                                                            uint32_t* bufferCountOutput, float* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferVector2fEXT)(XrSpatialSnapshotEXT snapshot,
                                                               const XrSpatialBufferGetInfoEXT* info,
                                                               uint32_t bufferCapacityInput,
                                                               uint32_t* bufferCountOutput, XrVector2f* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpatialBufferVector3fEXT)(XrSpatialSnapshotEXT snapshot,
                                                               const XrSpatialBufferGetInfoEXT* info,
                                                               uint32_t bufferCapacityInput,
                                                               uint32_t* bufferCountOutput, XrVector3f* buffer);

#endif /* XR_EXT_spatial_entity */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_ENTITY_H */
