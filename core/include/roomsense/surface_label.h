// What a runtime says a surface is, in one enum of ours: Quest scene labels, XR_EXT_spatial_plane_tracking's
// plane labels, Android XR's per-vertex labels and MSFT object kinds all map onto it. Carried with the
// triangles from the layer's mesh sources (and Quest captures) so that the pipeline can trust a runtime's
// semantics where it has any.
#pragma once
#include <cstdint>
#include <string_view>

namespace roomsense {

enum class SurfaceLabel : std::uint8_t {
  Unknown = 0,  // the runtime gave no label
  Floor,
  Ceiling,
  Wall,
  Table,        // any furniture top meant for placing things: table, desk, counter
  Seat,         // couch, chair
  Bed,
  Storage,      // cabinet, shelf
  WindowFrame,
  DoorFrame,
  Screen,       // a screen, a monitor, wall art: vertical, not a wall to place things on
  Other,        // labelled, but none of the above (a plant, a lamp, clutter)
};

constexpr std::string_view surface_label_name(SurfaceLabel label) {
  switch (label) {
    case SurfaceLabel::Unknown: return "unknown";
    case SurfaceLabel::Floor: return "floor";
    case SurfaceLabel::Ceiling: return "ceiling";
    case SurfaceLabel::Wall: return "wall";
    case SurfaceLabel::Table: return "table";
    case SurfaceLabel::Seat: return "seat";
    case SurfaceLabel::Bed: return "bed";
    case SurfaceLabel::Storage: return "storage";
    case SurfaceLabel::WindowFrame: return "window_frame";
    case SurfaceLabel::DoorFrame: return "door_frame";
    case SurfaceLabel::Screen: return "screen";
    case SurfaceLabel::Other: return "other";
  }
  return "unknown";
}

inline constexpr int kSurfaceLabelCount = static_cast<int>(SurfaceLabel::Other) + 1;

}  // namespace roomsense
