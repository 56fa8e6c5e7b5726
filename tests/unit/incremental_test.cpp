// IncrementalAnalysis (issue 19, item 1): rooms replayed chunk by chunk, in random order, with replacements
// and removals; after every step the result must equal a full analysis of the same chunks, bit for bit.
#include "rooms.h"
#include "roomsense/error.h"
#include "roomsense/export.h"
#include "roomsense/incremental.h"
#include "roomsense/mruk_room.h"
#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"
#include "same_features.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <stop_token>
#include <thread>

namespace {

using namespace roomsense;

// A chunk as a headset re-sends it, refined: every fifth triangle gone.
Scan refined(const Scan& chunk) {
  Scan out = chunk;
  out.indices.clear();
  for (std::size_t t = 0; t + 2 < chunk.indices.size(); t += 3)
    if ((t / 3) % 5 != 4) out.indices.insert(out.indices.end(), &chunk.indices[t], &chunk.indices[t] + 3);
  return out;
}

void expect_same(const AnalysisResult& got, const AnalysisResult& want, const std::string& step) {
  SCOPED_TRACE(step);
  ASSERT_EQ(got.status, want.status) << got.status_message << " / " << want.status_message;
  nlohmann::json a = nlohmann::json::parse(analysis_json(got, {})), b = nlohmann::json::parse(analysis_json(want, {}));
  a.erase("timings_ms");
  b.erase("timings_ms");
  EXPECT_TRUE(a == b) << "the JSON differs";
  ASSERT_EQ(got.features.has_value(), want.features.has_value());
  if (got.features) roomsense::test::expect_same_features(*got.features, *want.features);
  ASSERT_EQ(got.other_features.size(), want.other_features.size());
  for (std::size_t i = 0; i < got.other_features.size(); ++i)
    roomsense::test::expect_same_features(got.other_features[i], want.other_features[i]);
  EXPECT_EQ(got.voxels.grid.cells, want.voxels.grid.cells);
  EXPECT_EQ(got.voxels.voxel_tests, want.voxels.voxel_tests);
  EXPECT_EQ(got.voxels.level_counts, want.voxels.level_counts);
  EXPECT_EQ(got.voxels.levels, want.voxels.levels);
  EXPECT_EQ(got.voxels.column_counts, want.voxels.column_counts);
  EXPECT_EQ(got.voxels.column_any, want.voxels.column_any);
  roomsense::test::expect_same_bounds(got, want);
}

// inc.result() against a full analysis of its combined scan, warnings included; returns the full analysis.
AnalysisResult expect_same_as_full(IncrementalAnalysis& inc, const std::string& step, const AnalysisOptions& options = {}) {
  AnalysisResult want = analyze(inc.combined_scan(), options);
  const AnalysisResult& got = inc.result();
  EXPECT_EQ(got.warnings, want.warnings) << step;
  expect_same(got, want, step);
  return want;
}

// `scan` with a runtime's label on every triangle, by its normal and height: floor, ceiling, wall, table top.
Scan labelled_by_normals(Scan scan) {
  float low = INFINITY;
  for (const glm::vec3& v : scan.vertices) low = std::min(low, v.y);
  scan.labels.vertices = scan.vertices;
  scan.labels.indices = scan.indices;
  for (std::size_t t = 0; t + 2 < scan.indices.size(); t += 3) {
    const glm::vec3 a = scan.vertices[scan.indices[t]], b = scan.vertices[scan.indices[t + 1]], c = scan.vertices[scan.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float up = n.y / std::max(glm::length(n), 1e-12f);
    const float y = (a.y + b.y + c.y) / 3.0f;
    scan.labels.labels.push_back(up > 0.9f ? (y < low + 0.2f ? SurfaceLabel::Floor : SurfaceLabel::Table)
                                 : up < -0.9f ? SurfaceLabel::Ceiling
                                              : SurfaceLabel::Wall);
  }
  return scan;
}

// Adds the tiles in a random order; after a third of them, and then every few steps, replaces one with its
// refined version or removes one (and adds it back later). Compares with analyze() after every step.
void replay(const Scan& scan, unsigned seed, bool keeps_voxels = true) {
  const std::map<std::uint64_t, Scan> tiles = split_into_blocks(scan, 2.0f);
  ASSERT_GE(tiles.size(), 2u);
  std::vector<std::uint64_t> order;
  for (const auto& [id, chunk] : tiles) order.push_back(id);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  IncrementalAnalysis inc;
  std::vector<std::uint64_t> added, removed, refined_ids;
  std::size_t steps = 0, same_grid_steps = 0, bands_searched = 0, bands_total = 0, partly_searched = 0;
  std::optional<GridSpec> previous_grid;
  const auto check = [&](const std::string& what) {
    ++steps;
    const Scan combined = inc.combined_scan();
    const AnalysisResult want = [&] {
      try {
        return analyze(combined);
      } catch (const Error& e) {
        AnalysisResult failed;
        failed.status_message = e.what();
        failed.status = AnalysisStatus::NoFloorCeiling;
        return failed;
      }
    }();
    try {
      const AnalysisResult& got = inc.result();
      expect_same(got, want, what);
      // Under the grid of the previous step every step changes one chunk: at most that one is voxelized.
      const GridSpec& grid = got.voxels.grid.spec;
      if (keeps_voxels && previous_grid && previous_grid->origin == grid.origin && previous_grid->nx == grid.nx &&
          previous_grid->ny == grid.ny && previous_grid->nz == grid.nz) {
        ++same_grid_steps;
        EXPECT_LE(inc.revoxelized_chunks(), 1u) << what << ": of " << inc.chunk_count() << " chunks";
        bands_searched += inc.area_bands_searched();
        bands_total += inc.area_bands_total();
        if (inc.area_bands_searched() > 0 && inc.area_bands_searched() < inc.area_bands_total()) ++partly_searched;
      }
      previous_grid = grid;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), want.status_message) << what;
    }
  };
  for (std::size_t i = 0; i < order.size(); ++i) {
    inc.set_chunk(order[i], tiles.at(order[i]));
    added.push_back(order[i]);
    check("add " + std::to_string(i));
    if (i < order.size() / 3 || i % 3 != 0) continue;
    const std::uint64_t victim = added[rng() % added.size()];
    if (rng() % 2 == 0) {
      inc.set_chunk(victim, refined(tiles.at(victim)));
      refined_ids.push_back(victim);
      check("replace after add " + std::to_string(i));
    } else if (inc.remove_chunk(victim)) {
      added.erase(std::find(added.begin(), added.end(), victim));
      removed.push_back(victim);
      check("remove after add " + std::to_string(i));
    }
  }
  for (const std::uint64_t id : removed) {
    inc.set_chunk(id, tiles.at(id));
    check("add back");
  }
  // A chunk removed and set again as it was before the next result: the same chunk, held anew.
  for (const std::uint64_t id : order) {
    if (std::find(refined_ids.begin(), refined_ids.end(), id) != refined_ids.end()) continue;  // not as split
    ASSERT_TRUE(inc.remove_chunk(id));
    inc.set_chunk(id, tiles.at(id));
    check("removed and set again");
    break;
  }
  // Nothing changed: the previous result, at once.
  inc.result();
  EXPECT_TRUE(inc.reused_result());
  // Steps that leave the grid's extent as it was keep the other chunks' voxels (a step that moves it
  // voxelizes every chunk again); there are such steps in every room.
  // And their area searches keep the rectangles of the bands of rows whose features did not change.
  if (keeps_voxels) {
    EXPECT_GT(same_grid_steps, 0u) << "of " << steps << " steps";
    EXPECT_LT(bands_searched, bands_total) << "over " << same_grid_steps << " steps under an unchanged grid";
    EXPECT_GT(partly_searched, 0u) << "steps that searched some bands and kept the others";
  }
}

