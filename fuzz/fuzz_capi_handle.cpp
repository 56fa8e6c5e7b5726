// The handle C API (roomsense/roomsense.h) driven by a sequence of calls decoded from the bytes, on two
// analyzer slots: create with NULL, default, odd and out-of-range options (struct_size, voxel size, enums,
// flags); compute with NULL arrays, index counts that are not whole triangles and indices one past the end;
// every getter with capacities of 0, the count, one less, one more, NULL buffers and NULL counts (buffers are
// heap blocks of exactly the capacity, so ASan sees any write past it); waits, state polls, and destroy at any
// time, also while a compute runs; the placement queries with lengths, counts, enums and points in and out of
// range. Returned values are checked against the header's contract.
//   op (u8 % 13), slot (u8 % 2), then its arguments; at most 24 ops. Point clouds: capi_points.h.
#include "capi_points.h"
#include "roomsense/roomsense.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace {

using roomsense::fuzz::FuzzInput;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_capi_handle: contract broken: %s\n", what);
    std::abort();
  }
}

// RS_SUCCESS or one of the header's errors (rs_result_string knows every one; the list grows).
bool known(rs_result r) { return r == RS_SUCCESS || (r < 0 && std::strcmp(rs_result_string(r), "RS_UNKNOWN_RESULT") != 0); }

void create(FuzzInput& in, rs_analyzer*& slot) {
  rs_analyzer_destroy(slot);
  slot = nullptr;
  const std::uint8_t how = in.u8();
  // Exactly sizeof(rs_analyzer_options) on the heap: a read past the version the caller knows is an ASan report.
  auto options = std::make_unique<rs_analyzer_options>();
  rs_analyzer_options_init(options.get());
  static const std::uint32_t struct_sizes[] = {sizeof(rs_analyzer_options), 0, 4, sizeof(rs_analyzer_options) - 4,
                                               sizeof(rs_analyzer_options) + 4, 0xFFFFFFFFu};
  options->struct_size = struct_sizes[in.u8() % 6];
  static const float voxels[] = {0.0f, 0.1f, 0.25f, 0.5f, 1.0f, 0.05f, 0.0099f, 1.01f, -0.1f,
                                 std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()};
  options->voxel_size = voxels[in.u8() % (sizeof voxels / sizeof voxels[0])];
  options->thread_count = in.u8() % 3;
  const std::uint8_t f = in.u8();
  options->compute_flags = f < 200 ? f % 4 : in.u32();
  const std::uint8_t e = in.u8();
  // Any 32 bits, as a C or C# caller may pass them: stored as raw bits, since a C++ enum may not hold them.
  const std::uint32_t up = e % 2 + ((e & 0x80) ? in.u32() : 0), units = e % 3 + ((e & 0x40) ? in.u32() : 0);
  std::memcpy(&options->up_axis, &up, sizeof up);
  std::memcpy(&options->units, &units, sizeof units);
  options->left_handed = (e & 0x20) ? static_cast<int32_t>(in.u32()) : 0;
  rs_analyzer* out = nullptr;
  const rs_result r = rs_analyzer_create((how & 1) ? nullptr : options.get(), (how & 2) ? nullptr : &out);
  check(known(r), "a known result");
  if (how & 2) {
    check(r == RS_ERROR_INVALID_ARGUMENT, "NULL out is an invalid argument");
    return;
  }
  check((r == RS_SUCCESS) == (out != nullptr), "a handle exactly on success");
  slot = out;
}

// A scan as a caller passes it: up to 1024 vertices, maybe triangles (some indices out of range), maybe NULLs.
struct CallerMesh {
  std::vector<float> xyz;
  std::vector<std::uint32_t> indices;
  const float* xyz_ptr = nullptr;
  const std::uint32_t* index_ptr = nullptr;
  std::uint32_t vertex_count = 0, index_count = 0;
};
CallerMesh caller_mesh(FuzzInput& in) {
  CallerMesh m;
  const std::uint8_t how = in.u8();
  m.vertex_count = in.u16() % 1025;
  m.xyz = roomsense::fuzz::floats(in, 3 * std::size_t{m.vertex_count});
  if (how & 2) {
    const std::uint32_t index_count = in.u16() % 901;
    for (std::uint32_t i = 0; i < index_count; ++i) m.indices.push_back(in.u16() % (m.vertex_count + 1));
  }
  m.xyz_ptr = (how & 1) ? nullptr : m.xyz.data();
  m.index_ptr = (how & 4) ? nullptr : m.indices.data();
  m.index_count = (how & 4) ? 0 : static_cast<std::uint32_t>(m.indices.size());
  return m;
}

