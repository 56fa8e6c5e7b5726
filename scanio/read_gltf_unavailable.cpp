// read_gltf_file in a build without assimp (the Windows cross build: Debian has no MinGW assimp). The file is
// refused with one line that says why, as any unreadable file is; OBJ and PLY have their own readers.
#include "read_gltf.h"

#include "scan_file.h"

namespace roomsense::scanio {

Scan read_gltf_file(const std::string& path) {
  throw_read_error(path, "this build of roomsense reads no glTF (it was built without assimp); use .obj or .ply");
}

}  // namespace roomsense::scanio
