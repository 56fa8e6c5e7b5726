// Reader for Meta MR Utility Kit (MRUK) room JSON; see mruk_room.h for what it produces.
//
// Sources, read for the format and its conventions (cited, no code taken from them):
// - MRUK's Unity package com.meta.xr.mrutilitykit, Core/Scripts/SerializationHelpers.cs of the v6x releases
//   (the managed serializer; the file also ships in public projects that vendor older MRUK versions):
//   SceneData {CoordinateSystem, Rooms}, RoomData {UUID, RoomLayout, Anchors}, AnchorData {UUID,
//   SemanticClassifications, Transform {Translation, Rotation, Scale}, PlaneBounds {Min, Max}, VolumeBounds
//   {Min, Max}, PlaneBoundary2D, GlobalMesh {Positions, Indices}}; vectors written as arrays; Serialize()
//   writes each anchor's Unity localPosition, localEulerAngles and localScale, its PlaneRect and VolumeBounds
//   (anchor-local), PlaneBoundary2D and the global mesh's local vertices and triangles; Deserialize() turns an
//   "Unreal" file into Unity values with the mapping used in from_unreal below.
// - Same package, newer releases: yblei/IRIS-Meta-Quest3 Packages/com.meta.xr.mrutilitykit/Core/Scripts/
//   SerializationHelpers.cs (CoordinateSystem is only Unity or Unreal, now marked obsolete) and
//   darktable-mirror/com.meta.xr.mrutilitykit Core/Scripts/MRUK.Shared.cs: FlipZRotateY180 makes the Unity
//   transform from the runtime's native OpenXR anchor pose (Z mirrored, then 180 degrees about +Y), and
//   ConvertPlane / ConvertVolume / FlipX make the Unity plane rectangle, volume and boundary from the native
//   ones by mirroring X.
// - darktable-mirror/com.meta.xr.mrutilitykit Core/Scripts/MRUKAnchor.cs: a plane lies in the anchor's local
//   X/Y plane, its normal is local +Z (transform.forward).
// - The JSON rooms of MRUK's Unity tests (EffectMeshTests.cs): walls face the room with +Z, floors are rotated
//   (270, yaw, 0) and ceilings (90, yaw, 0), a table's VolumeBounds runs from z = 0 (its top) down to -height.
//
// The conversion, defined once below:
// - Unity is left-handed, +Y up, +Z forward. A Unity world point (x, y, z) is ours at (x, y, -z)
//   (from_unity_world; the mapping core's convert_to_roomsense_frame uses for left-handed Y-up scans).
// - An anchor's Transform places its local points: world = T + R (S * local), where R applies the Euler angles
//   as Unity does, Z first, then X, then Y about the fixed axes (R = Ry Rx Rz; Unity's rotation matrices are
//   numerically the usual ones, only the handedness of the space differs).
// - Undoing MRUK's own conversion gives the runtime's native anchor frame: rotation Mz R Mx (Mz, Mx the Z and X
//   mirrors; two mirrors make a proper rotation) at Mz T, and a Unity local point l is native Mx (S l)
//   (from_unity_local). That frame is the XR_FB scene anchor's: a plane in X/Y with +Z its normal into the room
//   (+Y up on walls), a table's volume below its top, z in [-height, 0].
// - A Quest capture's plane is the same surface with +Y into it and the rectangle in X/Z: the plane pose is the
//   native one turned -90 degrees about X (native (x, y, 0) is plane-entity (x, 0, y)). Volumes keep the native
//   frame, as in a capture.
// Global mesh triangles keep their order: the mirror turns Unity's clockwise front faces into our
// counter-clockwise ones (as in convert_to_roomsense_frame).
#include "roomsense/mruk_room.h"

#include "roomsense/error.h"
#include "json_member.h"
#include "scan_file.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <numeric>
#include <optional>
#include <vector>