// What rs_analyzer_compute and rs_analyzer_set_chunk both check before anything else.
void check_mesh_result(rs_result r, const rs_analyzer* a, const CallerMesh& m) {
  check(known(r), "a known result");
  if (a == nullptr) check(r == RS_ERROR_HANDLE_INVALID, "NULL analyzer");
  else if (m.xyz_ptr == nullptr || m.vertex_count == 0) check(r == RS_ERROR_EMPTY_INPUT || r == RS_ERROR_BUSY, "empty input");
  else if (m.index_count % 3 != 0) check(r == RS_ERROR_BAD_INDICES || r == RS_ERROR_BUSY, "bad index count");
}

void compute(FuzzInput& in, rs_analyzer* a) {
  const CallerMesh m = caller_mesh(in);
  check_mesh_result(rs_analyzer_compute(a, m.xyz_ptr, m.vertex_count, m.index_ptr, m.index_count), a, m);
}

// API 1.3: a chunk of id 0-3 set (or replaced), removed, or the chunks computed.
void chunks(FuzzInput& in, rs_analyzer* a, int op) {
  const std::uint64_t id = in.u8() % 4;
  if (op == 0) {
    const CallerMesh m = caller_mesh(in);
    check_mesh_result(rs_analyzer_set_chunk(a, id, m.xyz_ptr, m.vertex_count, m.index_ptr, m.index_count), a, m);
    return;
  }
  const rs_result r = op == 1 ? rs_analyzer_remove_chunk(a, id) : rs_analyzer_compute_chunks(a);
  check(known(r), "a known result");
  if (a == nullptr) check(r == RS_ERROR_HANDLE_INVALID, "NULL analyzer");
}

// A capacity for a two-call getter: 0, the count, one less, one more, or a small number.
std::uint32_t capacity(FuzzInput& in, std::uint32_t count) {
  switch (in.u8() % 5) {
    case 0: return 0;
    case 1: return count;
    case 2: return count > 0 ? count - 1 : 0;
    case 3: return count + 1;
    default: return in.u8();
  }
}

template <typename T, typename Get>
void two_call(FuzzInput& in, rs_analyzer* a, Get get) {
  const std::uint8_t how = in.u8();
  std::uint32_t count = 0;
  rs_result r = get(a, 0u, &count, static_cast<T*>(nullptr));
  check(known(r), "a known result");
  if (r != RS_SUCCESS) return;
  const std::uint32_t cap = capacity(in, count);
  std::unique_ptr<T[]> buffer(cap > 0 && !(how & 1) ? new T[cap] : nullptr);
  std::uint32_t got = 12345;
  r = get(a, cap, (how & 2) ? nullptr : &got, buffer.get());
  check(known(r), "a known result");
  if (how & 2) {
    check(r != RS_SUCCESS, "NULL count is refused");
  } else if (cap > 0 && buffer == nullptr) {
    check(r != RS_SUCCESS, "NULL buffer with a capacity is refused");
  } else if (r == RS_SUCCESS) {
    check(cap == 0 || got <= cap, "count within the capacity");
  } else if (r == RS_ERROR_SIZE_INSUFFICIENT) {
    check(cap < got, "insufficient only below the count");
  }
}