TEST(Incremental, SyntheticRoomsReplayedChunkByChunkEqualTheFullAnalysis) {
  for (const char* name : {"synthetic:default", "synthetic:thesis-room1", "synthetic:flat", "synthetic:house", "synthetic:loft",
                           "synthetic:rotated"}) {
    SCOPED_TRACE(name);
    replay(synth::generate_builtin_source(name), 19);
  }
  // A room of large triangles 20 km up: its surface heights' terms (height times area) are past what the exact
  // sums hold, so each height is summed over the whole scan in order, whether it arrived in chunks or not.
  Scan high = synth::generate_builtin_source("synthetic:large-triangles");
  for (glm::vec3& v : high.vertices) v.y += 20000.0f;
  ASSERT_EQ(analyze(high).status, AnalysisStatus::Ok);
  {
    SCOPED_TRACE("20 km up");
    replay(high, 23);
  }
  // Every triangle labelled, as Android XR labels its submeshes: each chunk's labelled voxels are kept.
  {
    SCOPED_TRACE("labelled");
    replay(labelled_by_normals(synth::generate_builtin_source("synthetic:thesis-room1")), 29);
  }
  // A point cloud (vertex mode, Eq. 3.6): blocks of vertices; the voxel stage runs whole, the result is equal.
  Scan cloud = synth::generate_builtin_source("synthetic:default");
  cloud.indices.clear();
  replay(cloud, 5, /*keeps_voxels=*/false);
}