namespace roomsense::scanio {
namespace {

using nlohmann::json;

constexpr double kMaxLength = 1000.0;                // metres: a coordinate or size beyond 1 km is a corrupt file
constexpr double kMaxDegrees = 1e5;                  // Euler angles; beyond this float rounding makes them noise
constexpr double kMinScale = 1e-3, kMaxScale = 1e3;  // Transform.Scale (MRUK writes 1)
constexpr std::size_t kMaxBoundaryPoints = 1024;     // real boundaries have tens; ear clipping is quadratic
constexpr std::uint64_t kTriangulationBudget = 200'000'000;  // point-in-triangle tests per file
constexpr double kUnrealUnitsPerMetre = 100.0;               // SerializationHelpers.UnrealWorldToMeters

// ---- The conversion (see the file comment) ---------------------------------------------------------------

glm::dvec3 from_unity_world(const glm::dvec3& p) { return {p.x, p.y, -p.z}; }
glm::dvec3 from_unity_local(const glm::dvec3& l) { return {-l.x, l.y, l.z}; }

glm::dmat3 unity_euler(const glm::dvec3& degrees) {
  const auto about = [](double deg, const glm::dvec3& axis) {
    return glm::mat3_cast(glm::angleAxis(glm::radians(deg), axis));
  };
  return about(degrees.y, {0, 1, 0}) * about(degrees.x, {1, 0, 0}) * about(degrees.z, {0, 0, 1});
}

// An anchor's native OpenXR frame in our world, and its Unity scale.
struct NativeFrame {
  glm::dmat3 rotation{1.0};
  glm::dvec3 position{0.0};
  glm::dvec3 scale{1.0};
  glm::dvec3 local(const glm::dvec3& unity_local) const { return from_unity_local(scale * unity_local); }
  glm::vec3 world(const glm::dvec3& native_local) const { return glm::vec3(rotation * native_local + position); }
};

NativeFrame native_frame(const glm::dvec3& translation, const glm::dvec3& euler_degrees, const glm::dvec3& scale) {
  const glm::dmat3 unity = unity_euler(euler_degrees);
  NativeFrame frame;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 axis(0.0);
    axis[i] = 1.0;
    frame.rotation[i] = from_unity_world(unity * from_unity_local(axis));  // Mz R Mx, column by column
  }
  frame.position = from_unity_world(translation);
  frame.scale = scale;
  return frame;
}

QuestPose pose_of(const glm::dmat3& rotation, const glm::dvec3& position) {
  QuestPose pose;
  pose.orientation = glm::normalize(glm::quat(glm::quat_cast(rotation)));
  pose.position = glm::vec3(position);
  return pose;
}

// A capture plane's frame from the native one: +Y into the surface (native -Z), the rectangle in X/Z.
const glm::dmat3 kNativeToPlaneEntity = glm::mat3_cast(glm::angleAxis(-glm::half_pi<double>(), glm::dvec3(1, 0, 0)));

// ---- The file --------------------------------------------------------------------------------------------

template <glm::length_t N>
struct Bounds {
  glm::vec<N, double> min{0.0}, max{0.0};
};
using Bounds2 = Bounds<2>;
using Bounds3 = Bounds<3>;

// One anchor, its values already in Unity's convention and metres.
struct Anchor {
  std::string uuid;
  std::string label;
  glm::dvec3 translation{0.0}, rotation{0.0}, scale{1.0};
  std::optional<Bounds2> plane;
  std::vector<glm::dvec2> boundary;
  std::optional<Bounds3> volume;
  const json* mesh = nullptr;
};

class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  QuestCapture read(const json& root) {
    if (root.is_discarded()) fail("it is not valid JSON");
    if (!root.is_object()) fail("the top level is not a JSON object");
    read_coordinate_system(root);
    const json* rooms = member(root, "Rooms");
    if (rooms == nullptr || !rooms->is_array()) fail("it has no \"Rooms\" array");
    if (rooms->empty()) fail("its \"Rooms\" array is empty");
    QuestCapture capture;
    for (std::size_t r = 0; r < rooms->size(); ++r) read_room((*rooms)[r], "Rooms[" + std::to_string(r) + "]", capture);
    if (capture.mesh.indices.empty()) fail("it holds no usable geometry (no plane, volume or global mesh triangles)");
    return capture;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::Io, "cannot read MRUK room '" + source_ + "': " + what);
  }

  // "Unity" (also when missing: the C# enum's default) or "Unreal"; Newtonsoft reads enum names case-blind.
  void read_coordinate_system(const json& root) {
    const json* system = member(root, "CoordinateSystem");
    if (system == nullptr) return;
    if (!system->is_string()) fail("CoordinateSystem is not a string");
    std::string name = system->get<std::string>();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (name == "unreal")
      unreal_ = true;
    else if (name != "unity")
      fail("CoordinateSystem \"" + system->get<std::string>().substr(0, 40) + "\" is neither \"Unity\" nor \"Unreal\"");
  }

  double number(const json& value, const std::string& where) const {
    if (!value.is_number()) fail(where + " is not a number");
    const double d = value.get<double>();
    if (!std::isfinite(d)) fail(where + " is not a finite number");
    return d;
  }

  template <glm::length_t N>
  glm::vec<N, double> vector_at(const json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != static_cast<std::size_t>(N))
      fail(where + " is not an array of " + std::to_string(N) + " numbers");
    glm::vec<N, double> out(0.0);
    for (glm::length_t i = 0; i < N; ++i)
      out[i] = number(value[static_cast<std::size_t>(i)], where + "[" + std::to_string(i) + "]");
    return out;
  }

  template <glm::length_t N>
  glm::vec<N, double> vector_member(const json& object, const char* key, const std::string& where) const {
    const json* value = member(object, key);
    if (value == nullptr) fail(where + " has no \"" + key + "\"");
    return vector_at<N>(*value, where + "." + key);
  }

  template <glm::length_t N>
  void check_length(const glm::vec<N, double>& v, const std::string& where) const {
    for (glm::length_t i = 0; i < N; ++i)
      if (std::fabs(v[i]) > kMaxLength) fail(where + " lies beyond 1 km");
  }

  // An anchor's "PlaneBounds" or "VolumeBounds", in Unity's convention; none where it has none.
  template <glm::length_t N>
  std::optional<Bounds<N>> bounds_member(const json& anchor, const char* key, const std::string& where) const {
    const json* bounds = member(anchor, key);
    if (bounds == nullptr) return std::nullopt;
    const std::string w = where + "." + key;
    if (!bounds->is_object()) fail(w + " is not an object");
    Bounds<N> b{vector_member<N>(*bounds, "Min", w), vector_member<N>(*bounds, "Max", w)};
    if (unreal_) b = from_unreal(b);
    check_length(b.min, w + ".Min");
    check_length(b.max, w + ".Max");
    for (glm::length_t i = 0; i < N; ++i)
      if (b.min[i] > b.max[i]) fail(w + ".Min exceeds Max");
    return b;
  }

  Anchor read_anchor(const json& a, const std::string& where) const {
    if (!a.is_object()) fail(where + " is not an object");
    Anchor anchor;
    if (const json* uuid = member(a, "UUID"); uuid != nullptr) {
      if (!uuid->is_string()) fail(where + ".UUID is not a string");
      anchor.uuid = uuid->get<std::string>();
    }
    if (const json* labels = member(a, "SemanticClassifications"); labels != nullptr) {
      if (!labels->is_array()) fail(where + ".SemanticClassifications is not an array");
      for (const json& label : *labels)
        if (!label.is_string()) fail(where + ".SemanticClassifications holds something that is not a string");
      if (!labels->empty()) anchor.label = labels->front().get<std::string>();
    }

    const json* transform = member(a, "Transform");
    if (transform == nullptr || !transform->is_object()) fail(where + " has no object \"Transform\"");
    const std::string t = where + ".Transform";
    anchor.translation = vector_member<3>(*transform, "Translation", t);
    anchor.rotation = vector_member<3>(*transform, "Rotation", t);
    if (member(*transform, "Scale") != nullptr) anchor.scale = vector_member<3>(*transform, "Scale", t);
    if (unreal_) from_unreal_transform(anchor);
    check_length(anchor.translation, t + ".Translation");
    for (int i = 0; i < 3; ++i) {
      if (std::fabs(anchor.rotation[i]) > kMaxDegrees) fail(t + ".Rotation is out of range");
      if (!(anchor.scale[i] >= kMinScale && anchor.scale[i] <= kMaxScale))
        fail(t + ".Scale is not between 0.001 and 1000");
    }

    anchor.plane = bounds_member<2>(a, "PlaneBounds", where);
    if (const json* boundary = member(a, "PlaneBoundary2D"); boundary != nullptr) {
      const std::string w = where + ".PlaneBoundary2D";
      if (!boundary->is_array()) fail(w + " is not an array");
      if (boundary->size() < 3) fail(w + " has fewer than 3 points");
      if (boundary->size() > kMaxBoundaryPoints)
        fail(w + " has " + std::to_string(boundary->size()) + " points, more than " +
             std::to_string(kMaxBoundaryPoints));
      for (std::size_t i = 0; i < boundary->size(); ++i) {
        glm::dvec2 p = vector_at<2>((*boundary)[i], w + "[" + std::to_string(i) + "]");
        if (unreal_) p = glm::dvec2(-p.x, p.y) / kUnrealUnitsPerMetre;
        check_length(p, w + "[" + std::to_string(i) + "]");
        anchor.boundary.push_back(p);
      }
      if (unreal_) std::reverse(anchor.boundary.begin(), anchor.boundary.end());
      if (!anchor.plane) {  // a boundary alone still makes a plane: its bounding rectangle
        Bounds2 box{anchor.boundary.front(), anchor.boundary.front()};
        for (const glm::dvec2& p : anchor.boundary) box = {glm::min(box.min, p), glm::max(box.max, p)};
        anchor.plane = box;
      }
    }
    anchor.volume = bounds_member<3>(a, "VolumeBounds", where);
    if (const json* mesh = member(a, "GlobalMesh"); mesh != nullptr) {
      if (!mesh->is_object()) fail(where + ".GlobalMesh is not an object");
      anchor.mesh = mesh;
    }
    return anchor;
  }

  // An "Unreal" file's values in Unity's convention: the mapping of MRUK's SerializationHelpers.Deserialize
  // (Unreal is X forward, Y right, Z up, centimetres).
  static void from_unreal_transform(Anchor& anchor) {
    const glm::dvec3 t = anchor.translation, r = anchor.rotation;
    anchor.translation = glm::dvec3(t.y, t.z, t.x) / kUnrealUnitsPerMetre;
    anchor.rotation = glm::dvec3(r.x, 180.0 + r.y, r.z);
  }
  static Bounds2 from_unreal(const Bounds2& b) {
    return {glm::dvec2(-b.max.x, b.min.y) / kUnrealUnitsPerMetre, glm::dvec2(-b.min.x, b.max.y) / kUnrealUnitsPerMetre};
  }
  static Bounds3 from_unreal(const Bounds3& b) {
    return {glm::dvec3(b.min.y, b.min.z, -b.max.x) / kUnrealUnitsPerMetre,
            glm::dvec3(b.max.y, b.max.z, -b.min.x) / kUnrealUnitsPerMetre};
  }
  // Unreal global mesh vertices are anchor-local centimetres like every other Unreal length (MRUK's C# reader
  // maps their axes but leaves them unscaled; we scale them with the rest).
  static glm::dvec3 from_unreal_vertex(const glm::dvec3& v) {
    return glm::dvec3(-v.y, v.z, -v.x) / kUnrealUnitsPerMetre;
  }

  // A native-local point from a Unity-local one, checked after Scale.
  glm::dvec3 local_point(const NativeFrame& frame, const glm::dvec3& unity_local, const std::string& where) const {
    const glm::dvec3 p = frame.local(unity_local);
    check_length(p, where);
    return p;
  }

  void read_room(const json& room, const std::string& where, QuestCapture& capture) {
    if (!room.is_object()) fail(where + " is not an object");
    const json* anchors = member(room, "Anchors");
    if (anchors == nullptr || !anchors->is_array()) fail(where + " has no \"Anchors\" array");
    Scan global, built;
    for (std::size_t i = 0; i < anchors->size(); ++i) {
      const std::string w = where + ".Anchors[" + std::to_string(i) + "]";
      const Anchor anchor = read_anchor((*anchors)[i], w);
      const NativeFrame frame = native_frame(anchor.translation, anchor.rotation, anchor.scale);
      bool geometry = false;
      if (anchor.plane) {
        const glm::dvec3 a = local_point(frame, {anchor.plane->min, 0.0}, w + ".PlaneBounds");
        const glm::dvec3 b = local_point(frame, {anchor.plane->max, 0.0}, w + ".PlaneBounds");
        const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
        // Native (x, y, 0) is plane-entity (x, 0, y): offset and extent carry over.
        const QuestPose pose = pose_of(frame.rotation * kNativeToPlaneEntity, frame.position);
        capture.planes.push_back(
            {anchor.uuid, anchor.label, pose, glm::vec2(lo.x, lo.y), glm::vec2(hi.x - lo.x, hi.y - lo.y)});
        geometry = true;
      }
      if (anchor.volume) {
        const glm::dvec3 a = local_point(frame, anchor.volume->min, w + ".VolumeBounds");
        const glm::dvec3 b = local_point(frame, anchor.volume->max, w + ".VolumeBounds");
        const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
        capture.volumes.push_back(
            {anchor.uuid, anchor.label, pose_of(frame.rotation, frame.position), glm::vec3(lo), glm::vec3(hi - lo)});
        append_box(frame, lo, hi, built);
        geometry = true;
      } else if (anchor.plane) {
        append_plane_polygon(anchor, frame, w, built);
      }
      if (anchor.mesh != nullptr && append_global_mesh(*anchor.mesh, frame, w + ".GlobalMesh", global)) geometry = true;
      if (!geometry) ++capture.skipped_entities;
    }
    append_scan(global.indices.empty() ? built : global, capture.mesh);
  }

  void append_scan(const Scan& from, Scan& into) const {
    const std::size_t base = into.vertices.size();
    if (base + from.vertices.size() > UINT32_MAX) fail("too many vertices for 32-bit indices");
    into.vertices.insert(into.vertices.end(), from.vertices.begin(), from.vertices.end());
    for (const std::uint32_t i : from.indices) into.indices.push_back(static_cast<std::uint32_t>(base + i));
  }

  // Returns whether the mesh added any triangle.
  bool append_global_mesh(const json& mesh, const NativeFrame& frame, const std::string& where, Scan& out) const {
    const json* positions = member(mesh, "Positions");
    const json* indices = member(mesh, "Indices");
    if (positions == nullptr || !positions->is_array()) fail(where + " has no \"Positions\" array");
    if (indices == nullptr || !indices->is_array()) fail(where + " has no \"Indices\" array");
    if (indices->size() % 3 != 0) fail(where + ".Indices is not a whole number of triangles");
    const std::size_t base = out.vertices.size();
    if (base + positions->size() > UINT32_MAX) fail("too many vertices for 32-bit indices");
    out.vertices.reserve(base + positions->size());  // bounded by the parsed text
    for (std::size_t i = 0; i < positions->size(); ++i) {
      const std::string w = where + ".Positions[" + std::to_string(i) + "]";
      glm::dvec3 v = vector_at<3>((*positions)[i], w);
      if (unreal_) v = from_unreal_vertex(v);
      out.vertices.push_back(frame.world(local_point(frame, v, w)));
    }
    out.indices.reserve(out.indices.size() + indices->size());
    for (std::size_t t = 0; t < indices->size(); t += 3) {
      std::array<std::uint32_t, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        const json& index = (*indices)[t + k];
        const std::string w = where + ".Indices[" + std::to_string(t + k) + "]";
        if (!index.is_number_integer()) fail(w + " is not an integer");
        const bool negative = index.is_number_unsigned() ? false : index.get<std::int64_t>() < 0;
        if (negative || index.get<std::uint64_t>() >= positions->size())
          fail(w + " is out of range for " + std::to_string(positions->size()) + " positions");
        tri[k] = static_cast<std::uint32_t>(base + index.get<std::uint64_t>());
      }
      if (unreal_) std::swap(tri[1], tri[2]);  // MRUK's C# reader reverses an Unreal file's index order
      out.indices.insert(out.indices.end(), tri.begin(), tri.end());
    }
    return !indices->empty();
  }

  // The plane's polygon (its boundary, else its bounds rectangle), front face towards native +Z: into the room.
  void append_plane_polygon(const Anchor& anchor, const NativeFrame& frame, const std::string& where, Scan& out) {
    std::vector<glm::dvec2> unity = anchor.boundary;
    if (unity.empty())
      unity = {anchor.plane->min,
               {anchor.plane->max.x, anchor.plane->min.y},
               anchor.plane->max,
               {anchor.plane->min.x, anchor.plane->max.y}};
    std::vector<glm::dvec3> native;
    native.reserve(unity.size());
    for (const glm::dvec2& p : unity) native.push_back(local_point(frame, {p, 0.0}, where + ".PlaneBoundary2D"));
    std::vector<glm::dvec2> flat;
    flat.reserve(native.size());
    for (const glm::dvec3& p : native) flat.emplace_back(p.x, p.y);
    const std::vector<std::array<std::uint32_t, 3>> triangles = triangulate(flat);
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (const glm::dvec3& p : native) out.vertices.push_back(frame.world(p));
    for (const auto& t : triangles)
      for (const std::uint32_t i : t) out.indices.push_back(base + i);
  }

  // A closed box of 12 triangles facing outwards. The native frame is a proper rotation, so the orientation
  // chosen in local coordinates holds in the world.
  static void append_box(const NativeFrame& frame, const glm::dvec3& lo, const glm::dvec3& hi, Scan& out) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    std::array<glm::dvec3, 8> corners{};
    for (std::uint32_t c = 0; c < 8; ++c) {
      corners[c] = {(c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z};
      out.vertices.push_back(frame.world(corners[c]));
    }
    static constexpr std::array<std::array<std::uint32_t, 4>, 6> kFaces = {
        {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}};  // each a cycle
    const glm::dvec3 centre = (lo + hi) * 0.5;
    for (std::array<std::uint32_t, 4> f : kFaces) {
      const glm::dvec3 normal = glm::cross(corners[f[1]] - corners[f[0]], corners[f[2]] - corners[f[0]]);
      const glm::dvec3 face_centre = (corners[f[0]] + corners[f[2]]) * 0.5;
      if (glm::dot(normal, face_centre - centre) < 0.0) std::swap(f[1], f[3]);
      for (const std::uint32_t i : {f[0], f[1], f[2], f[0], f[2], f[3]}) out.indices.push_back(base + i);
    }
  }

  // Ear clipping of a simple polygon; triangles counter-clockwise (front towards +Z) whatever the input's
  // orientation. A self-touching or degenerate polygon, where no ear is found, is cut at its first vertex
  // anyway so the loop always ends; zero-area triangles are dropped.
  std::vector<std::array<std::uint32_t, 3>> triangulate(const std::vector<glm::dvec2>& p) {
    const auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
      return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    double twice_area = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const glm::dvec2& a = p[i];
      const glm::dvec2& b = p[(i + 1) % p.size()];
      twice_area += a.x * b.y - b.x * a.y;
    }
    std::vector<std::uint32_t> ring(p.size());
    std::iota(ring.begin(), ring.end(), 0u);
    if (twice_area < 0.0) std::reverse(ring.begin(), ring.end());

    std::vector<std::array<std::uint32_t, 3>> triangles;
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      if (cross(p[a], p[b], p[c]) > 0.0) triangles.push_back({a, b, c});
    };
    while (ring.size() > 3) {
      const std::size_t m = ring.size();
      std::size_t ear = m;
      for (std::size_t i = 0; i < m && ear == m; ++i) {
        const std::uint32_t ia = ring[(i + m - 1) % m], ib = ring[i], ic = ring[(i + 1) % m];
        const glm::dvec2 &a = p[ia], &b = p[ib], &c = p[ic];
        if (cross(a, b, c) <= 0.0) continue;  // reflex or flat: no ear
        if (budget_ < m) fail("its PlaneBoundary2D polygons are too complex to triangulate");
        budget_ -= m;
        bool empty = true;
        for (std::size_t k = 0; k < m && empty; ++k) {
          const std::uint32_t ik = ring[k];
          if (ik == ia || ik == ib || ik == ic) continue;
          const glm::dvec2& q = p[ik];
          if (q == a || q == b || q == c) continue;
          if (cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 && cross(c, a, q) >= 0.0) empty = false;
        }
        if (empty) ear = i;
      }
      if (ear == m) ear = 0;
      emit(ring[(ear + m - 1) % m], ring[ear], ring[(ear + 1) % m]);
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    if (ring.size() == 3) emit(ring[0], ring[1], ring[2]);
    return triangles;
  }

  const std::string& source_;
  bool unreal_ = false;
  std::uint64_t budget_ = kTriangulationBudget;
};

