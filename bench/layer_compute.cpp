// xrComputeRoomEXTX as an application sees it: from the call to COMPLETED, through the Khronos loader, the layer and
// the simulated runtime (its scene work completing at once), on synthetic:thesis-room1 served in 2 m chunks, for
// each headset the runtime plays. Two cases per headset:
//   layer_compute/unchanged/HEADSET: the runtime's meshes and the submitted ones as at the last compute (the layer
//     queries the runtime and answers with the previous result);
//   layer_compute/changed/HEADSET: after the application submitted one more small mesh (a 10 cm square, standing,
//     away from the walls), with the runtime's meshes as they were: the analysis is an update. After each such
//     compute, one placement query (a 0.3 m object on a wall or the floor) is timed apart: the first use of a new
//     result, which builds its placement index (place_p50_ms, place_p90_ms).
//   layer_compute/scanning/HEADSET: the room being scanned over 3 s (ROOMSENSE_SIM_SCAN_SECONDS, for the headsets
//     that mesh live): one compute every 50 ms, each taking in the chunks that appeared or were refined since the
//     last (failed: those before enough of the room was scanned for a room).
// Each iteration is one compute; p50_ms and p90_ms are over the run's iterations, which are fixed (each changed
// compute adds a submitted mesh).
//
//   build/bench/roomsense_bench_layer --benchmark_filter=layer_compute
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <benchmark/benchmark.h>

#include "headless_session.h"
#include "percentiles.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using roomsense::bench::check;

XrTime now() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

enum class Room { Unchanged, Changed, Scanning };
constexpr double kScanSeconds = 3.0;
constexpr int kComputes = 60;

