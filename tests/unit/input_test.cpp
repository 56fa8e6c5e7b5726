// Input hygiene, frames and the grid budget (thesis Eq. 3.1-3.5).
#include "roomsense/analysis.h"
#include "roomsense/content_hash.h"
#include "roomsense/error.h"
#include "roomsense/input.h"
#include "roomsense/scan.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <limits>

namespace roomsense {
namespace {

// ContentHash tells every one-byte change of a mesh's arrays, and an array one zero byte longer, from the original
// (an IncrementalAnalysis takes a chunk whose hash is unchanged for one sent again as it was).
TEST(ContentHash, TellsEveryChangedByteAndLength) {
  std::mt19937 random(7);
  std::vector<float> vertices(3 * 101);
  for (float& v : vertices) v = std::uniform_real_distribution<float>(-5.0f, 5.0f)(random);
  const auto hash = [](const std::vector<float>& v) {
    ContentHash h;
    h.add(std::span<const float>(v));
    return h.value();
  };
  const std::uint64_t original = hash(vertices);
  EXPECT_EQ(hash(vertices), original);
  for (std::size_t byte = 0; byte < vertices.size() * sizeof(float); ++byte)
    for (const unsigned char flip : {0x01, 0x80}) {
      std::vector<float> changed = vertices;
      auto* bytes = reinterpret_cast<unsigned char*>(changed.data());
      bytes[byte] ^= flip;
      ASSERT_NE(hash(changed), original) << "byte " << byte;
    }
  std::vector<unsigned char> raw(vertices.size() * sizeof(float));
  std::memcpy(raw.data(), vertices.data(), raw.size());
  ContentHash shorter, longer;
  shorter.add(std::span<const unsigned char>(raw));
  raw.push_back(0);
  longer.add(std::span<const unsigned char>(raw));
  EXPECT_NE(shorter.value(), longer.value());
}

ErrorCode code_of(auto&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  ADD_FAILURE() << "no Error thrown";
  return ErrorCode::Io;
}

TEST(FlatArray, ThesisErrorCodes) {
  const float data[6] = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(code_of([&] { scan_from_flat_array(nullptr, 6); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, 0); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, -3); }), ErrorCode::EmptyInput);
  EXPECT_EQ(code_of([&] { scan_from_flat_array(data, 5); }), ErrorCode::SizeNotMultipleOfThree);
  const Scan scan = scan_from_flat_array(data, 6);
  ASSERT_EQ(scan.vertices.size(), 2u);
  EXPECT_EQ(scan.vertices[1], glm::vec3(3, 4, 5));
}

