// Layout and value checks for our own declarations of XR_EXT_future, XR_EXT_spatial_entity,
// XR_EXT_spatial_plane_tracking, XR_ML_world_mesh_detection and the shared basics in base_types.h.
// The expected numbers were printed by a probe compiled against the official OpenXR 1.1.53 openxr.h on
// x86-64 Linux (LP64). Against that header our blocks are skipped, so these tests then check the probe itself.
#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"
#include "roomsense/xr/ext/base_types.h"

#include <openxr/openxr.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

// Size and alignment of a struct.
#define EXPECT_LAYOUT(T, size, align)                            \
  do {                                                           \
    EXPECT_EQ(sizeof(T), std::size_t{size}) << "sizeof " #T;     \
    EXPECT_EQ(alignof(T), std::size_t{align}) << "alignof " #T;  \
  } while (0)

// Offset of one member.
#define EXPECT_OFFSET(T, member, offset) \
  EXPECT_EQ(offsetof(T, member), std::size_t{offset}) << #T "::" #member

// Value of an enumerant, a core-enum value we define as a macro, or an integer macro.
#define EXPECT_VALUE(name, value) EXPECT_EQ(static_cast<long long>(name), value##LL) << #name

// Value of a 64-bit flag bit.
#define EXPECT_FLAG(name, value) EXPECT_EQ(static_cast<std::uint64_t>(name), std::uint64_t{value}) << #name


// Struct layouts are those of a 64-bit target; 32-bit targets differ in pointer and handle sizes.
#if INTPTR_MAX == INT64_MAX

// --- base_types.h ---

TEST(SpatialMlBaseTypesLayout, XrUuid) {
  EXPECT_LAYOUT(XrUuid, 16, 1);
  EXPECT_OFFSET(XrUuid, data, 0);
}

TEST(SpatialMlBaseTypesLayout, XrExtent3Df) {
  EXPECT_LAYOUT(XrExtent3Df, 12, 4);
  EXPECT_OFFSET(XrExtent3Df, width, 0);
  EXPECT_OFFSET(XrExtent3Df, height, 4);
  EXPECT_OFFSET(XrExtent3Df, depth, 8);
}

TEST(SpatialMlBaseTypesLayout, XrBoxf) {
  EXPECT_LAYOUT(XrBoxf, 40, 4);
  EXPECT_OFFSET(XrBoxf, center, 0);
  EXPECT_OFFSET(XrBoxf, extents, 28);
}

TEST(SpatialMlBaseTypesLayout, XrExtent3DfEXT) {
  EXPECT_LAYOUT(XrExtent3DfEXT, 12, 4);
}

TEST(SpatialMlBaseTypesLayout, XrUuidEXT) {
  EXPECT_LAYOUT(XrUuidEXT, 16, 1);
}

// --- XR_EXT_future.h ---

TEST(ExtFutureLayout, XrFutureCancelInfoEXT) {
  EXPECT_LAYOUT(XrFutureCancelInfoEXT, 24, 8);
  EXPECT_OFFSET(XrFutureCancelInfoEXT, type, 0);
  EXPECT_OFFSET(XrFutureCancelInfoEXT, next, 8);
  EXPECT_OFFSET(XrFutureCancelInfoEXT, future, 16);
}

TEST(ExtFutureLayout, XrFuturePollInfoEXT) {
  EXPECT_LAYOUT(XrFuturePollInfoEXT, 24, 8);
  EXPECT_OFFSET(XrFuturePollInfoEXT, type, 0);
  EXPECT_OFFSET(XrFuturePollInfoEXT, next, 8);
  EXPECT_OFFSET(XrFuturePollInfoEXT, future, 16);
}

TEST(ExtFutureLayout, XrFutureCompletionBaseHeaderEXT) {
  EXPECT_LAYOUT(XrFutureCompletionBaseHeaderEXT, 24, 8);
  EXPECT_OFFSET(XrFutureCompletionBaseHeaderEXT, type, 0);
  EXPECT_OFFSET(XrFutureCompletionBaseHeaderEXT, next, 8);
  EXPECT_OFFSET(XrFutureCompletionBaseHeaderEXT, futureResult, 16);
}

