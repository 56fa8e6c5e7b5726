// The thesis C API (roomsense/RoomCreatorLibrary.h: six functions, two global jobs on worker threads) driven by
// a sequence of calls decoded from the bytes: starts with valid, odd, zero, negative sizes and NULL arrays,
// retrieves with NULL outputs, clean-ups at any time (also while a job runs), polls until done. Every returned
// array is read in full (ASan checks its length) and checked against the header's contract. Both jobs are
// cleaned up at the end, so that each input starts from idle.
//   op (u8 % 8), then its arguments; at most 24 ops. Point clouds: capi_points.h.
#include "capi_points.h"
#include "roomsense/RoomCreatorLibrary.h"

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

using roomsense::fuzz::FuzzInput;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_capi_thesis: contract broken: %s\n", what);
    std::abort();
  }
}

int start(FuzzInput& in, int (*fn)(const float*, int)) {
  const std::uint8_t how = in.u8();
  const std::size_t count = in.u16() % 3073;  // floats, up to 1024 vertices
  std::vector<float> xyz = roomsense::fuzz::floats(in, count);
  const float* data = (how & 1) ? nullptr : xyz.data();
  int size = static_cast<int>(count);
  switch ((how >> 1) % 4) {  // sizes that promise no more floats than there are
    case 1: size = 0; break;
    case 2: size = -static_cast<int>(count) - 1; break;
    case 3: size = INT_MIN; break;
    default: break;
  }
  const int code = fn(data, size);
  check(code == 0 || code == 1 || code == 2 || code == 4, "Start returns 0, 1, 2 or 4");
  if (data == nullptr || size < 1) check(code == 1, "Start returns 1 for NULL or a size below 1");
  else if (size % 3 != 0) check(code == 2, "Start returns 2 for a size not a multiple of 3");
  return code;
}

void retrieve_understanding(FuzzInput& in) {
  const std::uint8_t how = in.u8();
  int code = 99, size = 99;
  float* areas = RetrieveRoomUnderstanding((how & 1) ? nullptr : &code, (how & 2) ? nullptr : &size);
  if ((how & 3) != 0) return;
  check(code == -1 || code == 0 || code == 1, "Retrieve code -1, 0 or 1");
  if (code != 0) {
    check(areas == nullptr && size == 0, "NULL and size 0 without a result");
    return;
  }
  check(areas != nullptr && size >= 0 && size % 11 == 0, "11 floats per area, never NULL");
  for (int i = 0; i < size; i += 11) {
    const int flags = static_cast<int>(areas[i + 10]);
    check((flags & 7) != 0 && (flags & (8 | 16 | 32)) != 0 && (flags & (64 | 128 | 256 | 512)) != 0, "Eq. 3.58 flags");
  }
}

void retrieve_bounds(FuzzInput& in) {
  const std::uint8_t how = in.u8();
  int code = 99, vsize = 99, tsize = 99;
  float* mesh = RetrieveRoomBounds((how & 1) ? nullptr : &code, (how & 2) ? nullptr : &vsize, (how & 4) ? nullptr : &tsize);
  if ((how & 7) != 0) return;
  check(code == -1 || code == 0 || code == 1, "Retrieve code -1, 0 or 1");
  if (code != 0) {
    check(mesh == nullptr && vsize == 0 && tsize == 0, "NULL and sizes 0 without a result");
    return;
  }
  check(mesh != nullptr && vsize >= 0 && tsize >= 0 && vsize % 3 == 0 && tsize % 3 == 0, "whole vertices and triangles");
  for (int i = 0; i < tsize; ++i) {
    const float f = mesh[vsize + i];
    check(f >= 0.0f && static_cast<int>(f) < vsize / 3, "bounds index in range");
  }
}

// Polls until the job is not running; a job that never finishes is a hang (libFuzzer's -timeout reports it).
void wait_for(bool bounds) {
  for (;;) {
    int code = 0, a = 0, b = 0;
    if (bounds) RetrieveRoomBounds(&code, &a, &b);
    else RetrieveRoomUnderstanding(&code, &a);
    if (code != -1) return;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput in(data, size);
  for (int op = 0; op < 24 && !in.empty(); ++op) {
    switch (in.u8() % 8) {
      case 0: start(in, StartRoomUnderstanding); break;
      case 1: start(in, StartRoomBounds); break;
      case 2: retrieve_understanding(in); break;
      case 3: retrieve_bounds(in); break;
      case 4: check(CleanUpRoomUnderstanding() == 0, "CleanUp returns 0"); break;
      case 5: check(CleanUpRoomBounds() == 0, "CleanUp returns 0"); break;
      case 6: wait_for(false); break;
      case 7: wait_for(true); break;
    }
  }
  check(CleanUpRoomUnderstanding() == 0 && CleanUpRoomBounds() == 0, "CleanUp returns 0");
  int code = 0, n = 0, m = 0;
  check(RetrieveRoomUnderstanding(&code, &n) == nullptr && code == 1, "idle after CleanUp");
  check(RetrieveRoomBounds(&code, &n, &m) == nullptr && code == 1, "idle after CleanUp");
  return 0;
}