class IncrementalRealRoom : public testing::TestWithParam<const char*> {};

TEST_P(IncrementalRealRoom, ReplayedChunkByChunkEqualsTheFullAnalysis) {
  ROOMSENSE_REQUIRE_ROOM(path, GetParam());
  Scan scan;
  if (scanio::is_quest_capture_path(path.string())) {
    const scanio::QuestCapture capture = scanio::load_scene_capture(path.string());
    scan = capture.mesh;
    scan.labels = scanio::scene_labels(capture);
  } else {
    scan = scanio::load_mesh_file(path.string());
  }
  replay(scan, 7);
}

INSTANTIATE_TEST_SUITE_P(
    Rooms, IncrementalRealRoom,
    testing::Values("hololens1/holotoolkit_fake_spatial_mapping.obj", "hololens1/mrtk_example_spatial_mesh.obj",
                    "hololens2-su/SU_Kitchen_world_mesh.obj", "hololens2-su/SU_Apartment_world_mesh.obj",
                    "quest-iwer/living_room.json", "quest-iwer/meeting_room.json", "quest-iwer/music_room.json",
                    "quest-iwer/office_large.json", "quest-iwer/office_small.json",
                    "quest-iwer/living_room_global_mesh.obj", "quest-iwer/office_large_global_mesh.obj"),
    [](const testing::TestParamInfo<const char*>& info) {
      std::string name = std::filesystem::path(info.param).stem().string();
      std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
      return name;
    });

