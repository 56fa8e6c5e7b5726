// The layer under concurrent use, for ThreadSanitizer (scripts/tsan.sh; ctest label `concurrency`): the getters
// on 8 threads while computes run (and a ninth thread trying to compute meanwhile), 8 analyzers of one session
// computing on 8 threads and destroyed while they compute, the session destroyed under running analyses, and
// the standard spatial-entity API the layer serves used from 8 threads while its analysis thread re-queries.
// A small executable of its own (not part of layer_tests), so that the ThreadSanitizer job builds only this.
// test_lifecycle.cpp has the single-threaded lifetime cases (instances, sessions, export directory).
#include "spatial_client.h"  // first: the registry's declarations before the layer's header

#include "layer_harness.h"
#include "synthetic_room.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace layertest;

constexpr int kThreads = 8;

const Room& default_room() {
  static const Room room("synthetic:default");
  return room;
}

// One full read through every getter (two-call idiom); XR_ERROR_CALL_ORDER_INVALID before the first result.
// Returns the area count, or -1 before the first result; counts failures.
int read_all(const App& app, XrRoomAnalyzerEXTX a, std::atomic<int>& failures) {
  XrRoomComputeStateEXTX state;
  if (app.extx.state(a, &state) != XR_SUCCESS) ++failures;
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  const XrResult r = app.extx.layout(a, &layout);
  if (r == XR_ERROR_CALL_ORDER_INVALID) return -1;
  if (r != XR_SUCCESS) {
    ++failures;
    return -1;
  }
  uint32_t count = 0;
  if (app.extx.areas(a, 0, &count, nullptr) != XR_SUCCESS) ++failures;
  std::vector<XrRoomAreaEXTX> areas(count, {XR_TYPE_ROOM_AREA_EXTX, nullptr});
  uint32_t again = 0;
  // Every compute here analyses the same meshes, so the count cannot change between the two calls.
  if (app.extx.areas(a, count, &again, areas.data()) != XR_SUCCESS || again != count) ++failures;
  XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, nullptr};
  if (app.extx.bounds(a, &bounds) != XR_SUCCESS) ++failures;
  std::vector<XrVector3f> v(bounds.vertexCountOutput);
  std::vector<uint32_t> i(bounds.indexCountOutput);
  bounds.vertexCapacityInput = static_cast<uint32_t>(v.size());
  bounds.vertices = v.data();
  bounds.indexCapacityInput = static_cast<uint32_t>(i.size());
  bounds.indices = i.data();
  if (app.extx.bounds(a, &bounds) != XR_SUCCESS) ++failures;
  return static_cast<int>(count);
}

