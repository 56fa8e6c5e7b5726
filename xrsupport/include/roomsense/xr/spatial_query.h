// The checks xrQuerySpatialComponentDataEXT puts on the component lists an application chains to its result,
// shared by the servers of XR_EXT_spatial_entity (the layer's and the simulated runtime's): a list must be one
// the condition names, a list with a count needs its array, and each must hold one element per entity.
#pragma once
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"
#include "roomsense/xr/guard.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace roomsense::xr {

// One list the result may chain: its component, and, when chained, its element count and whether its array is set.
struct ChainedList {
  XrSpatialComponentTypeEXT component;
  bool chained = false;
  std::uint32_t count = 0;
  bool has_array = false;
};

// The list of `type` in the chain at `next` (into `out`, null when not chained), described.
template <typename List, typename Element>
ChainedList chained_list(void* next, XrStructureType type, XrSpatialComponentTypeEXT component, List*& out,
                         std::uint32_t List::*count, Element* List::*array) {
  out = find_next<List>(next, type);
  if (out == nullptr) return {component};
  return {component, true, out->*count, out->*array != nullptr};
}

// The lists of the components XR_EXT_spatial_plane_tracking serves, as chained at `next` (null when not), and
// described for lists_named and lists_fit.
struct PlaneComponentLists {
  XrSpatialComponentBounded2DListEXT* bounds = nullptr;
  XrSpatialComponentPlaneAlignmentListEXT* alignments = nullptr;
  XrSpatialComponentPolygon2DListEXT* polygons = nullptr;
  XrSpatialComponentMesh2DListEXT* meshes = nullptr;
  XrSpatialComponentPlaneSemanticLabelListEXT* labels = nullptr;
  std::array<ChainedList, 5> described{};
};
inline PlaneComponentLists plane_component_lists(void* next) {
  PlaneComponentLists l;
  l.described = {
      chained_list(next, XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, l.bounds,
                   &XrSpatialComponentBounded2DListEXT::boundCount, &XrSpatialComponentBounded2DListEXT::bounds),
      chained_list(next, XR_TYPE_SPATIAL_COMPONENT_PLANE_ALIGNMENT_LIST_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
                   l.alignments, &XrSpatialComponentPlaneAlignmentListEXT::planeAlignmentCount,
                   &XrSpatialComponentPlaneAlignmentListEXT::planeAlignments),
      chained_list(next, XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT, XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, l.polygons,
                   &XrSpatialComponentPolygon2DListEXT::polygonCount, &XrSpatialComponentPolygon2DListEXT::polygons),
      chained_list(next, XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT, l.meshes,
                   &XrSpatialComponentMesh2DListEXT::meshCount, &XrSpatialComponentMesh2DListEXT::meshes),
      chained_list(next, XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT,
                   XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT, l.labels,
                   &XrSpatialComponentPlaneSemanticLabelListEXT::semanticLabelCount,
                   &XrSpatialComponentPlaneSemanticLabelListEXT::semanticLabels)};
  return l;
}

// XR_ERROR_VALIDATION_FAILURE when a chained list carries a component the condition does not name (`wanted`), or
// is one of `refused` (lists the server never fills); XR_SUCCESS otherwise.
inline XrResult lists_named(std::span<const ChainedList> lists, const std::vector<XrSpatialComponentTypeEXT>& wanted,
                            const void* next, std::initializer_list<XrStructureType> refused) {
  for (const ChainedList& l : lists)
    if (l.chained && std::find(wanted.begin(), wanted.end(), l.component) == wanted.end()) return XR_ERROR_VALIDATION_FAILURE;
  for (XrStructureType type : refused)
    if (find_next<void>(next, type) != nullptr) return XR_ERROR_VALIDATION_FAILURE;
  return XR_SUCCESS;
}

// With `n` entities to write: XR_ERROR_VALIDATION_FAILURE for a list with a count but no array, then
// XR_ERROR_SIZE_INSUFFICIENT for one shorter than n; XR_SUCCESS otherwise.
inline XrResult lists_fit(std::span<const ChainedList> lists, std::uint32_t n) {
  for (const ChainedList& l : lists)
    if (l.chained && l.count > 0 && !l.has_array) return XR_ERROR_VALIDATION_FAILURE;
  for (const ChainedList& l : lists)
    if (l.chained && l.count < n) return XR_ERROR_SIZE_INSUFFICIENT;
  return XR_SUCCESS;
}

}  // namespace roomsense::xr
