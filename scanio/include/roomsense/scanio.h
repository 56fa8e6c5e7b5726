// Reading room scans from files, for the CLI, the simulated runtime, tests and benchmarks (never the layer:
// it must not pull assimp into an app's process).
#pragma once
#include "roomsense/scan.h"

#include <string>

namespace roomsense::scanio {

// OBJ, PLY, glTF and GLB through assimp. Every mesh of the file is merged into one Scan, with node
// transforms applied; polygons are triangulated; identical vertices are joined. A file of points only
// (a PLY point cloud) gives a Scan without indices. Throws Error(Io) with one clear line on failure.
Scan load_mesh_file(const std::string& path);

}  // namespace roomsense::scanio
