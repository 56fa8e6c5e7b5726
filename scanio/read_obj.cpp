// OBJ through Debian's tinyobjloader, by its streaming callback API: only positions and triangle indices are
// kept. Its other API stores normals, texture coordinates and a heap vector per face, several times the
// memory of what the pipeline needs (assimp, before, peaked at 6.6 GB for 10M vertices).
//
// What is read: `v` lines (a w is ignored) and `f` lines in every form (i, i/j, i//k, i/j/k), with negative
// indices relative to the vertices read so far. Polygons are fan-triangulated; faces of one or two vertices
// carry no surface and are skipped, but their indices are checked like any other. A face may refer to a
// vertex defined later in the file (as assimp allowed); every index is checked once the file is read. The
// first bad index is an error naming the face (numbered from 1, in file order, like OBJ's vertices) and the
// index as written. Lines tinyobjloader does not know (l, p, curves, mtllib, ...) are ignored. In a file with
// triangles, vertices no triangle uses are dropped (scan_file.h says why); one without keeps them as points.
#include "roomsense/scanio.h"

#include "scan_file.h"

#include <tiny_obj_loader.h>

#include <cstdint>
#include <limits>
#include <string>

namespace roomsense::scanio {
namespace {

struct ObjReader {
  const std::string& name;
  Scan scan;
  std::uint64_t faces = 0;
  // The largest 1-based index seen and the face it is in: checked against the vertex count at the end.
  std::uint64_t max_index = 0;
  std::uint64_t max_index_face = 0;

  void vertex(float x, float y, float z) {
    if (scan.vertices.size() >= std::numeric_limits<std::uint32_t>::max())
      throw_read_error(name, "it has more vertices than 32-bit indices can address");
    scan.vertices.emplace_back(x, y, z);
  }

  // Raw OBJ index (1-based, negative = relative, 0 = none) to a 0-based vertex index.
  std::uint32_t resolve(int raw) {
    const std::uint64_t defined = scan.vertices.size();
    if (raw > 0) {
      const auto one_based = std::uint64_t(raw);
      if (one_based > max_index) max_index = one_based, max_index_face = faces;
      return std::uint32_t(one_based - 1);
    }
    if (raw == 0) throw_read_error(name, "face " + std::to_string(faces) + " has a missing or zero vertex index");
    const std::uint64_t back = std::uint64_t(-std::int64_t(raw));
    if (back > defined)
      throw_read_error(name, "face " + std::to_string(faces) + " refers to vertex " + std::to_string(raw) +
                                 ", but only " + std::to_string(defined) + " vertices precede it");
    return std::uint32_t(defined - back);
  }

  void face(const tinyobj::index_t* indices, int count) {
    ++faces;
    if (count < 3) {
      for (int k = 0; k < count; ++k) resolve(indices[k].vertex_index);
      return;
    }
    const std::uint32_t first = resolve(indices[0].vertex_index);
    std::uint32_t previous = resolve(indices[1].vertex_index);
    for (int k = 2; k < count; ++k) {
      const std::uint32_t current = resolve(indices[k].vertex_index);
      scan.indices.insert(scan.indices.end(), {first, previous, current});
      previous = current;
    }
  }
};

}  // namespace

Scan read_obj(std::istream& in, const std::string& name) {
  ObjReader reader{name, {}};
  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
    static_cast<ObjReader*>(self)->vertex(x, y, z);
  };
  callbacks.index_cb = [](void* self, tinyobj::index_t* indices, int count) {
    static_cast<ObjReader*>(self)->face(indices, count);
  };
  std::string warnings, errors;
  // Our callbacks throw Error (and std::bad_alloc may come from anywhere): tinyobjloader holds only standard
  // containers while it parses, so the exceptions unwind through it cleanly.
  const bool ok = tinyobj::LoadObjWithCallback(in, callbacks, &reader, nullptr, &warnings, &errors);
  if (!ok) throw_read_error(name, errors.empty() ? "it is not a valid OBJ file" : errors.substr(0, errors.find('\n')));
  if (in.bad()) throw_read_error(name, "reading it failed");
  if (reader.scan.vertices.empty()) throw_read_error(name, "it holds no vertices");
  if (reader.max_index > reader.scan.vertices.size())
    throw_read_error(name, "face " + std::to_string(reader.max_index_face) + " refers to vertex " +
                               std::to_string(reader.max_index) + ", but the file has " +
                               std::to_string(reader.scan.vertices.size()) + " vertices");
  drop_unreferenced_vertices(reader.scan);
  return std::move(reader.scan);
}

}  // namespace roomsense::scanio