// Labels past the triangle-voxel test budget are dropped with the full analysis's warning, chunk by chunk too: as
// chunks come and go across the budget, every result (warnings included) equals the full analysis.
TEST(Incremental, LabelsPastTheTestBudgetGiveTheFullAnalysisWarnings) {
  // Each tile's labels also hold one large triangle across the tile's box (as a runtime's plane outline may be):
  // the labels then take many more triangle-voxel tests than the tile's own small triangles, so a budget can
  // hold the voxelization and drop the labels.
  std::map<std::uint64_t, Scan> tiles = split_into_blocks(labelled_by_normals(synth::generate_builtin_source("synthetic:default")), 2.0f);
  ASSERT_GE(tiles.size(), 4u);
  IncrementalAnalysis whole;
  for (auto& [id, tile] : tiles) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& v : tile.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    for (int copy = 0; copy < 8; ++copy) {
      const auto first = static_cast<std::uint32_t>(tile.labels.vertices.size());
      tile.labels.vertices.insert(tile.labels.vertices.end(), {lo, {hi.x, lo.y, lo.z}, hi});
      tile.labels.indices.insert(tile.labels.indices.end(), {first, first + 1, first + 2});
      tile.labels.labels.push_back(SurfaceLabel::Other);
    }
    whole.set_chunk(id, tile);
  }
  const Scan room = whole.combined_scan();
  AnalysisOptions options;
  // The room's voxelization fits the budget; its labels, taking about eight times as many tests, do not.
  options.voxel_test_budget = analyze(room).voxels.voxel_tests;
  IncrementalAnalysis inc(options);
  std::size_t over = 0, under = 0;
  const auto check = [&](const std::string& step) {
    const AnalysisResult want = expect_same_as_full(inc, step, options);
    const bool dropped = std::any_of(want.warnings.begin(), want.warnings.end(),
                                     [](const std::string& s) { return s.find("runtime labels ignored") != std::string::npos; });
    (dropped ? over : under) += 1;
  };
  for (const auto& [id, tile] : tiles) {
    inc.set_chunk(id, tile);
    check("add " + std::to_string(id));
  }
  for (const auto& [id, tile] : tiles) {
    if (!inc.remove_chunk(id)) continue;
    if (inc.chunk_count() == 0) break;
    check("remove " + std::to_string(id));
  }
  EXPECT_GT(over, 0u) << "no step past the budget";
  EXPECT_GT(under, 0u) << "no step within the budget";
}

// Labelled triangles that overlap a lot: the chunks' labelled voxels could hold more entries than the grid has
// voxels, so none are kept and the labels are voxelized whole; as the heavy chunks go, they are kept again. Every
// result equals the full analysis.
TEST(Incremental, HeavilyOverlappingLabelsAreVoxelizedWholeAndEqualTheFullAnalysis) {
  const Scan room = labelled_by_normals(synth::generate_builtin_source("synthetic:default"));
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : room.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  std::map<std::uint64_t, Scan> tiles = split_into_blocks(room, 2.0f);
  ASSERT_GE(tiles.size(), 4u);
  // Three chunks whose labels each hold the room's whole floor plan at 64 heights: each labels about every voxel
  // of the grid, so together they would hold about three entries per voxel.
  std::vector<std::uint64_t> heavy;
  for (auto& [id, tile] : tiles) {
    if (heavy.size() == 3) break;
    heavy.push_back(id);
    for (int level = 0; level < 64; ++level) {
      const float y = lo.y + (hi.y - lo.y) * (float(level) + 0.5f) / 64.0f;
      const auto first = static_cast<std::uint32_t>(tile.labels.vertices.size());
      tile.labels.vertices.insert(tile.labels.vertices.end(), {{lo.x, y, lo.z}, {hi.x, y, lo.z}, {hi.x, y, hi.z}, {lo.x, y, hi.z}});
      tile.labels.indices.insert(tile.labels.indices.end(), {first, first + 2, first + 1, first, first + 3, first + 2});
      tile.labels.labels.insert(tile.labels.labels.end(), 2, SurfaceLabel::Table);
    }
  }
  IncrementalAnalysis inc;
  const auto check = [&](const std::string& step) { expect_same_as_full(inc, step); };
  for (const auto& [id, tile] : tiles) inc.set_chunk(id, tile);
  check("all");
  for (const std::uint64_t id : heavy) {
    Scan light = tiles.at(id);
    light.labels = {};
    inc.set_chunk(id, light);
    check("chunk " + std::to_string(id) + " without its labels");
  }
  inc.set_chunk(heavy.front(), tiles.at(heavy.front()));
  check("one heavy chunk back");
}

