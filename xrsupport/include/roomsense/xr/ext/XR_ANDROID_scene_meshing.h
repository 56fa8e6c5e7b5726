/* roomsense: declarations for XR_ANDROID_scene_meshing (Android XR scene
 * meshes: a tracker, snapshots, submeshes with per-vertex semantic labels).
 * Used only where the system <openxr/openxr.h> lacks it.
 *
 * Sources: this extension is not in the Khronos OpenXR-SDK 1.1.53 header.
 * Names, values, member order and signatures follow the extension page on
 * developer.android.com/develop/xr/openxr/extensions/XR_ANDROID_scene_meshing
 * (registered extension number 719, revision 3), the registry man page
 * registry.khronos.org/OpenXR/specs/1.1/man/html/XrSceneSubmeshDataANDROID.html,
 * the LWJGL bindings (org.lwjgl.openxr.ANDROIDSceneMeshing: numeric values)
 * and the vendored header in GodotVR/godot_openxr_vendors
 * (thirdparty/androidxr/include/androidxr/xr_android_scene_meshing.h), which
 * agree with each other. */
#ifndef ROOMSENSE_XR_EXT_XR_ANDROID_SCENE_MESHING_H
#define ROOMSENSE_XR_EXT_XR_ANDROID_SCENE_MESHING_H

#include <openxr/openxr.h>

#include "base_types.h" /* XrUuid, XrExtent3Df, XrBoxf on pre-1.1 headers */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- XR_ANDROID_scene_meshing (registry extension 719, revision 3) ---- */
#ifndef XR_ANDROID_scene_meshing
#define XR_ANDROID_scene_meshing 1
#define XR_ANDROID_scene_meshing_SPEC_VERSION 3
#define XR_ANDROID_SCENE_MESHING_EXTENSION_NAME "XR_ANDROID_scene_meshing"

XR_DEFINE_HANDLE(XrSceneMeshingTrackerANDROID)
XR_DEFINE_HANDLE(XrSceneMeshSnapshotANDROID)

/* Values this extension adds to core enums. */
#define XR_TYPE_SYSTEM_SCENE_MESHING_PROPERTIES_ANDROID ((XrStructureType)1000718000)
#define XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID ((XrStructureType)1000718001)
#define XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID ((XrStructureType)1000718002)
#define XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID ((XrStructureType)1000718003)
#define XR_TYPE_SCENE_SUBMESH_STATE_ANDROID ((XrStructureType)1000718004)
#define XR_TYPE_SCENE_SUBMESH_DATA_ANDROID ((XrStructureType)1000718005)

#define XR_OBJECT_TYPE_SCENE_MESHING_TRACKER_ANDROID ((XrObjectType)1000718000)
#define XR_OBJECT_TYPE_SCENE_MESH_SNAPSHOT_ANDROID ((XrObjectType)1000718001)

typedef enum XrSceneMeshSemanticLabelSetANDROID {
    XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID = 0,
    /* Labels from XrSceneMeshSemanticLabelANDROID. */
    XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID = 1,
    XR_SCENE_MESH_SEMANTIC_LABEL_SET_MAX_ENUM_ANDROID = 0x7FFFFFFF
} XrSceneMeshSemanticLabelSetANDROID;

/* Per-vertex labels of the default set, stored one byte per vertex in
 * XrSceneSubmeshDataANDROID::vertexSemantics. */
typedef enum XrSceneMeshSemanticLabelANDROID {
    XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID = 0,
    XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID = 1,
    XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID = 2,
    XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID = 3,
    XR_SCENE_MESH_SEMANTIC_LABEL_TABLE_ANDROID = 4,
    XR_SCENE_MESH_SEMANTIC_LABEL_MAX_ENUM_ANDROID = 0x7FFFFFFF
} XrSceneMeshSemanticLabelANDROID;

