#include "roomsense/error.h"
#include "roomsense/export.h"

#include <cstdio>
#include <memory>

namespace roomsense {

void write_obj(const BoundsMesh& mesh, const std::string& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) throw Error(ErrorCode::Io, "cannot write '" + path + "'");
  std::fprintf(file.get(), "# roomsense room bounds: right-handed, +Y up, metres; CCW faces face free space\n");
  for (const glm::vec3& v : mesh.vertices) std::fprintf(file.get(), "v %.6g %.6g %.6g\n", v.x, v.y, v.z);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    std::fprintf(file.get(), "f %u %u %u\n", mesh.indices[t] + 1, mesh.indices[t + 1] + 1, mesh.indices[t + 2] + 1);
  if (std::ferror(file.get())) throw Error(ErrorCode::Io, "cannot write '" + path + "'");
}

void write_bounds(const BoundsMesh& mesh, const std::string& path) {
  const auto ends_with = [&](const char* ext) {
    const std::string e(ext);
    return path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
  };
  if (ends_with(".obj")) write_obj(mesh, path);
  else if (ends_with(".glb")) write_glb(mesh, path);
  else throw Error(ErrorCode::BadParameter, "bounds file '" + path + "' must end in .obj or .glb");
}

}  // namespace roomsense
