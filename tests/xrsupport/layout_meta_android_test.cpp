// Layout and value checks for our own declarations of XR_FB_spatial_entity(_query),
// XR_FB_scene, XR_FB_spatial_entity_container, XR_META_spatial_entity_mesh,
// XR_META_spatial_entity_discovery and XR_ANDROID_scene_meshing
// (xrsupport/include/roomsense/xr/ext/). The test builds against the system
// openxr.h (Debian 12: 1.0.20), where our blocks are the ones in use.
//
// Expected numbers (x86-64) were produced by a probe program compiled against
// the official Khronos header, OpenXR-SDK 1.1.53 include/openxr/openxr.h. The
// XR_ANDROID_scene_meshing numbers, which that header lacks, come from the same
// probe compiled against the vendored header in GodotVR/godot_openxr_vendors
// (thirdparty/androidxr/include/androidxr/xr_android_scene_meshing.h, generated
// from the registry XML, revision 3); its values agree with the Android XR
// extension page and the LWJGL bindings.

#ifndef XR_NO_PROTOTYPES
#define XR_NO_PROTOTYPES 1
#endif

#include <cstddef>
#include <cstdint>

#include <gtest/gtest.h>
#include <openxr/openxr.h>

#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_discovery.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

// These numbers hold for LP64 targets only.
static_assert(sizeof(void*) == 8, "layout numbers below are for 64-bit targets");

namespace {

// ---- XR_FB_spatial_entity.h ----

TEST(LayoutFbSpatialEntity, XrSystemSpatialEntityPropertiesFB) {
    EXPECT_EQ(sizeof(XrSystemSpatialEntityPropertiesFB), 24u);
    EXPECT_EQ(alignof(XrSystemSpatialEntityPropertiesFB), 8u);
    EXPECT_EQ(offsetof(XrSystemSpatialEntityPropertiesFB, type), 0u);
    EXPECT_EQ(offsetof(XrSystemSpatialEntityPropertiesFB, next), 8u);
    EXPECT_EQ(offsetof(XrSystemSpatialEntityPropertiesFB, supportsSpatialEntity), 16u);
}

TEST(LayoutFbSpatialEntity, XrSpatialAnchorCreateInfoFB) {
    EXPECT_EQ(sizeof(XrSpatialAnchorCreateInfoFB), 64u);
    EXPECT_EQ(alignof(XrSpatialAnchorCreateInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpatialAnchorCreateInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpatialAnchorCreateInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpatialAnchorCreateInfoFB, space), 16u);
    EXPECT_EQ(offsetof(XrSpatialAnchorCreateInfoFB, poseInSpace), 24u);
    EXPECT_EQ(offsetof(XrSpatialAnchorCreateInfoFB, time), 56u);
}

TEST(LayoutFbSpatialEntity, XrSpaceComponentStatusSetInfoFB) {
    EXPECT_EQ(sizeof(XrSpaceComponentStatusSetInfoFB), 32u);
    EXPECT_EQ(alignof(XrSpaceComponentStatusSetInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusSetInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusSetInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusSetInfoFB, componentType), 16u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusSetInfoFB, enabled), 20u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusSetInfoFB, timeout), 24u);
}

TEST(LayoutFbSpatialEntity, XrSpaceComponentStatusFB) {
    EXPECT_EQ(sizeof(XrSpaceComponentStatusFB), 24u);
    EXPECT_EQ(alignof(XrSpaceComponentStatusFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusFB, enabled), 16u);
    EXPECT_EQ(offsetof(XrSpaceComponentStatusFB, changePending), 20u);
}

TEST(LayoutFbSpatialEntity, XrEventDataSpatialAnchorCreateCompleteFB) {
    EXPECT_EQ(sizeof(XrEventDataSpatialAnchorCreateCompleteFB), 56u);
    EXPECT_EQ(alignof(XrEventDataSpatialAnchorCreateCompleteFB), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, requestId), 16u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, result), 24u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, space), 32u);
    EXPECT_EQ(offsetof(XrEventDataSpatialAnchorCreateCompleteFB, uuid), 40u);
}

