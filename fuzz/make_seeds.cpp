// Writes the seed corpora of the fuzz harnesses, made from the synthetic rooms (synthetic.h), so that no binary
// seed is kept in git: roomsense_fuzz_seeds OUTDIR writes OUTDIR/<harness>/<room>[.ext] for the harnesses
// analyze, obj, ply, quest_capture, capi_thesis and capi_handle. Every seed is a few kB to a few tens of kB:
// the rooms are built with large triangles (cell 0) or coarse cells and quantized to each harness's encoding
// (see the comment at the top of each harness).
#include "roomsense/synthetic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using roomsense::Scan;
namespace synth = roomsense::synth;

namespace {

struct Room {
  std::string name;
  Scan scan;
};

// Rooms of a few hundred triangles at most (large triangles), and one denser point cloud each for vertex mode.
std::vector<Room> coarse_rooms() {
  std::vector<Room> rooms;
  auto add = [&](std::string name, synth::RoomSpec spec, float cell) {
    spec.cell = cell;
    spec.noise = 0.0f;
    rooms.push_back({std::move(name), synth::generate(spec)});
  };
  add("default", synth::default_room(), 0.0f);
  add("large-triangles", synth::large_triangle_room(), 0.0f);
  add("rotated-30", synth::rotated_room(30.0f), 0.0f);
  add("pentagon", synth::pentagon_room(), 0.0f);
  synth::RoomSpec empty;
  empty.name = "empty";
  empty.outline = synth::rectangle(4.0f, 3.0f);
  add("empty", empty, 0.0f);
  return rooms;
}

// A small room for the C API harnesses, which compute at the libraries' 0.1 m default: 3 x 2.6 m, 2.2 m high,
// with a box and a table, so that a compute under ASan stays well below a second.
synth::RoomSpec small_room(float yaw_degrees, float cell) {
  synth::RoomSpec spec;
  spec.name = "small";
  spec.outline = synth::rectangle(3.0f, 2.6f, yaw_degrees * 3.14159265f / 180.0f);
  spec.ceiling_y = 2.2f;
  spec.boxes.push_back({{0.8f, 0.6f}, {0.6f, 0.5f}, 0.5f, 0.0f});
  spec.tables.push_back({{-0.5f, -0.3f}, {1.0f, 0.7f}, 0.72f, 0.0f});
  spec.cell = cell;
  spec.noise = 0.0f;
  return spec;
}

// Point clouds of the small room (vertex mode needs points all over each surface).
std::vector<Room> point_rooms() {
  return {{"small-points", synth::generate(small_room(0.0f, 0.2f))},
          {"small-turned-points", synth::generate(small_room(25.0f, 0.2f))}};
}

// At most max_triangles triangles, and only the vertices they use (renumbered).
Scan capped(const Scan& scan, std::size_t max_vertices, std::size_t max_triangles) {
  Scan out;
  std::vector<std::int64_t> map(scan.vertices.size(), -1);
  for (std::size_t t = 0; t + 2 < scan.indices.size() && out.indices.size() / 3 < max_triangles; t += 3) {
    std::size_t needed = 0;
    for (int k = 0; k < 3; ++k) needed += map[scan.indices[t + k]] < 0 ? 1 : 0;
    if (out.vertices.size() + needed > max_vertices) break;
    for (int k = 0; k < 3; ++k) {
      std::int64_t& m = map[scan.indices[t + k]];
      if (m < 0) {
        m = static_cast<std::int64_t>(out.vertices.size());
        out.vertices.push_back(scan.vertices[scan.indices[t + k]]);
      }
      out.indices.push_back(static_cast<std::uint32_t>(m));
    }
  }
  return out;
}

// Evenly spaced points of the scan, at most n.
std::vector<glm::vec3> subsample(const std::vector<glm::vec3>& points, std::size_t n) {
  if (points.size() <= n) return points;
  std::vector<glm::vec3> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(points[i * points.size() / n]);
  return out;
}

// Centred on the box of the points, so that a room fits the C API harnesses' +-2.56 m.
std::vector<glm::vec3> centred(std::vector<glm::vec3> points) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 c = 0.5f * (lo + hi);
  for (glm::vec3& p : points) p -= c;
  return points;
}

