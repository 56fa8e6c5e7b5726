// Both C APIs under concurrent use, for ThreadSanitizer (scripts/tsan.sh; ctest label `concurrency`) as much as
// for their results: the handle API on 8 threads sharing one analyzer (getters during computes, computes racing
// for BUSY), 8 analyzers on 8 threads, analyzers destroyed while they compute on 8 threads, and the thesis API's
// Retrieve functions polled from 8 threads while both jobs run and while a CleanUp waits for a worker, and the
// placement queries on 8 threads while computes replace the result they query.
// Everything uses the C box room (box_room.h), a point cloud that computes in milliseconds.
#include "roomsense/RoomCreatorLibrary.h"
#include "roomsense/roomsense.h"

#include "box_room.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr int kThreads = 8;

struct BoxRoom {
  std::vector<float> xyz;
  uint32_t count = 0;
  BoxRoom() {
    int n = 0;
    float* p = box_room(&n, 1);
    xyz.assign(p, p + 3 * static_cast<std::size_t>(n));
    std::free(p);
    count = static_cast<uint32_t>(n);
  }
};

const BoxRoom& room() {
  static const BoxRoom r;
  return r;
}

struct Analyzer {
  rs_analyzer* a = nullptr;
  explicit Analyzer(uint32_t threads = 0) {
    rs_analyzer_options o;
    rs_analyzer_options_init(&o);
    o.thread_count = threads;
    EXPECT_EQ(rs_analyzer_create(&o, &a), RS_SUCCESS);
  }
  ~Analyzer() { rs_analyzer_destroy(a); }
  Analyzer(const Analyzer&) = delete;
  Analyzer& operator=(const Analyzer&) = delete;
};

// What one full read of an analyzer's result gives, for comparing threads' views.
struct Snapshot {
  rs_result result = RS_SUCCESS;
  uint32_t areas = 0, bounds_vertices = 0, bounds_indices = 0;
  float floor_y = 0.0f, ceiling_y = 0.0f;
};

// Reads everything with the two-call idiom. Between two calls a new compute may finish or start, so the second
// call may say NOT_READY, or SIZE_INSUFFICIENT when the count changed (never here: every compute has the same
// input). Any other error is a failure.
Snapshot read_all(rs_analyzer* a, std::atomic<int>& failures) {
  Snapshot s;
  auto bad = [&](rs_result r) {
    return r != RS_SUCCESS && r != RS_ERROR_NOT_READY && r != RS_ERROR_NO_RESULT;
  };
  rs_state state = RS_STATE_MAX_ENUM;
  if (rs_analyzer_state(a, &state) != RS_SUCCESS || state > RS_STATE_FAILED) ++failures;
  auto layout = std::make_unique<rs_layout>();
  s.result = rs_analyzer_get_layout(a, layout.get());
  if (bad(s.result)) ++failures;
  if (s.result != RS_SUCCESS) return s;
  s.floor_y = layout->floor_y, s.ceiling_y = layout->ceiling_y;
  // Each second call only after a successful first one: its count sizes the buffer.
  rs_result r = rs_analyzer_get_areas(a, 0, &s.areas, nullptr);
  if (bad(r)) ++failures;
  if (r != RS_SUCCESS) s.result = r;  // a new compute started after the layout: not a full read
  if (r == RS_SUCCESS) {
    std::vector<rs_area> areas(s.areas + 1);
    uint32_t n = 0;
    r = rs_analyzer_get_areas(a, static_cast<uint32_t>(areas.size()), &n, areas.data());
    if (bad(r) || (r == RS_SUCCESS && n != s.areas)) ++failures;
  }
  r = rs_analyzer_get_bounds(a, 0, &s.bounds_vertices, nullptr, 0, &s.bounds_indices, nullptr);
  if (bad(r)) ++failures;
  if (r == RS_SUCCESS) {
    std::vector<float> xyz(3 * std::size_t{s.bounds_vertices} + 3);
    std::vector<uint32_t> idx(s.bounds_indices + 1);
    uint32_t vc = 0, ic = 0;
    r = rs_analyzer_get_bounds(a, s.bounds_vertices + 1, &vc, xyz.data(), s.bounds_indices + 1, &ic, idx.data());
    if (bad(r)) ++failures;
  }
  uint32_t chars = 0;
  r = rs_analyzer_get_message(a, 0, &chars, nullptr);
  if (bad(r)) ++failures;
  if (r == RS_SUCCESS) {
    std::string message(chars + 16, '\0');
    r = rs_analyzer_get_message(a, static_cast<uint32_t>(message.size()), &chars, message.data());
    if (bad(r)) ++failures;
  }
  return s;
}

