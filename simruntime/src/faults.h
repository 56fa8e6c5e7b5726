// A hostile runtime on request: ROOMSENSE_SIM_FAULTS (README.md, "Faults") makes chosen calls fail, scene
// computes and futures never complete, meshes come out broken, or the session get lost in the middle of a query.
// The plan is parsed and installed at each xrCreateInstance (config.cpp) and holds until the next one. Every
// entry point asks on_call() first (validate.h's guarded); the scene extensions ask pending(), faulty_mesh()
// and vertex_count() at the spots where they complete work and serve meshes.
#pragma once
#include <openxr/openxr.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace roomsense::sim::faults {

enum class MeshFault { None, Nan, Empty, Huge, Ragged, Range };

struct Fault {
  enum class Kind { Error, Pending, Mesh, Lost };
  Kind kind = Kind::Error;
  std::string target;                  // a function (error, lost) or a scene extension (pending, mesh); empty: all
  XrResult result = XR_SUCCESS;        // error
  MeshFault mesh = MeshFault::None;    // mesh
  std::uint32_t call = 1;              // lost: the session is lost at this call of the target
};

struct Plan {
  std::vector<Fault> faults;
};

// The scene extensions a pending or mesh fault may name (one per headset, as in ROOMSENSE_SIM_EXTENSIONS).
const std::vector<std::string_view>& fault_extensions();

// Parses a ROOMSENSE_SIM_FAULTS value. Throws std::invalid_argument with one short line naming the variable.
Plan parse(std::string_view spec);

// Makes `plan` the one every call consults (null: none), and forgets a session lost under the previous one.
void install(std::shared_ptr<const Plan> plan);

// At the entry of `function`: the error an error fault or a lost session makes it return, else XR_SUCCESS.
// The call that loses the session (lost fault) queues XR_SESSION_STATE_LOSS_PENDING for every session first.
XrResult on_call(const char* function) noexcept;

// Work of `extension` (a scene compute, a future, a space query, a snapshot) never completes.
bool pending(std::string_view extension);

// How meshes of `extension` are broken.
MeshFault mesh_fault(std::string_view extension);

inline constexpr std::uint32_t kHugeCount = 1u << 31;

// The vertex count a two-call of `extension` reports for `real` vertices at `capacity`: with mesh=huge, 2^31
// while the capacity does not hold the real ones (so the count call says 2^31, a short capacity fails with
// XR_ERROR_SIZE_INSUFFICIENT, and one that holds the real vertices gets them and their real count).
std::uint32_t vertex_count(std::string_view extension, std::size_t real, std::uint32_t capacity);

// A future's delay: never ready when `extension`'s work is pending (make_future treats max() as never).
inline std::chrono::milliseconds future_delay(std::string_view extension, std::chrono::milliseconds delay) {
  return pending(extension) ? std::chrono::milliseconds::max() : delay;
}

// `mesh` as `extension` serves it: itself, or a broken copy made in `scratch` (any type with `vertices` and
// `indices` vectors; per-vertex `normals` and `labels` are emptied with the vertices). nan: the first vertex
// of every mesh is NaN; empty: no vertices, no indices; ragged: one index more (a count not a multiple of 3);
// range: the last index points one past the last vertex.
template <typename Mesh>
const Mesh& faulty_mesh(std::string_view extension, const Mesh& mesh, Mesh& scratch) {
  const MeshFault fault = mesh_fault(extension);
  if (fault == MeshFault::None || fault == MeshFault::Huge) return mesh;
  scratch = mesh;
  auto& v = scratch.vertices;
  auto& i = scratch.indices;
  using Index = typename std::remove_reference_t<decltype(i)>::value_type;
  switch (fault) {
    case MeshFault::Nan:
      if (!v.empty()) {
        constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
        v.front().x = kNan;
        v.front().y = kNan;
        if constexpr (requires { v.front().z; }) v.front().z = kNan;
      }
      break;
    case MeshFault::Empty:
      v.clear();
      i.clear();
      if constexpr (requires { scratch.normals.clear(); }) scratch.normals.clear();
      if constexpr (requires { scratch.labels.clear(); }) scratch.labels.clear();
      break;
    case MeshFault::Ragged: i.push_back(i.empty() ? Index{0} : i.front()); break;
    case MeshFault::Range:
      if (!i.empty()) i.back() = static_cast<Index>(std::min<std::size_t>(v.size(), std::numeric_limits<Index>::max()));
      break;
    default: break;
  }
  return scratch;
}

}  // namespace roomsense::sim::faults
