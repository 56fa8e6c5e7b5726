/* roomsense: declarations for XR_ML_world_mesh_detection (Magic Leap 2 world
 * mesh: block states, then mesh blocks with uint16 indices, via futures).
 * Used only when the system <openxr/openxr.h> lacks the extension. */
#ifndef ROOMSENSE_XR_EXT_XR_ML_WORLD_MESH_DETECTION_H
#define ROOMSENSE_XR_EXT_XR_ML_WORLD_MESH_DETECTION_H

#include <openxr/openxr.h>

#include "XR_EXT_future.h"
#include "base_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef XR_ML_world_mesh_detection
#define XR_ML_world_mesh_detection 1
#define XR_ML_world_mesh_detection_SPEC_VERSION 1
#define XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME "XR_ML_world_mesh_detection"

XR_DEFINE_HANDLE(XrWorldMeshDetectorML)

/* Values this extension adds to core enums. */
#define XR_ERROR_WORLD_MESH_DETECTOR_PERMISSION_DENIED_ML ((XrResult)-1000474000)
#define XR_ERROR_WORLD_MESH_DETECTOR_SPACE_NOT_LOCATABLE_ML ((XrResult)-1000474001)

#define XR_OBJECT_TYPE_WORLD_MESH_DETECTOR_ML ((XrObjectType)1000474000)

#define XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML ((XrStructureType)1000474001)
#define XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML ((XrStructureType)1000474002)
#define XR_TYPE_WORLD_MESH_BLOCK_STATE_ML ((XrStructureType)1000474003)
#define XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML ((XrStructureType)1000474004)
#define XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML ((XrStructureType)1000474005)
#define XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML ((XrStructureType)1000474006)
#define XR_TYPE_WORLD_MESH_BUFFER_ML ((XrStructureType)1000474007)
#define XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML ((XrStructureType)1000474008)
#define XR_TYPE_WORLD_MESH_GET_INFO_ML ((XrStructureType)1000474009)
#define XR_TYPE_WORLD_MESH_BLOCK_ML ((XrStructureType)1000474010)
#define XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML ((XrStructureType)1000474011)
#define XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML ((XrStructureType)1000474012)

typedef enum XrWorldMeshDetectorLodML {
    XR_WORLD_MESH_DETECTOR_LOD_MINIMUM_ML = 0,
    XR_WORLD_MESH_DETECTOR_LOD_MEDIUM_ML = 1,
    XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML = 2,
    XR_WORLD_MESH_DETECTOR_LOD_MAX_ENUM_ML = 0x7FFFFFFF
} XrWorldMeshDetectorLodML;

typedef enum XrWorldMeshBlockStatusML {
    XR_WORLD_MESH_BLOCK_STATUS_NEW_ML = 0,
    XR_WORLD_MESH_BLOCK_STATUS_UPDATED_ML = 1,
    XR_WORLD_MESH_BLOCK_STATUS_DELETED_ML = 2,
    XR_WORLD_MESH_BLOCK_STATUS_UNCHANGED_ML = 3,
    XR_WORLD_MESH_BLOCK_STATUS_MAX_ENUM_ML = 0x7FFFFFFF
} XrWorldMeshBlockStatusML;

typedef enum XrWorldMeshBlockResultML {
    XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML = 0,
    XR_WORLD_MESH_BLOCK_RESULT_FAILED_ML = 1,
    XR_WORLD_MESH_BLOCK_RESULT_PENDING_ML = 2,
    XR_WORLD_MESH_BLOCK_RESULT_PARTIAL_UPDATE_ML = 3,
    XR_WORLD_MESH_BLOCK_RESULT_MAX_ENUM_ML = 0x7FFFFFFF
} XrWorldMeshBlockResultML;

/* Mesh request options (64-bit flags). */
typedef XrFlags64 XrWorldMeshDetectorFlagsML;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_POINT_CLOUD_BIT_ML = 0x00000001;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_COMPUTE_NORMALS_BIT_ML = 0x00000002;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_COMPUTE_CONFIDENCE_BIT_ML = 0x00000004;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_PLANARIZE_BIT_ML = 0x00000008;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_REMOVE_MESH_SKIRT_BIT_ML = 0x00000010;
static const XrWorldMeshDetectorFlagsML XR_WORLD_MESH_DETECTOR_INDEX_ORDER_CW_BIT_ML = 0x00000020;

typedef struct XrWorldMeshDetectorCreateInfoML {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
} XrWorldMeshDetectorCreateInfoML;

/* Step 1: which blocks exist in a box, and how they changed. */
typedef struct XrWorldMeshBlockStateML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrUuidEXT uuid;
    XrPosef meshBoundingBoxCenter;
    XrExtent3DfEXT meshBoundingBoxExtents;
    XrTime lastUpdateTime;
    XrWorldMeshBlockStatusML status;
} XrWorldMeshBlockStateML;