TEST(CapiConcurrency, HandleGettersOnEightThreadsDuringComputes) {
  Analyzer an(2);
  ASSERT_NE(an.a, nullptr);
  std::atomic<bool> done{false};
  std::atomic<int> failures{0}, full_reads{0}, busy{0};
  std::atomic<uint32_t> areas_seen{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      while (!done.load()) {
        if (t == 0) {  // one thread also tries to start computes, every few milliseconds: BUSY while one runs
          const rs_result r = rs_analyzer_compute(an.a, room().xyz.data(), room().count, nullptr, 0);
          if (r == RS_ERROR_BUSY) ++busy;
          else if (r != RS_SUCCESS) ++failures;
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        const Snapshot s = read_all(an.a, failures);
        if (s.result == RS_SUCCESS) {
          ++full_reads;
          uint32_t expected = 0;
          if (!areas_seen.compare_exchange_strong(expected, s.areas) && expected != s.areas) ++failures;
        }
      }
    });
  for (int round = 0; round < 3; ++round) {
    rs_state state = RS_STATE_IDLE;
    const rs_result r = rs_analyzer_compute(an.a, room().xyz.data(), room().count, nullptr, 0);
    EXPECT_TRUE(r == RS_SUCCESS || r == RS_ERROR_BUSY) << rs_result_string(r);
    EXPECT_EQ(rs_analyzer_wait(an.a, 120000, &state), RS_SUCCESS);
    // Thread 0 may start the next compute between the wait and its state read: RUNNING is fine too.
    EXPECT_TRUE(state == RS_STATE_READY || state == RS_STATE_RUNNING) << state;
  }
  done = true;
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(full_reads.load(), 0);
  EXPECT_GT(areas_seen.load(), 0u);
  std::printf("[ figures  ] %d full reads, %d computes refused as busy\n", full_reads.load(), busy.load());
}

TEST(CapiConcurrency, HandleEightAnalyzersOnEightThreads) {
  std::atomic<int> failures{0};
  std::vector<Snapshot> results(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      Analyzer an(t % 3);  // 0 (all hardware threads), 1 or 2 pipeline threads: results do not depend on it
      rs_state state = RS_STATE_IDLE;
      if (rs_analyzer_compute(an.a, room().xyz.data(), room().count, nullptr, 0) != RS_SUCCESS ||
          rs_analyzer_wait(an.a, RS_WAIT_INFINITE, &state) != RS_SUCCESS || state != RS_STATE_READY)
        ++failures;
      results[t] = read_all(an.a, failures);
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(results[t].result, RS_SUCCESS);
    EXPECT_GT(results[t].areas, 0u);
    EXPECT_EQ(results[t].areas, results[0].areas) << "thread " << t;
    EXPECT_EQ(results[t].bounds_vertices, results[0].bounds_vertices) << "thread " << t;
    EXPECT_EQ(results[t].floor_y, results[0].floor_y) << "thread " << t;
  }
}

TEST(CapiConcurrency, HandleDestroyedWhileComputingOnEightThreads) {
  std::vector<std::thread> threads;
  std::atomic<int> failures{0};
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 3; ++round) {
        rs_analyzer* a = nullptr;
        if (rs_analyzer_create(nullptr, &a) != RS_SUCCESS) {
          ++failures;
          continue;
        }
        if (rs_analyzer_compute(a, room().xyz.data(), room().count, nullptr, 0) != RS_SUCCESS) ++failures;
        if ((t + round) % 2 == 1) std::this_thread::sleep_for(std::chrono::milliseconds(t + round));
        rs_analyzer_destroy(a);  // waits for the worker
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
}

