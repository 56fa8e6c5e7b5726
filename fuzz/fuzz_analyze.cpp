// roomsense::analyze on arbitrary triangle soups and point clouds. The bytes decode as
//   u8  voxel size: 0.05 + 0.45 * b / 255 m (within the valid range; coarse, so that a grid stays small)
//   u8  flags: 1 vertex mode, 2 raw float32 coordinates (NaN, Inf, huge), 4 keep outliers, 8 no areas,
//       16 no bounds, 32 min_plateau 0, 64 a point cloud (no indices)
//   u16 vertex count (mod 513), then the vertices: 3 x float32, or 3 x int16 / 2048 m (+-16 m)
//   the rest: u16 indices, each mod (vertex count + 1), so that the last value is one past the end (at most
//   300 triangles' worth; a count that is not a multiple of 3 is kept, to exercise that check)
// The voxel budget is 2^15 voxels (a 5 x 4 m room at 0.2 m) and one thread, so that one input takes tens of
// milliseconds under ASan (the area search is the slow stage); a finer grid is refused (GridTooLarge). roomsense::Error is the
// documented answer to bad input; anything else escaping, a sanitizer report, or a broken invariant of the
// result (a bounds mesh that is not closed, an index out of range, a non-finite area) is a finding.
#include "fuzz_input.h"
#include "roomsense/analysis.h"
#include "roomsense/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_analyze: invariant broken: %s\n", what);
    std::abort();
  }
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// README / bounds.h: closed, every edge in exactly two triangles, each direction once (consistent winding).
void check_bounds(const roomsense::BoundsMesh& mesh) {
  check(mesh.indices.size() % 3 == 0, "bounds index count is a multiple of 3");
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[t + e], b = mesh.indices[t + (e + 1) % 3];
      check(a < mesh.vertices.size() && b < mesh.vertices.size(), "bounds index in range");
      check(a != b, "no degenerate bounds triangle");
      check(++directed[{a, b}] == 1, "each directed bounds edge once");
    }
  for (const auto& [edge, n] : directed) check(directed.count({edge.second, edge.first}) == 1, "bounds mesh closed");
  for (const glm::vec3& v : mesh.vertices) check(finite(v), "finite bounds vertex");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  roomsense::fuzz::FuzzInput in(data, size);
  roomsense::AnalysisOptions options;
  options.voxel_size = 0.05f + 0.45f * static_cast<float>(in.u8()) / 255.0f;
  const std::uint8_t flags = in.u8();
  if (flags & 1) options.mode = roomsense::VoxelMode::Vertices;
  options.reject_outliers = (flags & 4) == 0;
  options.find_areas = (flags & 8) == 0;
  options.build_bounds = (flags & 16) == 0;
  if (flags & 32) options.bounds.min_plateau_area = 0.0f;
  options.voxel_budget = std::size_t{1} << 15;
  options.threads = 1;

  roomsense::Scan scan;
  const std::uint32_t vertex_count = in.u16() % 513;
  scan.vertices.reserve(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    glm::vec3 p;
    if (flags & 2) {
      p.x = in.f32(), p.y = in.f32(), p.z = in.f32();
    } else {
      p.x = in.i16() / 2048.0f, p.y = in.i16() / 2048.0f, p.z = in.i16() / 2048.0f;
    }
    scan.vertices.push_back(p);
  }
  if ((flags & 64) == 0) {
    const std::size_t index_count = std::min<std::size_t>(in.remaining() / 2, 900);
    for (std::size_t i = 0; i < index_count; ++i) scan.indices.push_back(in.u16() % (vertex_count + 1));
  }

  try {
    const roomsense::AnalysisResult r = roomsense::analyze(scan, options);
    check(r.input.vertices == scan.vertices.size(), "input vertex count");
    if (r.ok()) {
      check(!r.storeys.empty(), "a storey when ok");
      check(std::isfinite(r.floor_y) && std::isfinite(r.ceiling_y) && r.floor_y < r.ceiling_y, "floor below ceiling");
      for (const roomsense::Area& a : r.areas) {
        check(finite(a.center) && finite(a.normal), "finite area");
        check(std::fabs(glm::length(a.normal) - 1.0f) < 1e-3f, "unit area normal");
      }
      if (options.build_bounds) check_bounds(r.bounds);
    } else {
      check(r.areas.empty(), "no areas without a room");
    }
  } catch (const roomsense::Error&) {
    // bad input, reported as documented
  }
  return 0;
}