TEST(ExtFutureLayout, XrFutureCompletionEXT) {
  EXPECT_LAYOUT(XrFutureCompletionEXT, 24, 8);
  EXPECT_OFFSET(XrFutureCompletionEXT, type, 0);
  EXPECT_OFFSET(XrFutureCompletionEXT, next, 8);
  EXPECT_OFFSET(XrFutureCompletionEXT, futureResult, 16);
}

TEST(ExtFutureLayout, XrFuturePollResultEXT) {
  EXPECT_LAYOUT(XrFuturePollResultEXT, 24, 8);
  EXPECT_OFFSET(XrFuturePollResultEXT, type, 0);
  EXPECT_OFFSET(XrFuturePollResultEXT, next, 8);
  EXPECT_OFFSET(XrFuturePollResultEXT, state, 16);
}

// --- XR_EXT_spatial_entity.h ---

TEST(ExtSpatialEntityLayout, XrSpatialCapabilityComponentTypesEXT) {
  EXPECT_LAYOUT(XrSpatialCapabilityComponentTypesEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialCapabilityComponentTypesEXT, type, 0);
  EXPECT_OFFSET(XrSpatialCapabilityComponentTypesEXT, next, 8);
  EXPECT_OFFSET(XrSpatialCapabilityComponentTypesEXT, componentTypeCapacityInput, 16);
  EXPECT_OFFSET(XrSpatialCapabilityComponentTypesEXT, componentTypeCountOutput, 20);
  EXPECT_OFFSET(XrSpatialCapabilityComponentTypesEXT, componentTypes, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialCapabilityConfigurationBaseHeaderEXT) {
  EXPECT_LAYOUT(XrSpatialCapabilityConfigurationBaseHeaderEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationBaseHeaderEXT, type, 0);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationBaseHeaderEXT, next, 8);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationBaseHeaderEXT, capability, 16);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationBaseHeaderEXT, enabledComponentCount, 20);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationBaseHeaderEXT, enabledComponents, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialContextCreateInfoEXT) {
  EXPECT_LAYOUT(XrSpatialContextCreateInfoEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialContextCreateInfoEXT, type, 0);
  EXPECT_OFFSET(XrSpatialContextCreateInfoEXT, next, 8);
  EXPECT_OFFSET(XrSpatialContextCreateInfoEXT, capabilityConfigCount, 16);
  EXPECT_OFFSET(XrSpatialContextCreateInfoEXT, capabilityConfigs, 24);
}

TEST(ExtSpatialEntityLayout, XrCreateSpatialContextCompletionEXT) {
  EXPECT_LAYOUT(XrCreateSpatialContextCompletionEXT, 32, 8);
  EXPECT_OFFSET(XrCreateSpatialContextCompletionEXT, type, 0);
  EXPECT_OFFSET(XrCreateSpatialContextCompletionEXT, next, 8);
  EXPECT_OFFSET(XrCreateSpatialContextCompletionEXT, futureResult, 16);
  EXPECT_OFFSET(XrCreateSpatialContextCompletionEXT, spatialContext, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialDiscoverySnapshotCreateInfoEXT) {
  EXPECT_LAYOUT(XrSpatialDiscoverySnapshotCreateInfoEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialDiscoverySnapshotCreateInfoEXT, type, 0);
  EXPECT_OFFSET(XrSpatialDiscoverySnapshotCreateInfoEXT, next, 8);
  EXPECT_OFFSET(XrSpatialDiscoverySnapshotCreateInfoEXT, componentTypeCount, 16);
  EXPECT_OFFSET(XrSpatialDiscoverySnapshotCreateInfoEXT, componentTypes, 24);
}

TEST(ExtSpatialEntityLayout, XrCreateSpatialDiscoverySnapshotCompletionInfoEXT) {
  EXPECT_LAYOUT(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, 40, 8);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, type, 0);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, next, 8);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, baseSpace, 16);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, time, 24);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionInfoEXT, future, 32);
}