TEST(PrepareInput, SkipsNonFiniteVerticesAndTheirTriangles) {
  Scan scan;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  scan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 0, 0}, {0, inf, 0}};
  scan.indices = {0, 1, 2, 0, 1, 3, 2, 4, 1};
  const PreparedInput in = prepare_input(scan);
  EXPECT_EQ(in.skipped_vertices, 2u);
  EXPECT_EQ(in.dropped_triangles, 2u);
  EXPECT_EQ(in.vertices.size(), 3u);
  EXPECT_EQ(in.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(PrepareInput, RejectsBadIndices) {
  Scan scan;
  scan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  scan.indices = {0, 1};
  EXPECT_EQ(code_of([&] { prepare_input(scan); }), ErrorCode::BadIndices);
  scan.indices = {0, 1, 3};
  EXPECT_EQ(code_of([&] { prepare_input(scan); }), ErrorCode::BadIndices);
  EXPECT_EQ(code_of([&] { prepare_input(Scan{}); }), ErrorCode::EmptyInput);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(code_of([&] { prepare_input(Scan{{{nan, nan, nan}}, {}}); }), ErrorCode::NoValidVertices);
}

TEST(PrepareInput, RejectsAStrayVertexOneKilometreAway) {
  Scan scan = synth::generate(synth::default_room());
  scan.vertices.push_back({1000.0f, 0.0f, 0.0f});
  const AnalysisResult r = analyze(scan);
  EXPECT_EQ(r.input.outlier_vertices, 1u);
  EXPECT_TRUE(r.ok());
  EXPECT_LT(r.voxels.grid.spec.nx, 60);  // the room is 5 m wide
  ASSERT_FALSE(r.warnings.empty());
}

TEST(PrepareInput, AnAnalysisOfWhatIsLeftEqualsOneOfTheCleanScan) {
  // analyze() reads the scan in place where nothing is removed and the renumbered arrays where something is:
  // a NaN vertex and a stray one, with triangles on them, leave exactly the clean room's analysis.
  const Scan clean = synth::generate(synth::default_room());
  Scan dirty = clean;
  const auto n = std::uint32_t(dirty.vertices.size());
  dirty.vertices.push_back({std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f});
  dirty.vertices.push_back({1000.0f, 0.0f, 0.0f});
  dirty.indices.insert(dirty.indices.end(), {0, 1, n, n + 1, 2, 3});
  const AnalysisResult a = analyze(clean), b = analyze(dirty);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(b.input.skipped_vertices, 1u);
  EXPECT_EQ(b.input.outlier_vertices, 1u);
  EXPECT_EQ(b.input.dropped_triangles, 2u);
  EXPECT_EQ(a.voxels.grid.cells, b.voxels.grid.cells);
  EXPECT_EQ(a.floor_y, b.floor_y);
  ASSERT_EQ(a.areas.size(), b.areas.size());
  for (std::size_t i = 0; i < a.areas.size(); ++i) EXPECT_EQ(a.areas[i].center, b.areas[i].center) << i;
  EXPECT_EQ(a.bounds.vertices, b.bounds.vertices);
  EXPECT_EQ(a.bounds.indices, b.bounds.indices);
}

TEST(GridBudget, AbsurdExtentsAreRefusedNotAllocated) {
  // Too few vertices for the outlier test: the grid budget must catch it.
  Scan scan{{{0, 0, 0}, {5000, 10, 5000}, {1, 1, 1}}, {}};
  EXPECT_EQ(code_of([&] { analyze(scan); }), ErrorCode::GridTooLarge);
  EXPECT_EQ(code_of([&] { make_grid_spec({0, 0, 0}, {1, 1, 1}, 0.0f); }), ErrorCode::BadParameter);
  EXPECT_EQ(code_of([&] { make_grid_spec({0, 0, 0}, {1, 1, 1}, std::nanf("")); }), ErrorCode::BadParameter);
}

TEST(Frames, UnityUnrealAndZUpMapToOurFrame) {
  const auto converted = [](glm::vec3 p, SourceFrame f) {
    Scan s{{p}, {}};
    convert_to_roomsense_frame(s, f);
    return s.vertices[0];
  };
  // Unity: left-handed, Y up, forward +Z; ours: forward -Z.
  EXPECT_EQ(converted({1, 2, 3}, {UpAxis::Y, Units::Metres, true}), glm::vec3(1, 2, -3));
  // Unreal (Eq. 3.2): x = y_u / 100, y = z_u / 100, z = x_u / 100 (Unity frame), then Unity -> ours.
  const glm::vec3 unreal = converted({300, 100, 200}, {UpAxis::Z, Units::Centimetres, true});
  EXPECT_NEAR(unreal.x, 1.0f, 1e-6f);
  EXPECT_NEAR(unreal.y, 2.0f, 1e-6f);
  EXPECT_NEAR(unreal.z, -3.0f, 1e-6f);
  // Right-handed Z up (Blender): up becomes +Y, +Y (forward) becomes -Z.
  const glm::vec3 blender = converted({1000, 2000, 3000}, {UpAxis::Z, Units::Millimetres, false});
  EXPECT_NEAR(blender.x, 1.0f, 1e-6f);
  EXPECT_NEAR(blender.y, 3.0f, 1e-6f);
  EXPECT_NEAR(blender.z, -2.0f, 1e-6f);
}

TEST(Frames, AConvertedUnityRoomGivesTheSameLevels) {
  const Scan ours = synth::generate(synth::default_room());
  Scan unity = ours;
  for (glm::vec3& v : unity.vertices) v.z = -v.z;  // what a Unity export of the room holds
  convert_to_roomsense_frame(unity, {UpAxis::Y, Units::Metres, true});
  const AnalysisResult a = analyze(ours), b = analyze(unity);
  EXPECT_EQ(a.floor_y, b.floor_y);
  EXPECT_EQ(a.ceiling_y, b.ceiling_y);
  EXPECT_EQ(a.bounds.indices.size(), b.bounds.indices.size());
}

}  // namespace
}  // namespace roomsense
