// A built-in synthetic room as the layer's tests submit it through xrSubmitRoomMeshEXTX.
#pragma once
#include "roomsense/synthetic.h"

#include <openxr/openxr.h>

#include <cstdint>
#include <vector>

namespace layertest {

struct Room {
  std::vector<XrVector3f> vertices;
  std::vector<std::uint32_t> indices;
  explicit Room(const char* source) {
    const roomsense::Scan s = roomsense::synth::generate_builtin_source(source);
    for (const glm::vec3& v : s.vertices) vertices.push_back({v.x, v.y, v.z});
    indices = s.indices;
  }
};

}  // namespace layertest