TEST(ExtSpatialEntityLayout, XrCreateSpatialDiscoverySnapshotCompletionEXT) {
  EXPECT_LAYOUT(XrCreateSpatialDiscoverySnapshotCompletionEXT, 32, 8);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionEXT, type, 0);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionEXT, next, 8);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionEXT, futureResult, 16);
  EXPECT_OFFSET(XrCreateSpatialDiscoverySnapshotCompletionEXT, snapshot, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentDataQueryConditionEXT) {
  EXPECT_LAYOUT(XrSpatialComponentDataQueryConditionEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentDataQueryConditionEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentDataQueryConditionEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentDataQueryConditionEXT, componentTypeCount, 16);
  EXPECT_OFFSET(XrSpatialComponentDataQueryConditionEXT, componentTypes, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentDataQueryResultEXT) {
  EXPECT_LAYOUT(XrSpatialComponentDataQueryResultEXT, 48, 8);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityIdCapacityInput, 16);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityIdCountOutput, 20);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityIds, 24);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityStateCapacityInput, 32);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityStateCountOutput, 36);
  EXPECT_OFFSET(XrSpatialComponentDataQueryResultEXT, entityStates, 40);
}

TEST(ExtSpatialEntityLayout, XrSpatialBufferEXT) {
  EXPECT_LAYOUT(XrSpatialBufferEXT, 16, 8);
  EXPECT_OFFSET(XrSpatialBufferEXT, bufferId, 0);
  EXPECT_OFFSET(XrSpatialBufferEXT, bufferType, 8);
}

TEST(ExtSpatialEntityLayout, XrSpatialBufferGetInfoEXT) {
  EXPECT_LAYOUT(XrSpatialBufferGetInfoEXT, 24, 8);
  EXPECT_OFFSET(XrSpatialBufferGetInfoEXT, type, 0);
  EXPECT_OFFSET(XrSpatialBufferGetInfoEXT, next, 8);
  EXPECT_OFFSET(XrSpatialBufferGetInfoEXT, bufferId, 16);
}

TEST(ExtSpatialEntityLayout, XrSpatialBounded2DDataEXT) {
  EXPECT_LAYOUT(XrSpatialBounded2DDataEXT, 36, 4);
  EXPECT_OFFSET(XrSpatialBounded2DDataEXT, center, 0);
  EXPECT_OFFSET(XrSpatialBounded2DDataEXT, extents, 28);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentBounded2DListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentBounded2DListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentBounded2DListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentBounded2DListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentBounded2DListEXT, boundCount, 16);
  EXPECT_OFFSET(XrSpatialComponentBounded2DListEXT, bounds, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentBounded3DListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentBounded3DListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentBounded3DListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentBounded3DListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentBounded3DListEXT, boundCount, 16);
  EXPECT_OFFSET(XrSpatialComponentBounded3DListEXT, bounds, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentParentListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentParentListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentParentListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentParentListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentParentListEXT, parentCount, 16);
  EXPECT_OFFSET(XrSpatialComponentParentListEXT, parents, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialMeshDataEXT) {
  EXPECT_LAYOUT(XrSpatialMeshDataEXT, 64, 8);
  EXPECT_OFFSET(XrSpatialMeshDataEXT, origin, 0);
  EXPECT_OFFSET(XrSpatialMeshDataEXT, vertexBuffer, 32);
  EXPECT_OFFSET(XrSpatialMeshDataEXT, indexBuffer, 48);
}

TEST(ExtSpatialEntityLayout, XrSpatialComponentMesh3DListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentMesh3DListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentMesh3DListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentMesh3DListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentMesh3DListEXT, meshCount, 16);
  EXPECT_OFFSET(XrSpatialComponentMesh3DListEXT, meshes, 24);
}

