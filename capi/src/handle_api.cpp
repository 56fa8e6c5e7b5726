// The handle-based C API (roomsense.h): one Job per analyzer, no globals. The worker converts the scan,
// runs analyze() and turns its result into the C structs once, so that the getters only copy under the
// job's lock.
#include "roomsense/roomsense.h"

#include "job.h"
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/incremental.h"
#include "roomsense/queries.h"
#include "roomsense/scan.h"

#include <algorithm>
#include <cstddef>
#include <chrono>
#include <memory>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <new>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

// The C structs are part of the ABI that bindings (C#, Python ctypes) copy: 4-byte enums, no padding.
static_assert(sizeof(rs_result) == 4 && sizeof(rs_area_type) == 4 && sizeof(rs_state) == 4);
static_assert(sizeof(rs_vec3) == 12 && sizeof(rs_quat) == 16);
static_assert(sizeof(rs_area) == 4 * 4 + 2 * 12 + 16 + 4 * 12 + 4 * 4);
static_assert(sizeof(rs_analyzer_options) == 7 * 4);
static_assert(sizeof(rs_placement) == 3 * 4 + 2 * 12 + 16 + 4 * 12 + 3 * 4);
static_assert(sizeof(rs_room) == 4 * 4 + 12 && sizeof(rs_area_place) == 8 && RS_NO_ROOM == roomsense::kNoRoom);
static_assert(sizeof(rs_ray_hit) == 4 * 4 + 2 * 12 && sizeof(rs_surface_point) == 2 * 4 + 2 * 12);
// The query has no implicit padding: `reserved` fills the 4 bytes before the 8-byte seed.
static_assert(sizeof(rs_placement_query) == 104 && offsetof(rs_placement_query, reserved) == 92 &&
              offsetof(rs_placement_query, seed) == 96);
// The surface bits and enums carry core's values (queries.h, areas.h), as the extension's do.
static_assert(int(RS_SURFACE_WALL) == int(roomsense::kOnWall) && int(RS_SURFACE_FLOOR) == int(roomsense::kOnFloor) &&
              int(RS_SURFACE_CEILING) == int(roomsense::kOnCeiling) &&
              int(RS_SURFACE_FURNITURE) == int(roomsense::kOnFurniture) &&
              int(RS_SURFACE_ANY) == int(roomsense::kOnAnySurface));
static_assert(RS_REACH_FILTER_CLOSE == int(roomsense::ReachFilter::Close) &&
              RS_REACH_FILTER_DISTANCE == int(roomsense::ReachFilter::Distance));
static_assert(RS_SHORTFALL_NONE == int(roomsense::PlacementShortfall::None) &&
              RS_SHORTFALL_NO_SURFACE == int(roomsense::PlacementShortfall::NoSurface) &&
              RS_SHORTFALL_NO_SPACE == int(roomsense::PlacementShortfall::NoSpace) &&
              RS_SHORTFALL_NO_HEADROOM == int(roomsense::PlacementShortfall::NoHeadroom) &&
              RS_SHORTFALL_NO_REACH == int(roomsense::PlacementShortfall::NoReach) &&
              RS_SHORTFALL_TOO_FEW == int(roomsense::PlacementShortfall::TooFew));
static_assert(RS_AREA_TYPE_NONE == 0 && RS_AREA_TYPE_WALL == int(roomsense::AreaType::Wall) &&
              RS_AREA_TYPE_FLOOR == int(roomsense::AreaType::Floor) &&
              RS_AREA_TYPE_CEILING == int(roomsense::AreaType::Ceiling) &&
              RS_AREA_TYPE_FURNITURE == int(roomsense::AreaType::Furniture));

namespace roomsense::capi {

// The placement queries of a result, built at the first query (on the asking thread, outside the job's lock;
// concurrent queries wait for the one build), as the layer's are: built at every compute, their index took some
// 0.45 ms of an update's 1.4 ms on thesis-room1 through this API (bench/README.md, stop 94), for engines that
// may never query.
class LazyQueries {
 public:
  explicit LazyQueries(std::shared_ptr<const AnalysisResult> analysis) : analysis_(std::move(analysis)) {}
  const RoomQueries& get() const {
    std::call_once(once_, [&] { queries_ = RoomQueries(*analysis_); });
    return queries_;
  }

