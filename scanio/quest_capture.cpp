// Parser for Quest scene captures; see quest_capture.h for the file's conventions.
#include "roomsense/quest_capture.h"

#include "roomsense/error.h"
#include "json_member.h"
#include "scan_file.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace roomsense::scanio {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw Error(ErrorCode::Io, "cannot read Quest capture '" + source + "': " + what);
}

// Strict RFC 4648 decoding: padding only at the end, no stray characters, whole quanta. The bytes go to
// `sink(data, size)` in runs of kBase64Run (a multiple of 12: whole vertices and whole triangles), never as
// one buffer of the whole field: a capture can hold a gigabyte of base64, and the decoded copy would be a
// second gigabyte next to the Scan it is decoded into.
constexpr std::size_t kBase64Run = 3 * 1024;

std::size_t base64_decoded_size(const std::string& text, const std::string& source, const std::string& field) {
  if (text.size() % 4 != 0) fail(source, field + " is not whole base64 (length " + std::to_string(text.size()) + ")");
  std::size_t padding = 0;
  if (!text.empty() && text.back() == '=') padding = (text.size() >= 2 && text[text.size() - 2] == '=') ? 2 : 1;
  return text.size() / 4 * 3 - padding;
}

template <class Sink>
void decode_base64(const std::string& text, const std::string& source, const std::string& field, Sink&& sink) {
  static const std::array<std::int8_t, 256> table = [] {
    std::array<std::int8_t, 256> t{};
    t.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(alphabet[i])] = static_cast<std::int8_t>(i);
    return t;
  }();
  const std::size_t padding = text.size() / 4 * 3 - base64_decoded_size(text, source, field);
  std::array<std::uint8_t, kBase64Run> run{};
  std::size_t used = 0;
  for (std::size_t i = 0; i < text.size(); i += 4) {
    std::uint32_t quantum = 0;
    const bool last = i + 4 == text.size();
    for (std::size_t k = 0; k < 4; ++k) {
      const char c = text[i + k];
      int value = 0;
      if (c == '=' && last && k >= 4 - padding) value = 0;
      else if ((value = table[static_cast<unsigned char>(c)]) < 0) fail(source, field + " holds a character that is not base64");
      quantum = (quantum << 6) | static_cast<std::uint32_t>(value);
    }
    run[used++] = static_cast<std::uint8_t>(quantum >> 16);
    if (!last || padding < 2) run[used++] = static_cast<std::uint8_t>(quantum >> 8);
    if (!last || padding < 1) run[used++] = static_cast<std::uint8_t>(quantum);
    if (used == run.size() || last) {
      sink(run.data(), used);
      used = 0;
    }
  }
}

const json& object_at(const json& parent, const char* key, const std::string& source, const std::string& where) {
  const json* value = member(parent, key);
  if (value == nullptr || !value->is_object()) fail(source, where + " has no object \"" + key + "\"");
  return *value;
}

// Protobuf's JSON form leaves out zero fields: missing reads as 0, anything but a number is an error.
float number_at(const json& parent, const char* key, const std::string& source, const std::string& where) {
  const json* value = member(parent, key);
  if (value == nullptr) return 0.0f;
  if (!value->is_number()) fail(source, where + "." + key + " is not a number");
  const double d = value->get<double>();
  if (!std::isfinite(d) || std::fabs(d) > 1e6) fail(source, where + "." + key + " is out of range");
  return static_cast<float>(d);
}

QuestPose pose_from(const json& locatable, const std::string& source, const std::string& where) {
  const json& position = object_at(locatable, "position", source, where);
  const json& orientation = object_at(locatable, "orientation", source, where);
  QuestPose pose;
  pose.position = {number_at(position, "x", source, where + ".position"), number_at(position, "y", source, where + ".position"),
                   number_at(position, "z", source, where + ".position")};
  const std::string o = where + ".orientation";
  glm::quat q(number_at(orientation, "w", source, o), number_at(orientation, "x", source, o),
              number_at(orientation, "y", source, o), number_at(orientation, "z", source, o));
  const float length = glm::length(q);
  if (!(length > 0.5f && length < 1.5f)) fail(source, o + " is not a unit quaternion");
  pose.orientation = q / length;
  return pose;
}