// API 1.3: chunks set and removed on four threads while four others compute the chunks and read the result:
// every compute that starts ends READY (the box room's halves are each a room), and the chunks a compute
// applies never race the ones being set. Then destroyed while a compute of chunks runs.
TEST(CapiConcurrency, HandleChunksSetOnFourThreadsWhileFourCompute) {
  Analyzer an;
  // Chunk 0: the whole box room; chunks 1..4: copies of it, set and removed.
  ASSERT_EQ(rs_analyzer_set_chunk(an.a, 0, room().xyz.data(), room().count, nullptr, 0), RS_SUCCESS);
  std::vector<std::thread> threads;
  std::atomic<int> failures{0};
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 6; ++round) {
        if (t < kThreads / 2) {
          const uint64_t id = 1 + uint64_t(t);
          if (rs_analyzer_set_chunk(an.a, id, room().xyz.data(), room().count, nullptr, 0) != RS_SUCCESS) ++failures;
          const rs_result removed = rs_analyzer_remove_chunk(an.a, id);
          if (removed != RS_SUCCESS) ++failures;
          continue;
        }
        const rs_result started = rs_analyzer_compute_chunks(an.a);
        if (started != RS_SUCCESS && started != RS_ERROR_BUSY) ++failures;
        rs_state state = RS_STATE_IDLE;
        if (rs_analyzer_wait(an.a, RS_WAIT_INFINITE, &state) != RS_SUCCESS || state != RS_STATE_READY) ++failures;
        uint32_t count = 0;
        const rs_result got = rs_analyzer_get_areas(an.a, 0, &count, nullptr);
        if (got != RS_SUCCESS && got != RS_ERROR_NOT_READY) ++failures;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(rs_analyzer_compute_chunks(an.a), RS_SUCCESS);  // ~Analyzer destroys it while it may still run
}

// Queries copy the result's RoomQueries out under the job's lock and run outside it: a compute that replaces the
// result meanwhile must neither race them nor change an answer (the same room, so the same placements).
TEST(CapiConcurrency, HandleQueriesOnEightThreadsDuringComputes) {
  rs_analyzer* a = nullptr;
  ASSERT_EQ(rs_analyzer_create(nullptr, &a), RS_SUCCESS);
  ASSERT_EQ(rs_analyzer_compute(a, room().xyz.data(), room().count, nullptr, 0), RS_SUCCESS);
  ASSERT_EQ(rs_analyzer_wait(a, RS_WAIT_INFINITE, nullptr), RS_SUCCESS);
  rs_placement_query q;
  rs_placement_query_init(&q);
  q.surfaces = RS_SURFACE_FLOOR | RS_SURFACE_FURNITURE;
  q.max_count = 4;
  rs_placement expected[4];
  uint32_t expected_count = 0;
  ASSERT_EQ(rs_analyzer_find_placements(a, &q, 4, &expected_count, expected, nullptr), RS_SUCCESS);
  ASSERT_EQ(expected_count, 4u);

  std::atomic<bool> done{false};
  std::atomic<int> answered{0}, bad{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      const rs_vec3 origin{BOX_CX, 0.0f, BOX_CZ}, down{0.0f, -1.0f, 0.0f};
      while (!done.load()) {
        if (t % 2 == 0) {
          rs_placement got[4];
          uint32_t count = 0;
          const rs_result r = rs_analyzer_find_placements(a, &q, 4, &count, got, nullptr);
          if (r == RS_SUCCESS) {
            ++answered;
            if (count != expected_count || std::memcmp(got, expected, sizeof got) != 0) ++bad;
          } else if (r != RS_ERROR_NOT_READY) {
            ++bad;
          }
        } else {
          rs_ray_hit hit{};
          const rs_result r = rs_analyzer_raycast(a, &origin, &down, 0.0f, &hit);
          if (r == RS_SUCCESS) {
            ++answered;
            if (!hit.hit || hit.surface != RS_AREA_TYPE_FLOOR) ++bad;
          } else if (r != RS_ERROR_NOT_READY) {
            ++bad;
          }
        }
      }
    });
  for (int round = 0; round < 6; ++round) {
    EXPECT_EQ(rs_analyzer_compute(a, room().xyz.data(), room().count, nullptr, 0), RS_SUCCESS);
    EXPECT_EQ(rs_analyzer_wait(a, RS_WAIT_INFINITE, nullptr), RS_SUCCESS);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  done = true;
  for (auto& t : threads) t.join();
  EXPECT_EQ(bad.load(), 0);
  EXPECT_GT(answered.load(), 0);
  rs_analyzer_destroy(a);
}