TEST(ExtSpatialEntityLayout, XrSpatialEntityFromIdCreateInfoEXT) {
  EXPECT_LAYOUT(XrSpatialEntityFromIdCreateInfoEXT, 24, 8);
  EXPECT_OFFSET(XrSpatialEntityFromIdCreateInfoEXT, type, 0);
  EXPECT_OFFSET(XrSpatialEntityFromIdCreateInfoEXT, next, 8);
  EXPECT_OFFSET(XrSpatialEntityFromIdCreateInfoEXT, entityId, 16);
}

TEST(ExtSpatialEntityLayout, XrSpatialUpdateSnapshotCreateInfoEXT) {
  EXPECT_LAYOUT(XrSpatialUpdateSnapshotCreateInfoEXT, 64, 8);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, type, 0);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, next, 8);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, entityCount, 16);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, entities, 24);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, componentTypeCount, 32);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, componentTypes, 40);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, baseSpace, 48);
  EXPECT_OFFSET(XrSpatialUpdateSnapshotCreateInfoEXT, time, 56);
}

TEST(ExtSpatialEntityLayout, XrEventDataSpatialDiscoveryRecommendedEXT) {
  EXPECT_LAYOUT(XrEventDataSpatialDiscoveryRecommendedEXT, 24, 8);
  EXPECT_OFFSET(XrEventDataSpatialDiscoveryRecommendedEXT, type, 0);
  EXPECT_OFFSET(XrEventDataSpatialDiscoveryRecommendedEXT, next, 8);
  EXPECT_OFFSET(XrEventDataSpatialDiscoveryRecommendedEXT, spatialContext, 16);
}

TEST(ExtSpatialEntityLayout, XrSpatialFilterTrackingStateEXT) {
  EXPECT_LAYOUT(XrSpatialFilterTrackingStateEXT, 24, 8);
  EXPECT_OFFSET(XrSpatialFilterTrackingStateEXT, type, 0);
  EXPECT_OFFSET(XrSpatialFilterTrackingStateEXT, next, 8);
  EXPECT_OFFSET(XrSpatialFilterTrackingStateEXT, trackingState, 16);
}

// --- XR_EXT_spatial_plane_tracking.h ---

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialCapabilityConfigurationPlaneTrackingEXT) {
  EXPECT_LAYOUT(XrSpatialCapabilityConfigurationPlaneTrackingEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationPlaneTrackingEXT, type, 0);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationPlaneTrackingEXT, next, 8);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationPlaneTrackingEXT, capability, 16);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationPlaneTrackingEXT, enabledComponentCount, 20);
  EXPECT_OFFSET(XrSpatialCapabilityConfigurationPlaneTrackingEXT, enabledComponents, 24);
}

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialComponentPlaneAlignmentListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentPlaneAlignmentListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentPlaneAlignmentListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentPlaneAlignmentListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentPlaneAlignmentListEXT, planeAlignmentCount, 16);
  EXPECT_OFFSET(XrSpatialComponentPlaneAlignmentListEXT, planeAlignments, 24);
}

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialComponentMesh2DListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentMesh2DListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentMesh2DListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentMesh2DListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentMesh2DListEXT, meshCount, 16);
  EXPECT_OFFSET(XrSpatialComponentMesh2DListEXT, meshes, 24);
}

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialPolygon2DDataEXT) {
  EXPECT_LAYOUT(XrSpatialPolygon2DDataEXT, 48, 8);
  EXPECT_OFFSET(XrSpatialPolygon2DDataEXT, origin, 0);
  EXPECT_OFFSET(XrSpatialPolygon2DDataEXT, vertexBuffer, 32);
}

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialComponentPolygon2DListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentPolygon2DListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentPolygon2DListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentPolygon2DListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentPolygon2DListEXT, polygonCount, 16);
  EXPECT_OFFSET(XrSpatialComponentPolygon2DListEXT, polygons, 24);
}

