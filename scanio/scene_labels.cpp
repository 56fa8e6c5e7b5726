// A scene capture's anchors as the runtime's labels (Scan::labels): each plane's rectangle and each volume's
// box, labelled by its Meta semantic label (the names Quest captures and MRUK rooms share).
#include "roomsense/quest_capture.h"

#include <array>
#include <utility>

namespace roomsense::scanio {

SurfaceLabel surface_label_of_meta(std::string_view label) {
  static constexpr std::array<std::pair<std::string_view, SurfaceLabel>, 19> kLabels = {{
      {"FLOOR", SurfaceLabel::Floor},
      {"CEILING", SurfaceLabel::Ceiling},
      {"WALL_FACE", SurfaceLabel::Wall},
      {"INNER_WALL_FACE", SurfaceLabel::Wall},
      {"TABLE", SurfaceLabel::Table},
      {"COUCH", SurfaceLabel::Seat},
      {"CHAIR", SurfaceLabel::Seat},
      {"BED", SurfaceLabel::Bed},
      {"STORAGE", SurfaceLabel::Storage},
      {"SHELF", SurfaceLabel::Storage},
      {"WINDOW_FRAME", SurfaceLabel::WindowFrame},
      {"DOOR_FRAME", SurfaceLabel::DoorFrame},
      {"SCREEN", SurfaceLabel::Screen},
      {"WALL_ART", SurfaceLabel::Screen},
      {"LAMP", SurfaceLabel::Other},
      {"PLANT", SurfaceLabel::Other},
      {"OTHER", SurfaceLabel::Other},
      {"WALL_OPENING", SurfaceLabel::DoorFrame},
      {"OPENING", SurfaceLabel::DoorFrame},
  }};
  for (const auto& [name, surface] : kLabels)
    if (name == label) return surface;
  // GLOBAL_MESH, UNRECOGNIZED, INVISIBLE_WALL_FACE (a boundary drawn where there is no surface) and labels
  // of later revisions say nothing about a surface.
  return SurfaceLabel::Unknown;
}

LabelledTriangles scene_labels(const QuestCapture& capture) {
  LabelledTriangles out;
  for (const QuestPlane& plane : capture.planes) {
    const SurfaceLabel label = surface_label_of_meta(plane.label);
    if (label == SurfaceLabel::Unknown) continue;
    const OrientedRect r = plane_rect(plane);
    std::vector<glm::vec3> corners;
    for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
      corners.push_back(r.pose.apply(glm::vec3(0.5f * r.width * c.x, 0.5f * r.height * c.y, 0.0f)));
    out.add(corners, {0, 1, 2, 0, 2, 3}, label);
  }
  for (const QuestVolume& volume : capture.volumes) {
    const SurfaceLabel label = surface_label_of_meta(volume.label);
    if (label == SurfaceLabel::Unknown) continue;
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back(volume.pose.apply(
          volume.offset + volume.extent * glm::vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1))));
    // The six faces of the box (corner i has bit 0 = +x, bit 1 = +y, bit 2 = +z); labels need no winding.
    out.add(corners, {0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                      2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 3, 7, 1, 7, 5},
            label);
  }
  return out;
}

}  // namespace roomsense::scanio