 private:
  std::shared_ptr<const AnalysisResult> analysis_;
  mutable std::once_flag once_;
  mutable RoomQueries queries_;
};

// A finished compute, already in C form. The default is an internal failure, what a job that threw holds.
struct HandleOutput {
  rs_result status = RS_ERROR_INTERNAL;
  std::string message = "internal error";
  rs_layout layout{};
  std::vector<rs_storey> storeys;
  std::vector<rs_area> areas;
  std::vector<rs_area_place> area_places;  // one per area
  std::vector<rs_room> rooms;
  std::vector<float> bounds_xyz;
  std::vector<std::uint32_t> bounds_indices;
  struct Mesh {
    std::vector<float> xyz;
    std::vector<std::uint32_t> indices;
  };
  std::vector<Mesh> room_bounds;  // one per room
  std::shared_ptr<const LazyQueries> queries;  // a successful result's; shared: copied out of the lock, queried there
};

// What an analyzer's job holds: its output, shared with the chunks' kept one (Chunks::last). Null where the job's
// work threw: it reads as the default HandleOutput, an internal failure.
using SharedOutput = std::shared_ptr<const HandleOutput>;

namespace {

rs_vec3 to_c(const glm::vec3& v) { return {v.x, v.y, v.z}; }
rs_quat to_c(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }
glm::vec3 from_c(const rs_vec3& v) { return {v.x, v.y, v.z}; }

// The pose members rs_area and rs_placement share: centre, normal, orientation and corners.
template <class C, class Corners>
void set_pose(C& c, const glm::vec3& center, const glm::vec3& normal, const glm::quat& orientation,
              const Corners& corners) {
  c.center = to_c(center);
  c.normal = to_c(normal);
  c.orientation = to_c(orientation);
  for (std::size_t i = 0; i < 4; ++i) c.corners[i] = to_c(corners[i]);
}

rs_area to_c(const Area& a) {
  rs_area c{};
  c.type = static_cast<rs_area_type>(a.type);
  c.size = static_cast<rs_area_size>(a.size);
  c.reach = static_cast<rs_reach>(a.reach);
  c.flags = a.flags;
  set_pose(c, a.center, a.normal, a.orientation(), a.corners);
  c.half_width = a.half_width;
  c.half_height = a.half_height;
  c.rotation_deg = a.rotation_deg;
  c.volume_height = a.volume_height;
  return c;
}

rs_placement to_c(const Placement& p) {
  rs_placement c{};
  c.surface = static_cast<rs_area_type>(p.surface);
  c.reach = static_cast<rs_reach>(p.reach);
  c.storey = p.storey;
  set_pose(c, p.center, p.normal, p.orientation(), p.corners());
  c.width = p.footprint.x;
  c.depth = p.footprint.y;
  c.margin = p.margin;
  return c;
}

std::uint32_t clamp_u32(std::size_t n) {
  return static_cast<std::uint32_t>(std::min<std::size_t>(n, std::numeric_limits<std::uint32_t>::max()));
}

rs_result to_result(ErrorCode code) {
  switch (code) {
    case ErrorCode::EmptyInput: return RS_ERROR_EMPTY_INPUT;
    case ErrorCode::SizeNotMultipleOfThree: return RS_ERROR_INVALID_ARGUMENT;
    case ErrorCode::BadIndices: return RS_ERROR_BAD_INDICES;
    case ErrorCode::NoValidVertices: return RS_ERROR_NO_VALID_VERTICES;
    case ErrorCode::GridTooLarge: return RS_ERROR_GRID_TOO_LARGE;
    case ErrorCode::BadParameter: return RS_ERROR_INVALID_ARGUMENT;
    case ErrorCode::Io: return RS_ERROR_INTERNAL;
    case ErrorCode::TooMuchWork: return RS_ERROR_TOO_MUCH_WORK;
    case ErrorCode::Cancelled: return RS_ERROR_INTERNAL;  // never seen: only a destroyed analyzer is cancelled
  }
  return RS_ERROR_INTERNAL;
}

HandleOutput convert(std::shared_ptr<const AnalysisResult> analysis) {
  const AnalysisResult& r = *analysis;
  HandleOutput out;
  const GridSpec& spec = r.voxels.grid.spec;
  rs_layout& l = out.layout;
  l.floor_y = r.floor_y;
  l.ceiling_y = r.ceiling_y;
  l.input_vertex_count = clamp_u32(r.input.vertices);
  l.input_triangle_count = clamp_u32(r.input.triangles);
  l.skipped_vertex_count = clamp_u32(r.input.skipped_vertices);
  l.outlier_vertex_count = clamp_u32(r.input.outlier_vertices);
  l.voxel_size = spec.voxel_size;
  l.grid_origin = to_c(spec.origin);
  l.grid_dims[0] = static_cast<std::uint32_t>(spec.nx);
  l.grid_dims[1] = static_cast<std::uint32_t>(spec.ny);
  l.grid_dims[2] = static_cast<std::uint32_t>(spec.nz);
  const StageTimings& t = r.timings;
  l.timings = {t.prepare, t.voxelize, t.features, t.areas, t.reduce, t.classify, t.bounds, t.total};

  out.message = r.status_message;
  for (const std::string& warning : r.warnings) out.message += "; " + warning;
  if (!r.ok()) {
    out.status = RS_ERROR_NO_ROOM;
    return out;
  }
  for (const Storey& s : r.storeys) out.storeys.push_back({s.floor_y, s.ceiling_y});
  out.areas.reserve(r.areas.size());
  for (const Area& a : r.areas) out.areas.push_back(to_c(a));
  out.area_places.reserve(r.areas.size());
  for (const Area& a : r.areas) out.area_places.push_back({a.storey, a.room});
  for (const Room& room : r.rooms)
    out.rooms.push_back({room.storey, room.floor_area, to_c(room.center), room.floor_y, room.ceiling_y});
  out.bounds_xyz.reserve(r.bounds.vertices.size() * 3);
  for (const glm::vec3& v : r.bounds.vertices) out.bounds_xyz.insert(out.bounds_xyz.end(), {v.x, v.y, v.z});
  out.bounds_indices = r.bounds.indices;
  for (const BoundsMesh& mesh : r.room_bounds) {
    HandleOutput::Mesh& m = out.room_bounds.emplace_back();
    for (const glm::vec3& v : mesh.vertices) m.xyz.insert(m.xyz.end(), {v.x, v.y, v.z});
    m.indices = mesh.indices;
  }
  if (out.storeys.size() > 0xffffffffu || out.areas.size() > 0xffffffffu || r.bounds.vertices.size() > 0xffffffffu ||
      out.bounds_indices.size() > 0xffffffffu) {
    out.status = RS_ERROR_INTERNAL;
    out.message = "a result too large for 32-bit counts";
    return out;
  }
  l.storey_count = static_cast<std::uint32_t>(out.storeys.size());
  l.area_count = static_cast<std::uint32_t>(out.areas.size());
  l.bounds_vertex_count = static_cast<std::uint32_t>(r.bounds.vertices.size());
  l.bounds_index_count = static_cast<std::uint32_t>(out.bounds_indices.size());
  out.queries = std::make_shared<const LazyQueries>(std::move(analysis));
  out.status = RS_SUCCESS;
  return out;
}

// Runs make() (an analysis and its conversion); errors become the output's status and message.
template <class Make>
SharedOutput run_guarded(Make&& make) {
  const auto failed = [](HandleOutput out) { return std::make_shared<const HandleOutput>(std::move(out)); };
  try {
    return make();
  } catch (const Error& e) {
    HandleOutput out;
    out.status = to_result(e.code());
    out.message = e.what();
    return failed(std::move(out));
  } catch (const std::bad_alloc&) {
    HandleOutput out;
    out.status = RS_ERROR_OUT_OF_MEMORY;
    out.message = "out of memory";
    return failed(std::move(out));
  } catch (const std::exception& e) {
    HandleOutput out;
    out.message = std::string("internal error: ") + e.what();
    return failed(std::move(out));
  }
}

SharedOutput run(Scan& scan, const SourceFrame& frame, const AnalysisOptions& options) {
  return run_guarded([&] {
    convert_to_roomsense_frame(scan, frame);
    return std::make_shared<const HandleOutput>(convert(std::make_shared<const AnalysisResult>(analyze(scan, options))));
  });
}

// The chunks of API 1.3: changes wait in `pending` (any thread, under the mutex) until a compute applies them
// to `analysis`, which only the job's worker touches (one compute at a time).
struct Chunks {
  std::mutex mutex;
  std::map<std::uint64_t, std::optional<Scan>> pending;  // the latest change per id (nullopt: remove)
  std::set<std::uint64_t> ids;  // held once the pending changes apply
  std::optional<IncrementalAnalysis> analysis;
  SharedOutput last;  // the output of analysis's latest result, where it was converted (worker only)
};

}  // namespace
}  // namespace roomsense::capi