void layer_compute(benchmark::State& state, const char* extension, Room room) {
  const bool changed = room == Room::Changed;
  unsetenv("DISABLE_XR_APILAYER_ROOMSENSE");
  if (room == Room::Scanning)
    setenv("ROOMSENSE_SIM_SCAN_SECONDS", std::to_string(kScanSeconds).c_str(), 1);
  else
    unsetenv("ROOMSENSE_SIM_SCAN_SECONDS");
  setenv("ROOMSENSE_SIM_EXTENSIONS", extension, 1);
  setenv("ROOMSENSE_SIM_SCENE", "synthetic:thesis-room1", 1);
  setenv("ROOMSENSE_SIM_COMPUTE_DELAY_MS", "0", 1);
  const auto scan_start = std::chrono::steady_clock::now();  // no later than the instance's creation
  const roomsense::bench::HeadlessSession app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME});
  const auto create = app.proc<PFN_xrCreateRoomAnalyzerEXTX>("xrCreateRoomAnalyzerEXTX");
  const auto compute = app.proc<PFN_xrComputeRoomEXTX>("xrComputeRoomEXTX");
  const auto get_state = app.proc<PFN_xrGetRoomComputeStateEXTX>("xrGetRoomComputeStateEXTX");
  const auto submit = app.proc<PFN_xrSubmitRoomMeshEXTX>("xrSubmitRoomMeshEXTX");
  const auto find_placements = app.proc<PFN_xrFindRoomPlacementsEXTX>("xrFindRoomPlacementsEXTX");
  const XrRoomAnalyzerCreateInfoEXTX analyzer_info{XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, nullptr, app.local, 0.0f,
                                                   XR_ROOM_COMPUTE_BACKEND_CPU_EXTX};
  XrRoomAnalyzerEXTX analyzer = XR_NULL_HANDLE;
  check(create(app.session, &analyzer_info, &analyzer), "xrCreateRoomAnalyzerEXTX");
  // One compute, timed from the call to COMPLETED; the state is polled every 50 us (not spun: the analysis has
  // the machine's two cores).
  std::size_t failed = 0;
  const auto run = [&] {
    const XrRoomComputeInfoEXTX compute_info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr, now(), XR_TRUE};
    const auto start = std::chrono::steady_clock::now();
    check(compute(analyzer, &compute_info), "xrComputeRoomEXTX");
    XrRoomComputeStateEXTX s = XR_ROOM_COMPUTE_STATE_RUNNING_EXTX;
    for (;;) {
      check(get_state(analyzer, &s), "xrGetRoomComputeStateEXTX");
      if (s != XR_ROOM_COMPUTE_STATE_RUNNING_EXTX) break;
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
    if (s != XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) {
      if (room != Room::Scanning) throw std::runtime_error("the compute failed");
      ++failed;
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  if (room != Room::Scanning) run();  // the whole room, the first time
  // The first placement query on the compute's result, timed from the call to its return.
  const auto place = [&] {
    XrRoomPlacementQueryEXTX query{};
    query.type = XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX;
    query.objectSize = {0.3f, 0.3f, 0.3f};
    query.surfaces = XR_ROOM_SURFACE_WALL_BIT_EXTX | XR_ROOM_SURFACE_FLOOR_BIT_EXTX;
    query.maxPlacements = 1;
    XrRoomPlacementEXTX found{};
    found.type = XR_TYPE_ROOM_PLACEMENT_EXTX;
    XrRoomPlacementsEXTX placements{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr, 1, 0, &found, {}};
    const auto start = std::chrono::steady_clock::now();
    check(find_placements(analyzer, &query, &placements), "xrFindRoomPlacementsEXTX");
    if (placements.placementCountOutput != 1) throw std::runtime_error("no placement found");
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<double> seconds, place_seconds;
  for (auto _ : state) {
    if (room == Room::Scanning) {  // the next compute's slot of the scan
      state.PauseTiming();
      std::this_thread::sleep_until(scan_start + std::chrono::microseconds(
                                                     std::int64_t(1e6 * kScanSeconds * double(seconds.size() + 1) / kComputes)));
      state.ResumeTiming();
    }
    if (changed) {
      state.PauseTiming();
      const float x = -1.0f + 0.1f * float(seconds.size() % 20);
      const XrVector3f v[] = {{x, 1.0f, 0.0f}, {x + 0.1f, 1.0f, 0.0f}, {x + 0.1f, 1.1f, 0.0f}, {x, 1.1f, 0.0f}};
      const uint32_t i[] = {0, 2, 1, 0, 3, 2};
      const XrRoomMeshEXTX mesh{XR_TYPE_ROOM_MESH_EXTX, nullptr, {{0, 0, 0, 1}, {0, 0, 0}}, 4, v, 6, i};
      check(submit(analyzer, &mesh), "xrSubmitRoomMeshEXTX");
      state.ResumeTiming();
    }
    seconds.push_back(run());
    state.SetIterationTime(seconds.back());
    if (changed) {
      state.PauseTiming();
      place_seconds.push_back(place());
      state.ResumeTiming();
    }
  }
  roomsense::bench::set_percentiles(state, std::move(seconds));
  roomsense::bench::set_percentiles(state, std::move(place_seconds), "place_");
  if (room == Room::Scanning) state.counters["failed"] = double(failed);
  unsetenv("ROOMSENSE_SIM_SCAN_SECONDS");
}

#define LAYER_COMPUTE_CASE(mode, name, extension, room) \
  BENCHMARK_CAPTURE(layer_compute, mode/name, extension, room)->UseManualTime()->Iterations(kComputes)->Unit(benchmark::kMillisecond);
#define LAYER_COMPUTE_CASES(name, extension)                    \
  LAYER_COMPUTE_CASE(unchanged, name, extension, Room::Unchanged) \
  LAYER_COMPUTE_CASE(changed, name, extension, Room::Changed)
LAYER_COMPUTE_CASES(hololens2, "XR_MSFT_scene_understanding")
LAYER_COMPUTE_CASES(quest3, "XR_META_spatial_entity_mesh")
LAYER_COMPUTE_CASES(android_xr, "XR_ANDROID_scene_meshing")
LAYER_COMPUTE_CASES(magic_leap2, "XR_ML_world_mesh_detection")
LAYER_COMPUTE_CASE(scanning, hololens2, "XR_MSFT_scene_understanding", Room::Scanning)
LAYER_COMPUTE_CASE(scanning, android_xr, "XR_ANDROID_scene_meshing", Room::Scanning)
LAYER_COMPUTE_CASE(scanning, magic_leap2, "XR_ML_world_mesh_detection", Room::Scanning)

}  // namespace
