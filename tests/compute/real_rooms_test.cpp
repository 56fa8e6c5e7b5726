// CPU vs Vulkan, bit for bit, on every real scan in ../shared/rooms, in both voxel modes, with the
// Khronos validation layer watching.
#include "roomsense/grid.h"
#include "roomsense/input.h"
#include "roomsense/scanio.h"
#include "vulkan_test_env.h"

#include <map>
#include <string>
#include <tuple>

namespace roomsense {
namespace {

const char* const kRooms[] = {
    "hololens1/holotoolkit_fake_spatial_mapping.obj",
    "hololens1/mrtk_example_spatial_mesh.obj",
    "hololens2-su/SU_Apartment_world_mesh.obj",
    "hololens2-su/SU_Kitchen_world_mesh.obj",
    "quest-iwer/living_room_global_mesh.obj",
    "quest-iwer/meeting_room_global_mesh.obj",
    "quest-iwer/music_room_global_mesh.obj",
    "quest-iwer/office_large_global_mesh.obj",
    "quest-iwer/office_small_global_mesh.obj",
};

struct Prepared {
  GridSpec spec;
  std::vector<glm::vec3> grid_vertices;
  std::vector<std::uint32_t> indices;
};

// Loaded once per room for both modes: assimp dominates otherwise.
const Prepared& prepared(const std::filesystem::path& path) {
  static std::map<std::string, Prepared> cache;
  auto it = cache.find(path.string());
  if (it == cache.end()) {
    const PreparedInput in = prepare_input(scanio::load_mesh_file(path.string()));
    Prepared p;
    p.spec = make_grid_spec(in.lo, in.hi, kDefaultVoxelSize);
    p.grid_vertices = to_grid_units(in.vertices, p.spec);
    p.indices = in.indices;
    it = cache.emplace(path.string(), std::move(p)).first;
  }
  return it->second;
}

class RealRoom : public ::testing::TestWithParam<std::tuple<const char*, VoxelMode>> {};

TEST_P(RealRoom, VulkanMatchesCpuBitForBit) {
  ROOMSENSE_REQUIRE_ROOM(path, std::get<0>(GetParam()));
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const Prepared& p = prepared(path);
  VoxelizeRequest request;
  request.spec = p.spec;
  request.grid_vertices = p.grid_vertices;
  request.indices = p.indices;
  request.mode = std::get<1>(GetParam());

  const VoxelStageResult cpu = CpuVoxelStage().run(request);
  ValidationScope validation(*stage);
  const VoxelStageResult gpu = stage->run(request);
  EXPECT_FALSE(stage->last_timings().fell_back) << "the Vulkan run fell back to the CPU";
  test::expect_identical(cpu, gpu);
  EXPECT_TRUE(cpu.levels.has_value()) << "a real room should have a floor and a ceiling";
}

std::string room_name(const ::testing::TestParamInfo<RealRoom::ParamType>& info) {
  std::string name = std::get<0>(info.param);
  name = name.substr(name.find('/') + 1);
  name = name.substr(0, name.find('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + (std::get<1>(info.param) == VoxelMode::Triangles ? "_triangles" : "_vertices");
}

INSTANTIATE_TEST_SUITE_P(Scans, RealRoom,
                         ::testing::Combine(::testing::ValuesIn(kRooms),
                                            ::testing::Values(VoxelMode::Vertices, VoxelMode::Triangles)),
                         room_name);

}  // namespace
}  // namespace roomsense
