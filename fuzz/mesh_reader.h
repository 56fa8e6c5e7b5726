// The body of the mesh-file reader harnesses (fuzz_obj.cpp, fuzz_ply.cpp): the bytes are the file. With the
// stream readers (scanio.h's read_obj / read_ply; CMake defines ROOMSENSE_FUZZ_STREAM_READERS when the header
// declares them) the bytes go through an istream; otherwise through load_mesh_file on a file in a private tmpfs
// directory (/dev/shm), which is slower but reaches the same parser. Error(Io) is the readers' documented answer
// to bad input; any other exception, a sanitizer report, or a Scan with an index out of range is a finding.
#pragma once
#include "roomsense/error.h"
#include "roomsense/scanio.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#if ROOMSENSE_FUZZ_STREAM_READERS
#include <sstream>
#else
#include <filesystem>
#include <fstream>
#include <unistd.h>
#endif

namespace roomsense::fuzz {

inline void check_scan(const Scan& scan, const char* harness) {
  const bool whole = scan.indices.size() % 3 == 0;
  bool in_range = true;
  for (const std::uint32_t i : scan.indices) in_range = in_range && i < scan.vertices.size();
  if (!whole || !in_range) {
    std::fprintf(stderr, "%s: invariant broken: %s\n", harness, whole ? "index out of range" : "partial triangle");
    std::abort();
  }
}

#if ROOMSENSE_FUZZ_STREAM_READERS
template <Scan (*Read)(std::istream&, const std::string&)>
int read_mesh(const std::uint8_t* data, std::size_t size, const char* extension, const char* harness) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    check_scan(Read(in, std::string("fuzz") + extension), harness);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Io) {
      std::fprintf(stderr, "%s: Error with code %d, expected Io: %s\n", harness, static_cast<int>(e.code()), e.what());
      std::abort();
    }
  }
  return 0;
}
#else
inline int load_mesh(const std::uint8_t* data, std::size_t size, const char* extension, const char* harness) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::path("/dev/shm") / ("roomsense-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::filesystem::path file = dir / (std::string("input") + extension);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    check_scan(scanio::load_mesh_file(file.string()), harness);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Io) {
      std::fprintf(stderr, "%s: Error with code %d, expected Io: %s\n", harness, static_cast<int>(e.code()), e.what());
      std::abort();
    }
  }
  return 0;
}
#endif

}  // namespace roomsense::fuzz
