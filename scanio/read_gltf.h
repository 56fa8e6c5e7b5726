// glTF and GLB through assimp: the only formats left to it (OBJ and PLY have their own lean readers).
#pragma once
#include "roomsense/scan.h"

#include <string>

namespace roomsense::scanio {

// Every mesh of the file merged into one Scan, node transforms applied, polygons triangulated, identical
// vertices joined. Throws Error(Io) with one line on failure. `path` must name a regular file.
Scan read_gltf_file(const std::string& path);

}  // namespace roomsense::scanio