struct rs_analyzer {
  // The analyses' worker threads, kept from one compute to the next (options.kept_threads points here).
  std::optional<roomsense::KeptThreads> kept_threads;
  roomsense::AnalysisOptions options;
  roomsense::SourceFrame frame;
  roomsense::capi::Chunks chunks;
  roomsense::capi::Job<roomsense::capi::SharedOutput> job;  // last: its worker stops before the rest goes
};

namespace roomsense::capi {
namespace {

// What the getters share: calls f with the result when one is ready (or failed, if failed_too), else
// says why not.
template <class F>
rs_result with_ready_output(rs_analyzer* analyzer, bool failed_too, F&& f) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  return analyzer->job.inspect([&](JobPhase phase, const SharedOutput* held) -> rs_result {
    if (phase == JobPhase::Running) return RS_ERROR_NOT_READY;
    if (phase == JobPhase::Idle || held == nullptr) return RS_ERROR_NO_RESULT;
    const HandleOutput threw;
    const HandleOutput& out = *held ? **held : threw;
    if (out.status != RS_SUCCESS && !failed_too) return out.status;
    return f(out);
  });
}

// The two-call idiom for one array: count always set; the elements copied when capacity suffices.
template <class T>
rs_result copy_out(const std::vector<T>& from, std::uint32_t capacity, std::uint32_t* count, T* to) {
  *count = static_cast<std::uint32_t>(from.size());
  if (capacity == 0) return RS_SUCCESS;
  if (capacity < from.size()) return RS_ERROR_SIZE_INSUFFICIENT;
  if (!from.empty()) std::memcpy(to, from.data(), from.size() * sizeof(T));
  return RS_SUCCESS;
}

// What rs_analyzer_compute and rs_analyzer_set_chunk take: 3 floats per vertex, indices into them.
rs_result check_caller_mesh(const float* xyz, uint32_t vertex_count, const uint32_t* indices, uint32_t index_count) {
  if (xyz == nullptr || vertex_count == 0) return RS_ERROR_EMPTY_INPUT;
  if (index_count % 3 != 0 || (indices == nullptr && index_count != 0)) return RS_ERROR_BAD_INDICES;
  for (uint32_t i = 0; i < index_count; ++i)
    if (indices[i] >= vertex_count) return RS_ERROR_BAD_INDICES;
  return RS_SUCCESS;
}

// The caller's mesh copied into a Scan (check_caller_mesh passed).
Scan caller_scan(const float* xyz, uint32_t vertex_count, const uint32_t* indices, uint32_t index_count) {
  Scan scan;
  scan.vertices.resize(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) scan.vertices[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  if (index_count != 0) scan.indices.assign(indices, indices + index_count);
  return scan;
}

rs_result guarded(auto&& body) {
  try {
    return body();
  } catch (const Error& e) {  // core's checks of a query's values: BadParameter
    return to_result(e.code());
  } catch (const std::bad_alloc&) {
    return RS_ERROR_OUT_OF_MEMORY;
  } catch (...) {
    return RS_ERROR_INTERNAL;
  }
}

// The queries of the last successful compute, or why there are none; `out` stays empty then, so that a query
// on it still checks its arguments (core throws BadParameter) before the state is reported.
rs_result ready_queries(rs_analyzer* analyzer, std::shared_ptr<const LazyQueries>& out) {
  return with_ready_output(analyzer, false, [&](const HandleOutput& o) {
    out = o.queries;
    return RS_SUCCESS;
  });
}

// One placement query: `ask` runs on the last result's queries, copied out of the lock (and built there at the
// first query), and `write` stores its answer. `ask` runs even when there is no result (on empty queries), so
// that bad arguments are reported before the state, as everywhere in this API; core throws BadParameter for them.
rs_result answer(rs_analyzer* analyzer, auto&& ask, auto&& write) {
  return guarded([&] {
    std::shared_ptr<const LazyQueries> queries;
    const rs_result state = ready_queries(analyzer, queries);
    auto found = ask(queries ? queries->get() : RoomQueries());
    if (state != RS_SUCCESS) return state;
    return write(found);
  });
}

// A C caller can pass any 32 bits in an enum field; read as an integer (see rs_analyzer_create).
template <class Enum>
std::uint32_t raw(const Enum& e) {
  static_assert(sizeof(Enum) == sizeof(std::uint32_t));
  std::uint32_t v = 0;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

bool finite(const rs_vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What core cannot check itself: the C struct's version, enum values and flags. Lengths are core's (queries.h).
std::optional<PlacementQuery> to_core(const rs_placement_query& c) {
  if (c.struct_size < sizeof(rs_placement_query) || c.reserved != 0) return std::nullopt;
  if (raw(c.reach) > RS_REACH_FILTER_DISTANCE) return std::nullopt;
  if (c.has_user_position != 0 && !finite(c.user_position)) return std::nullopt;
  if (c.has_near_point != 0 && !finite(c.near_point)) return std::nullopt;
  if (!finite(c.face_direction)) return std::nullopt;
  PlacementQuery q;
  q.size = from_c(c.size);
  q.surfaces = c.surfaces;
  q.clearance = c.clearance;
  q.clearance_above = c.clearance_above;
  q.edge_distance = c.edge_distance;
  q.reach = static_cast<ReachFilter>(raw(c.reach));
  if (c.has_user_position != 0) q.user_position = from_c(c.user_position);
  if (c.user_reach != 0.0f) q.user_reach = c.user_reach;
  if (c.has_near_point != 0) q.near = from_c(c.near_point);
  q.face_direction = from_c(c.face_direction);
  q.max_count = c.max_count;
  q.allow_overlap = c.allow_overlap != 0;
  q.seed = c.seed;
  return q;
}

rs_surface_point to_c(const std::optional<SurfacePoint>& p) {
  rs_surface_point c{};
  if (!p) return c;
  c.found = 1;
  c.surface = static_cast<rs_area_type>(p->surface);
  c.position = to_c(p->position);
  c.normal = to_c(p->normal);
  return c;
}

// A point in free space: no surface (RS_AREA_TYPE_NONE) and no normal.
rs_surface_point to_c(const std::optional<glm::vec3>& p) {
  rs_surface_point c{};
  c.found = p ? 1 : 0;
  if (p) c.position = to_c(*p);
  return c;
}

}  // namespace
}  // namespace roomsense::capi

using namespace roomsense::capi;

namespace {

// The two-call idiom on a mesh (rs_analyzer_get_bounds): `mesh` picks it from the output, null when there is none.
template <class Pick>
rs_result get_mesh(rs_analyzer* analyzer, Pick mesh, uint32_t vertex_capacity, uint32_t* vertex_count, float* xyz,
                   uint32_t index_capacity, uint32_t* index_count, uint32_t* indices) {
  if (analyzer != nullptr &&
      (vertex_count == nullptr || index_count == nullptr || (vertex_capacity != 0 && xyz == nullptr) ||
       (index_capacity != 0 && indices == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false, [&](const HandleOutput& o) {
      const auto picked = mesh(o);
      if (!picked) return RS_ERROR_INVALID_ARGUMENT;
      const auto& [from_xyz, from_indices] = *picked;
      const std::size_t vertices = from_xyz.size() / 3;
      *vertex_count = static_cast<uint32_t>(vertices);
      *index_count = static_cast<uint32_t>(from_indices.size());
      if (vertex_capacity == 0 && index_capacity == 0) return RS_SUCCESS;
      if (vertex_capacity < vertices || index_capacity < from_indices.size()) return RS_ERROR_SIZE_INSUFFICIENT;
      if (!from_xyz.empty()) std::memcpy(xyz, from_xyz.data(), from_xyz.size() * sizeof(float));
      if (!from_indices.empty()) std::memcpy(indices, from_indices.data(), from_indices.size() * sizeof(uint32_t));
      return RS_SUCCESS;
    });
  });
}

using MeshView = std::pair<const std::vector<float>&, const std::vector<std::uint32_t>&>;

}  // namespace

extern "C" {

const char* rs_result_string(rs_result result) {
  switch (result) {
#define RS_NAME(x) \
  case x: return #x;
    RS_NAME(RS_SUCCESS)
    RS_NAME(RS_ERROR_INVALID_ARGUMENT)
    RS_NAME(RS_ERROR_HANDLE_INVALID)
    RS_NAME(RS_ERROR_SIZE_INSUFFICIENT)
    RS_NAME(RS_ERROR_BUSY)
    RS_NAME(RS_ERROR_NOT_READY)
    RS_NAME(RS_ERROR_NO_RESULT)
    RS_NAME(RS_ERROR_EMPTY_INPUT)
    RS_NAME(RS_ERROR_BAD_INDICES)
    RS_NAME(RS_ERROR_NO_VALID_VERTICES)
    RS_NAME(RS_ERROR_GRID_TOO_LARGE)
    RS_NAME(RS_ERROR_NO_ROOM)
    RS_NAME(RS_ERROR_OUT_OF_MEMORY)
    RS_NAME(RS_ERROR_INTERNAL)
    RS_NAME(RS_ERROR_TOO_MUCH_WORK)
#undef RS_NAME
    default: break;
  }
  return "RS_UNKNOWN_RESULT";
}

uint32_t rs_api_version(void) { return RS_API_VERSION; }

void rs_analyzer_options_init(rs_analyzer_options* options) {
  if (options == nullptr) return;
  *options = rs_analyzer_options{};
  options->struct_size = sizeof(rs_analyzer_options);
  options->voxel_size = roomsense::kDefaultVoxelSize;
  options->compute_flags = RS_COMPUTE_AREAS | RS_COMPUTE_BOUNDS;
  options->up_axis = RS_UP_AXIS_Y;
  options->units = RS_UNITS_METRES;
}

rs_result rs_analyzer_create(const rs_analyzer_options* options, rs_analyzer** out) {
  if (out == nullptr) return RS_ERROR_INVALID_ARGUMENT;
  *out = nullptr;
  rs_analyzer_options o;
  rs_analyzer_options_init(&o);
  if (options != nullptr) {
    if (options->struct_size < sizeof(rs_analyzer_options)) return RS_ERROR_INVALID_ARGUMENT;
    o = *options;
  }
  const float voxel = o.voxel_size == 0.0f ? roomsense::kDefaultVoxelSize : o.voxel_size;
  if (!(voxel >= roomsense::kMinVoxelSize && voxel <= roomsense::kMaxVoxelSize)) return RS_ERROR_INVALID_ARGUMENT;
  // A C or C# caller can pass any 32 bits in an enum field; a C++ enum cannot hold values beyond its
  // enumerators' range (reading one is undefined: UBSan's enum check), so they are checked as raw integers.
  std::uint32_t up_axis = 0, units = 0;
  std::memcpy(&up_axis, &o.up_axis, sizeof up_axis);
  std::memcpy(&units, &o.units, sizeof units);
  if (up_axis != RS_UP_AXIS_Y && up_axis != RS_UP_AXIS_Z) return RS_ERROR_INVALID_ARGUMENT;
  if (units != RS_UNITS_METRES && units != RS_UNITS_CENTIMETRES && units != RS_UNITS_MILLIMETRES)
    return RS_ERROR_INVALID_ARGUMENT;
  const std::uint32_t all = RS_COMPUTE_AREAS | RS_COMPUTE_BOUNDS;
  if ((o.compute_flags & ~all) != 0) return RS_ERROR_INVALID_ARGUMENT;
  const std::uint32_t flags = o.compute_flags == 0 ? all : o.compute_flags;
  return guarded([&] {
    auto a = std::make_unique<rs_analyzer>();  // freed if the threads cannot start
    a->options.voxel_size = voxel;
    a->options.threads = o.thread_count;
    a->options.kept_threads = &a->kept_threads.emplace(o.thread_count);
    a->options.find_areas = (flags & RS_COMPUTE_AREAS) != 0;
    a->options.build_bounds = (flags & RS_COMPUTE_BOUNDS) != 0;
    a->frame.up = o.up_axis == RS_UP_AXIS_Z ? roomsense::UpAxis::Z : roomsense::UpAxis::Y;
    a->frame.units = o.units == RS_UNITS_CENTIMETRES   ? roomsense::Units::Centimetres
                     : o.units == RS_UNITS_MILLIMETRES ? roomsense::Units::Millimetres
                                                       : roomsense::Units::Metres;
    a->frame.left_handed = o.left_handed != 0;
    *out = a.release();
    return RS_SUCCESS;
  });
}

void rs_analyzer_destroy(rs_analyzer* analyzer) {
  try {
    delete analyzer;  // ~Job stops a running worker and joins it
  } catch (...) {
  }
}

rs_result rs_analyzer_compute(rs_analyzer* analyzer, const float* xyz, uint32_t vertex_count, const uint32_t* indices,
                              uint32_t index_count) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (const rs_result bad = check_caller_mesh(xyz, vertex_count, indices, index_count); bad != RS_SUCCESS) return bad;
  if (analyzer->job.phase() == JobPhase::Running) return RS_ERROR_BUSY;  // before copying a large scan
  return guarded([&] {
    roomsense::Scan scan = caller_scan(xyz, vertex_count, indices, index_count);
    const roomsense::SourceFrame frame = analyzer->frame;
    roomsense::AnalysisOptions options = analyzer->options;
    try {
      const bool started = analyzer->job.start(
          [scan = std::move(scan), frame, options](std::stop_token stop) mutable {
            options.stop = std::move(stop);
            return run(scan, frame, options);
          },
          /*replace_result=*/true);
      return started ? RS_SUCCESS : RS_ERROR_BUSY;
    } catch (const std::system_error&) {
      return RS_ERROR_INTERNAL;  // no thread could be started
    }
  });
}

rs_result rs_analyzer_set_chunk(rs_analyzer* analyzer, uint64_t chunk_id, const float* xyz, uint32_t vertex_count,
                                const uint32_t* indices, uint32_t index_count) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (const rs_result bad = check_caller_mesh(xyz, vertex_count, indices, index_count); bad != RS_SUCCESS) return bad;
  return guarded([&] {
    roomsense::Scan chunk = caller_scan(xyz, vertex_count, indices, index_count);
    roomsense::convert_to_roomsense_frame(chunk, analyzer->frame);
    const std::lock_guard lock(analyzer->chunks.mutex);
    analyzer->chunks.pending.insert_or_assign(chunk_id, std::move(chunk));
    analyzer->chunks.ids.insert(chunk_id);
    return RS_SUCCESS;
  });
}

rs_result rs_analyzer_remove_chunk(rs_analyzer* analyzer, uint64_t chunk_id) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  return guarded([&] {
    const std::lock_guard lock(analyzer->chunks.mutex);
    if (analyzer->chunks.ids.erase(chunk_id) == 0) return RS_ERROR_INVALID_ARGUMENT;
    analyzer->chunks.pending.insert_or_assign(chunk_id, std::nullopt);
    return RS_SUCCESS;
  });
}

