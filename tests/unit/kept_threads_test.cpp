// KeptThreads (roomsense/kept_threads.h): analyses on threads kept from one to the next give what analyses on
// their own threads give, one after another and side by side from several threads, and an analysis on another
// thread count than the kept threads' starts its own.
#include "roomsense/analysis.h"
#include "roomsense/kept_threads.h"
#include "roomsense/synthetic.h"
#include "../../core/src/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>

#include <thread>
#include <vector>

namespace roomsense {
namespace {

// The CPU stage, noting the pool the analysis runs its loops on.
class PoolWitness final : public VoxelStage {
 public:
  std::string name() const override { return "cpu"; }
  VoxelStageResult run(const VoxelizeRequest& request) override {
    seen = detail::WorkerPool::current();
    return CpuVoxelStage(2).run(request);
  }
  std::atomic<detail::WorkerPool*> seen = nullptr;
};

void expect_same(const AnalysisResult& a, const AnalysisResult& b) {
  EXPECT_EQ(a.voxels.grid.cells, b.voxels.grid.cells);
  ASSERT_TRUE(a.features && b.features);
  EXPECT_EQ(a.features->free_floor, b.features->free_floor);
  EXPECT_EQ(a.features->normals, b.features->normals);
  ASSERT_EQ(a.areas.size(), b.areas.size());
  for (std::size_t i = 0; i < a.areas.size(); ++i) {
    EXPECT_EQ(a.areas[i].center, b.areas[i].center);
    EXPECT_EQ(a.areas[i].type, b.areas[i].type);
  }
  EXPECT_EQ(a.bounds.vertices, b.bounds.vertices);
  EXPECT_EQ(a.bounds.indices, b.bounds.indices);
}

TEST(KeptThreads, AnalysesOnKeptThreadsEqualAnalysesOnTheirOwn) {
  const Scan scan = synth::generate(synth::rotated_room(20.0f));
  AnalysisOptions own;
  own.threads = 2;
  const AnalysisResult want = analyze(scan, own);
  ASSERT_FALSE(want.areas.empty());

  KeptThreads kept(2);
  EXPECT_EQ(kept.threads(), 2u);
  EXPECT_NE(kept.pool(), nullptr);
  AnalysisOptions with_kept = own;
  with_kept.kept_threads = &kept;
  PoolWitness witness;
  with_kept.voxel_stage = &witness;
  for (int i = 0; i < 3; ++i) {
    expect_same(analyze(scan, with_kept), want);
    EXPECT_EQ(witness.seen.load(), kept.pool());
  }

  // Side by side: three threads share the kept threads.
  std::vector<AnalysisResult> side(3);
  {
    std::vector<std::jthread> callers;
    for (AnalysisResult& r : side) callers.emplace_back([&] { r = analyze(scan, with_kept); });
  }
  for (const AnalysisResult& r : side) expect_same(r, want);

  // Another count: the analysis starts its own threads.
  AnalysisOptions three = with_kept;
  three.threads = 3;
  expect_same(analyze(scan, three), want);
  EXPECT_NE(witness.seen.load(), kept.pool());
  EXPECT_NE(witness.seen.load(), nullptr);

  // One thread keeps none.
  EXPECT_EQ(KeptThreads(1).pool(), nullptr);
}

}  // namespace
}  // namespace roomsense
