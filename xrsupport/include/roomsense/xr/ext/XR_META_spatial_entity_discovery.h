/* roomsense: declarations for XR_META_spatial_entity_discovery (finding
 * spaces by uuid or component with xrDiscoverSpacesMETA). Used only where the
 * system <openxr/openxr.h> lacks it. */
#ifndef ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_DISCOVERY_H
#define ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_DISCOVERY_H

#include <openxr/openxr.h>

#include "base_types.h"
#include "XR_FB_spatial_entity.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- XR_META_spatial_entity_discovery (registry extension 248, revision 1) ---- */
#ifndef XR_META_spatial_entity_discovery
#define XR_META_spatial_entity_discovery 1
#define XR_META_spatial_entity_discovery_SPEC_VERSION 1
#define XR_META_SPATIAL_ENTITY_DISCOVERY_EXTENSION_NAME "XR_META_spatial_entity_discovery"

#define XR_TYPE_SYSTEM_SPACE_DISCOVERY_PROPERTIES_META ((XrStructureType)1000247000)
#define XR_TYPE_SPACE_DISCOVERY_INFO_META ((XrStructureType)1000247001)
#define XR_TYPE_SPACE_FILTER_UUID_META ((XrStructureType)1000247003)
#define XR_TYPE_SPACE_FILTER_COMPONENT_META ((XrStructureType)1000247004)
#define XR_TYPE_SPACE_DISCOVERY_RESULT_META ((XrStructureType)1000247005)
#define XR_TYPE_SPACE_DISCOVERY_RESULTS_META ((XrStructureType)1000247006)
#define XR_TYPE_EVENT_DATA_SPACE_DISCOVERY_RESULTS_AVAILABLE_META ((XrStructureType)1000247007)
#define XR_TYPE_EVENT_DATA_SPACE_DISCOVERY_COMPLETE_META ((XrStructureType)1000247008)

/* Chained to XrSystemProperties. */
typedef struct XrSystemSpaceDiscoveryPropertiesMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrBool32 supportsSpaceDiscovery;
} XrSystemSpaceDiscoveryPropertiesMETA;

/* Base header of the filter structs listed in XrSpaceDiscoveryInfoMETA. */
typedef struct XR_MAY_ALIAS XrSpaceFilterBaseHeaderMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
} XrSpaceFilterBaseHeaderMETA;

typedef struct XrSpaceDiscoveryInfoMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t filterCount;
    const XrSpaceFilterBaseHeaderMETA* const* filters;
} XrSpaceDiscoveryInfoMETA;

typedef struct XrSpaceFilterUuidMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t uuidCount;
    const XrUuidEXT* uuids;
} XrSpaceFilterUuidMETA;

typedef struct XrSpaceFilterComponentMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrSpaceComponentTypeFB componentType;
} XrSpaceFilterComponentMETA;

typedef struct XrSpaceDiscoveryResultMETA {
    XrSpace space;
    XrUuidEXT uuid;
} XrSpaceDiscoveryResultMETA;

typedef struct XrSpaceDiscoveryResultsMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    uint32_t resultCapacityInput;
    uint32_t resultCountOutput;
    XrSpaceDiscoveryResultMETA* results;
} XrSpaceDiscoveryResultsMETA;

typedef struct XrEventDataSpaceDiscoveryResultsAvailableMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
} XrEventDataSpaceDiscoveryResultsAvailableMETA;

typedef struct XrEventDataSpaceDiscoveryCompleteMETA {
    XrStructureType type;
    const void* XR_MAY_ALIAS next;
    XrAsyncRequestIdFB requestId;
    XrResult result;
} XrEventDataSpaceDiscoveryCompleteMETA;

typedef XrResult(XRAPI_PTR* PFN_xrDiscoverSpacesMETA)(
    XrSession session, const XrSpaceDiscoveryInfoMETA* info, XrAsyncRequestIdFB* requestId);
typedef XrResult(XRAPI_PTR* PFN_xrRetrieveSpaceDiscoveryResultsMETA)(
    XrSession session, XrAsyncRequestIdFB requestId, XrSpaceDiscoveryResultsMETA* results);
#endif /* XR_META_spatial_entity_discovery */

#ifdef __cplusplus
}
#endif

#endif /* ROOMSENSE_XR_EXT_XR_META_SPATIAL_ENTITY_DISCOVERY_H */