rs_result rs_analyzer_compute_chunks(rs_analyzer* analyzer) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  {
    const std::lock_guard lock(analyzer->chunks.mutex);
    if (analyzer->chunks.ids.empty()) return RS_ERROR_EMPTY_INPUT;
  }
  return guarded([&] {
    try {
      const bool started = analyzer->job.start(
          [analyzer](std::stop_token stop) {
            roomsense::capi::Chunks& chunks = analyzer->chunks;
            std::map<std::uint64_t, std::optional<roomsense::Scan>> changes;
            {
              const std::lock_guard lock(chunks.mutex);
              changes.swap(chunks.pending);
            }
            if (!chunks.analysis) chunks.analysis.emplace(analyzer->options);
            for (auto& [id, chunk] : changes) {
              if (chunk) chunks.analysis->set_chunk(id, std::move(*chunk));
              else chunks.analysis->remove_chunk(id);
            }
            chunks.last = roomsense::capi::run_guarded([&] {
              chunks.analysis->set_stop(std::move(stop));
              const roomsense::AnalysisResult& result = chunks.analysis->result();
              // No chunk changed: the last output, where it succeeded, with the query index a query may have built
              // for it, rather than a new conversion (and a new index at the next query: 0.45 ms on thesis-room1).
              if (chunks.analysis->reused_result() && chunks.last && chunks.last->status == RS_SUCCESS)
                return chunks.last;
              return std::make_shared<const roomsense::capi::HandleOutput>(
                  roomsense::capi::convert(std::make_shared<const roomsense::AnalysisResult>(result)));
            });
            return chunks.last;
          },
          /*replace_result=*/true);
      return started ? RS_SUCCESS : RS_ERROR_BUSY;
    } catch (const std::system_error&) {
      return RS_ERROR_INTERNAL;
    }
  });
}