TEST(ExtSpatialPlaneTrackingLayout, XrSpatialComponentPlaneSemanticLabelListEXT) {
  EXPECT_LAYOUT(XrSpatialComponentPlaneSemanticLabelListEXT, 32, 8);
  EXPECT_OFFSET(XrSpatialComponentPlaneSemanticLabelListEXT, type, 0);
  EXPECT_OFFSET(XrSpatialComponentPlaneSemanticLabelListEXT, next, 8);
  EXPECT_OFFSET(XrSpatialComponentPlaneSemanticLabelListEXT, semanticLabelCount, 16);
  EXPECT_OFFSET(XrSpatialComponentPlaneSemanticLabelListEXT, semanticLabels, 24);
}

// --- XR_ML_world_mesh_detection.h ---

TEST(MlWorldMeshDetectionLayout, XrWorldMeshDetectorCreateInfoML) {
  EXPECT_LAYOUT(XrWorldMeshDetectorCreateInfoML, 16, 8);
  EXPECT_OFFSET(XrWorldMeshDetectorCreateInfoML, type, 0);
  EXPECT_OFFSET(XrWorldMeshDetectorCreateInfoML, next, 8);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBlockStateML) {
  EXPECT_LAYOUT(XrWorldMeshBlockStateML, 88, 8);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, uuid, 16);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, meshBoundingBoxCenter, 32);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, meshBoundingBoxExtents, 60);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, lastUpdateTime, 72);
  EXPECT_OFFSET(XrWorldMeshBlockStateML, status, 80);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshStateRequestInfoML) {
  EXPECT_LAYOUT(XrWorldMeshStateRequestInfoML, 72, 8);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, type, 0);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, next, 8);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, baseSpace, 16);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, time, 24);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, boundingBoxCenter, 32);
  EXPECT_OFFSET(XrWorldMeshStateRequestInfoML, boundingBoxExtents, 60);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshStateRequestCompletionML) {
  EXPECT_LAYOUT(XrWorldMeshStateRequestCompletionML, 48, 8);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, type, 0);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, next, 8);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, futureResult, 16);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, timestamp, 24);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, meshBlockStateCapacityInput, 32);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, meshBlockStateCountOutput, 36);
  EXPECT_OFFSET(XrWorldMeshStateRequestCompletionML, meshBlockStates, 40);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBufferRecommendedSizeInfoML) {
  EXPECT_LAYOUT(XrWorldMeshBufferRecommendedSizeInfoML, 24, 8);
  EXPECT_OFFSET(XrWorldMeshBufferRecommendedSizeInfoML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBufferRecommendedSizeInfoML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBufferRecommendedSizeInfoML, maxBlockCount, 16);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBufferSizeML) {
  EXPECT_LAYOUT(XrWorldMeshBufferSizeML, 24, 8);
  EXPECT_OFFSET(XrWorldMeshBufferSizeML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBufferSizeML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBufferSizeML, size, 16);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBufferML) {
  EXPECT_LAYOUT(XrWorldMeshBufferML, 32, 8);
  EXPECT_OFFSET(XrWorldMeshBufferML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBufferML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBufferML, bufferSize, 16);
  EXPECT_OFFSET(XrWorldMeshBufferML, buffer, 24);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBlockRequestML) {
  EXPECT_LAYOUT(XrWorldMeshBlockRequestML, 40, 8);
  EXPECT_OFFSET(XrWorldMeshBlockRequestML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBlockRequestML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBlockRequestML, uuid, 16);
  EXPECT_OFFSET(XrWorldMeshBlockRequestML, lod, 32);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshGetInfoML) {
  EXPECT_LAYOUT(XrWorldMeshGetInfoML, 48, 8);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, type, 0);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, next, 8);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, flags, 16);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, fillHoleLength, 24);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, disconnectedComponentArea, 28);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, blockCount, 32);
  EXPECT_OFFSET(XrWorldMeshGetInfoML, blocks, 40);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshBlockML) {
  EXPECT_LAYOUT(XrWorldMeshBlockML, 112, 8);
  EXPECT_OFFSET(XrWorldMeshBlockML, type, 0);
  EXPECT_OFFSET(XrWorldMeshBlockML, next, 8);
  EXPECT_OFFSET(XrWorldMeshBlockML, uuid, 16);
  EXPECT_OFFSET(XrWorldMeshBlockML, blockResult, 32);
  EXPECT_OFFSET(XrWorldMeshBlockML, lod, 36);
  EXPECT_OFFSET(XrWorldMeshBlockML, flags, 40);
  EXPECT_OFFSET(XrWorldMeshBlockML, indexCount, 48);
  EXPECT_OFFSET(XrWorldMeshBlockML, indexBuffer, 56);
  EXPECT_OFFSET(XrWorldMeshBlockML, vertexCount, 64);
  EXPECT_OFFSET(XrWorldMeshBlockML, vertexBuffer, 72);
  EXPECT_OFFSET(XrWorldMeshBlockML, normalCount, 80);
  EXPECT_OFFSET(XrWorldMeshBlockML, normalBuffer, 88);
  EXPECT_OFFSET(XrWorldMeshBlockML, confidenceCount, 96);
  EXPECT_OFFSET(XrWorldMeshBlockML, confidenceBuffer, 104);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshRequestCompletionInfoML) {
  EXPECT_LAYOUT(XrWorldMeshRequestCompletionInfoML, 32, 8);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionInfoML, type, 0);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionInfoML, next, 8);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionInfoML, meshSpace, 16);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionInfoML, meshSpaceLocateTime, 24);
}

