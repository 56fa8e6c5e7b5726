// The C# binding (bindings/csharp/RoomCreatorLibrary.cs) under Mono against libRoomCreatorLibrary: this test
// writes a shared room's vertices, the C structs' sizes and offsets, and the C API's own results into a
// folder, then runs BindingTest.exe there, which checks its struct layouts against the C compiler's and
// that every result it gets through the binding equals the C API's, bit for bit.
#include "roomsense/RoomCreatorLibrary.h"
#include "roomsense/roomsense.h"
#include "roomsense/scanio.h"
#include "rooms.h"
#include "test_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

template <typename T>
void write_bytes(const fs::path& path, const T* data, std::size_t count) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(count * sizeof(T)));
}

// "name size offset..." per struct: every field's offset in declaration order, arrays element by element.
#define OFF(type, field) << ' ' << offsetof(type, field)
void write_layouts(const fs::path& path) {
  std::ofstream out(path);
  out << "AnalyzerOptions " << sizeof(rs_analyzer_options) OFF(rs_analyzer_options, struct_size)
      OFF(rs_analyzer_options, voxel_size) OFF(rs_analyzer_options, thread_count) OFF(rs_analyzer_options, compute_flags)
      OFF(rs_analyzer_options, up_axis) OFF(rs_analyzer_options, units) OFF(rs_analyzer_options, left_handed) << '\n';
  out << "Layout " << sizeof(rs_layout) OFF(rs_layout, floor_y) OFF(rs_layout, ceiling_y) OFF(rs_layout, storey_count)
      OFF(rs_layout, area_count) OFF(rs_layout, bounds_vertex_count) OFF(rs_layout, bounds_index_count)
      OFF(rs_layout, input_vertex_count) OFF(rs_layout, input_triangle_count) OFF(rs_layout, skipped_vertex_count)
      OFF(rs_layout, outlier_vertex_count) OFF(rs_layout, voxel_size) OFF(rs_layout, grid_origin)
      OFF(rs_layout, grid_dims[0]) OFF(rs_layout, grid_dims[1]) OFF(rs_layout, grid_dims[2]) OFF(rs_layout, timings) << '\n';
  out << "Timings " << sizeof(rs_timings) OFF(rs_timings, prepare) OFF(rs_timings, voxelize) OFF(rs_timings, features)
      OFF(rs_timings, areas) OFF(rs_timings, reduce) OFF(rs_timings, classify) OFF(rs_timings, bounds)
      OFF(rs_timings, total) << '\n';
  out << "Storey " << sizeof(rs_storey) OFF(rs_storey, floor_y) OFF(rs_storey, ceiling_y) << '\n';
  out << "Room " << sizeof(rs_room) OFF(rs_room, storey) OFF(rs_room, floor_area) OFF(rs_room, center)
      OFF(rs_room, floor_y) OFF(rs_room, ceiling_y) << '\n';
  out << "AreaPlace " << sizeof(rs_area_place) OFF(rs_area_place, storey) OFF(rs_area_place, room) << '\n';
  out << "Area " << sizeof(rs_area) OFF(rs_area, type) OFF(rs_area, size) OFF(rs_area, reach) OFF(rs_area, flags)
      OFF(rs_area, center) OFF(rs_area, normal) OFF(rs_area, orientation) OFF(rs_area, corners[0])
      OFF(rs_area, corners[1]) OFF(rs_area, corners[2]) OFF(rs_area, corners[3]) OFF(rs_area, half_width)
      OFF(rs_area, half_height) OFF(rs_area, rotation_deg) OFF(rs_area, volume_height) << '\n';
  out << "PlacementQuery " << sizeof(rs_placement_query) OFF(rs_placement_query, struct_size)
      OFF(rs_placement_query, size) OFF(rs_placement_query, surfaces) OFF(rs_placement_query, clearance)
      OFF(rs_placement_query, clearance_above) OFF(rs_placement_query, edge_distance) OFF(rs_placement_query, reach)
      OFF(rs_placement_query, has_user_position) OFF(rs_placement_query, user_position)
      OFF(rs_placement_query, user_reach) OFF(rs_placement_query, has_near_point) OFF(rs_placement_query, near_point)
      OFF(rs_placement_query, face_direction) OFF(rs_placement_query, max_count) OFF(rs_placement_query, allow_overlap)
      OFF(rs_placement_query, reserved) OFF(rs_placement_query, seed) << '\n';
  out << "Placement " << sizeof(rs_placement) OFF(rs_placement, surface) OFF(rs_placement, reach)
      OFF(rs_placement, storey) OFF(rs_placement, center) OFF(rs_placement, normal) OFF(rs_placement, orientation)
      OFF(rs_placement, corners[0]) OFF(rs_placement, corners[1]) OFF(rs_placement, corners[2])
      OFF(rs_placement, corners[3]) OFF(rs_placement, width) OFF(rs_placement, depth) OFF(rs_placement, margin) << '\n';
  out << "RayHit " << sizeof(rs_ray_hit) OFF(rs_ray_hit, hit) OFF(rs_ray_hit, scanned) OFF(rs_ray_hit, surface)
      OFF(rs_ray_hit, distance) OFF(rs_ray_hit, position) OFF(rs_ray_hit, normal) << '\n';
  out << "Location " << sizeof(rs_location) OFF(rs_location, inside) OFF(rs_location, free) OFF(rs_location, storey) << '\n';
  out << "SurfacePoint " << sizeof(rs_surface_point) OFF(rs_surface_point, found) OFF(rs_surface_point, surface)
      OFF(rs_surface_point, position) OFF(rs_surface_point, normal) << '\n';
  out << "Vec3 " << sizeof(rs_vec3) OFF(rs_vec3, x) OFF(rs_vec3, y) OFF(rs_vec3, z) << '\n';
  out << "Quat " << sizeof(rs_quat) OFF(rs_quat, x) OFF(rs_quat, y) OFF(rs_quat, z) OFF(rs_quat, w) << '\n';
}
#undef OFF

