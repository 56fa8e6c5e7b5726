/* roomsense: declarations for XR_META_spatial_entity_mesh (the triangle mesh
 * component of a scene space, read with xrGetSpaceTriangleMeshMETA). Used only
 * where the system <openxr/openxr.h> lacks it. */
#ifndef ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_MESH_H
#define ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_MESH_H

#include <openxr/openxr.h>

#include "base_types.h"
#include "XR_FB_spatial_entity.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- XR_META_spatial_entity_mesh (registry extension 270, revision 1) ---- */
#ifndef XR_META_spatial_entity_mesh
#define XR_META_spatial_entity_mesh 1
#define XR_META_spatial_entity_mesh_SPEC_VERSION 1
#define XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME "XR_META_spatial_entity_mesh"

/* A value added to XrSpaceComponentTypeFB. */
#define XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META ((XrSpaceComponentTypeFB)1000269000)

#define XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META ((XrStructureType)1000269001)
#define XR_TYPE_SPACE_TRIANGLE_MESH_META ((XrStructureType)1000269002)

typedef struct XrSpaceTriangleMeshGetInfoMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
} XrSpaceTriangleMeshGetInfoMETA;

/* Two-call idiom on both arrays; indices hold three per triangle. */
typedef struct XrSpaceTriangleMeshMETA {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t vertexCapacityInput;
    uint32_t vertexCountOutput;
    XrVector3f* vertices;
    uint32_t indexCapacityInput;
    uint32_t indexCountOutput;
    uint32_t* indices;
} XrSpaceTriangleMeshMETA;

typedef XrResult(XRAPI_PTR* PFN_xrGetSpaceTriangleMeshMETA)(
    XrSpace space, const XrSpaceTriangleMeshGetInfoMETA* getInfo,
    XrSpaceTriangleMeshMETA* triangleMeshOutput);
#endif /* XR_META_spatial_entity_mesh */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_MESH_H */