TEST(MlWorldMeshDetectionLayout, XrWorldMeshRequestCompletionML) {
  EXPECT_LAYOUT(XrWorldMeshRequestCompletionML, 32, 8);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionML, type, 0);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionML, next, 8);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionML, futureResult, 16);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionML, blockCount, 20);
  EXPECT_OFFSET(XrWorldMeshRequestCompletionML, blocks, 24);
}

#endif  // INTPTR_MAX == INT64_MAX

// --- base_types.h ---

TEST(SpatialMlBaseTypesValues, MatchRegistry) {
  EXPECT_VALUE(XR_UUID_SIZE, 16);
  EXPECT_VALUE(XR_EXT_uuid_SPEC_VERSION, 1);
  EXPECT_VALUE(XR_UUID_SIZE_EXT, 16);
  EXPECT_EQ(std::string(XR_EXT_UUID_EXTENSION_NAME), "XR_EXT_uuid");
}

// --- XR_EXT_future.h ---

TEST(ExtFutureValues, MatchRegistry) {
  EXPECT_VALUE(XR_ERROR_FUTURE_PENDING_EXT, -1000469001);
  EXPECT_VALUE(XR_ERROR_FUTURE_INVALID_EXT, -1000469002);
  EXPECT_VALUE(XR_TYPE_FUTURE_CANCEL_INFO_EXT, 1000469000);
  EXPECT_VALUE(XR_TYPE_FUTURE_POLL_INFO_EXT, 1000469001);
  EXPECT_VALUE(XR_TYPE_FUTURE_COMPLETION_EXT, 1000469002);
  EXPECT_VALUE(XR_TYPE_FUTURE_POLL_RESULT_EXT, 1000469003);
  EXPECT_VALUE(XR_FUTURE_STATE_PENDING_EXT, 1);
  EXPECT_VALUE(XR_FUTURE_STATE_READY_EXT, 2);
  EXPECT_VALUE(XR_FUTURE_STATE_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_EXT_future_SPEC_VERSION, 1);
  EXPECT_VALUE(XR_NULL_FUTURE_EXT, 0);
  EXPECT_EQ(std::string(XR_EXT_FUTURE_EXTENSION_NAME), "XR_EXT_future");
}

// --- XR_EXT_spatial_entity.h ---