typedef enum XrSceneMeshTrackingStateANDROID {
    XR_SCENE_MESH_TRACKING_STATE_INITIALIZING_ANDROID = 0,
    XR_SCENE_MESH_TRACKING_STATE_TRACKING_ANDROID = 1,
    XR_SCENE_MESH_TRACKING_STATE_WAITING_ANDROID = 2,
    XR_SCENE_MESH_TRACKING_STATE_ERROR_ANDROID = 3,
    XR_SCENE_MESH_TRACKING_STATE_MAX_ENUM_ANDROID = 0x7FFFFFFF
} XrSceneMeshTrackingStateANDROID;

/* Chained to XrSystemProperties. */
typedef struct XrSystemSceneMeshingPropertiesANDROID {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrBool32 supportsSceneMeshing;
} XrSystemSceneMeshingPropertiesANDROID;

typedef struct XrSceneMeshingTrackerCreateInfoANDROID {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSceneMeshSemanticLabelSetANDROID semanticLabelSet;
    XrBool32 enableNormals;
} XrSceneMeshingTrackerCreateInfoANDROID;

typedef struct XrSceneMeshSnapshotCreateInfoANDROID {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpace baseSpace;
    XrTime time;
    XrBoxf boundingBox;
} XrSceneMeshSnapshotCreateInfoANDROID;

typedef struct XrSceneMeshSnapshotCreationResultANDROID {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSceneMeshSnapshotANDROID snapshot;
    XrSceneMeshTrackingStateANDROID trackingState;
} XrSceneMeshSnapshotCreationResultANDROID;

typedef struct XrSceneSubmeshStateANDROID {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    XrUuid submeshId;
    XrTime lastUpdatedTime;
    XrPosef submeshPoseInBaseSpace;
    XrExtent3Df bounds;
} XrSceneSubmeshStateANDROID;

/* The application fills submeshId and the capacities; vertexNormals may be
 * NULL when the tracker was made without normals, vertexSemantics when its
 * label set is NONE. */
typedef struct XrSceneSubmeshDataANDROID {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrUuid submeshId;
    uint32_t vertexCapacityInput;
    uint32_t vertexCountOutput;
    XrVector3f* vertexPositions;
    XrVector3f* vertexNormals;
    uint8_t* vertexSemantics;
    uint32_t indexCapacityInput;
    uint32_t indexCountOutput;
    uint32_t* indices;
} XrSceneSubmeshDataANDROID;

typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSupportedSemanticLabelSetsANDROID)(
    XrInstance instance, XrSystemId systemId, uint32_t supportedSemanticLabelSetsInputCapacity,
    uint32_t* supportedSemanticLabelSetsOutputCount,
    XrSceneMeshSemanticLabelSetANDROID* supportedSemanticLabelSets);
typedef XrResult(XRAPI_PTR* PFN_xrCreateSceneMeshingTrackerANDROID)(
    XrSession session, const XrSceneMeshingTrackerCreateInfoANDROID* createInfo,
    XrSceneMeshingTrackerANDROID* tracker);
typedef XrResult(XRAPI_PTR* PFN_xrDestroySceneMeshingTrackerANDROID)(
    XrSceneMeshingTrackerANDROID tracker);
typedef XrResult(XRAPI_PTR* PFN_xrCreateSceneMeshSnapshotANDROID)(
    XrSceneMeshingTrackerANDROID tracker, const XrSceneMeshSnapshotCreateInfoANDROID* createInfo,
    XrSceneMeshSnapshotCreationResultANDROID* outSnapshotCreationResult);
typedef XrResult(XRAPI_PTR* PFN_xrDestroySceneMeshSnapshotANDROID)(
    XrSceneMeshSnapshotANDROID snapshot);
typedef XrResult(XRAPI_PTR* PFN_xrGetAllSubmeshStatesANDROID)(
    XrSceneMeshSnapshotANDROID snapshot, uint32_t submeshStateCapacityInput,
    uint32_t* submeshStateCountOutput, XrSceneSubmeshStateANDROID* submeshStates);
typedef XrResult(XRAPI_PTR* PFN_xrGetSubmeshDataANDROID)(
    XrSceneMeshSnapshotANDROID snapshot, uint32_t submeshDataCount,
    XrSceneSubmeshDataANDROID* inoutSubmeshData);
#endif /* XR_ANDROID_scene_meshing */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_ANDROID_SCENE_MESHING_H */
