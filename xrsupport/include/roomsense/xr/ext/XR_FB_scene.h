/* roomsense: declarations for XR_FB_scene (bounding boxes, semantic labels,
 * 2D boundaries and room layout of scene spaces) and
 * XR_FB_spatial_entity_container. Used only where the system
 * <openxr/openxr.h> lacks them. */
#ifndef ROOMSENSE_XR_EXT_XR_FB_SCENE_H
#define ROOMSENSE_XR_EXT_XR_FB_SCENE_H

#include <openxr/openxr.h>

#include "base_types.h"
#include "XR_FB_spatial_entity.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- XR_FB_scene (registry extension 176, revision 4) ---- */
#ifndef XR_FB_scene
#define XR_FB_scene 1
#define XR_FB_scene_SPEC_VERSION 4
#define XR_FB_SCENE_EXTENSION_NAME "XR_FB_scene"

#define XR_TYPE_SEMANTIC_LABELS_FB ((XrStructureType)1000175000)
#define XR_TYPE_ROOM_LAYOUT_FB ((XrStructureType)1000175001)
#define XR_TYPE_BOUNDARY_2D_FB ((XrStructureType)1000175002)
#define XR_TYPE_SEMANTIC_LABELS_SUPPORT_INFO_FB ((XrStructureType)1000175010)

typedef XrFlags64 XrSemanticLabelsSupportFlagsFB;
static const XrSemanticLabelsSupportFlagsFB XR_SEMANTIC_LABELS_SUPPORT_MULTIPLE_SEMANTIC_LABELS_BIT_FB = 0x00000001;
static const XrSemanticLabelsSupportFlagsFB XR_SEMANTIC_LABELS_SUPPORT_ACCEPT_DESK_TO_TABLE_MIGRATION_BIT_FB = 0x00000002;
static const XrSemanticLabelsSupportFlagsFB XR_SEMANTIC_LABELS_SUPPORT_ACCEPT_INVISIBLE_WALL_FACE_BIT_FB = 0x00000004;

/* An alias of the core 1.1 XrExtent3Df (base_types.h supplies that one on
 * older headers). */
typedef XrExtent3Df XrExtent3DfFB;

typedef struct XrOffset3DfFB {
    float x;
    float y;
    float z;
} XrOffset3DfFB;

typedef struct XrRect3DfFB {
    XrOffset3DfFB offset;
    XrExtent3DfFB extent;
} XrRect3DfFB;

/* buffer receives comma-separated labels, e.g. "FLOOR" or "TABLE,DESK". */
typedef struct XrSemanticLabelsFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t bufferCapacityInput;
    uint32_t bufferCountOutput;
    char* buffer;
} XrSemanticLabelsFB;

typedef struct XrRoomLayoutFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrUuidEXT floorUuid;
    XrUuidEXT ceilingUuid;
    uint32_t wallUuidCapacityInput;
    uint32_t wallUuidCountOutput;
    XrUuidEXT* wallUuids;
} XrRoomLayoutFB;

typedef struct XrBoundary2DFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t vertexCapacityInput;
    uint32_t vertexCountOutput;
    XrVector2f* vertices;
} XrBoundary2DFB;

/* Chained to XrSemanticLabelsFB. */
typedef struct XrSemanticLabelsSupportInfoFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSemanticLabelsSupportFlagsFB flags;
    const char* recognizedLabels;
} XrSemanticLabelsSupportInfoFB;

typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceBoundingBox2DFB)(
    XrSession session, XrSpace space, XrRect2Df* boundingBox2DOutput);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceBoundingBox3DFB)(
    XrSession session, XrSpace space, XrRect3DfFB* boundingBox3DOutput);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceSemanticLabelsFB)(
    XrSession session, XrSpace space, XrSemanticLabelsFB* semanticLabelsOutput);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceBoundary2DFB)(
    XrSession session, XrSpace space, XrBoundary2DFB* boundary2DOutput);
typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceRoomLayoutFB)(
    XrSession session, XrSpace space, XrRoomLayoutFB* roomLayoutOutput);
#endif /* XR_FB_scene */

/* ---- XR_FB_spatial_entity_container (registry extension 200, revision 2) ---- */
#ifndef XR_FB_spatial_entity_container
#define XR_FB_spatial_entity_container 1
#define XR_FB_spatial_entity_container_SPEC_VERSION 2
#define XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME "XR_FB_spatial_entity_container"

#define XR_TYPE_SPACE_CONTAINER_FB ((XrStructureType)1000199000)

typedef struct XrSpaceContainerFB {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t uuidCapacityInput;
    uint32_t uuidCountOutput;
    XrUuidEXT* uuids;
} XrSpaceContainerFB;

typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceContainerFB)(
    XrSession session, XrSpace space, XrSpaceContainerFB* spaceContainerOutput);
#endif /* XR_FB_spatial_entity_container */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_FB_SCENE_H */
