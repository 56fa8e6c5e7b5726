// Reading room scans from files, for the CLI, the simulated runtime, tests and benchmarks (never the layer:
// it must not pull assimp into an app's process).
#pragma once
#include "roomsense/scan.h"

#include <istream>
#include <string>

namespace roomsense::scanio {

// A mesh file, by its content ("ply" magic) and extension (case-insensitive): OBJ through tinyobjloader,
// PLY through our own validating reader, glTF and GLB through assimp. Polygons are fan-triangulated. OBJ and
// PLY keep the file's vertices as they are (no joining of equal positions), less those no triangle uses; glTF
// merges every mesh with its node transform and joins identical vertices. A file of points only (a PLY point cloud) gives a Scan without indices. Throws Error(Io) with one
// line, "cannot read '<path>': ...", on failure (also when the path is a directory, FIFO or device).
Scan load_mesh_file(const std::string& path);

// The OBJ and PLY readers on any stream (fuzzers, tests); `name` stands for the file in messages. Faces of
// fewer than three vertices are skipped (their indices are still checked); an index out of range is an
// error naming the face and the index. See read_obj.cpp and read_ply.cpp for exactly what is read.
Scan read_obj(std::istream& in, const std::string& name);
Scan read_ply(std::istream& in, const std::string& name);

}  // namespace roomsense::scanio