// The thesis API's two jobs, each polled from 8 threads: every thread sees -1 until the job is done, then the
// same array. A CleanUp called while the job runs waits for its worker while the readers keep polling.
TEST(CapiConcurrency, ThesisRetrieveOnEightThreadsWhileBothJobsRun) {
  const std::vector<float>& xyz = room().xyz;
  const int size = static_cast<int>(xyz.size());
  for (int round = 0; round < 2; ++round) {
    ASSERT_EQ(StartRoomUnderstanding(xyz.data(), size), 0);
    ASSERT_EQ(StartRoomBounds(xyz.data(), size), 0);
    std::atomic<int> failures{0};
    std::atomic<float*> areas_seen{nullptr}, mesh_seen{nullptr};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        const bool bounds = t % 2 == 1;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
        for (;;) {
          int code = 99, a = 0, b = 0;
          float* p = bounds ? RetrieveRoomBounds(&code, &a, &b) : RetrieveRoomUnderstanding(&code, &a);
          if (code == -1) {
            if (std::chrono::steady_clock::now() > deadline) {
              ++failures;
              return;
            }
            std::this_thread::yield();
            continue;
          }
          if (code != 0 || p == nullptr) {
            ++failures;
            return;
          }
          float* expected = nullptr;
          std::atomic<float*>& seen = bounds ? mesh_seen : areas_seen;
          if (!seen.compare_exchange_strong(expected, p) && expected != p) ++failures;
          return;
        }
      });
    for (auto& t : threads) t.join();
    EXPECT_EQ(failures.load(), 0) << "round " << round;
    EXPECT_EQ(CleanUpRoomUnderstanding(), 0);
    EXPECT_EQ(CleanUpRoomBounds(), 0);
  }
  // CleanUp while the jobs run, with readers polling meanwhile: they see -1, then 1 (no job), never a crash.
  ASSERT_EQ(StartRoomUnderstanding(xyz.data(), size), 0);
  ASSERT_EQ(StartRoomBounds(xyz.data(), size), 0);
  std::atomic<bool> done{false};
  std::atomic<int> bad{0};
  std::vector<std::thread> readers;
  for (int t = 0; t < kThreads; ++t)
    readers.emplace_back([&, t] {
      while (!done.load()) {
        int code = 99, a = 0, b = 0;
        if (t % 2) RetrieveRoomBounds(&code, &a, &b);
        else RetrieveRoomUnderstanding(&code, &a);
        if (code != -1 && code != 0 && code != 1) ++bad;
        std::this_thread::yield();
      }
    });
  EXPECT_EQ(CleanUpRoomUnderstanding(), 0);
  EXPECT_EQ(CleanUpRoomBounds(), 0);
  done = true;
  for (auto& t : readers) t.join();
  EXPECT_EQ(bad.load(), 0);
  int code = 99, n = 0;
  EXPECT_EQ(RetrieveRoomUnderstanding(&code, &n), nullptr);
  EXPECT_EQ(code, 1);
}

}  // namespace
