// The Quest scene-capture reader (roomsense/quest_capture.h) on arbitrary text: parse_quest_capture, then the
// rectangles of every plane and volume. Error(Io) is its documented answer to anything malformed; any other
// exception, a sanitizer report, or a mesh with an index out of range or a non-finite vertex is a finding.
#include "roomsense/error.h"
#include "roomsense/quest_capture.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_quest_capture: invariant broken: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const roomsense::scanio::QuestCapture capture = roomsense::scanio::parse_quest_capture(text, "fuzz.json");
    const roomsense::Scan& mesh = capture.mesh;
    check(mesh.indices.size() % 3 == 0, "whole triangles");
    for (const std::uint32_t i : mesh.indices) check(i < mesh.vertices.size(), "index in range");
    for (const glm::vec3& v : mesh.vertices)
      check(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z), "finite vertex");
    float sink = 0.0f;  // the rectangles are computed for their sanitizer checks, whatever their values
    for (const roomsense::scanio::QuestPlane& plane : capture.planes) {
      const roomsense::scanio::OrientedRect r = roomsense::scanio::plane_rect(plane);
      sink += r.width + r.pose.position.x;
    }
    for (const roomsense::scanio::QuestVolume& volume : capture.volumes) {
      const roomsense::scanio::OrientedRect r = roomsense::scanio::volume_top_rect(volume);
      sink += r.height + r.pose.orientation.w;
    }
    volatile float keep = sink;
    (void)keep;
  } catch (const roomsense::Error& e) {
    check(e.code() == roomsense::ErrorCode::Io, "Error(Io) for bad captures");
  }
  return 0;
}