TEST(LayoutFbSpatialEntity, XrEventDataSpaceSetStatusCompleteFB) {
    EXPECT_EQ(sizeof(XrEventDataSpaceSetStatusCompleteFB), 64u);
    EXPECT_EQ(alignof(XrEventDataSpaceSetStatusCompleteFB), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, requestId), 16u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, result), 24u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, space), 32u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, uuid), 40u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, componentType), 56u);
    EXPECT_EQ(offsetof(XrEventDataSpaceSetStatusCompleteFB, enabled), 60u);
}

TEST(LayoutFbSpatialEntity, XrSpaceQueryInfoBaseHeaderFB) {
    EXPECT_EQ(sizeof(XrSpaceQueryInfoBaseHeaderFB), 16u);
    EXPECT_EQ(alignof(XrSpaceQueryInfoBaseHeaderFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoBaseHeaderFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoBaseHeaderFB, next), 8u);
}

TEST(LayoutFbSpatialEntity, XrSpaceFilterInfoBaseHeaderFB) {
    EXPECT_EQ(sizeof(XrSpaceFilterInfoBaseHeaderFB), 16u);
    EXPECT_EQ(alignof(XrSpaceFilterInfoBaseHeaderFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterInfoBaseHeaderFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceFilterInfoBaseHeaderFB, next), 8u);
}

TEST(LayoutFbSpatialEntity, XrSpaceQueryInfoFB) {
    EXPECT_EQ(sizeof(XrSpaceQueryInfoFB), 48u);
    EXPECT_EQ(alignof(XrSpaceQueryInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, queryAction), 16u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, maxResultCount), 20u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, timeout), 24u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, filter), 32u);
    EXPECT_EQ(offsetof(XrSpaceQueryInfoFB, excludeFilter), 40u);
}

TEST(LayoutFbSpatialEntity, XrSpaceStorageLocationFilterInfoFB) {
    EXPECT_EQ(sizeof(XrSpaceStorageLocationFilterInfoFB), 24u);
    EXPECT_EQ(alignof(XrSpaceStorageLocationFilterInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceStorageLocationFilterInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceStorageLocationFilterInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceStorageLocationFilterInfoFB, location), 16u);
}

TEST(LayoutFbSpatialEntity, XrSpaceUuidFilterInfoFB) {
    EXPECT_EQ(sizeof(XrSpaceUuidFilterInfoFB), 32u);
    EXPECT_EQ(alignof(XrSpaceUuidFilterInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceUuidFilterInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceUuidFilterInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceUuidFilterInfoFB, uuidCount), 16u);
    EXPECT_EQ(offsetof(XrSpaceUuidFilterInfoFB, uuids), 24u);
}

TEST(LayoutFbSpatialEntity, XrSpaceComponentFilterInfoFB) {
    EXPECT_EQ(sizeof(XrSpaceComponentFilterInfoFB), 24u);
    EXPECT_EQ(alignof(XrSpaceComponentFilterInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentFilterInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceComponentFilterInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceComponentFilterInfoFB, componentType), 16u);
}

TEST(LayoutFbSpatialEntity, XrSpaceQueryResultFB) {
    EXPECT_EQ(sizeof(XrSpaceQueryResultFB), 24u);
    EXPECT_EQ(alignof(XrSpaceQueryResultFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultFB, space), 0u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultFB, uuid), 8u);
}

TEST(LayoutFbSpatialEntity, XrSpaceQueryResultsFB) {
    EXPECT_EQ(sizeof(XrSpaceQueryResultsFB), 32u);
    EXPECT_EQ(alignof(XrSpaceQueryResultsFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultsFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultsFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultsFB, resultCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultsFB, resultCountOutput), 20u);
    EXPECT_EQ(offsetof(XrSpaceQueryResultsFB, results), 24u);
}

TEST(LayoutFbSpatialEntity, XrEventDataSpaceQueryResultsAvailableFB) {
    EXPECT_EQ(sizeof(XrEventDataSpaceQueryResultsAvailableFB), 24u);
    EXPECT_EQ(alignof(XrEventDataSpaceQueryResultsAvailableFB), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryResultsAvailableFB, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryResultsAvailableFB, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryResultsAvailableFB, requestId), 16u);
}

