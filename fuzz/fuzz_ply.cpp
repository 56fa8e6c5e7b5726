// The PLY reader on arbitrary bytes (see mesh_reader.h): ASCII and binary, either endianness. Dictionary: ply.dict.
#include "mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
#if ROOMSENSE_FUZZ_STREAM_READERS
  return roomsense::fuzz::read_mesh<roomsense::scanio::read_ply>(data, size, ".ply", "fuzz_ply");
#else
  return roomsense::fuzz::load_mesh(data, size, ".ply", "fuzz_ply");
#endif
}
