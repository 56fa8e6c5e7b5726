/* roomsense: declarations for XR_EXT_spatial_plane_tracking (the plane
 * tracking capability of XR_EXT_spatial_entity and its plane components).
 * Used only when the system <openxr/openxr.h> lacks the extension. */
#ifndef ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_PLANE_TRACKING_H
#define ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_PLANE_TRACKING_H

#include <openxr/openxr.h>

#include "XR_EXT_spatial_entity.h"

#ifdef __cplusplus
extern "C" {
#endif

/* XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT and the component types
 * PLANE_ALIGNMENT, MESH_2D, POLYGON_2D and PLANE_SEMANTIC_LABEL are members
 * of the enums declared in XR_EXT_spatial_entity.h. */
#ifndef XR_EXT_spatial_plane_tracking
#define XR_EXT_spatial_plane_tracking 1
#define XR_EXT_spatial_plane_tracking_SPEC_VERSION 1
#define XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME "XR_EXT_spatial_plane_tracking"

#define XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT ((XrStructureType)1000741000)
#define XR_TYPE_SPATIAL_COMPONENT_PLANE_ALIGNMENT_LIST_EXT ((XrStructureType)1000741001)
#define XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT ((XrStructureType)1000741002)
#define XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT ((XrStructureType)1000741003)
#define XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT ((XrStructureType)1000741004)

typedef enum XrSpatialPlaneAlignmentEXT {
    XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT = 0,
    XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT = 1,
    XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT = 2,
    XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT = 3,
    XR_SPATIAL_PLANE_ALIGNMENT_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialPlaneAlignmentEXT;

typedef enum XrSpatialPlaneSemanticLabelEXT {
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT = 1,
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT = 2,
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT = 3,
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT = 4,
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT = 5,
    XR_SPATIAL_PLANE_SEMANTIC_LABEL_MAX_ENUM_EXT = 0x7FFFFFFF
} XrSpatialPlaneSemanticLabelEXT;

/* Same layout as XrSpatialCapabilityConfigurationBaseHeaderEXT; capability
 * is XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT. */
typedef struct XrSpatialCapabilityConfigurationPlaneTrackingEXT {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpatialCapabilityEXT capability;
    uint32_t enabledComponentCount;
    const XrSpatialComponentTypeEXT* enabledComponents;
} XrSpatialCapabilityConfigurationPlaneTrackingEXT;

/* The lists below chain to XrSpatialComponentDataQueryResultEXT, one element
 * per entity id returned by the query. */
typedef struct XrSpatialComponentPlaneAlignmentListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t planeAlignmentCount;
    XrSpatialPlaneAlignmentEXT* planeAlignments;
} XrSpatialComponentPlaneAlignmentListEXT;

/* 2D triangle mesh in the plane: XrVector2f vertices, index buffer. */
typedef struct XrSpatialComponentMesh2DListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t meshCount;
    XrSpatialMeshDataEXT* meshes;
} XrSpatialComponentMesh2DListEXT;

typedef struct XrSpatialPolygon2DDataEXT {
    XrPosef origin;
    XrSpatialBufferEXT vertexBuffer;
} XrSpatialPolygon2DDataEXT;

typedef struct XrSpatialComponentPolygon2DListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t polygonCount;
    XrSpatialPolygon2DDataEXT* polygons;
} XrSpatialComponentPolygon2DListEXT;

typedef struct XrSpatialComponentPlaneSemanticLabelListEXT {
    XrStructureType type;
    void* XR_MAY_ALIAS next;
    uint32_t semanticLabelCount;
    XrSpatialPlaneSemanticLabelEXT* semanticLabels;
} XrSpatialComponentPlaneSemanticLabelListEXT;

#endif /* XR_EXT_spatial_plane_tracking */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_EXT_SPATIAL_PLANE_TRACKING_H */