std::string text_at(const json& parent, const char* key) {
  const json* value = member(parent, key);
  return value != nullptr && value->is_string() ? value->get<std::string>() : std::string();
}

// Decodes one mesh into `out` and then frees its base64 text: the capture's DOM shrinks while the Scan grows.
void append_mesh(json& triangles, const QuestPose& pose, Scan& out, const std::string& source, const std::string& where) {
  json* vertices = triangles.contains("vertices") ? &triangles["vertices"] : nullptr;
  json* indices = triangles.contains("indices") ? &triangles["indices"] : nullptr;
  if (vertices == nullptr || !vertices->is_string()) fail(source, where + ".vertices is not a base64 string");
  if (indices == nullptr || !indices->is_string()) fail(source, where + ".indices is not a base64 string");
  std::string& vertex_text = vertices->get_ref<std::string&>();
  std::string& index_text = indices->get_ref<std::string&>();
  const std::size_t vertex_bytes = base64_decoded_size(vertex_text, source, where + ".vertices");
  const std::size_t index_bytes = base64_decoded_size(index_text, source, where + ".indices");
  if (vertex_bytes % 12 != 0) fail(source, where + ".vertices is not a whole number of float32 xyz");
  if (index_bytes % 12 != 0) fail(source, where + ".indices is not a whole number of uint32 triangles");
  const std::size_t vertex_count = vertex_bytes / 12;
  const std::size_t base = out.vertices.size();
  if (base + vertex_count > UINT32_MAX) fail(source, "too many vertices for 32-bit indices");
  // The counts come from the decoded sizes of strings already in memory: reserving them is safe.
  out.vertices.reserve(base + vertex_count);
  decode_base64(vertex_text, source, where + ".vertices", [&](const std::uint8_t* bytes, std::size_t size) {
    for (std::size_t offset = 0; offset < size; offset += 12) {
      float xyz[3];
      std::memcpy(xyz, bytes + offset, sizeof xyz);  // the file is little-endian, like the hosts we build for
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
        fail(source, where + ".vertices holds a NaN or infinite coordinate");
      out.vertices.push_back(pose.apply({xyz[0], xyz[1], xyz[2]}));
    }
  });
  std::string().swap(vertex_text);
  out.indices.reserve(out.indices.size() + index_bytes / 4);
  decode_base64(index_text, source, where + ".indices", [&](const std::uint8_t* bytes, std::size_t size) {
    for (std::size_t offset = 0; offset < size; offset += 4) {
      std::uint32_t index = 0;
      std::memcpy(&index, bytes + offset, sizeof index);
      if (index >= vertex_count) fail(source, where + ".indices holds index " + std::to_string(index) + " beyond " +
                                                 std::to_string(vertex_count) + " vertices");
      out.indices.push_back(static_cast<std::uint32_t>(base + index));
    }
  });
  std::string().swap(index_text);
}

// Builds the rect pose from a centre and the three axes (columns) of the OpenXR-convention frame, given in the
// entity's frame.
OrientedRect rect_in_entity(const QuestPose& entity, const glm::vec3& centre, const glm::mat3& axes, float width, float height) {
  OrientedRect rect;
  rect.pose.position = entity.apply(centre);
  rect.pose.orientation = glm::normalize(entity.orientation * glm::quat_cast(axes));
  rect.width = width;
  rect.height = height;
  return rect;
}

}  // namespace

OrientedRect plane_rect(const QuestPlane& plane) {
  const glm::vec3 centre(plane.offset.x + plane.extent.x * 0.5f, 0.0f, plane.offset.y + plane.extent.y * 0.5f);
  // X stays X, Y along the rectangle's second side (entity Z), Z (the normal) out of the surface: entity -Y.
  const glm::mat3 axes(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0));
  return rect_in_entity(plane.pose, centre, axes, plane.extent.x, plane.extent.y);
}

OrientedRect volume_top_rect(const QuestVolume& volume) {
  // Which signed entity axis points most nearly up in the world.
  const glm::vec3 up_in_entity = glm::inverse(volume.pose.orientation) * glm::vec3(0, 1, 0);
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(up_in_entity[a]) > std::fabs(up_in_entity[axis])) axis = a;
  const float sign = up_in_entity[axis] >= 0.0f ? 1.0f : -1.0f;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // cyclic order keeps the frame right-handed
  glm::vec3 centre = volume.offset + volume.extent * 0.5f;
  centre[axis] = sign > 0 ? volume.offset[axis] + volume.extent[axis] : volume.offset[axis];
  glm::vec3 x(0), y(0), z(0);
  x[u] = 1.0f;
  z[axis] = sign;
  y = glm::cross(z, x);
  return rect_in_entity(volume.pose, centre, glm::mat3(x, y, z), volume.extent[u], volume.extent[v]);
}

