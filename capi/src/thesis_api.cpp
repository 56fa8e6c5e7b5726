// The thesis-compatible C API (thesis §3.8): six functions over two global jobs, room understanding and
// room bounds. The globals are function-local statics, created on first use and ended at exit
// (platform::ProcessWide); they are the only globals of the library (the handle API has none). Semantics and the
// frame are documented in RoomCreatorLibrary.h.
#include "roomsense/RoomCreatorLibrary.h"

#include "job.h"
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/platform.h"
#include "roomsense/scan.h"

#include <climits>
#include <utility>
#include <vector>

namespace roomsense::capi {
namespace {

constexpr int kOk = 0;
constexpr int kNoInput = 1;             // thesis: no input array, or a size below 1
constexpr int kSizeNotMultipleOf3 = 2;
constexpr int kBusy = 4;
constexpr int kRunning = -1;            // Retrieve: not finished yet
constexpr int kNoResult = 1;            // Retrieve: finished without a result

constexpr int kFloatsPerArea = 11;
constexpr int kFloatsPerPlace = 2;      // RetrieveRoomUnderstandingPlaces
// Bounds indices travel as floats; every integer below 2^24 is exact in a float.
constexpr std::size_t kMaxExactFloatIndex = std::size_t{1} << 24;

// What a finished job hands to Retrieve. The default is "no result", what a job that threw holds.
struct ThesisOutput {
  int code = kNoResult;
  std::vector<float> data;  // never empty-capacity when code is kOk, so data() is not null
  int first_size = 0;       // understanding: the array size; bounds: the vertex part
  int second_size = 0;      // bounds: the triangle part
};

Job<ThesisOutput>& understanding_job() {
  static platform::ProcessWide<Job<ThesisOutput>> held;  // ended at exit, not on Windows: ProcessWide says why
  return held.value;
}

Job<ThesisOutput>& bounds_job() {
  static platform::ProcessWide<Job<ThesisOutput>> held;  // ended at exit, not on Windows: ProcessWide says why
  return held.value;
}

// The 11 floats of one area, in the thesis's order (§3.8). Coordinates pass through: see "Frame" in
// RoomCreatorLibrary.h for why the rotation keeps its value in Unity's left-handed frame.
void append_area(std::vector<float>& out, const Area& a) {
  out.insert(out.end(), {a.center.x, a.center.y, a.center.z, a.normal.x, a.normal.y, a.normal.z, a.half_height,
                         a.half_width, a.rotation_deg, a.volume_height, static_cast<float>(a.flags)});
}

ThesisOutput understand(const Scan& scan, std::stop_token stop) {
  AnalysisOptions options;
  options.stop = std::move(stop);
  options.build_bounds = false;
  const AnalysisResult result = analyze(scan, options);
  ThesisOutput out;
  if (!result.ok()) return out;
  if (result.areas.size() > std::size_t(INT_MAX / (kFloatsPerArea + kFloatsPerPlace))) return out;
  // The thesis's array, then (beyond the thesis) each area's storey and room: RetrieveRoomUnderstandingPlaces.
  out.data.reserve(result.areas.size() * (kFloatsPerArea + kFloatsPerPlace) + 1);  // + 1: a valid pointer for zero areas
  for (const Area& area : result.areas) append_area(out.data, area);
  out.first_size = static_cast<int>(out.data.size());
  for (const Area& area : result.areas)
    out.data.insert(out.data.end(), {static_cast<float>(area.storey), static_cast<float>(area.room)});
  out.second_size = static_cast<int>(out.data.size()) - out.first_size;
  out.code = kOk;
  return out;
}

ThesisOutput bound(const Scan& scan, std::stop_token stop) {
  AnalysisOptions options;
  options.stop = std::move(stop);
  options.find_areas = false;
  options.area_features = false;  // the bounds alone are returned
  const AnalysisResult result = analyze(scan, options);
  ThesisOutput out;
  if (!result.ok()) return out;
  const BoundsMesh& mesh = result.bounds;
  const std::size_t floats = mesh.vertices.size() * 3 + mesh.indices.size();
  if (mesh.vertices.size() >= kMaxExactFloatIndex || floats > std::size_t(INT_MAX)) return out;
  out.data.reserve(floats + 1);
  for (const glm::vec3& v : mesh.vertices) out.data.insert(out.data.end(), {v.x, v.y, v.z});
  for (const std::uint32_t i : mesh.indices) out.data.push_back(static_cast<float>(i));
  out.first_size = static_cast<int>(mesh.vertices.size() * 3);
  out.second_size = static_cast<int>(mesh.indices.size());
  out.code = kOk;
  return out;
}

int start(Job<ThesisOutput>& job, const float* positions, int size, ThesisOutput (*work)(const Scan&, std::stop_token)) {
  // Input checks first, without touching the job: bad input is reported as such even while it is busy.
  if (positions == nullptr || size < 1) return kNoInput;
  if (size % 3 != 0) return kSizeNotMultipleOf3;
  if (job.phase() != JobPhase::Idle) return kBusy;
  Scan scan;
  try {
    scan = scan_from_flat_array(positions, size);  // the copy the worker owns
  } catch (const Error& e) {
    return e.code() == ErrorCode::SizeNotMultipleOfThree ? kSizeNotMultipleOf3 : kNoInput;
  } catch (...) {  // out of memory: the job "finished with an internal error", as the thesis reports it
    return job.finish_now(ThesisOutput{}) ? kOk : kBusy;
  }
  try {
    return job.start([work, scan = std::move(scan)](std::stop_token stop) { return work(scan, std::move(stop)); }, /*replace_result=*/false) ? kOk
                                                                                                       : kBusy;
  } catch (...) {  // no thread, or no memory for the closure
    return job.finish_now(ThesisOutput{}) ? kOk : kBusy;
  }
}

float* retrieve(Job<ThesisOutput>& job, int* error_code, int* first_size, int* second_size) {
  int code = kNoResult, first = 0, second = 0;
  float* data = nullptr;
  try {
    job.inspect([&](JobPhase phase, ThesisOutput* out) {
      if (phase == JobPhase::Running) {
        code = kRunning;
      } else if (phase == JobPhase::Done && out != nullptr && out->code == kOk) {
        code = kOk;
        first = out->first_size;
        second = out->second_size;
        data = out->data.data();
      }
    });
  } catch (...) {  // a lock that failed: report "no result"
    code = kNoResult;
    first = second = 0;
    data = nullptr;
  }
  if (error_code != nullptr) *error_code = code;
  if (first_size != nullptr) *first_size = first;
  if (second_size != nullptr) *second_size = second;
  return data;
}

int clean_up(Job<ThesisOutput>& job) {
  try {
    job.clear();
  } catch (...) {  // only a failing lock or join could throw; nothing more to do about it here
  }
  return kOk;
}

}  // namespace
}  // namespace roomsense::capi