TEST(LayerConcurrency, GettersOnEightThreadsDuringComputes) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  app.submit(a, default_room().vertices, default_room().indices);
  std::atomic<bool> done{false};
  std::atomic<int> failures{0}, reads{0}, refused{0}, areas{-1};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&] {
      while (!done.load()) {
        const int n = read_all(app, a, failures);
        if (n < 0) continue;
        ++reads;
        int expected = -1;
        if (!areas.compare_exchange_strong(expected, n) && expected != n) ++failures;
      }
    });
  // A ninth thread tries to compute while computes run: XR_ERROR_CALL_ORDER_INVALID then, never a race.
  threads.emplace_back([&] {
    XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
    info.includeRuntimeMeshes = XR_FALSE;
    while (!done.load()) {
      info.time = now();
      const XrResult r = app.extx.compute(a, &info);
      if (r == XR_ERROR_CALL_ORDER_INVALID) ++refused;
      else if (r != XR_SUCCESS) ++failures;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  for (int round = 0; round < 3; ++round) {
    XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
    info.time = now();
    const XrResult r = app.extx.compute(a, &info);
    EXPECT_TRUE(r == XR_SUCCESS || r == XR_ERROR_CALL_ORDER_INVALID) << r;
    EXPECT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  }
  done = true;
  for (auto& t : threads) t.join();
  EXPECT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(reads.load(), 0);
  EXPECT_GT(areas.load(), 0);
  std::printf("[ figures  ] %d full reads, %d computes refused while running\n", reads.load(), refused.load());
}

TEST(LayerConcurrency, EightAnalyzersComputeAndAreDestroyedOnEightThreads) {
  App app;
  std::atomic<int> failures{0}, completed{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 2; ++round) {
        XrRoomAnalyzerCreateInfoEXTX info{XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, nullptr};
        info.baseSpace = app.local;
        info.backend = XR_ROOM_COMPUTE_BACKEND_CPU_EXTX;
        XrRoomAnalyzerEXTX a = XR_NULL_HANDLE;
        if (app.extx.create(app.session, &info, &a) != XR_SUCCESS) {
          ++failures;
          continue;
        }
        XrRoomMeshEXTX mesh{XR_TYPE_ROOM_MESH_EXTX, nullptr};
        mesh.pose = {{0, 0, 0, 1}, {0, 0, 0}};
        mesh.vertexCount = static_cast<uint32_t>(default_room().vertices.size());
        mesh.vertices = default_room().vertices.data();
        mesh.indexCount = static_cast<uint32_t>(default_room().indices.size());
        mesh.indices = default_room().indices.data();
        XrRoomComputeInfoEXTX compute{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
        compute.time = now();
        if (app.extx.submit(a, &mesh) != XR_SUCCESS || app.extx.compute(a, &compute) != XR_SUCCESS) ++failures;
        if ((t + round) % 2 == 0) {  // half wait for the result, half are destroyed while they compute
          if (app.wait(a) == XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX && read_all(app, a, failures) > 0) ++completed;
          else ++failures;
        }
        if (app.extx.destroy(a) != XR_SUCCESS) ++failures;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(completed.load(), kThreads);
}

// Analyzers of one session query the runtime from their own workers: they share the source's kept scene observer
// (one query computes on it at a time) and the chunks it served. Each result's JSON and placement index, built at
// their first use, are asked for from two threads at once, and both get the same answer.
TEST(LayerConcurrency, AnalyzersOfOneSessionShareTheRuntimeQueryAndTheResultsLazyParts) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_MSFT_scene_understanding"));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  std::atomic<int> failures{0}, completed{0};
  const auto read_json = [&](XrRoomAnalyzerEXTX a) {
    XrRoomAnalysisJsonEXTX json{XR_TYPE_ROOM_ANALYSIS_JSON_EXTX, nullptr};
    XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, &json};
    if (app.extx.layout(a, &layout) != XR_SUCCESS) return std::string();
    std::vector<char> text(json.jsonCountOutput);
    json.jsonCapacityInput = json.jsonCountOutput;
    json.json = text.data();
    if (app.extx.layout(a, &layout) != XR_SUCCESS || text.empty()) return std::string();
    return std::string(text.data());
  };
  const auto placements = [&](XrRoomAnalyzerEXTX a) {
    XrRoomPlacementQueryEXTX q{XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX, nullptr};
    q.objectSize = {0.3f, 0.3f, 0.3f};
    q.surfaces = XR_ROOM_SURFACE_FLOOR_BIT_EXTX;
    q.maxPlacements = 3;
    XrRoomPlacementsEXTX out{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
    return app.extx.place(a, &q, &out) == XR_SUCCESS ? int(out.placementCountOutput) : -1;
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads / 2; ++t)
    threads.emplace_back([&] {
      const XrRoomAnalyzerEXTX a = app.analyzer();
      for (int round = 0; round < 2; ++round) {
        if (app.compute(a, true) != XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) {
          ++failures;
          continue;
        }
        std::string json[2];
        int found[2] = {-1, -1};
        std::thread other([&] { json[1] = read_json(a), found[1] = placements(a); });
        json[0] = read_json(a), found[0] = placements(a);
        other.join();
        if (json[0].empty() || json[0] != json[1] || found[0] <= 0 || found[0] != found[1]) ++failures;
        else ++completed;
      }
      if (app.extx.destroy(a) != XR_SUCCESS) ++failures;
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(completed.load(), kThreads);
}

TEST(LayerConcurrency, SessionDestroyedUnderEightRunningAnalyses) {
  App app;
  for (int round = 0; round < 2; ++round) {
    std::vector<XrRoomAnalyzerEXTX> analyzers;
    for (int t = 0; t < kThreads; ++t) {
      const XrRoomAnalyzerEXTX a = app.analyzer();
      app.submit(a, default_room().vertices, default_room().indices);
      app.start(a, false);
      analyzers.push_back(a);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(3 * round));
    app.close_session();  // stops and waits for every analysis
    XrRoomComputeStateEXTX state;
    for (const XrRoomAnalyzerEXTX a : analyzers) EXPECT_EQ(app.extx.state(a, &state), XR_ERROR_HANDLE_INVALID);
    app.open_session();
  }
}

// Contexts, discoveries, queries, entities and update snapshots on 8 threads, events polled meanwhile, while the
// layer's analysis thread looks at the runtime's meshes every 100 ms; then the session goes away with discoveries
// pending on every thread's context.
TEST(LayerConcurrency, SpatialEntitiesOnEightThreads) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_META_spatial_entity_mesh"));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv interval("ROOMSENSE_SPATIAL_INTERVAL_MS", std::string("100"));
  auto app = std::make_unique<SpatialClient>();
  std::atomic<int> failures{0}, planes_seen{0};
  std::atomic<bool> done{false};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&] {
      for (int round = 0; round < 3; ++round) {
        const ContextSteps c = app->create_context(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, kPlaneComponents);
        if (!c.ok()) {
          ++failures;
          return;
        }
        const SnapshotSteps d = app->discover(c.context);
        if (!d.ok()) ++failures;
        const SpatialQuery q = app->query(d.snapshot, {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT});
        if (q.result != XR_SUCCESS) ++failures;
        planes_seen += static_cast<int>(q.ids.size());
        std::vector<XrSpatialEntityEXT> entities;
        for (XrSpatialEntityIdEXT id : q.ids) {
          XrSpatialEntityEXT e = XR_NULL_HANDLE;
          if (app->entity(c.context, id, e) == XR_SUCCESS) entities.push_back(e);
        }
        XrSpatialSnapshotEXT update = XR_NULL_HANDLE;
        if (!entities.empty() && app->update(c.context, entities, {}, update) == XR_SUCCESS) app->fn.destroySnapshot(update);
        if (app->fn.destroySnapshot(d.snapshot) != XR_SUCCESS) ++failures;
        if (round < 2) {
          if (app->fn.destroyContext(c.context) != XR_SUCCESS) ++failures;
        } else {
          // Left for the session to take down, with a discovery pending.
          if (app->start_discovery(c.context, {}).start != XR_SUCCESS) ++failures;
        }
      }
    });
  std::thread events([&] {
    while (!done) {
      XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
      const XrResult r = xrPollEvent(app->instance, &event);
      if (r != XR_SUCCESS && r != XR_EVENT_UNAVAILABLE) ++failures;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  for (std::thread& t : threads) t.join();
  done = true;
  events.join();
  app.reset();  // session and instance destroyed with a discovery pending on every context
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(planes_seen.load(), 0);
}

}  // namespace