struct Bytes {
  std::vector<std::uint8_t> b;
  void u8(unsigned v) { b.push_back(static_cast<std::uint8_t>(v)); }
  void u16(unsigned v) { u8(v & 0xFF), u8((v >> 8) & 0xFF); }
  void i16(int v) { u16(static_cast<unsigned>(v) & 0xFFFF); }
  void quantized(float v) {  // capi_points.h: one byte, v / 0.02 m, 0x80 excluded
    const long q = std::lround(v / 0.02f);
    u8(static_cast<std::uint8_t>(static_cast<std::int8_t>(std::clamp(q, -127L, 127L))));
  }
};

void write(const fs::path& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}
void write(const fs::path& path, const std::string& text) { write(path, text.data(), text.size()); }
void write(const fs::path& path, const Bytes& bytes) { write(path, bytes.b.data(), bytes.b.size()); }

// fuzz_analyze: voxel byte, flags, u16 vertex count, int16 / 2048 coordinates, u16 indices.
Bytes analyze_seed(const Scan& s, std::uint8_t voxel, std::uint8_t flags) {
  Bytes out;
  out.u8(voxel);
  out.u8(flags);
  out.u16(static_cast<unsigned>(s.vertices.size()));
  for (const glm::vec3& v : s.vertices)
    for (int k = 0; k < 3; ++k) out.i16(static_cast<int>(std::lround(std::clamp(v[k] * 2048.0f, -32767.0f, 32767.0f))));
  if ((flags & 64) == 0)
    for (const std::uint32_t i : s.indices) out.u16(i);
  return out;
}

std::string obj_text(const Scan& s) {
  std::ostringstream out;
  out << "# " << s.vertices.size() << " vertices\no room\n";
  for (const glm::vec3& v : s.vertices) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3)
    out << "f " << s.indices[t] + 1 << ' ' << s.indices[t + 1] + 1 << ' ' << s.indices[t + 2] + 1 << '\n';
  return out.str();
}

std::string ply_header(const Scan& s, const char* format) {
  std::ostringstream out;
  out << "ply\nformat " << format << " 1.0\ncomment roomsense fuzz seed\nelement vertex " << s.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << s.indices.size() / 3
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  return out.str();
}

std::string ply_ascii(const Scan& s) {
  std::ostringstream out;
  out << ply_header(s, "ascii");
  for (const glm::vec3& v : s.vertices) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3)
    out << "3 " << s.indices[t] << ' ' << s.indices[t + 1] << ' ' << s.indices[t + 2] << '\n';
  return out.str();
}

std::string ply_binary(const Scan& s) {
  std::string out = ply_header(s, "binary_little_endian");
  auto raw = [&](const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); };
  for (const glm::vec3& v : s.vertices) raw(&v.x, 12);
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
    out.push_back(3);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t i = static_cast<std::int32_t>(s.indices[t + k]);
      raw(&i, 4);
    }
  }
  return out;
}

std::string base64(const void* data, std::size_t size) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const std::uint8_t*>(data);
  std::string out;
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t n = (std::uint32_t{p[i]} << 16) | (i + 1 < size ? std::uint32_t{p[i + 1]} << 8 : 0) |
                            (i + 2 < size ? std::uint32_t{p[i + 2]} : 0);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < size ? table[(n >> 6) & 63] : '=';
    out += i + 2 < size ? table[n & 63] : '=';
  }
  return out;
}

