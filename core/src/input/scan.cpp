#include "roomsense/error.h"
#include "roomsense/scan.h"

#include <string>

namespace roomsense {

Scan scan_from_flat_array(const float* data, long long size) {
  if (data == nullptr || size < 1)
    throw Error(ErrorCode::EmptyInput, "no vertex array, or an array size below 1");
  if (size % 3 != 0)
    throw Error(ErrorCode::SizeNotMultipleOfThree,
                "the vertex array holds " + std::to_string(size) + " floats, not a multiple of 3");
  Scan scan;
  scan.vertices.reserve(static_cast<std::size_t>(size / 3));
  for (long long i = 0; i < size; i += 3) scan.vertices.emplace_back(data[i], data[i + 1], data[i + 2]);
  return scan;
}

void convert_to_roomsense_frame(Scan& scan, const SourceFrame& frame) {
  const float scale = frame.units == Units::Centimetres   ? 0.01f
                      : frame.units == Units::Millimetres ? 0.001f
                                                          : 1.0f;
  // Each mapping sends the source's up axis to +Y. A left-handed source is mirrored (determinant -1) and
  // keeps its triangle order: a mirror turns the clockwise front faces of Unity and Unreal into the
  // counter-clockwise front faces of OpenXR, so indices stay as they are.
  const auto convert = [&](glm::vec3& v) {
    const glm::vec3 p = v * scale;
    if (frame.up == UpAxis::Y)
      v = frame.left_handed ? glm::vec3(p.x, p.y, -p.z)   // Unity: forward +Z becomes OpenXR's -Z
                            : p;                          // already ours
    else
      v = frame.left_handed ? glm::vec3(p.y, p.z, -p.x)   // Unreal, Eq. 3.2 then Unity -> OpenXR
                            : glm::vec3(p.x, p.z, -p.y);  // right-handed Z-up (Blender, most scanners)
  };
  for (glm::vec3& v : scan.vertices) convert(v);
  for (glm::vec3& v : scan.labels.vertices) convert(v);
}

void LabelledTriangles::add(const std::vector<glm::vec3>& mesh_vertices, const std::vector<std::uint32_t>& mesh_indices,
                            SurfaceLabel label) {
  add(mesh_vertices, mesh_indices, std::vector<SurfaceLabel>(mesh_indices.size() / 3, label));
}

void LabelledTriangles::add(const std::vector<glm::vec3>& mesh_vertices, const std::vector<std::uint32_t>& mesh_indices,
                            const std::vector<SurfaceLabel>& triangle_labels) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), mesh_vertices.begin(), mesh_vertices.end());
  for (const std::uint32_t i : mesh_indices) indices.push_back(base + i);
  labels.insert(labels.end(), triangle_labels.begin(), triangle_labels.end());
}

}  // namespace roomsense