namespace {

QuestCapture capture_from(json& root, const std::string& source) {
  if (root.is_discarded()) fail(source, "it is not valid JSON");
  if (!root.is_object()) fail(source, "the top level is not a JSON object");
  json* entities = root.contains("spatialEntities") ? &root["spatialEntities"] : nullptr;
  if (entities == nullptr || !entities->is_array()) fail(source, "it has no \"spatialEntities\" array");

  QuestCapture capture;
  std::size_t index = 0;
  for (json& entity : *entities) {
    const std::string where = "spatialEntities[" + std::to_string(index++) + "]";
    if (!entity.is_object()) fail(source, where + " is not an object");
    const json* locatable = member(entity, "locatable_META");
    if (locatable == nullptr) {
      ++capture.skipped_entities;
      continue;
    }
    if (!locatable->is_object()) fail(source, where + ".locatable_META is not an object");
    const QuestPose pose = pose_from(*locatable, source, where + ".locatable_META");
    const std::string label = text_at(entity, "semanticLabel_META");
    if (json* mesh = entity.contains("triangleMesh_META") ? &entity["triangleMesh_META"] : nullptr; mesh != nullptr) {
      if (!mesh->is_object()) fail(source, where + ".triangleMesh_META is not an object");
      append_mesh(*mesh, pose, capture.mesh, source, where + ".triangleMesh_META");
    }
    if (const json* rect = member(entity, "bounded2D_META"); rect != nullptr) {
      if (!rect->is_object()) fail(source, where + ".bounded2D_META is not an object");
      const std::string w = where + ".bounded2D_META";
      const json& offset = object_at(*rect, "offset", source, w);
      const json& extent = object_at(*rect, "extent", source, w);
      QuestPlane plane{text_at(entity, "uuid"), label, pose,
                       {number_at(offset, "x", source, w), number_at(offset, "y", source, w)},
                       {number_at(extent, "width", source, w), number_at(extent, "height", source, w)}};
      if (plane.extent.x < 0 || plane.extent.y < 0) fail(source, w + ".extent is negative");
      capture.planes.push_back(std::move(plane));
    }
    if (const json* box = member(entity, "bounded3D_META"); box != nullptr) {
      if (!box->is_object()) fail(source, where + ".bounded3D_META is not an object");
      const std::string w = where + ".bounded3D_META";
      const json& offset = object_at(*box, "offset", source, w);
      const json& extent = object_at(*box, "extent", source, w);
      QuestVolume volume{text_at(entity, "uuid"), label, pose,
                         {number_at(offset, "x", source, w), number_at(offset, "y", source, w), number_at(offset, "z", source, w)},
                         {number_at(extent, "width", source, w), number_at(extent, "height", source, w),
                          number_at(extent, "depth", source, w)}};
      if (volume.extent.x < 0 || volume.extent.y < 0 || volume.extent.z < 0) fail(source, w + ".extent is negative");
      capture.volumes.push_back(std::move(volume));
    }
  }
  if (capture.mesh.vertices.empty()) fail(source, "it holds no triangleMesh_META vertices");
  return capture;
}

}  // namespace

QuestCapture parse_quest_capture(std::string_view json_text, const std::string& source) {
  json root = json::parse(json_text.begin(), json_text.end(), nullptr, /*allow_exceptions=*/false);
  return capture_from(root, source);
}

QuestCapture load_quest_capture(const std::string& path) {
  // Parsed straight from the file: a copy of the whole text next to its DOM would double the peak of a
  // gigabyte capture.
  std::ifstream in = open_scan_file(path);
  json root = json::parse(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), nullptr,
                          /*allow_exceptions=*/false);
  if (in.bad()) throw_read_error(path, "reading it failed");
  return capture_from(root, path);
}

bool is_quest_capture_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".json";
}

}  // namespace roomsense::scanio
