// The runtime's semantics on the voxel grid: which labels (surface_label.h) pass through each voxel. Built
// from a scan's LabelledTriangles; the room features use it to trust what the runtime knows (a window frame is
// no wall to hang things on, a table top is a furniture top).
#pragma once
#include "roomsense/grid.h"
#include "roomsense/scan.h"
#include "roomsense/surface_label.h"

#include <cstdint>
#include <string>
#include <vector>

namespace roomsense {

using LabelMask = std::uint16_t;
static_assert(kSurfaceLabelCount <= 16, "a LabelMask holds one bit per SurfaceLabel");

constexpr LabelMask label_bit(SurfaceLabel label) { return LabelMask(1u << unsigned(label)); }
constexpr LabelMask label_bits(std::initializer_list<SurfaceLabel> labels) {
  LabelMask m = 0;
  for (SurfaceLabel l : labels) m = LabelMask(m | label_bit(l));
  return m;
}

// Surfaces to place things on (furniture tops); surfaces in a wall that are no place for a wall area; what
// stands on the floor.
inline constexpr LabelMask kFurnitureTopLabels =
    label_bits({SurfaceLabel::Table, SurfaceLabel::Seat, SurfaceLabel::Bed, SurfaceLabel::Storage});
inline constexpr LabelMask kWallOpeningLabels =
    label_bits({SurfaceLabel::WindowFrame, SurfaceLabel::DoorFrame, SurfaceLabel::Screen});
inline constexpr LabelMask kStandingLabels = LabelMask(kFurnitureTopLabels | label_bit(SurfaceLabel::Other));

struct LabelGrid {
  std::vector<LabelMask> masks;  // per voxel (GridSpec::index); empty when the scan has no usable labels
  LabelMask present = 0;         // every label that occurs
  bool empty() const { return masks.empty(); }
  bool has_any(LabelMask m) const { return (present & m) != 0; }
  LabelMask at(const GridSpec& spec, int x, int y, int z) const {
    return masks.empty() || !spec.contains(x, y, z) ? LabelMask{0} : masks[spec.index(x, y, z)];
  }
};

// Every voxel a labelled triangle touches gets the triangle's label (the test of triangle mode). Triangles
// with non-finite or out-of-range corners, or wholly outside the grid, are dropped; past `test_budget`
// triangle-voxel tests the labels are dropped altogether. Each drop adds one line to `warnings`.
LabelGrid voxelize_labels(const GridSpec& spec, const LabelledTriangles& labels, std::uint64_t test_budget,
                          std::vector<std::string>& warnings);

}  // namespace roomsense
