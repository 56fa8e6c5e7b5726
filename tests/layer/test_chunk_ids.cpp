// The layer's chunk ids (layer/src/chunk_ids.h): a mesh keeps its IncrementalAnalysis chunk wherever the runtime
// lists it, and a new one sorts last, so a mesh listed before the others leaves their voxels alone.
#include "../../layer/src/chunk_ids.h"

#include "json_without_timings.h"
#include "roomsense/export.h"
#include "roomsense/incremental.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

namespace roomsense {
namespace {

using test::json_without_timings;
using roomsense::layer::ChunkIds;

TEST(ChunkIds, AMeshKeepsItsIdWhereverItIsListedAndANewOneSortsLast) {
  ChunkIds chunks;
  EXPECT_EQ(chunks.assign({"a", "b", "c"}), (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(chunks.assign({"x", "c", "a"}), (std::vector<std::uint64_t>{3, 2, 0}));  // b gone, x new
  EXPECT_EQ(chunks.assign({"a", "a", "x"}), (std::vector<std::uint64_t>{0, 4, 3}));  // a twice: two meshes
  EXPECT_EQ(chunks.assign({"a", "c", "a"}), (std::vector<std::uint64_t>{0, 5, 4}));  // c was forgotten: new
  EXPECT_EQ(chunks.assign({}), (std::vector<std::uint64_t>{}));
  EXPECT_EQ(chunks.assign({"a"}), (std::vector<std::uint64_t>{6}));
}

// The pieces of one compute in chunk order, as the layer's analyzer gives them to its IncrementalAnalysis
// (analyze_pieces): each piece set under its id, every other chunk removed.
void set_pieces(IncrementalAnalysis& inc, const std::vector<std::uint64_t>& ids, const std::vector<const Scan*>& pieces) {
  std::vector<std::size_t> order(ids.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  for (const std::size_t i : order) inc.set_chunk(ids[i], *pieces[i]);
  for (const std::uint64_t id : inc.chunk_ids())
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) inc.remove_chunk(id);
}

// A runtime that lists a new mesh first: with ids by position every mesh after it would move to another chunk and
// be voxelized again; with ChunkIds only the new one is, and the result is the full analysis of the chunks.
TEST(ChunkIds, AMeshListedFirstLeavesTheOthersVoxelsAlone) {
  const std::map<std::uint64_t, Scan> blocks = split_into_blocks(synth::generate_builtin_source("synthetic:thesis-room1"));
  ASSERT_GE(blocks.size(), 4u);
  std::vector<std::string> keys;
  std::vector<const Scan*> pieces;
  for (const auto& [id, block] : blocks) keys.push_back("runtime:" + std::to_string(id)), pieces.push_back(&block);
  const std::string new_key = keys.back();
  const Scan* new_piece = pieces.back();
  keys.pop_back(), pieces.pop_back();

  ChunkIds chunks;
  IncrementalAnalysis by_key, by_position;
  std::vector<std::uint64_t> positions(pieces.size());
  std::iota(positions.begin(), positions.end(), std::uint64_t{0});
  set_pieces(by_key, chunks.assign(keys), pieces);
  set_pieces(by_position, positions, pieces);
  ASSERT_TRUE(by_key.result().ok());
  ASSERT_TRUE(by_position.result().ok());

  keys.insert(keys.begin(), new_key), pieces.insert(pieces.begin(), new_piece);
  positions.push_back(positions.size());
  set_pieces(by_key, chunks.assign(keys), pieces);
  set_pieces(by_position, positions, pieces);
  const AnalysisResult& got = by_key.result();
  by_position.result();
  EXPECT_EQ(by_key.revoxelized_chunks(), 1u);
  EXPECT_EQ(by_position.revoxelized_chunks(), pieces.size());
  EXPECT_EQ(json_without_timings(got), json_without_timings(analyze(by_key.combined_scan())));

  // Listed in another order, nothing changed: no chunk is voxelized again.
  std::reverse(keys.begin(), keys.end()), std::reverse(pieces.begin(), pieces.end());
  set_pieces(by_key, chunks.assign(keys), pieces);
  by_key.result();
  EXPECT_TRUE(by_key.reused_result());
}

}  // namespace
}  // namespace roomsense