// Stops at the first top-level key that tells MRUK ("Rooms") from a Quest capture ("spatialEntities").
class TopLevelSniffer final : public json::json_sax_t {
 public:
  bool rooms = false;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    ++depth_;
    return true;
  }
  bool end_object() override { return --depth_ > 0; }
  bool start_array(std::size_t) override { return ++depth_ > 1; }  // a top-level array is no room file
  bool end_array() override {
    --depth_;
    return true;
  }
  bool key(string_t& name) override {
    if (depth_ != 1) return true;
    if (name == "Rooms") rooms = true;
    return !rooms && name != "spatialEntities";
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool value() const { return depth_ > 0; }  // a bare top-level value is no room file
  int depth_ = 0;
};

}  // namespace

QuestCapture parse_mruk_room(std::string_view json_text, const std::string& source_name) {
  const json root = json::parse(json_text.begin(), json_text.end(), nullptr, /*allow_exceptions=*/false);
  return Reader(source_name).read(root);
}

QuestCapture load_mruk_room(const std::string& path) {
  std::ifstream in = open_scan_file(path);
  const json root = json::parse(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), nullptr,
                                /*allow_exceptions=*/false);
  if (in.bad()) throw_read_error(path, "reading it failed");
  return Reader(path).read(root);
}

QuestCapture load_scene_capture(const std::string& path) {
  return is_mruk_room_json(file_head(path, std::size_t{1} << 20)) ? load_mruk_room(path) : load_quest_capture(path);
}

bool is_mruk_room_json(std::string_view json_text) {
  constexpr std::size_t kSniffBytes = std::size_t{1} << 20;
  const std::string_view head = json_text.substr(0, kSniffBytes);
  TopLevelSniffer sniffer;
  static_cast<void>(json::sax_parse(head.begin(), head.end(), &sniffer));
  return sniffer.rooms;
}

}  // namespace roomsense::scanio