// Labels that are not their chunk's own: a labelled triangle indexing past its chunk's label vertices (in the
// combined scan, into the next chunk's), and a chunk with a label more than it has labelled triangles (in the
// combined scan, the next chunk's first triangle takes it, and every label after shifts). The chunks are then
// read as the combined scan holds them, and every result equals the full analysis, warnings included.
TEST(Incremental, LabelsReachingPastTheirChunkEqualTheFullAnalysis) {
  std::map<std::uint64_t, Scan> tiles = split_into_blocks(labelled_by_normals(synth::generate_builtin_source("synthetic:default")), 2.0f);
  ASSERT_GE(tiles.size(), 4u);
  auto it = tiles.begin();
  Scan& past_vertices = it->second;
  ASSERT_FALSE(past_vertices.labels.indices.empty());
  past_vertices.labels.indices.back() = std::uint32_t(past_vertices.labels.vertices.size() + 2);
  const std::uint64_t past_vertices_id = it->first;
  Scan& extra_label = (++it)->second;
  extra_label.labels.labels.push_back(SurfaceLabel::Table);
  const std::uint64_t extra_label_id = it->first;
  IncrementalAnalysis inc;
  const auto check = [&](const std::string& step) { expect_same_as_full(inc, step); };
  for (const auto& [id, tile] : tiles) {
    if (id == extra_label_id) continue;
    inc.set_chunk(id, tile);
  }
  check("an index past its chunk's label vertices");
  inc.set_chunk(past_vertices_id, labelled_by_normals(split_into_blocks(synth::generate_builtin_source("synthetic:default"), 2.0f).at(past_vertices_id)));
  check("that chunk's labels its own again");
  inc.set_chunk(extra_label_id, tiles.at(extra_label_id));
  check("a chunk with a label past its triangles");
}