namespace {

rs_state state_of(JobPhase phase, const SharedOutput* held) {
  if (phase == JobPhase::Running) return RS_STATE_RUNNING;
  if (phase == JobPhase::Idle || held == nullptr) return RS_STATE_IDLE;
  return *held && (*held)->status == RS_SUCCESS ? RS_STATE_READY : RS_STATE_FAILED;
}

}  // namespace

rs_result rs_analyzer_state(rs_analyzer* analyzer, rs_state* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (out == nullptr) return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    *out = analyzer->job.inspect(state_of);
    return RS_SUCCESS;
  });
}

rs_result rs_analyzer_wait(rs_analyzer* analyzer, uint32_t timeout_ms, rs_state* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  return guarded([&] {
    // The state the wait ended on: read after it, under a second lock, it could be a compute another thread
    // started meanwhile (RUNNING after an infinite wait).
    const std::optional<std::chrono::milliseconds> timeout =
        timeout_ms == RS_WAIT_INFINITE ? std::nullopt : std::optional(std::chrono::milliseconds(timeout_ms));
    const rs_state state = analyzer->job.wait_and_inspect(timeout, state_of);
    if (out != nullptr) *out = state;
    return RS_SUCCESS;
  });
}

rs_result rs_analyzer_get_layout(rs_analyzer* analyzer, rs_layout* out) {
  if (analyzer != nullptr && out == nullptr) return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false, [&](const HandleOutput& o) {
      *out = o.layout;
      return RS_SUCCESS;
    });
  });
}