// A Quest capture (quest_capture.h): the room as one GLOBAL_MESH entity at a turned pose (the vertices given in
// its frame), and a floor, a wall and a table plane, and a box.
std::string quest_json(const Scan& s) {
  // Entity pose: 90 degrees about +Y (w, y = cos 45, sin 45), at (0.5, 0, -0.25). Vertices in its frame: the
  // inverse rotation, -90 degrees about +Y maps (x, y, z) to (-z, y, x).
  std::vector<float> xyz;
  for (const glm::vec3& v : s.vertices) {
    const glm::vec3 p = v - glm::vec3(0.5f, 0.0f, -0.25f);
    xyz.insert(xyz.end(), {-p.z, p.y, p.x});
  }
  const std::vector<std::uint32_t>& idx = s.indices;
  std::ostringstream out;
  out << R"({"type":"scene","version":1,"spatialEntities":[)"
      << R"({"uuid":"00000000-0000-0000-0000-000000000001","semanticLabel_META":"FLOOR","locatable_META":)"
      << R"({"orientation":{"x":1,"w":0},"position":{"y":0.01}},"bounded2D_META":{"offset":{"x":-2,"y":-1.5},)"
      << R"("extent":{"width":4,"height":3}}},)"
      << R"({"uuid":"00000000-0000-0000-0000-000000000002","semanticLabel_META":"WALL_FACE","locatable_META":)"
      << R"({"orientation":{"x":0.7071068,"w":0.7071068},"position":{"z":-1.5,"y":1.3}},"bounded2D_META":)"
      << R"({"offset":{"x":-2,"y":-1.3},"extent":{"width":4,"height":2.6}}},)"
      << R"({"uuid":"00000000-0000-0000-0000-000000000003","semanticLabel_META":"TABLE","locatable_META":)"
      << R"({"orientation":{"x":-0.7071068,"w":0.7071068},"position":{"x":0.5,"y":0.75}},"bounded3D_META":)"
      << R"({"offset":{"x":-0.6,"y":-0.4,"z":-0.75},"extent":{"width":1.2,"height":0.8,"depth":0.75}}},)"
      << R"({"uuid":"00000000-0000-0000-0000-000000000004","semanticLabel_META":"GLOBAL_MESH","locatable_META":)"
      << R"({"orientation":{"y":0.7071068,"w":0.7071068},"position":{"x":0.5,"z":-0.25}},"triangleMesh_META":)"
      << R"({"vertices":")" << base64(xyz.data(), xyz.size() * 4) << R"(","indices":")"
      << base64(idx.data(), idx.size() * 4) << R"("}}]})";
  return out.str();
}

// fuzz_capi_thesis: start understanding, wait, retrieve; start bounds, wait, retrieve; clean up both.
Bytes thesis_seed(const std::vector<glm::vec3>& points) {
  Bytes out;
  auto start = [&](unsigned op) {
    out.u8(op);
    out.u8(0);
    out.u16(static_cast<unsigned>(3 * points.size()));
    for (const glm::vec3& p : points)
      for (int k = 0; k < 3; ++k) out.quantized(p[k]);
  };
  start(0);
  out.u8(6), out.u8(2), out.u8(0);
  start(1);
  out.u8(7), out.u8(3), out.u8(0);
  out.u8(4), out.u8(5);
  return out;
}

// fuzz_capi_handle's create of slot 0 with the defaults (0.1 m voxels).
void handle_create(Bytes& out) {
  out.u8(0), out.u8(0);                                   // create, slot 0
  out.u8(0), out.u8(0), out.u8(1), out.u8(1), out.u8(0), out.u8(0);  // how, struct_size, voxel, threads, flags, enums
}

// fuzz_capi_handle's caller mesh (caller_mesh): the scan with its triangles.
void handle_mesh(Bytes& out, const Scan& s) {
  out.u8(2);                                              // with indices
  out.u16(static_cast<unsigned>(s.vertices.size()));
  for (const glm::vec3& v : s.vertices)
    for (int k = 0; k < 3; ++k) out.quantized(v[k]);
  out.u16(static_cast<unsigned>(s.indices.size()));
  for (const std::uint32_t i : s.indices) out.u16(i);
}