// Bad chunks: an index past the chunk's own vertices is refused even where the combined scan would have a
// vertex there; removing what is not there says so; an empty analyzer is EmptyInput.
TEST(Incremental, BadChunksAreRefusedAndNothingIsLost) {
  IncrementalAnalysis inc;
  EXPECT_FALSE(inc.remove_chunk(3));
  EXPECT_THROW(inc.result(), Error);
  const Scan room = synth::generate_builtin_source("synthetic:default");
  inc.set_chunk(1, room);
  const std::size_t areas = inc.result().areas.size();
  ASSERT_GT(areas, 0u);
  Scan bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  bad.indices = {0, 1, 5};
  inc.set_chunk(2, bad);
  try {
    inc.result();
    ADD_FAILURE() << "a chunk index past its own vertices was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadIndices);
    EXPECT_NE(std::string(e.what()).find("chunk 2"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(inc.remove_chunk(2));
  EXPECT_EQ(inc.result().areas.size(), areas);  // the room as before: chunk 1 kept its voxels
  EXPECT_EQ(inc.revoxelized_chunks(), 0u);
}

// A chunk refused for its indices among others (not the last by id: chunks after it are placed again) leaves
// nothing behind: the next result, with the chunk mended or gone, equals the full analysis. Refused first, the
// combined scan lost its place list while keeping every array, and the next result kept the old triangles too.
TEST(Incremental, AChunkRefusedAmongOthersLeavesTheNextResultEqualToTheFullAnalysis) {
  const std::map<std::uint64_t, Scan> tiles = split_into_blocks(synth::generate_builtin_source("synthetic:thesis-room1"));
  ASSERT_GE(tiles.size(), 4u);
  IncrementalAnalysis inc;
  for (const auto& [id, chunk] : tiles) inc.set_chunk(id, chunk);
  inc.result();
  Scan bad = tiles.begin()->second;
  bad.indices.back() = std::uint32_t(bad.vertices.size());
  for (const auto& [id, mend] : {std::pair{std::next(tiles.begin(), 2)->first, "restored"},
                                 std::pair{tiles.begin()->first, "removed"}}) {
    SCOPED_TRACE(mend);
    inc.set_chunk(id, bad);
    EXPECT_THROW(inc.result(), Error);
    if (std::string(mend) == "restored") inc.set_chunk(id, tiles.at(id));
    else inc.remove_chunk(id);
    expect_same(inc.result(), analyze(inc.combined_scan()), "after the refused chunk");
  }
}

// Chunks with NaN vertices and with outliers (a vertex a kilometre away) among clean ones: the input checks,
// which an IncrementalAnalysis runs chunk by chunk, skip and reject exactly what analyze() does on the
// combined scan, whether they arrive, are replaced or leave.
TEST(Incremental, ChunksWithNaNVerticesOrOutliersEqualTheFullAnalysis) {
  const Scan room = synth::generate_builtin_source("synthetic:default");
  const std::map<std::uint64_t, Scan> tiles = split_into_blocks(room, 2.0f);
  IncrementalAnalysis inc;
  for (const auto& [id, tile] : tiles) inc.set_chunk(id, tile);
  const auto check = [&](const std::string& what) {
    const AnalysisResult want = analyze(inc.combined_scan());
    expect_same(inc.result(), want, what);
  };
  check("clean");
  const std::uint64_t first = tiles.begin()->first, last = tiles.rbegin()->first;
  Scan with_nan = tiles.at(first);
  with_nan.vertices[0] = glm::vec3(NAN, 0.0f, 0.0f);
  Scan with_outlier = tiles.at(last);
  with_outlier.vertices.back() += glm::vec3(1000.0f, 0.0f, 0.0f);
  inc.set_chunk(first, with_nan);
  check("a NaN vertex in the first chunk");
  EXPECT_GT(inc.result().input.skipped_vertices, 0u);
  inc.set_chunk(last, with_outlier);
  check("and an outlier in the last");
  EXPECT_GT(inc.result().input.outlier_vertices, 0u);
  inc.set_chunk(first, tiles.at(first));
  check("the NaN vertex replaced");
  inc.set_chunk(7, with_outlier);  // before every tile in id order
  check("an outlier chunk in front");
  inc.remove_chunk(7);
  inc.set_chunk(last, tiles.at(last));
  check("clean again");
  EXPECT_EQ(inc.result().input.outlier_vertices, 0u);
  EXPECT_EQ(inc.result().input.skipped_vertices, 0u);
}

// A closed box of side `side` (two triangles a face) with its lowest corner at `corner`.
Scan box(const glm::vec3& corner, float side) {
  Scan s;
  for (int i = 0; i < 8; ++i)
    s.vertices.push_back(corner + side * glm::vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)));
  s.indices = {0, 1, 3, 0, 3, 2, 4, 7, 5, 4, 6, 7, 0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  return s;
}

// synthetic:default in 2 x 2 m blocks, each set on `inc` as a chunk; returns the room's box (lowest, highest corner).
std::pair<glm::vec3, glm::vec3> default_room_in_blocks(IncrementalAnalysis& inc) {
  const Scan room = synth::generate_builtin_source("synthetic:default");
  for (const auto& [id, tile] : split_into_blocks(room, 2.0f)) inc.set_chunk(id, tile);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : room.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return {lo, hi};
}

// The voxel stage counts levels and columns again only where chunks changed, from the previous result's counts,
// which hold only where its grid came from the chunks the stage keeps. A result whose input checks removed a
// vertex is voxelized whole (the stage keeps no chunk): a box dropped with it, alone in its columns, must
// leave the next counts too.
TEST(Incremental, CountsAfterAWholeVoxelizationEqualTheFullAnalysis) {
  IncrementalAnalysis inc;
  const auto [lo, hi] = default_room_in_blocks(inc);
  // The far box holds the grid's extent; the near one stands in columns no other chunk reaches.
  inc.set_chunk(1001, box({hi.x + 2.0f, lo.y, lo.z}, 0.3f));
  inc.set_chunk(1002, box({hi.x + 0.8f, lo.y, lo.z}, 0.3f));
  Scan with_nan = box({lo.x + 1.0f, lo.y, lo.z + 1.0f}, 0.3f);
  const Scan clean = with_nan;
  with_nan.vertices[0] = glm::vec3(NAN, 0.0f, 0.0f);
  inc.set_chunk(1003, with_nan);
  expect_same(inc.result(), analyze(inc.combined_scan()), "a NaN vertex: voxelized whole");
  ASSERT_GT(inc.result().input.skipped_vertices, 0u);
  inc.remove_chunk(1002);
  inc.set_chunk(1003, clean);
  const AnalysisResult& got = inc.result();
  const AnalysisResult want = analyze(inc.combined_scan());
  ASSERT_EQ(got.voxels.grid.spec, want.voxels.grid.spec);  // the same grid: counted from the previous result
  expect_same(got, want, "the near box gone, the NaN vertex mended");
}

// A chunk voxelized again lists its marks from the cells of its vertices' box, and clears them there for the next
// chunk. Vertices no triangle uses widen that box: a few beside a box (the box of every vertex serves), or two at
// the room's far corners (then the box of the used vertices is found instead). Each chunk's voxels, and the next
// chunk's of the same update, equal the full analysis's as they come, change and go.
TEST(Incremental, ChunksWithUnusedVerticesEqualTheFullAnalysis) {
  IncrementalAnalysis inc;
  const auto [lo, hi] = default_room_in_blocks(inc);
  const auto with_unused = [](Scan chunk, std::initializer_list<glm::vec3> unused) {
    chunk.vertices.insert(chunk.vertices.end(), unused);
    return chunk;
  };
  const glm::vec3 mid = 0.5f * (lo + hi);
  const Scan spanning = with_unused(box(mid, 0.3f), {lo, hi});
  const Scan beside = with_unused(box(mid + glm::vec3(0.8f, 0.0f, 0.0f), 0.2f), {mid + glm::vec3(1.2f, 0.1f, 0.3f)});
  inc.set_chunk(5, spanning);
  inc.set_chunk(6, beside);
  expect_same(inc.result(), analyze(inc.combined_scan()), "a box with the room's corners unused, one beside");
  inc.set_chunk(5, with_unused(box(mid + glm::vec3(-0.7f, 0.0f, 0.4f), 0.3f), {hi, lo}));
  inc.set_chunk(6, with_unused(box(mid + glm::vec3(0.9f, 0.0f, -0.5f), 0.2f), {mid}));
  expect_same(inc.result(), analyze(inc.combined_scan()), "both moved");
  inc.remove_chunk(5);
  expect_same(inc.result(), analyze(inc.combined_scan()), "the spanning one gone");
  inc.remove_chunk(6);
  expect_same(inc.result(), analyze(inc.combined_scan()), "both gone");
}

// A result cancelled at any point (the voxels, the features, halfway through the area searches and their
// reductions) leaves nothing half-kept: the next result, without a stop, equals the full analysis. The stops
// come after delays spread over an update's time, so they land in every stage.
TEST(Incremental, AResultCancelledAnywhereLeavesTheNextEqualToTheFullAnalysis) {
  const std::map<std::uint64_t, Scan> tiles = split_into_blocks(synth::generate_builtin_source("synthetic:thesis-room1"));
  IncrementalAnalysis inc;
  for (const auto& [id, chunk] : tiles) inc.set_chunk(id, chunk);
  inc.result();
  std::mt19937 rng(35);
  std::size_t cancelled = 0;
  for (int step = 0; step < 24; ++step) {
    const auto it = std::next(tiles.begin(), std::ptrdiff_t(rng() % tiles.size()));
    if (step % 3 == 2) inc.remove_chunk(it->first);
    else inc.set_chunk(it->first, step % 3 == 0 ? refined(it->second) : it->second);
    std::stop_source stop;
    inc.set_stop(stop.get_token());
    std::thread stopper([&stop, delay = std::chrono::microseconds(500 * step)] {
      std::this_thread::sleep_for(delay);
      stop.request_stop();
    });
    try {
      inc.result();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::Cancelled) << e.what();
      ++cancelled;
    }
    stopper.join();
    inc.set_stop({});
    expect_same(inc.result(), analyze(inc.combined_scan()), "after step " + std::to_string(step));
    if (step % 3 == 2) inc.set_chunk(it->first, it->second);
  }
  EXPECT_GT(cancelled, 0u);
}

}  // namespace