rs_result rs_analyzer_get_storeys(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count, rs_storey* storeys) {
  if (analyzer != nullptr && (count == nullptr || (capacity != 0 && storeys == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false,
                             [&](const HandleOutput& o) { return copy_out(o.storeys, capacity, count, storeys); });
  });
}

rs_result rs_analyzer_get_areas(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count, rs_area* areas) {
  if (analyzer != nullptr && (count == nullptr || (capacity != 0 && areas == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false,
                             [&](const HandleOutput& o) { return copy_out(o.areas, capacity, count, areas); });
  });
}

rs_result rs_analyzer_get_rooms(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count, rs_room* rooms) {
  if (analyzer != nullptr && (count == nullptr || (capacity != 0 && rooms == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false,
                             [&](const HandleOutput& o) { return copy_out(o.rooms, capacity, count, rooms); });
  });
}

rs_result rs_analyzer_get_area_places(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count,
                                      rs_area_place* places) {
  if (analyzer != nullptr && (count == nullptr || (capacity != 0 && places == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, false,
                             [&](const HandleOutput& o) { return copy_out(o.area_places, capacity, count, places); });
  });
}

rs_result rs_analyzer_get_bounds(rs_analyzer* analyzer, uint32_t vertex_capacity, uint32_t* vertex_count, float* xyz,
                                 uint32_t index_capacity, uint32_t* index_count, uint32_t* indices) {
  return get_mesh(
      analyzer, [](const HandleOutput& o) { return std::optional<MeshView>(MeshView(o.bounds_xyz, o.bounds_indices)); },
      vertex_capacity, vertex_count, xyz, index_capacity, index_count, indices);
}