TEST(LayoutFbSpatialEntity, XrEventDataSpaceQueryCompleteFB) {
    EXPECT_EQ(sizeof(XrEventDataSpaceQueryCompleteFB), 32u);
    EXPECT_EQ(alignof(XrEventDataSpaceQueryCompleteFB), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryCompleteFB, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryCompleteFB, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryCompleteFB, requestId), 16u);
    EXPECT_EQ(offsetof(XrEventDataSpaceQueryCompleteFB, result), 24u);
}

TEST(LayoutFbSpatialEntity, ScalarsAndHandles) {
    EXPECT_EQ(sizeof(XrAsyncRequestIdFB), 8u);
    EXPECT_EQ(alignof(XrAsyncRequestIdFB), 8u);
}

TEST(ConstantsFbSpatialEntity, Values) {
    EXPECT_EQ(static_cast<int64_t>(XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB), INT64_C(-1000113000));
    EXPECT_EQ(static_cast<int64_t>(XR_ERROR_SPACE_COMPONENT_NOT_ENABLED_FB), INT64_C(-1000113001));
    EXPECT_EQ(static_cast<int64_t>(XR_ERROR_SPACE_COMPONENT_STATUS_PENDING_FB), INT64_C(-1000113002));
    EXPECT_EQ(static_cast<int64_t>(XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB), INT64_C(-1000113003));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_COMPONENT_STATUS_FB), INT64_C(1000113001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPATIAL_ANCHOR_CREATE_INFO_FB), INT64_C(1000113003));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SYSTEM_SPATIAL_ENTITY_PROPERTIES_FB), INT64_C(1000113004));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB), INT64_C(1000113005));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB), INT64_C(1000113006));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB), INT64_C(1000113007));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_QUERY_INFO_FB), INT64_C(1000156001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_QUERY_RESULTS_FB), INT64_C(1000156002));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_STORAGE_LOCATION_FILTER_INFO_FB), INT64_C(1000156003));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB), INT64_C(1000156052));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_UUID_FILTER_INFO_FB), INT64_C(1000156054));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB), INT64_C(1000156103));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB), INT64_C(1000156104));
    EXPECT_EQ(static_cast<int64_t>(XR_FB_spatial_entity_SPEC_VERSION), INT64_C(3));
    EXPECT_EQ(static_cast<int64_t>(XR_FB_spatial_entity_query_SPEC_VERSION), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_STORABLE_FB), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_SHARABLE_FB), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_BOUNDED_2D_FB), INT64_C(3));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_BOUNDED_3D_FB), INT64_C(4));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_SEMANTIC_LABELS_FB), INT64_C(5));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB), INT64_C(6));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_SPACE_CONTAINER_FB), INT64_C(7));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_MAX_ENUM_FB), INT64_C(2147483647));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_QUERY_ACTION_LOAD_FB), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_QUERY_ACTION_MAX_ENUM_FB), INT64_C(2147483647));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_STORAGE_LOCATION_INVALID_FB), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_STORAGE_LOCATION_LOCAL_FB), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_STORAGE_LOCATION_CLOUD_FB), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_STORAGE_LOCATION_MAX_ENUM_FB), INT64_C(2147483647));
    EXPECT_STREQ(XR_FB_SPATIAL_ENTITY_EXTENSION_NAME, "XR_FB_spatial_entity");
    EXPECT_STREQ(XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME, "XR_FB_spatial_entity_query");
}

// ---- XR_FB_scene.h ----

TEST(LayoutFbScene, XrOffset3DfFB) {
    EXPECT_EQ(sizeof(XrOffset3DfFB), 12u);
    EXPECT_EQ(alignof(XrOffset3DfFB), 4u);
    EXPECT_EQ(offsetof(XrOffset3DfFB, x), 0u);
    EXPECT_EQ(offsetof(XrOffset3DfFB, y), 4u);
    EXPECT_EQ(offsetof(XrOffset3DfFB, z), 8u);
}

TEST(LayoutFbScene, XrRect3DfFB) {
    EXPECT_EQ(sizeof(XrRect3DfFB), 24u);
    EXPECT_EQ(alignof(XrRect3DfFB), 4u);
    EXPECT_EQ(offsetof(XrRect3DfFB, offset), 0u);
    EXPECT_EQ(offsetof(XrRect3DfFB, extent), 12u);
}

