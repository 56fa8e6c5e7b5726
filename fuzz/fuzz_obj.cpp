// The OBJ reader on arbitrary bytes (see mesh_reader.h). Dictionary: obj.dict.
#include "mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
#if ROOMSENSE_FUZZ_STREAM_READERS
  return roomsense::fuzz::read_mesh<roomsense::scanio::read_obj>(data, size, ".obj", "fuzz_obj");
#else
  return roomsense::fuzz::load_mesh(data, size, ".obj", "fuzz_obj");
#endif
}