using namespace roomsense::capi;

extern "C" {

int StartRoomUnderstanding(const float* VertexPositions, int ArraySize) {
  try {
    return start(understanding_job(), VertexPositions, ArraySize, understand);
  } catch (...) {
    return kNoInput;  // unreachable: start catches what it can cause; nothing may cross the C boundary
  }
}

float* RetrieveRoomUnderstanding(int* OutErrorCode, int* OutArraySize) {
  try {
    return retrieve(understanding_job(), OutErrorCode, OutArraySize, nullptr);
  } catch (...) {
    return nullptr;
  }
}

float* RetrieveRoomUnderstandingPlaces(int* OutErrorCode, int* OutArraySize) {
  try {
    int areas_size = 0;
    float* const areas = retrieve(understanding_job(), OutErrorCode, &areas_size, OutArraySize);
    return areas == nullptr ? nullptr : areas + areas_size;
  } catch (...) {
    return nullptr;
  }
}

int CleanUpRoomUnderstanding(void) {
  try {
    return clean_up(understanding_job());
  } catch (...) {
    return kOk;
  }
}

int StartRoomBounds(const float* VertexPositions, int ArraySize) {
  try {
    return start(bounds_job(), VertexPositions, ArraySize, bound);
  } catch (...) {
    return kNoInput;
  }
}

float* RetrieveRoomBounds(int* OutErrorCode, int* OutVertexSize, int* OutTriangleSize) {
  try {
    return retrieve(bounds_job(), OutErrorCode, OutVertexSize, OutTriangleSize);
  } catch (...) {
    return nullptr;
  }
}

int CleanUpRoomBounds(void) {
  try {
    return clean_up(bounds_job());
  } catch (...) {
    return kOk;
  }
}

}  // extern "C"