TEST(LayoutFbScene, XrSemanticLabelsFB) {
    EXPECT_EQ(sizeof(XrSemanticLabelsFB), 32u);
    EXPECT_EQ(alignof(XrSemanticLabelsFB), 8u);
    EXPECT_EQ(offsetof(XrSemanticLabelsFB, type), 0u);
    EXPECT_EQ(offsetof(XrSemanticLabelsFB, next), 8u);
    EXPECT_EQ(offsetof(XrSemanticLabelsFB, bufferCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrSemanticLabelsFB, bufferCountOutput), 20u);
    EXPECT_EQ(offsetof(XrSemanticLabelsFB, buffer), 24u);
}

TEST(LayoutFbScene, XrRoomLayoutFB) {
    EXPECT_EQ(sizeof(XrRoomLayoutFB), 64u);
    EXPECT_EQ(alignof(XrRoomLayoutFB), 8u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, type), 0u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, next), 8u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, floorUuid), 16u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, ceilingUuid), 32u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, wallUuidCapacityInput), 48u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, wallUuidCountOutput), 52u);
    EXPECT_EQ(offsetof(XrRoomLayoutFB, wallUuids), 56u);
}

TEST(LayoutFbScene, XrBoundary2DFB) {
    EXPECT_EQ(sizeof(XrBoundary2DFB), 32u);
    EXPECT_EQ(alignof(XrBoundary2DFB), 8u);
    EXPECT_EQ(offsetof(XrBoundary2DFB, type), 0u);
    EXPECT_EQ(offsetof(XrBoundary2DFB, next), 8u);
    EXPECT_EQ(offsetof(XrBoundary2DFB, vertexCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrBoundary2DFB, vertexCountOutput), 20u);
    EXPECT_EQ(offsetof(XrBoundary2DFB, vertices), 24u);
}

TEST(LayoutFbScene, XrSemanticLabelsSupportInfoFB) {
    EXPECT_EQ(sizeof(XrSemanticLabelsSupportInfoFB), 32u);
    EXPECT_EQ(alignof(XrSemanticLabelsSupportInfoFB), 8u);
    EXPECT_EQ(offsetof(XrSemanticLabelsSupportInfoFB, type), 0u);
    EXPECT_EQ(offsetof(XrSemanticLabelsSupportInfoFB, next), 8u);
    EXPECT_EQ(offsetof(XrSemanticLabelsSupportInfoFB, flags), 16u);
    EXPECT_EQ(offsetof(XrSemanticLabelsSupportInfoFB, recognizedLabels), 24u);
}

TEST(LayoutFbScene, XrSpaceContainerFB) {
    EXPECT_EQ(sizeof(XrSpaceContainerFB), 32u);
    EXPECT_EQ(alignof(XrSpaceContainerFB), 8u);
    EXPECT_EQ(offsetof(XrSpaceContainerFB, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceContainerFB, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceContainerFB, uuidCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrSpaceContainerFB, uuidCountOutput), 20u);
    EXPECT_EQ(offsetof(XrSpaceContainerFB, uuids), 24u);
}

TEST(LayoutFbScene, ScalarsAndHandles) {
    EXPECT_EQ(sizeof(XrSemanticLabelsSupportFlagsFB), 8u);
    EXPECT_EQ(alignof(XrSemanticLabelsSupportFlagsFB), 8u);
    EXPECT_EQ(sizeof(XrExtent3DfFB), 12u);
    EXPECT_EQ(alignof(XrExtent3DfFB), 4u);
}

TEST(ConstantsFbScene, Values) {
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SEMANTIC_LABELS_FB), INT64_C(1000175000));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_ROOM_LAYOUT_FB), INT64_C(1000175001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_BOUNDARY_2D_FB), INT64_C(1000175002));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SEMANTIC_LABELS_SUPPORT_INFO_FB), INT64_C(1000175010));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_CONTAINER_FB), INT64_C(1000199000));
    EXPECT_EQ(static_cast<int64_t>(XR_FB_scene_SPEC_VERSION), INT64_C(4));
    EXPECT_EQ(static_cast<int64_t>(XR_FB_spatial_entity_container_SPEC_VERSION), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SEMANTIC_LABELS_SUPPORT_MULTIPLE_SEMANTIC_LABELS_BIT_FB), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SEMANTIC_LABELS_SUPPORT_ACCEPT_DESK_TO_TABLE_MIGRATION_BIT_FB), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SEMANTIC_LABELS_SUPPORT_ACCEPT_INVISIBLE_WALL_FACE_BIT_FB), INT64_C(4));
    EXPECT_STREQ(XR_FB_SCENE_EXTENSION_NAME, "XR_FB_scene");
    EXPECT_STREQ(XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME, "XR_FB_spatial_entity_container");
}