TEST(ExtSpatialEntityValues, MatchRegistry) {
  EXPECT_VALUE(XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT, -1000740001);
  EXPECT_VALUE(XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT, -1000740002);
  EXPECT_VALUE(XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT, -1000740003);
  EXPECT_VALUE(XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT, -1000740004);
  EXPECT_VALUE(XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT, -1000740005);
  EXPECT_VALUE(XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT, -1000740006);
  EXPECT_VALUE(XR_OBJECT_TYPE_SPATIAL_ENTITY_EXT, 1000740000);
  EXPECT_VALUE(XR_OBJECT_TYPE_SPATIAL_CONTEXT_EXT, 1000740001);
  EXPECT_VALUE(XR_OBJECT_TYPE_SPATIAL_SNAPSHOT_EXT, 1000740002);
  EXPECT_VALUE(XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT, 1000740000);
  EXPECT_VALUE(XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT, 1000740001);
  EXPECT_VALUE(XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT, 1000740002);
  EXPECT_VALUE(XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT, 1000740003);
  EXPECT_VALUE(XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT, 1000740004);
  EXPECT_VALUE(XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT, 1000740005);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT, 1000740006);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT, 1000740007);
  EXPECT_VALUE(XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT, 1000740008);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, 1000740009);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_BOUNDED_3D_LIST_EXT, 1000740010);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_PARENT_LIST_EXT, 1000740011);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_MESH_3D_LIST_EXT, 1000740012);
  EXPECT_VALUE(XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT, 1000740013);
  EXPECT_VALUE(XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT, 1000740014);
  EXPECT_VALUE(XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT, 1000740015);
  EXPECT_VALUE(XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT, 1000740016);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, 1000741000);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_MARKER_TRACKING_QR_CODE_EXT, 1000743000);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_MARKER_TRACKING_MICRO_QR_CODE_EXT, 1000743001);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_MARKER_TRACKING_ARUCO_MARKER_EXT, 1000743002);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_MARKER_TRACKING_APRIL_TAG_EXT, 1000743003);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_ANCHOR_EXT, 1000762000);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_FEATURE_MARKER_TRACKING_FIXED_SIZE_MARKERS_EXT, 1000743000);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_FEATURE_MARKER_TRACKING_STATIC_MARKERS_EXT, 1000743001);
  EXPECT_VALUE(XR_SPATIAL_CAPABILITY_FEATURE_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, 1);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_3D_EXT, 2);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_PARENT_EXT, 3);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT, 4);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT, 1000741000);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT, 1000741001);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, 1000741002);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT, 1000741003);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_MARKER_EXT, 1000743000);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_ANCHOR_EXT, 1000762000);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_PERSISTENCE_EXT, 1000763000);
  EXPECT_VALUE(XR_SPATIAL_COMPONENT_TYPE_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_SPATIAL_ENTITY_TRACKING_STATE_STOPPED_EXT, 1);
  EXPECT_VALUE(XR_SPATIAL_ENTITY_TRACKING_STATE_PAUSED_EXT, 2);
  EXPECT_VALUE(XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT, 3);
  EXPECT_VALUE(XR_SPATIAL_ENTITY_TRACKING_STATE_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_UNKNOWN_EXT, 0);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_STRING_EXT, 1);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_UINT8_EXT, 2);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_UINT16_EXT, 3);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_UINT32_EXT, 4);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_FLOAT_EXT, 5);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT, 6);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_VECTOR3F_EXT, 7);
  EXPECT_VALUE(XR_SPATIAL_BUFFER_TYPE_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_EXT_spatial_entity_SPEC_VERSION, 1);
  EXPECT_VALUE(XR_NULL_SPATIAL_ENTITY_ID_EXT, 0);
  EXPECT_VALUE(XR_NULL_SPATIAL_BUFFER_ID_EXT, 0);
  EXPECT_EQ(std::string(XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME), "XR_EXT_spatial_entity");
}

// --- XR_EXT_spatial_plane_tracking.h ---

TEST(ExtSpatialPlaneTrackingValues, MatchRegistry) {
  EXPECT_VALUE(XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT, 1000741000);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_PLANE_ALIGNMENT_LIST_EXT, 1000741001);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, 1000741002);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT, 1000741003);
  EXPECT_VALUE(XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT, 1000741004);
  EXPECT_VALUE(XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT, 0);
  EXPECT_VALUE(XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT, 1);
  EXPECT_VALUE(XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT, 2);
  EXPECT_VALUE(XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT, 3);
  EXPECT_VALUE(XR_SPATIAL_PLANE_ALIGNMENT_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT, 1);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT, 2);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT, 3);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT, 4);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT, 5);
  EXPECT_VALUE(XR_SPATIAL_PLANE_SEMANTIC_LABEL_MAX_ENUM_EXT, 2147483647);
  EXPECT_VALUE(XR_EXT_spatial_plane_tracking_SPEC_VERSION, 1);
  EXPECT_EQ(std::string(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME), "XR_EXT_spatial_plane_tracking");
}