// The thesis API's two jobs on xyz, polled to the end; the arrays as the library returns them.
std::vector<float> thesis_areas(const std::vector<float>& xyz) {
  EXPECT_EQ(StartRoomUnderstanding(xyz.data(), int(xyz.size())), 0);
  int code = -1, size = 0;
  const float* data = nullptr;
  do data = RetrieveRoomUnderstanding(&code, &size);
  while (code == -1);
  EXPECT_EQ(code, 0);
  std::vector<float> out(data, data + (code == 0 ? size : 0));
  CleanUpRoomUnderstanding();
  return out;
}

std::vector<float> thesis_bounds(const std::vector<float>& xyz) {
  EXPECT_EQ(StartRoomBounds(xyz.data(), int(xyz.size())), 0);
  int code = -1, vertices = 0, triangles = 0;
  const float* data = nullptr;
  do data = RetrieveRoomBounds(&code, &vertices, &triangles);
  while (code == -1);
  EXPECT_EQ(code, 0);
  std::vector<float> out{float(vertices), float(triangles)};
  if (code == 0) out.insert(out.end(), data, data + vertices + triangles);
  CleanUpRoomBounds();
  return out;
}

TEST(CSharpBinding, EqualsTheCApiOnASharedRoomUnderMono) {
  ROOMSENSE_REQUIRE_ROOM(room, "hololens2-su/SU_Kitchen_world_mesh.obj");
  const roomsense::Scan scan = roomsense::scanio::load_mesh_file(room.string());
  std::vector<float> xyz;
  for (const auto& v : scan.vertices) xyz.insert(xyz.end(), {v.x, v.y, v.z});
  const std::vector<std::uint32_t>& indices = scan.indices;

  const fs::path dir = roomsense::test::scratch_dir() / "csharp";
  fs::create_directories(dir);
  write_bytes(dir / "vertices.bin", xyz.data(), xyz.size());
  write_bytes(dir / "indices.bin", indices.data(), indices.size());
  write_layouts(dir / "layouts.txt");
  const std::vector<float> areas = thesis_areas(xyz), bounds = thesis_bounds(xyz);
  ASSERT_GT(areas.size(), 0u);
  write_bytes(dir / "thesis_areas.bin", areas.data(), areas.size());
  write_bytes(dir / "thesis_bounds.bin", bounds.data(), bounds.size());

  // The handle API on the triangles: areas, bounds, storeys, one placement query, a fan of rays.
  rs_analyzer* a = nullptr;
  ASSERT_EQ(rs_analyzer_create(nullptr, &a), RS_SUCCESS);
  ASSERT_EQ(rs_analyzer_compute(a, xyz.data(), std::uint32_t(xyz.size() / 3), indices.data(), std::uint32_t(indices.size())),
            RS_SUCCESS);
  rs_state state = RS_STATE_IDLE;
  ASSERT_EQ(rs_analyzer_wait(a, RS_WAIT_INFINITE, &state), RS_SUCCESS);
  ASSERT_EQ(state, RS_STATE_READY);
  std::uint32_t n = 0;
  ASSERT_EQ(rs_analyzer_get_areas(a, 0, &n, nullptr), RS_SUCCESS);
  std::vector<rs_area> handle_areas(n);
  ASSERT_EQ(rs_analyzer_get_areas(a, n, &n, handle_areas.data()), RS_SUCCESS);
  write_bytes(dir / "handle_areas.bin", handle_areas.data(), handle_areas.size());
  std::uint32_t nv = 0, ni = 0;
  ASSERT_EQ(rs_analyzer_get_bounds(a, 0, &nv, nullptr, 0, &ni, nullptr), RS_SUCCESS);
  std::vector<float> bxyz(3 * nv);
  std::vector<std::uint32_t> bidx(ni);
  ASSERT_EQ(rs_analyzer_get_bounds(a, nv, &nv, bxyz.data(), ni, &ni, bidx.data()), RS_SUCCESS);
  write_bytes(dir / "handle_bounds_xyz.bin", bxyz.data(), bxyz.size());
  write_bytes(dir / "handle_bounds_indices.bin", bidx.data(), bidx.size());
  ASSERT_EQ(rs_analyzer_get_storeys(a, 0, &n, nullptr), RS_SUCCESS);
  std::vector<rs_storey> storeys(n);
  ASSERT_EQ(rs_analyzer_get_storeys(a, n, &n, storeys.data()), RS_SUCCESS);
  write_bytes(dir / "handle_storeys.bin", storeys.data(), storeys.size());
  ASSERT_EQ(rs_analyzer_get_rooms(a, 0, &n, nullptr), RS_SUCCESS);
  std::vector<rs_room> rooms(n);
  ASSERT_EQ(rs_analyzer_get_rooms(a, n, &n, rooms.data()), RS_SUCCESS);
  write_bytes(dir / "handle_rooms.bin", rooms.data(), rooms.size());
  ASSERT_EQ(rs_analyzer_get_area_places(a, 0, &n, nullptr), RS_SUCCESS);
  std::vector<rs_area_place> places(n);
  ASSERT_EQ(rs_analyzer_get_area_places(a, n, &n, places.data()), RS_SUCCESS);
  write_bytes(dir / "handle_area_places.bin", places.data(), places.size());
  ASSERT_EQ(rs_analyzer_get_room_bounds(a, 0, 0, &nv, nullptr, 0, &ni, nullptr), RS_SUCCESS);
  std::vector<std::uint32_t> room_idx(ni);
  std::vector<float> room_xyz(3 * nv);
  ASSERT_EQ(rs_analyzer_get_room_bounds(a, 0, nv, &nv, room_xyz.data(), ni, &ni, room_idx.data()), RS_SUCCESS);
  write_bytes(dir / "handle_room0_indices.bin", room_idx.data(), room_idx.size());
  rs_placement_query q;
  rs_placement_query_init(&q);
  q.surfaces = RS_SURFACE_FURNITURE | RS_SURFACE_FLOOR;
  q.max_count = 8;
  q.seed = 42;
  rs_placement_shortfall shortfall = RS_SHORTFALL_NONE;
  ASSERT_EQ(rs_analyzer_find_placements(a, &q, 0, &n, nullptr, &shortfall), RS_SUCCESS);
  std::vector<rs_placement> placements(n);
  ASSERT_EQ(rs_analyzer_find_placements(a, &q, n, &n, placements.data(), &shortfall), RS_SUCCESS);
  ASSERT_GT(n, 0u);
  write_bytes(dir / "handle_placements.bin", placements.data(), placements.size());
  rs_layout layout{};
  ASSERT_EQ(rs_analyzer_get_layout(a, &layout), RS_SUCCESS);
  const rs_vec3 middle{layout.grid_origin.x + 0.5f * layout.voxel_size * float(layout.grid_dims[0]),
                       0.5f * (layout.floor_y + layout.ceiling_y),
                       layout.grid_origin.z + 0.5f * layout.voxel_size * float(layout.grid_dims[2])};
  std::vector<rs_ray_hit> hits;
  for (int i = 0; i < 16; ++i) {
    const float angle = 0.3927f * float(i);
    const rs_vec3 direction{std::cos(angle), -0.3f, std::sin(angle)};
    rs_ray_hit hit{};
    ASSERT_EQ(rs_analyzer_raycast(a, &middle, &direction, 0.0f, &hit), RS_SUCCESS);
    hits.push_back(hit);
  }
  write_bytes(dir / "handle_rays.bin", hits.data(), hits.size());
  write_bytes(dir / "middle.bin", &middle, 1);
  rs_analyzer_destroy(a);

  // Mono finds libRoomCreatorLibrary.so through LD_LIBRARY_PATH (the test's environment).
  const std::string command = std::string(ROOMSENSE_MONO) + " " + ROOMSENSE_BINDING_TEST + " " + dir.string() + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  std::printf("%s", output.c_str());
  EXPECT_EQ(status, 0) << command;
  EXPECT_NE(output.find("BindingTest: ok"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
