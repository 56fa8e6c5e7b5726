// The layer's chunk feed (layer/src/chunk_feed.h): a compute gives the IncrementalAnalysis only the meshes whose
// content, labels or triangle mode changed, and every result equals the full analysis of all the meshes merged as
// the layer merges them.
#include "../../layer/src/chunk_feed.h"

#include "json_without_timings.h"
#include "roomsense/export.h"
#include "roomsense/incremental.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace roomsense {
namespace {

using test::json_without_timings;
using roomsense::layer::ChunkFeed;
using roomsense::layer::FedPiece;
using roomsense::layer::MeshPiece;

// The pieces merged as analyze_pieces() merges them for a whole analysis: chunk_of each, in order.
Scan merged(const std::vector<FedPiece>& pieces) {
  bool triangles = false;
  for (const FedPiece& p : pieces) triangles = triangles || !p.mesh->indices.empty();
  IncrementalAnalysis whole;
  for (std::size_t i = 0; i < pieces.size(); ++i) whole.set_chunk(i, layer::chunk_of(pieces[i], triangles));
  return whole.combined_scan();
}

TEST(ChunkFeed, GivesTheAnalysisOnlyWhatChangedAndEqualsTheFullAnalysis) {
  const std::map<std::uint64_t, Scan> blocks = split_into_blocks(synth::generate_builtin_source("synthetic:thesis-room1"));
  std::vector<MeshPiece> meshes;
  std::vector<std::vector<SurfaceLabel>> labels;
  for (const auto& [id, block] : blocks) {
    meshes.push_back({block.vertices, block.indices});
    labels.emplace_back(block.indices.size() / 3, SurfaceLabel::Unknown);
  }
  ASSERT_GE(meshes.size(), 6u);
  MeshPiece points{meshes[2].vertices, {}};  // a point cloud among triangle meshes: its vertices become triangles
  std::vector<std::uint64_t> ids;
  const auto pieces_of = [&](const std::vector<std::size_t>& which, const std::vector<MeshPiece*>& swap = {}) {
    std::vector<FedPiece> pieces;
    ids.clear();
    for (std::size_t k = 0; k < which.size(); ++k) {
      const MeshPiece* mesh = k < swap.size() && swap[k] ? swap[k] : &meshes[which[k]];
      const std::vector<SurfaceLabel>* l = which[k] % 2 == 0 && !mesh->indices.empty() ? &labels[which[k]] : nullptr;
      pieces.push_back({mesh, l, layer::piece_key(*mesh, l)});
      ids.push_back(which[k]);
    }
    return pieces;
  };
  ChunkFeed feed;
  IncrementalAnalysis incremental;
  const auto compute = [&](const std::vector<FedPiece>& pieces, std::size_t expect_fed, const std::string& step) {
    SCOPED_TRACE(step);
    feed.feed(incremental, pieces, ids);
    EXPECT_EQ(feed.fed(), expect_fed);
    EXPECT_EQ(feed.fed() + feed.kept(), pieces.size());
    const AnalysisResult& got = incremental.result();
    ASSERT_TRUE(got.ok()) << got.status_message;
    EXPECT_EQ(json_without_timings(got), json_without_timings(analyze(merged(pieces))));
  };
  std::vector<std::size_t> all(meshes.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  compute(pieces_of(all), all.size(), "first");
  compute(pieces_of(all), 0, "the same meshes again");
  MeshPiece refined = meshes[3];
  refined.indices.resize(refined.indices.size() - 30);
  std::vector<MeshPiece*> swap(all.size(), nullptr);
  swap[3] = &refined;
  compute(pieces_of(all, swap), 1, "one mesh refined");
  labels[4][0] = SurfaceLabel::Floor;
  compute(pieces_of(all, swap), 1, "one mesh's labels changed");
  std::vector<std::size_t> fewer(all.begin() + 1, all.end());
  compute(pieces_of(fewer, std::vector<MeshPiece*>(swap.begin() + 1, swap.end())), 0, "one mesh gone");
  swap[2] = &points;
  compute(pieces_of(all, swap), 2, "the first back, and a point cloud for another");
  EXPECT_EQ(incremental.chunk_count(), all.size());
}

TEST(ChunkFeed, TheWorkloadIsTheMergedScansFromKeptBounds) {
  const std::map<std::uint64_t, Scan> blocks = split_into_blocks(synth::generate_builtin_source("synthetic:default"));
  std::vector<MeshPiece> meshes;
  for (const auto& [id, block] : blocks) meshes.push_back({block.vertices, block.indices});
  meshes[0].vertices.push_back(glm::vec3(NAN, 0.0f, 0.0f));  // not finite: outside the bounds
  std::vector<FedPiece> pieces;
  std::vector<std::uint64_t> ids;
  for (std::size_t i = 0; i < meshes.size(); ++i) pieces.push_back({&meshes[i], nullptr, layer::piece_key(meshes[i], nullptr)}), ids.push_back(i);
  ChunkFeed feed;
  for (int round = 0; round < 2; ++round) {  // measured, then kept
    const VoxelWorkload got = feed.workload(pieces, ids, 0.1f), want = estimate_voxel_workload(merged(pieces), 0.1f);
    EXPECT_EQ(got.voxels, want.voxels) << round;
    EXPECT_EQ(got.triangles, want.triangles) << round;
  }
}

}  // namespace
}  // namespace roomsense