void get_bounds(FuzzInput& in, rs_analyzer* a) {
  const std::uint8_t how = in.u8();
  std::uint32_t vc = 0, ic = 0;
  rs_result r = rs_analyzer_get_bounds(a, 0, &vc, nullptr, 0, &ic, nullptr);
  check(known(r), "a known result");
  if (r != RS_SUCCESS) return;
  check(ic % 3 == 0, "whole triangles");
  const std::uint32_t vcap = capacity(in, vc), icap = capacity(in, ic);
  std::unique_ptr<float[]> xyz(vcap > 0 && !(how & 1) ? new float[3 * std::size_t{vcap}] : nullptr);
  std::unique_ptr<std::uint32_t[]> idx(icap > 0 && !(how & 2) ? new std::uint32_t[icap] : nullptr);
  std::uint32_t gv = 0, gi = 0;
  r = rs_analyzer_get_bounds(a, vcap, (how & 4) ? nullptr : &gv, xyz.get(), icap, (how & 8) ? nullptr : &gi, idx.get());
  check(known(r), "a known result");
  if (r == RS_SUCCESS && (vcap > 0 || icap > 0) && xyz && idx && !(how & 12))
    for (std::uint32_t i = 0; i < gi; ++i) check(idx[i] < gv, "bounds index in range");
}

void get_message(FuzzInput& in, rs_analyzer* a) {
  std::uint32_t count = 0;
  rs_result r = rs_analyzer_get_message(a, 0, &count, nullptr);
  check(known(r), "a known result");
  if (r != RS_SUCCESS) return;
  check(count >= 1, "the count includes the NUL");
  const std::uint32_t cap = capacity(in, count);
  std::unique_ptr<char[]> buffer(cap > 0 ? new char[cap] : nullptr);
  r = rs_analyzer_get_message(a, cap, &count, buffer.get());
  check(known(r), "a known result");
  if (r == RS_SUCCESS && cap > 0) check(std::memchr(buffer.get(), 0, cap) != nullptr, "NUL-terminated");
}

// A length for a query: valid, at the limits, past them, negative, NaN and infinite.
float length(FuzzInput& in) {
  static const float lengths[] = {0.0f, 0.05f, 0.3f, 1.0f, 5.0f, 100.0f, 100.5f, -0.1f,
                                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()};
  return lengths[in.u8() % (sizeof lengths / sizeof lengths[0])];
}

rs_vec3 point(FuzzInput& in) {
  const std::vector<float> v = roomsense::fuzz::floats(in, 3);
  return {v[0], v[1], v[2]};
}

void find_placements(FuzzInput& in, rs_analyzer* a) {
  // Exactly sizeof(rs_placement_query) on the heap, as create's options.
  auto q = std::make_unique<rs_placement_query>();
  rs_placement_query_init(q.get());
  const std::uint8_t how = in.u8();
  if (how & 1) q->struct_size = in.u8();
  q->size = {length(in), length(in), length(in)};
  q->surfaces = (how & 2) ? in.u32() : in.u8() % 16;
  q->clearance = length(in);
  q->clearance_above = length(in);
  q->edge_distance = length(in);
  const std::uint32_t reach = (how & 4) ? in.u32() : in.u8() % 3;
  std::memcpy(&q->reach, &reach, sizeof reach);
  q->has_user_position = in.u8() & 1;
  q->user_position = point(in);
  q->user_reach = length(in);
  q->has_near_point = in.u8() & 1;
  q->near_point = point(in);
  q->face_direction = (how & 8) ? point(in) : rs_vec3{0, 0, 0};
  q->max_count = (how & 16) ? in.u32() : in.u8() % 20;
  q->allow_overlap = in.u8() & 1;
  if (how & 128) q->reserved = in.u8();
  q->seed = in.u32();
  rs_placement_shortfall shortfall = RS_SHORTFALL_MAX_ENUM;
  two_call<rs_placement>(in, a, [&](rs_analyzer* h, std::uint32_t cap, std::uint32_t* count, rs_placement* out) {
    const rs_result r = rs_analyzer_find_placements(h, (how & 32) ? nullptr : q.get(), cap, count, out,
                                                    (how & 64) ? nullptr : &shortfall);
    if (r == RS_SUCCESS && !(how & 64))
      check(shortfall >= RS_SHORTFALL_NONE && shortfall <= RS_SHORTFALL_TOO_FEW, "a known shortfall");
    if (r == RS_SUCCESS && count != nullptr) check(*count <= q->max_count, "at most max_count placements");
    return r;
  });
}