rs_result rs_analyzer_get_room_bounds(rs_analyzer* analyzer, uint32_t room, uint32_t vertex_capacity,
                                      uint32_t* vertex_count, float* xyz, uint32_t index_capacity, uint32_t* index_count,
                                      uint32_t* indices) {
  return get_mesh(
      analyzer,
      [room](const HandleOutput& o) {
        if (room >= o.room_bounds.size()) return std::optional<MeshView>();
        return std::optional<MeshView>(MeshView(o.room_bounds[room].xyz, o.room_bounds[room].indices));
      },
      vertex_capacity, vertex_count, xyz, index_capacity, index_count, indices);
}

rs_result rs_analyzer_get_message(rs_analyzer* analyzer, uint32_t capacity, uint32_t* count, char* buffer) {
  if (analyzer != nullptr && (count == nullptr || (capacity != 0 && buffer == nullptr)))
    return RS_ERROR_INVALID_ARGUMENT;
  return guarded([&] {
    return with_ready_output(analyzer, true, [&](const HandleOutput& o) {
      const std::size_t needed = std::min<std::size_t>(o.message.size() + 1, 0xffffffffu);
      *count = static_cast<uint32_t>(needed);
      if (capacity == 0) return RS_SUCCESS;
      if (capacity < needed) return RS_ERROR_SIZE_INSUFFICIENT;
      std::memcpy(buffer, o.message.data(), needed - 1);
      buffer[needed - 1] = '\0';
      return RS_SUCCESS;
    });
  });
}

