// Exports: OBJ round trip, GLB structure, the analysis JSON's contract (DESIGN.md).
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/export.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"
#include "synthetic_fixture.h"
#include "test_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>


namespace roomsense {
namespace {

std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

TEST(Export, ObjRoundTripsThroughTheLoader) {
  const BoundsMesh& m = test::analysed(synth::default_room()).result.bounds;
  const std::string path = test::temp_path("bounds.obj");
  write_bounds(m, path);
  const Scan back = scanio::load_mesh_file(path);
  EXPECT_EQ(back.vertices.size(), m.vertices.size());
  EXPECT_EQ(back.indices.size(), m.indices.size());
}

// A build with assimp reads the GLB back; one without (the Windows cross build) refuses it with one line.
TEST(Export, GlbRoundTripsThroughTheLoaderOrIsRefusedWithOneLine) {
  const BoundsMesh& m = test::analysed(synth::default_room()).result.bounds;
  const std::string path = test::temp_path("bounds.glb");
  write_bounds(m, path);
#if ROOMSENSE_SCANIO_READS_GLTF
  const Scan back = scanio::load_mesh_file(path);
  EXPECT_EQ(back.indices.size(), m.indices.size());
  EXPECT_GT(back.vertices.size(), 0u);
#else
  try {
    scanio::load_mesh_file(path);
    ADD_FAILURE() << "a build without assimp read " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(std::string(e.what()), "cannot read '" + path +
                                         "': this build of roomsense reads no glTF (it was built without assimp); "
                                         "use .obj or .ply");
  }
#endif
}

TEST(Export, GlbHasAValidContainerAndAccessors) {
  const BoundsMesh& m = test::analysed(synth::default_room()).result.bounds;
  GlbScene scene;
  scene.add_mesh("room_bounds", m.vertices, m.indices);
  scene.add_mesh("area", {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 2, 1}, std::array<float, 4>{1, 0, 0, 0.5f});
  const std::vector<std::uint8_t> glb = scene.encode();
  ASSERT_GE(glb.size(), 28u);
  EXPECT_EQ(u32(glb, 0), 0x46546C67u);
  EXPECT_EQ(u32(glb, 4), 2u);
  EXPECT_EQ(u32(glb, 8), glb.size());
  const std::uint32_t json_len = u32(glb, 12);
  EXPECT_EQ(u32(glb, 16), 0x4E4F534Au);
  EXPECT_EQ(json_len % 4, 0u);
  const auto doc = nlohmann::json::parse(std::string(glb.begin() + 20, glb.begin() + 20 + json_len));
  const std::size_t bin_at = 20 + json_len;
  const std::uint32_t bin_len = u32(glb, bin_at);
  EXPECT_EQ(u32(glb, bin_at + 4), 0x004E4942u);
  EXPECT_EQ(bin_at + 8 + bin_len, glb.size());
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>(), bin_len);
  EXPECT_EQ(doc["nodes"].size(), 2u);
  EXPECT_EQ(doc["nodes"][0]["name"], "room_bounds");
  for (const auto& view : doc["bufferViews"])
    EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(), bin_len);
  EXPECT_EQ(doc["accessors"][0]["count"].get<std::size_t>(), m.vertices.size());
  EXPECT_EQ(doc["accessors"][1]["count"].get<std::size_t>(), m.indices.size());
  EXPECT_EQ(doc["materials"].size(), 1u);
  EXPECT_THROW(write_bounds(m, test::temp_path("bounds.stl")), Error);
}

// Members added in the one pass print exactly as the document parsed, the member added and printed again (the
// layer's "openxr" was added so), and a value that is not JSON is refused.
TEST(Export, AnalysisJsonMembersPrintAsTheDocumentWithThemAdded) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const std::string extra = R"({"mesh_source": "XR_MSFT_scene_understanding", "runtime_meshes": 16, "compute_ms": 1.25})";
  nlohmann::json want = nlohmann::json::parse(analysis_json(room.result, {"synthetic:default", 1.5}));
  want["openxr"] = nlohmann::json::parse(extra);
  EXPECT_EQ(analysis_json(room.result, {"synthetic:default", 1.5}, {{"openxr", extra}}), want.dump(2));
  EXPECT_THROW(analysis_json(room.result, {}, {{"openxr", "{not json"}}), Error);
}

TEST(Export, AnalysisJsonFollowsTheContract) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const auto doc = nlohmann::json::parse(analysis_json(room.result, {"synthetic:default", 1.5}));
  EXPECT_EQ(doc["schema"], "roomsense.analysis/1");
  EXPECT_EQ(doc["input"]["file"], "synthetic:default");
  EXPECT_EQ(doc["input"]["vertices"].get<std::size_t>(), room.scan.vertices.size());
  EXPECT_EQ(doc["input"]["triangles"].get<std::size_t>(), room.scan.indices.size() / 3);
  EXPECT_EQ(doc["input"]["skipped_vertices"], 0);
  EXPECT_EQ(doc["grid"]["voxel_size"].get<float>(), 0.1f);
  EXPECT_EQ(doc["grid"]["origin"].size(), 3u);
  EXPECT_EQ(doc["grid"]["dims"][0].get<int>(), room.result.voxels.grid.spec.nx);
  EXPECT_NEAR(doc["floor_y"].get<float>(), 0.0f, 0.03f);
  EXPECT_NEAR(doc["ceiling_y"].get<float>(), 2.6f, 0.03f);
  ASSERT_GE(doc["storeys"].size(), 1u);
  EXPECT_EQ(doc["storeys"][0]["floor_y"], doc["floor_y"]);
  EXPECT_TRUE(doc["areas"].is_array());
  EXPECT_EQ(doc["bounds"]["triangles"].get<std::size_t>(), room.result.bounds.indices.size() / 3);
  EXPECT_TRUE(doc["bounds"]["closed"].get<bool>());
  for (const char* key : {"load", "voxelize", "features", "areas", "reduce", "classify", "bounds", "total_compute"})
    EXPECT_TRUE(doc["timings_ms"][key].is_number()) << key;
  EXPECT_GT(doc["timings_ms"]["total_compute"].get<double>(), 0.0);
}

}  // namespace
}  // namespace roomsense