void point_queries(FuzzInput& in, rs_analyzer* a) {
  const std::uint8_t how = in.u8();
  const rs_vec3 origin = point(in), direction = point(in);
  rs_result r;
  switch (how % 4) {
    case 0: {
      auto hit = std::make_unique<rs_ray_hit>();
      r = rs_analyzer_raycast(a, (how & 4) ? nullptr : &origin, &direction, length(in), (how & 8) ? nullptr : hit.get());
      if (r == RS_SUCCESS && hit->hit) check(std::isfinite(hit->distance) && hit->distance >= 0.0f, "a finite hit");
      break;
    }
    case 1: {
      auto where = std::make_unique<rs_location>();
      r = rs_analyzer_locate(a, (how & 4) ? nullptr : &origin, (how & 8) ? nullptr : where.get());
      if (r == RS_SUCCESS) check(!where->free || where->inside, "free space is inside");
      break;
    }
    case 2: {
      auto p = std::make_unique<rs_surface_point>();
      const std::uint32_t surfaces = (how & 4) ? in.u32() : in.u8() % 16;
      r = rs_analyzer_random_point_on_surface(a, surfaces, length(in), in.u32(), (how & 8) ? nullptr : p.get());
      if (r == RS_SUCCESS && p->found) check(p->surface >= RS_AREA_TYPE_WALL && p->surface <= RS_AREA_TYPE_FURNITURE, "a surface");
      break;
    }
    default: {
      auto p = std::make_unique<rs_surface_point>();
      r = rs_analyzer_random_point_in_room(a, length(in), in.u32(), (how & 8) ? nullptr : p.get());
      break;
    }
  }
  check(known(r), "a known result");
  if (a == nullptr) check(r == RS_ERROR_HANDLE_INVALID, "NULL analyzer");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput in(data, size);
  rs_analyzer* slots[2] = {nullptr, nullptr};
  for (int op = 0; op < 24 && !in.empty(); ++op) {
    const std::uint8_t code = in.u8() % 16;
    rs_analyzer*& slot = slots[in.u8() % 2];
    switch (code) {
      case 0: create(in, slot); break;
      case 1: compute(in, slot); break;
      case 2: {
        rs_state state = RS_STATE_MAX_ENUM;
        const bool null_out = in.u8() & 1;
        const rs_result r = rs_analyzer_state(slot, null_out ? nullptr : &state);
        check(known(r), "a known result");
        if (r == RS_SUCCESS) check(state >= RS_STATE_IDLE && state <= RS_STATE_FAILED, "a known state");
        break;
      }
      case 3: {
        static const std::uint32_t timeouts[] = {0, 1, 20, RS_WAIT_INFINITE};
        rs_state state = RS_STATE_MAX_ENUM;
        const std::uint8_t how = in.u8();
        const rs_result r = rs_analyzer_wait(slot, timeouts[how % 4], (how & 4) ? nullptr : &state);
        check(known(r), "a known result");
        if (r == RS_SUCCESS && !(how & 4)) {
          check(state >= RS_STATE_IDLE && state <= RS_STATE_FAILED, "a known state");
          if (how % 4 == 3) check(state != RS_STATE_RUNNING, "no compute runs after an infinite wait");
        }
        break;
      }
      case 4: {
        auto layout = std::make_unique<rs_layout>();
        const rs_result r = rs_analyzer_get_layout(slot, (in.u8() & 1) ? nullptr : layout.get());
        check(known(r), "a known result");
        break;
      }
      case 5: two_call<rs_storey>(in, slot, rs_analyzer_get_storeys); break;
      case 6: two_call<rs_area>(in, slot, rs_analyzer_get_areas); break;
      case 7: get_bounds(in, slot); break;
      case 8: get_message(in, slot); break;
      case 9:
        rs_analyzer_destroy(slot);  // also while a compute runs: it is waited for
        slot = nullptr;
        break;
      case 10: {
        const std::uint32_t raw = in.u32();
        rs_result r;
        std::memcpy(&r, &raw, sizeof r);
        check(rs_result_string(r) != nullptr, "a name for every result");
        break;
      }
      case 11: find_placements(in, slot); break;
      case 12: point_queries(in, slot); break;
      case 13: case 14: case 15: chunks(in, slot, code - 13); break;
    }
  }
  rs_analyzer_destroy(slots[0]);
  rs_analyzer_destroy(slots[1]);
  return 0;
}
