/* roomsense: small OpenXR basics that newer headers have and OpenXR 1.0.20
 * (Debian 12) lacks: XR_DEFINE_OPAQUE_64, the 1.1 core types XrUuid,
 * XrExtent3Df and XrBoxf, XrExtent3DfEXT, and XR_EXT_uuid. Each piece is
 * declared only when the system <openxr/openxr.h> does not already have it. */
#ifndef ROOMSENSE_XR_EXT_BASE_TYPES_H
#define ROOMSENSE_XR_EXT_BASE_TYPES_H

#include <openxr/openxr.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Opaque 64-bit values (futures and the like): a pointer-sized struct
 * pointer on 64-bit targets, a plain uint64_t elsewhere, as in newer headers. */
#if !defined(XR_DEFINE_OPAQUE_64)
#if (XR_PTR_SIZE == 8)
#define XR_DEFINE_OPAQUE_64(object) typedef struct object##_T* object;
#else
#define XR_DEFINE_OPAQUE_64(object) typedef uint64_t object;
#endif
#endif

/* XrUuid: core since OpenXR 1.1 (which defines XR_UUID_SIZE with it). */
#if !defined(XR_UUID_SIZE)
#define XR_UUID_SIZE 16
typedef struct XrUuid {
    uint8_t data[XR_UUID_SIZE];
} XrUuid;
#endif

/* XrExtent3Df and XrBoxf: core since OpenXR 1.1. Headers 1.0.24-1.0.34 only
 * had the extension spellings (XrExtent3DfFB, XrExtent3DfEXT), which stay
 * distinct types there; the layout is the same. */
#if !defined(XR_VERSION_1_1)
typedef struct XrExtent3Df {
    float width;
    float height;
    float depth;
} XrExtent3Df;

typedef struct XrBoxf {
    XrPosef center;
    XrExtent3Df extents;
} XrBoxf;
#endif

/* XrExtent3DfEXT: a struct in XR_EXT_plane_detection (1.0.28-1.0.34), an alias
 * of XrExtent3Df since 1.1. Needed by XR_ML_world_mesh_detection. A header of
 * ours for XR_EXT_plane_detection must not declare it again. */
#if !defined(XR_VERSION_1_1) && !defined(XR_EXT_plane_detection)
typedef XrExtent3Df XrExtent3DfEXT;
#endif

/* XR_EXT_uuid. Every header that has XrUuidEXT (1.0.21 onwards, including
 * those that declare it inside XR_FB_spatial_entity) also defines XR_EXT_uuid,
 * so this one guard is enough. Newer headers make XrUuidEXT an alias of
 * XrUuid; so do we. */
#ifndef XR_EXT_uuid
#define XR_EXT_uuid 1
#define XR_EXT_uuid_SPEC_VERSION 1
#define XR_EXT_UUID_EXTENSION_NAME "XR_EXT_uuid"
#define XR_UUID_SIZE_EXT 16
typedef XrUuid XrUuidEXT;
#endif

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_BASE_TYPES_H */