typedef struct XrWorldMeshStateRequestInfoML {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace baseSpace;
    XrTime time;
    XrPosef boundingBoxCenter;
    XrExtent3DfEXT boundingBoxExtents;
} XrWorldMeshStateRequestInfoML;

typedef struct XrWorldMeshStateRequestCompletionML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
    XrTime timestamp;
    uint32_t meshBlockStateCapacityInput;
    uint32_t meshBlockStateCountOutput;
    XrWorldMeshBlockStateML* meshBlockStates;
} XrWorldMeshStateRequestCompletionML;

/* Step 2: a runtime-allocated buffer that will hold the mesh data. */
typedef struct XrWorldMeshBufferRecommendedSizeInfoML {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t maxBlockCount;
} XrWorldMeshBufferRecommendedSizeInfoML;

typedef struct XrWorldMeshBufferSizeML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t size;
} XrWorldMeshBufferSizeML;

typedef struct XrWorldMeshBufferML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t bufferSize;
    void* XR_MAY_ALIAS buffer;
} XrWorldMeshBufferML;

/* Step 3: request meshes for chosen blocks. */
typedef struct XrWorldMeshBlockRequestML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrUuidEXT uuid;
    XrWorldMeshDetectorLodML lod;
} XrWorldMeshBlockRequestML;

typedef struct XrWorldMeshGetInfoML {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrWorldMeshDetectorFlagsML flags;
    float fillHoleLength;
    float disconnectedComponentArea;
    uint32_t blockCount;
    XrWorldMeshBlockRequestML* blocks;
} XrWorldMeshGetInfoML;

/* One block's mesh; the arrays point into the XrWorldMeshBufferML. */
typedef struct XrWorldMeshBlockML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrUuidEXT uuid;
    XrWorldMeshBlockResultML blockResult;
    XrWorldMeshDetectorLodML lod;
    XrWorldMeshDetectorFlagsML flags;
    uint32_t indexCount;
    uint16_t* indexBuffer;
    uint32_t vertexCount;
    XrVector3f* vertexBuffer;
    uint32_t normalCount;
    XrVector3f* normalBuffer;
    uint32_t confidenceCount;
    float* confidenceBuffer;
} XrWorldMeshBlockML;

typedef struct XrWorldMeshRequestCompletionInfoML {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace meshSpace;
    XrTime meshSpaceLocateTime;
} XrWorldMeshRequestCompletionInfoML;

typedef struct XrWorldMeshRequestCompletionML {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrResult futureResult;
    uint32_t blockCount;
    XrWorldMeshBlockML* blocks;
} XrWorldMeshRequestCompletionML;

typedef XrResult(XRAPI_PTR* PFN_xrCreateWorldMeshDetectorML)(XrSession session,
                                                             const XrWorldMeshDetectorCreateInfoML* createInfo,
                                                             XrWorldMeshDetectorML* detector);
typedef XrResult(XRAPI_PTR* PFN_xrDestroyWorldMeshDetectorML)(XrWorldMeshDetectorML detector);
typedef XrResult(XRAPI_PTR* PFN_xrRequestWorldMeshStateAsyncML)(XrWorldMeshDetectorML detector,
                                                                const XrWorldMeshStateRequestInfoML* stateRequest,
                                                                XrFutureEXT* future);
typedef XrResult(XRAPI_PTR* PFN_xrRequestWorldMeshStateCompleteML)(XrWorldMeshDetectorML detector, XrFutureEXT future,
                                                                   XrWorldMeshStateRequestCompletionML* completion);
typedef XrResult(XRAPI_PTR* PFN_xrGetWorldMeshBufferRecommendSizeML)(
    XrWorldMeshDetectorML detector, const XrWorldMeshBufferRecommendedSizeInfoML* sizeInfo,
    XrWorldMeshBufferSizeML* size);
typedef XrResult(XRAPI_PTR* PFN_xrAllocateWorldMeshBufferML)(XrWorldMeshDetectorML detector,
                                                             const XrWorldMeshBufferSizeML* size,
                                                             XrWorldMeshBufferML* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrFreeWorldMeshBufferML)(XrWorldMeshDetectorML detector,
                                                         const XrWorldMeshBufferML* buffer);
typedef XrResult(XRAPI_PTR* PFN_xrRequestWorldMeshAsyncML)(XrWorldMeshDetectorML detector,
                                                           const XrWorldMeshGetInfoML* getInfo,
                                                           XrWorldMeshBufferML* buffer, XrFutureEXT* future);
typedef XrResult(XRAPI_PTR* PFN_xrRequestWorldMeshCompleteML)(XrWorldMeshDetectorML detector,
                                                              const XrWorldMeshRequestCompletionInfoML* completionInfo,
                                                              XrFutureEXT future,
                                                              XrWorldMeshRequestCompletionML* completion);

#endif /* XR_ML_world_mesh_detection */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_ML_WORLD_MESH_DETECTION_H */
