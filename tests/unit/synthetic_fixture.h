// Analyses of the built-in synthetic rooms, computed once per test binary.
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/synthetic.h"

#include <map>
#include <string>

namespace roomsense::test {

struct AnalysedRoom {
  synth::RoomSpec spec;
  Scan scan;
  AnalysisResult result;
};

inline const AnalysedRoom& analysed(const synth::RoomSpec& spec) {
  static std::map<std::string, AnalysedRoom> cache;
  auto it = cache.find(spec.name);
  if (it == cache.end()) {
    AnalysedRoom room{spec, synth::generate(spec), {}};
    room.result = analyze(room.scan);
    it = cache.emplace(spec.name, std::move(room)).first;
  }
  return it->second;
}

// A point's (x, z): where it lies on the floor plan.
inline glm::vec2 xz(const glm::vec3& v) { return {v.x, v.z}; }

// Centre of column (x, z) in world (x, z).
inline glm::vec2 column_centre(const GridSpec& s, int x, int z) {
  return {s.origin.x + (float(x) + 0.5f) * s.voxel_size, s.origin.z + (float(z) + 0.5f) * s.voxel_size};
}

}  // namespace roomsense::test
