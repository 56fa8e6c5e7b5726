// A guard before assimp reads a PLY file: the header's element counts must fit the file. A header that
// claims a billion vertices in a 200-byte file would otherwise make the reader allocate and loop for them.
#pragma once
#include <string>

namespace roomsense::scanio {

// Throws Error(Io) when `path` is a PLY file whose declared elements cannot fit in its size.
void check_ply_header(const std::string& path);

}  // namespace roomsense::scanio