// ---- XR_META_spatial_entity_mesh.h ----

TEST(LayoutMetaSpatialEntityMesh, XrSpaceTriangleMeshGetInfoMETA) {
    EXPECT_EQ(sizeof(XrSpaceTriangleMeshGetInfoMETA), 16u);
    EXPECT_EQ(alignof(XrSpaceTriangleMeshGetInfoMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshGetInfoMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshGetInfoMETA, next), 8u);
}

TEST(LayoutMetaSpatialEntityMesh, XrSpaceTriangleMeshMETA) {
    EXPECT_EQ(sizeof(XrSpaceTriangleMeshMETA), 48u);
    EXPECT_EQ(alignof(XrSpaceTriangleMeshMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, vertexCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, vertexCountOutput), 20u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, vertices), 24u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, indexCapacityInput), 32u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, indexCountOutput), 36u);
    EXPECT_EQ(offsetof(XrSpaceTriangleMeshMETA, indices), 40u);
}

TEST(ConstantsMetaSpatialEntityMesh, Values) {
    EXPECT_EQ(static_cast<int64_t>(XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META), INT64_C(1000269000));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META), INT64_C(1000269001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_TRIANGLE_MESH_META), INT64_C(1000269002));
    EXPECT_EQ(static_cast<int64_t>(XR_META_spatial_entity_mesh_SPEC_VERSION), INT64_C(1));
    EXPECT_STREQ(XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME, "XR_META_spatial_entity_mesh");
}

// ---- XR_META_spatial_entity_discovery.h ----

TEST(LayoutMetaSpatialEntityDiscovery, XrSystemSpaceDiscoveryPropertiesMETA) {
    EXPECT_EQ(sizeof(XrSystemSpaceDiscoveryPropertiesMETA), 24u);
    EXPECT_EQ(alignof(XrSystemSpaceDiscoveryPropertiesMETA), 8u);
    EXPECT_EQ(offsetof(XrSystemSpaceDiscoveryPropertiesMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSystemSpaceDiscoveryPropertiesMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSystemSpaceDiscoveryPropertiesMETA, supportsSpaceDiscovery), 16u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceFilterBaseHeaderMETA) {
    EXPECT_EQ(sizeof(XrSpaceFilterBaseHeaderMETA), 16u);
    EXPECT_EQ(alignof(XrSpaceFilterBaseHeaderMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterBaseHeaderMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceFilterBaseHeaderMETA, next), 8u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceDiscoveryInfoMETA) {
    EXPECT_EQ(sizeof(XrSpaceDiscoveryInfoMETA), 32u);
    EXPECT_EQ(alignof(XrSpaceDiscoveryInfoMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryInfoMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryInfoMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryInfoMETA, filterCount), 16u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryInfoMETA, filters), 24u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceFilterUuidMETA) {
    EXPECT_EQ(sizeof(XrSpaceFilterUuidMETA), 32u);
    EXPECT_EQ(alignof(XrSpaceFilterUuidMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterUuidMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceFilterUuidMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterUuidMETA, uuidCount), 16u);
    EXPECT_EQ(offsetof(XrSpaceFilterUuidMETA, uuids), 24u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceFilterComponentMETA) {
    EXPECT_EQ(sizeof(XrSpaceFilterComponentMETA), 24u);
    EXPECT_EQ(alignof(XrSpaceFilterComponentMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterComponentMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceFilterComponentMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceFilterComponentMETA, componentType), 16u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceDiscoveryResultMETA) {
    EXPECT_EQ(sizeof(XrSpaceDiscoveryResultMETA), 24u);
    EXPECT_EQ(alignof(XrSpaceDiscoveryResultMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultMETA, space), 0u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultMETA, uuid), 8u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrSpaceDiscoveryResultsMETA) {
    EXPECT_EQ(sizeof(XrSpaceDiscoveryResultsMETA), 32u);
    EXPECT_EQ(alignof(XrSpaceDiscoveryResultsMETA), 8u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultsMETA, type), 0u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultsMETA, next), 8u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultsMETA, resultCapacityInput), 16u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultsMETA, resultCountOutput), 20u);
    EXPECT_EQ(offsetof(XrSpaceDiscoveryResultsMETA, results), 24u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrEventDataSpaceDiscoveryResultsAvailableMETA) {
    EXPECT_EQ(sizeof(XrEventDataSpaceDiscoveryResultsAvailableMETA), 24u);
    EXPECT_EQ(alignof(XrEventDataSpaceDiscoveryResultsAvailableMETA), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryResultsAvailableMETA, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryResultsAvailableMETA, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryResultsAvailableMETA, requestId), 16u);
}