void rs_placement_query_init(rs_placement_query* query) {
  if (query == nullptr) return;
  *query = rs_placement_query{};
  query->struct_size = sizeof(rs_placement_query);
  const roomsense::PlacementQuery defaults;
  query->size = to_c(defaults.size);
  query->surfaces = defaults.surfaces;
  query->user_reach = defaults.user_reach;
  query->max_count = defaults.max_count;
}

rs_result rs_analyzer_find_placements(rs_analyzer* analyzer, const rs_placement_query* query, uint32_t capacity,
                                      uint32_t* count, rs_placement* placements, rs_placement_shortfall* shortfall) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (query == nullptr || count == nullptr || (capacity != 0 && placements == nullptr)) return RS_ERROR_INVALID_ARGUMENT;
  const std::optional<roomsense::PlacementQuery> q = to_core(*query);
  if (!q) return RS_ERROR_INVALID_ARGUMENT;
  return answer(
      analyzer, [&](const roomsense::RoomQueries& queries) { return queries.find_placements(*q); },
      [&](const roomsense::PlacementResult& found) {
        std::vector<rs_placement> out;
        out.reserve(found.placements.size());
        for (const roomsense::Placement& p : found.placements) out.push_back(to_c(p));
        if (shortfall != nullptr) *shortfall = static_cast<rs_placement_shortfall>(found.shortfall);
        return copy_out(out, capacity, count, placements);
      });
}

rs_result rs_analyzer_raycast(rs_analyzer* analyzer, const rs_vec3* origin, const rs_vec3* direction, float max_distance,
                              rs_ray_hit* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (origin == nullptr || direction == nullptr || out == nullptr || !std::isfinite(max_distance) || max_distance < 0.0f)
    return RS_ERROR_INVALID_ARGUMENT;
  return answer(
      analyzer,
      [&](const roomsense::RoomQueries& queries) {
        return queries.raycast(from_c(*origin), from_c(*direction), max_distance == 0.0f ? INFINITY : max_distance);
      },
      [&](const std::optional<roomsense::RayHit>& h) {
        *out = rs_ray_hit{};
        if (h) {
          out->hit = 1;
          out->scanned = h->scanned ? 1 : 0;
          out->surface = static_cast<rs_area_type>(h->surface);
          out->distance = h->distance;
          out->position = to_c(h->position);
          out->normal = to_c(h->normal);
        }
        return RS_SUCCESS;
      });
}

rs_result rs_analyzer_locate(rs_analyzer* analyzer, const rs_vec3* point, rs_location* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (point == nullptr || out == nullptr || !finite(*point)) return RS_ERROR_INVALID_ARGUMENT;
  return answer(
      analyzer, [&](const roomsense::RoomQueries& queries) { return queries.locate(from_c(*point)); },
      [&](const roomsense::RoomLocation& where) {
        *out = {where.inside ? 1 : 0, where.free ? 1 : 0, where.storey};
        return RS_SUCCESS;
      });
}

rs_result rs_analyzer_random_point_on_surface(rs_analyzer* analyzer, uint32_t surfaces, float edge_distance,
                                              uint64_t seed, rs_surface_point* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (out == nullptr) return RS_ERROR_INVALID_ARGUMENT;
  return answer(
      analyzer,
      [&](const roomsense::RoomQueries& queries) { return queries.random_point_on_surface(surfaces, edge_distance, seed); },
      [&](const auto& found) {
        *out = to_c(found);
        return RS_SUCCESS;
      });
}

rs_result rs_analyzer_random_point_in_room(rs_analyzer* analyzer, float clearance, uint64_t seed,
                                           rs_surface_point* out) {
  if (analyzer == nullptr) return RS_ERROR_HANDLE_INVALID;
  if (out == nullptr) return RS_ERROR_INVALID_ARGUMENT;
  return answer(
      analyzer, [&](const roomsense::RoomQueries& queries) { return queries.random_point_in_room(clearance, seed); },
      [&](const auto& found) {
        *out = to_c(found);
        return RS_SUCCESS;
      });
}

}  // extern "C"