// --- XR_ML_world_mesh_detection.h ---

TEST(MlWorldMeshDetectionValues, MatchRegistry) {
  EXPECT_VALUE(XR_ERROR_WORLD_MESH_DETECTOR_PERMISSION_DENIED_ML, -1000474000);
  EXPECT_VALUE(XR_ERROR_WORLD_MESH_DETECTOR_SPACE_NOT_LOCATABLE_ML, -1000474001);
  EXPECT_VALUE(XR_OBJECT_TYPE_WORLD_MESH_DETECTOR_ML, 1000474000);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML, 1000474001);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML, 1000474002);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BLOCK_STATE_ML, 1000474003);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML, 1000474004);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML, 1000474005);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML, 1000474006);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BUFFER_ML, 1000474007);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML, 1000474008);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_GET_INFO_ML, 1000474009);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_BLOCK_ML, 1000474010);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML, 1000474011);
  EXPECT_VALUE(XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML, 1000474012);
  EXPECT_VALUE(XR_WORLD_MESH_DETECTOR_LOD_MINIMUM_ML, 0);
  EXPECT_VALUE(XR_WORLD_MESH_DETECTOR_LOD_MEDIUM_ML, 1);
  EXPECT_VALUE(XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML, 2);
  EXPECT_VALUE(XR_WORLD_MESH_DETECTOR_LOD_MAX_ENUM_ML, 2147483647);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_STATUS_NEW_ML, 0);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_STATUS_UPDATED_ML, 1);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_STATUS_DELETED_ML, 2);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_STATUS_UNCHANGED_ML, 3);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_STATUS_MAX_ENUM_ML, 2147483647);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML, 0);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_RESULT_FAILED_ML, 1);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_RESULT_PENDING_ML, 2);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_RESULT_PARTIAL_UPDATE_ML, 3);
  EXPECT_VALUE(XR_WORLD_MESH_BLOCK_RESULT_MAX_ENUM_ML, 2147483647);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_POINT_CLOUD_BIT_ML, 0x1);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_COMPUTE_NORMALS_BIT_ML, 0x2);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_COMPUTE_CONFIDENCE_BIT_ML, 0x4);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_PLANARIZE_BIT_ML, 0x8);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_REMOVE_MESH_SKIRT_BIT_ML, 0x10);
  EXPECT_FLAG(XR_WORLD_MESH_DETECTOR_INDEX_ORDER_CW_BIT_ML, 0x20);
  EXPECT_VALUE(XR_ML_world_mesh_detection_SPEC_VERSION, 1);
  EXPECT_EQ(std::string(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME), "XR_ML_world_mesh_detection");
}

// Handles and atoms are 64-bit on every target; XrFutureEXT is an opaque 64-bit value.
TEST(SpatialAndMlHandles, AreSixtyFourBit) {
  EXPECT_EQ(sizeof(XrFutureEXT), 8u);
  EXPECT_EQ(sizeof(XrSpatialEntityIdEXT), 8u);
  EXPECT_EQ(sizeof(XrSpatialBufferIdEXT), 8u);
  EXPECT_EQ(sizeof(XrSpatialEntityEXT), 8u);
  EXPECT_EQ(sizeof(XrSpatialContextEXT), 8u);
  EXPECT_EQ(sizeof(XrSpatialSnapshotEXT), 8u);
  EXPECT_EQ(sizeof(XrWorldMeshDetectorML), 8u);
  EXPECT_EQ(sizeof(XrWorldMeshDetectorFlagsML), 8u);
}

}  // namespace
