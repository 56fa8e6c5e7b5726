// Which reader a mesh file goes to. By content first for PLY (its "ply" magic, whatever the file is called),
// then by extension, case-insensitively: .obj to tinyobjloader, .ply to our PLY reader (which then says the
// magic is missing), .gltf/.glb to assimp. Anything else is refused by name, rather than handed to assimp's
// dozens of importers that nobody tests here.
#include "roomsense/scanio.h"

#include "read_gltf.h"
#include "scan_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace roomsense::scanio {
namespace {

bool starts_with_ply_magic(const std::string& head) {
  return head.rfind("ply\n", 0) == 0 || head.rfind("ply\r\n", 0) == 0;
}

}  // namespace

Scan load_mesh_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string head = file_head(path, 5);  // also refuses directories, FIFOs and devices by name
  if (starts_with_ply_magic(head) || ext == ".ply") {
    std::ifstream in = open_scan_file(path);
    return read_ply(in, path);
  }
  if (ext == ".obj") {
    std::ifstream in = open_scan_file(path);
    return read_obj(in, path);
  }
  if (ext == ".gltf" || ext == ".glb" || head.rfind("glTF", 0) == 0) return read_gltf_file(path);
  throw_read_error(path, (ext.empty() ? std::string("it has no extension and is not PLY")
                                      : "unknown mesh format '" + ext + "'") +
                             " (roomsense reads .obj, .ply, .gltf and .glb)");
}

}  // namespace roomsense::scanio
