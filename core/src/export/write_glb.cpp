// glTF 2.0 binary container (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html#binary-gltf-layout):
// a 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded with zeros, both to 4 bytes.
#include "roomsense/error.h"
#include "roomsense/export.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>

namespace roomsense {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr int kFloat = 5126, kUnsignedInt = 5125, kArrayBuffer = 34962, kElementArrayBuffer = 34963, kTriangles = 4;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
}

template <class T>
std::size_t append_bytes(std::vector<std::uint8_t>& bin, const std::vector<T>& data) {
  const std::size_t offset = bin.size();
  bin.resize(offset + data.size() * sizeof(T));
  if (!data.empty()) std::memcpy(bin.data() + offset, data.data(), data.size() * sizeof(T));
  while (bin.size() % 4 != 0) bin.push_back(0);
  return offset;
}

}  // namespace

void GlbScene::add_mesh(std::string name, const std::vector<glm::vec3>& vertices,
                        const std::vector<std::uint32_t>& indices, std::optional<std::array<float, 4>> rgba) {
  meshes_.push_back({std::move(name), vertices, indices, rgba});
}

std::vector<std::uint8_t> GlbScene::encode() const {
  using nlohmann::json;
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "roomsense"}}}, {"scene", 0}};
  json nodes = json::array(), meshes = json::array(), accessors = json::array(), views = json::array(),
       materials = json::array();
  std::vector<std::uint8_t> bin;
  for (const Mesh& m : meshes_) {
    if (m.vertices.empty() || m.indices.empty()) continue;  // glTF accessors need count >= 1
    glm::vec3 lo = m.vertices.front(), hi = m.vertices.front();
    for (const glm::vec3& v : m.vertices) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    const std::size_t vertex_offset = append_bytes(bin, m.vertices);
    const std::size_t index_offset = append_bytes(bin, m.indices);
    const std::size_t view = views.size(), accessor = accessors.size();
    views.push_back({{"buffer", 0}, {"byteOffset", vertex_offset}, {"byteLength", m.vertices.size() * 12},
                     {"target", kArrayBuffer}});
    views.push_back({{"buffer", 0}, {"byteOffset", index_offset}, {"byteLength", m.indices.size() * 4},
                     {"target", kElementArrayBuffer}});
    accessors.push_back({{"bufferView", view}, {"componentType", kFloat}, {"count", m.vertices.size()},
                         {"type", "VEC3"}, {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
    accessors.push_back({{"bufferView", view + 1}, {"componentType", kUnsignedInt}, {"count", m.indices.size()},
                         {"type", "SCALAR"}});
    json primitive = {{"attributes", {{"POSITION", accessor}}}, {"indices", accessor + 1}, {"mode", kTriangles}};
    if (m.rgba) {
      const auto& c = *m.rgba;
      json material = {{"name", m.name},
                       {"doubleSided", true},
                       {"pbrMetallicRoughness",
                        {{"baseColorFactor", {c[0], c[1], c[2], c[3]}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}}};
      if (c[3] < 1.0f) material["alphaMode"] = "BLEND";
      primitive["material"] = materials.size();
      materials.push_back(material);
    }
    nodes.push_back({{"name", m.name}, {"mesh", meshes.size()}});
    meshes.push_back({{"name", m.name}, {"primitives", json::array({primitive})}});
  }
  json scene_nodes = json::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) scene_nodes.push_back(i);
  doc["scenes"] = json::array({{{"nodes", scene_nodes}}});
  doc["nodes"] = nodes;
  if (!meshes.empty()) {
    doc["meshes"] = meshes;
    doc["accessors"] = accessors;
    doc["bufferViews"] = views;
    doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
  }
  if (!materials.empty()) doc["materials"] = materials;

  std::string text = doc.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  std::vector<std::uint8_t> out;
  const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
  put_u32(out, kGlbMagic);
  put_u32(out, 2);
  put_u32(out, std::uint32_t(total));
  put_u32(out, std::uint32_t(text.size()));
  put_u32(out, kChunkJson);
  out.insert(out.end(), text.begin(), text.end());
  if (!bin.empty()) {
    put_u32(out, std::uint32_t(bin.size()));
    put_u32(out, kChunkBin);
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

void GlbScene::write(const std::string& path) const {
  const std::vector<std::uint8_t> bytes = encode();
  std::ofstream file(path, std::ios::binary);
  if (!file) throw Error(ErrorCode::Io, "cannot write '" + path + "'");
  file.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!file) throw Error(ErrorCode::Io, "cannot write '" + path + "'");
}

void write_glb(const BoundsMesh& mesh, const std::string& path) {
  GlbScene scene;
  scene.add_mesh("room_bounds", mesh.vertices, mesh.indices);
  scene.write(path);
}

}  // namespace roomsense