TEST(LayoutMetaSpatialEntityDiscovery, XrEventDataSpaceDiscoveryCompleteMETA) {
    EXPECT_EQ(sizeof(XrEventDataSpaceDiscoveryCompleteMETA), 32u);
    EXPECT_EQ(alignof(XrEventDataSpaceDiscoveryCompleteMETA), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryCompleteMETA, type), 0u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryCompleteMETA, next), 8u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryCompleteMETA, requestId), 16u);
    EXPECT_EQ(offsetof(XrEventDataSpaceDiscoveryCompleteMETA, result), 24u);
}

TEST(ConstantsMetaSpatialEntityDiscovery, Values) {
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SYSTEM_SPACE_DISCOVERY_PROPERTIES_META), INT64_C(1000247000));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_DISCOVERY_INFO_META), INT64_C(1000247001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_FILTER_UUID_META), INT64_C(1000247003));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_FILTER_COMPONENT_META), INT64_C(1000247004));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_DISCOVERY_RESULT_META), INT64_C(1000247005));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SPACE_DISCOVERY_RESULTS_META), INT64_C(1000247006));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPACE_DISCOVERY_RESULTS_AVAILABLE_META), INT64_C(1000247007));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_EVENT_DATA_SPACE_DISCOVERY_COMPLETE_META), INT64_C(1000247008));
    EXPECT_EQ(static_cast<int64_t>(XR_META_spatial_entity_discovery_SPEC_VERSION), INT64_C(1));
    EXPECT_STREQ(XR_META_SPATIAL_ENTITY_DISCOVERY_EXTENSION_NAME, "XR_META_spatial_entity_discovery");
}

// ---- XR_ANDROID_scene_meshing.h ----

TEST(LayoutAndroidSceneMeshing, XrSystemSceneMeshingPropertiesANDROID) {
    EXPECT_EQ(sizeof(XrSystemSceneMeshingPropertiesANDROID), 24u);
    EXPECT_EQ(alignof(XrSystemSceneMeshingPropertiesANDROID), 8u);
    EXPECT_EQ(offsetof(XrSystemSceneMeshingPropertiesANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSystemSceneMeshingPropertiesANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSystemSceneMeshingPropertiesANDROID, supportsSceneMeshing), 16u);
}

TEST(LayoutAndroidSceneMeshing, XrSceneMeshingTrackerCreateInfoANDROID) {
    EXPECT_EQ(sizeof(XrSceneMeshingTrackerCreateInfoANDROID), 24u);
    EXPECT_EQ(alignof(XrSceneMeshingTrackerCreateInfoANDROID), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshingTrackerCreateInfoANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSceneMeshingTrackerCreateInfoANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshingTrackerCreateInfoANDROID, semanticLabelSet), 16u);
    EXPECT_EQ(offsetof(XrSceneMeshingTrackerCreateInfoANDROID, enableNormals), 20u);
}

TEST(LayoutAndroidSceneMeshing, XrSceneMeshSnapshotCreateInfoANDROID) {
    EXPECT_EQ(sizeof(XrSceneMeshSnapshotCreateInfoANDROID), 72u);
    EXPECT_EQ(alignof(XrSceneMeshSnapshotCreateInfoANDROID), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreateInfoANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreateInfoANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreateInfoANDROID, baseSpace), 16u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreateInfoANDROID, time), 24u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreateInfoANDROID, boundingBox), 32u);
}