// fuzz_capi_handle: create (defaults, 0.1 m), compute (triangles), wait, then every getter and query, destroy.
Bytes handle_seed(const Scan& s) {
  Bytes out;
  handle_create(out);
  out.u8(1), out.u8(0);                                   // compute, slot 0
  handle_mesh(out, s);
  out.u8(3), out.u8(0), out.u8(3);                        // wait, infinite
  out.u8(4), out.u8(0), out.u8(0);                        // layout
  out.u8(5), out.u8(0), out.u8(0), out.u8(1);             // storeys, capacity = count
  out.u8(6), out.u8(0), out.u8(0), out.u8(1);             // areas
  out.u8(7), out.u8(0), out.u8(0), out.u8(1), out.u8(1);  // bounds
  out.u8(8), out.u8(0), out.u8(1);                        // message
  out.u8(11), out.u8(0), out.u8(0);                       // find placements, slot 0, how
  out.u8(2), out.u8(2), out.u8(2), out.u8(15);            // a 0.3 m cube on any surface
  out.u8(0), out.u8(0), out.u8(0), out.u8(0), out.u8(0);  // no clearances, any reach, no user
  for (int k = 0; k < 3; ++k) out.quantized(0.0f);
  out.u8(0), out.u8(0);                                   // default user reach, no near point
  for (int k = 0; k < 3; ++k) out.quantized(0.0f);
  out.u8(3), out.u8(0), out.u16(7), out.u16(0);           // 3 placements, no overlap, seed 7
  out.u8(0), out.u8(1);                                   // two calls, capacity = count
  out.u8(12), out.u8(0), out.u8(0);                       // raycast from the origin
  for (int k = 0; k < 3; ++k) out.quantized(0.0f);
  out.quantized(1.0f), out.quantized(-0.5f), out.quantized(0.0f), out.u8(0);
  out.u8(12), out.u8(0), out.u8(2);                       // a random point on floor or ceiling
  for (int k = 0; k < 6; ++k) out.quantized(0.0f);        // (the unused ray)
  out.u8(6), out.u8(1), out.u16(3), out.u16(0);
  out.u8(9), out.u8(0);                                   // destroy
  return out;
}

// fuzz_capi_handle, API 1.3: create, the scan as chunk 0, compute the chunks, wait, areas, chunk 0 removed,
// compute the chunks (no chunk left), destroy.
Bytes handle_chunks_seed(const Scan& s) {
  Bytes out;
  handle_create(out);
  out.u8(13), out.u8(0), out.u8(0);                       // set chunk, slot 0, id 0
  handle_mesh(out, s);
  out.u8(15), out.u8(0), out.u8(0);                       // compute the chunks
  out.u8(3), out.u8(0), out.u8(3);                        // wait, infinite
  out.u8(6), out.u8(0), out.u8(0), out.u8(1);             // areas
  out.u8(14), out.u8(0), out.u8(0);                       // remove chunk 0
  out.u8(15), out.u8(0), out.u8(0);                       // compute the chunks: none left
  out.u8(9), out.u8(0);                                   // destroy
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
    return 2;
  }
  const fs::path root = argv[1];
  for (const char* h : {"analyze", "obj", "ply", "quest_capture", "capi_thesis", "capi_handle"})
    fs::create_directories(root / h);
  std::size_t files = 0;
  for (const Room& room : coarse_rooms()) {
    const Scan small = capped(room.scan, 512, 300);
    write(root / "analyze" / (room.name + "-triangles"), analyze_seed(small, 85, 0));  // 0.2 m voxels
    write(root / "analyze" / (room.name + "-coarse"), analyze_seed(small, 142, 32));   // 0.3 m, no plateaus
    write(root / "obj" / (room.name + ".obj"), obj_text(small));
    write(root / "ply" / (room.name + ".ply"), ply_ascii(small));
    write(root / "ply" / (room.name + "-binary.ply"), ply_binary(small));
    write(root / "quest_capture" / (room.name + ".json"), quest_json(small));
    files += 6;
  }
  for (const float yaw : {0.0f, 30.0f}) {
    Scan s = capped(synth::generate(small_room(yaw, 0.0f)), 1024, 300);
    s.vertices = centred(s.vertices);
    write(root / "capi_handle" / ("small-" + std::to_string(static_cast<int>(yaw))), handle_seed(s));
    write(root / "capi_handle" / ("chunks-" + std::to_string(static_cast<int>(yaw))), handle_chunks_seed(s));
    files += 2;
  }
  for (const Room& room : point_rooms()) {
    const std::vector<glm::vec3> points = centred(subsample(room.scan.vertices, 1024));
    Scan cloud;
    cloud.vertices = subsample(room.scan.vertices, 512);
    write(root / "analyze" / (room.name + "-vertices"), analyze_seed(cloud, 85, 1 | 64));
    write(root / "capi_thesis" / room.name, thesis_seed(points));
    files += 2;
  }
  std::printf("wrote %zu seeds to %s\n", files, root.string().c_str());
  return 0;
}