TEST(LayoutAndroidSceneMeshing, XrSceneMeshSnapshotCreationResultANDROID) {
    EXPECT_EQ(sizeof(XrSceneMeshSnapshotCreationResultANDROID), 32u);
    EXPECT_EQ(alignof(XrSceneMeshSnapshotCreationResultANDROID), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreationResultANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreationResultANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreationResultANDROID, snapshot), 16u);
    EXPECT_EQ(offsetof(XrSceneMeshSnapshotCreationResultANDROID, trackingState), 24u);
}

TEST(LayoutAndroidSceneMeshing, XrSceneSubmeshStateANDROID) {
    EXPECT_EQ(sizeof(XrSceneSubmeshStateANDROID), 80u);
    EXPECT_EQ(alignof(XrSceneSubmeshStateANDROID), 8u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, submeshId), 16u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, lastUpdatedTime), 32u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, submeshPoseInBaseSpace), 40u);
    EXPECT_EQ(offsetof(XrSceneSubmeshStateANDROID, bounds), 68u);
}

TEST(LayoutAndroidSceneMeshing, XrSceneSubmeshDataANDROID) {
    EXPECT_EQ(sizeof(XrSceneSubmeshDataANDROID), 80u);
    EXPECT_EQ(alignof(XrSceneSubmeshDataANDROID), 8u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, type), 0u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, next), 8u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, submeshId), 16u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, vertexCapacityInput), 32u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, vertexCountOutput), 36u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, vertexPositions), 40u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, vertexNormals), 48u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, vertexSemantics), 56u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, indexCapacityInput), 64u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, indexCountOutput), 68u);
    EXPECT_EQ(offsetof(XrSceneSubmeshDataANDROID, indices), 72u);
}

TEST(LayoutAndroidSceneMeshing, ScalarsAndHandles) {
    EXPECT_EQ(sizeof(XrSceneMeshingTrackerANDROID), 8u);
    EXPECT_EQ(alignof(XrSceneMeshingTrackerANDROID), 8u);
    EXPECT_EQ(sizeof(XrSceneMeshSnapshotANDROID), 8u);
    EXPECT_EQ(alignof(XrSceneMeshSnapshotANDROID), 8u);
}

TEST(ConstantsAndroidSceneMeshing, Values) {
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SYSTEM_SCENE_MESHING_PROPERTIES_ANDROID), INT64_C(1000718000));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID), INT64_C(1000718001));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID), INT64_C(1000718002));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID), INT64_C(1000718003));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SCENE_SUBMESH_STATE_ANDROID), INT64_C(1000718004));
    EXPECT_EQ(static_cast<int64_t>(XR_TYPE_SCENE_SUBMESH_DATA_ANDROID), INT64_C(1000718005));
    EXPECT_EQ(static_cast<int64_t>(XR_OBJECT_TYPE_SCENE_MESHING_TRACKER_ANDROID), INT64_C(1000718000));
    EXPECT_EQ(static_cast<int64_t>(XR_OBJECT_TYPE_SCENE_MESH_SNAPSHOT_ANDROID), INT64_C(1000718001));
    EXPECT_EQ(static_cast<int64_t>(XR_ANDROID_scene_meshing_SPEC_VERSION), INT64_C(3));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_SET_MAX_ENUM_ANDROID), INT64_C(2147483647));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID), INT64_C(3));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_TABLE_ANDROID), INT64_C(4));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_SEMANTIC_LABEL_MAX_ENUM_ANDROID), INT64_C(2147483647));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_TRACKING_STATE_INITIALIZING_ANDROID), INT64_C(0));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_TRACKING_STATE_TRACKING_ANDROID), INT64_C(1));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_TRACKING_STATE_WAITING_ANDROID), INT64_C(2));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_TRACKING_STATE_ERROR_ANDROID), INT64_C(3));
    EXPECT_EQ(static_cast<int64_t>(XR_SCENE_MESH_TRACKING_STATE_MAX_ENUM_ANDROID), INT64_C(2147483647));
    EXPECT_STREQ(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, "XR_ANDROID_scene_meshing");
}

}  // namespace
