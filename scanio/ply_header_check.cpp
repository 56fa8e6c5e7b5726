#include "ply_header_check.h"

#include "roomsense/error.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace roomsense::scanio {
namespace {

std::uint64_t type_size(const std::string& t) {
  static const std::map<std::string, std::uint64_t> sizes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},   {"short", 2},   {"ushort", 2},  {"int16", 2},
      {"uint16", 2}, {"int", 4},   {"uint", 4},  {"int32", 4},   {"uint32", 4},  {"float", 4},   {"float32", 4},
      {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(t);
  return it == sizes.end() ? 1 : it->second;
}

}  // namespace

void check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return;  // not PLY: nothing to check
  bool ascii = false;
  std::uint64_t minimum = 0, count = 0, per_element = 0;
  const auto close_element = [&] {
    // Saturating: a count of 2^60 must not wrap around to something small.
    const std::uint64_t bytes = per_element == 0 ? 0 : count > UINT64_MAX / per_element ? UINT64_MAX : count * per_element;
    minimum = bytes > UINT64_MAX - minimum ? UINT64_MAX : minimum + bytes;
  };
  for (int lines = 0; std::getline(in, line) && lines < 10000; ++lines) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format") {
      std::string kind;
      words >> kind;
      ascii = kind == "ascii";
    } else if (word == "element") {
      close_element();
      std::string name;
      words >> name >> count;
      per_element = 0;
    } else if (word == "property") {
      std::string type;
      words >> type;
      // ASCII needs at least a digit and a separator per value; a list needs at least its count.
      per_element += ascii ? 2 : (type == "list" ? [&] { std::string t; words >> t; return type_size(t); }() : type_size(type));
    } else if (word == "end_header") {
      close_element();
      std::error_code ec;
      const std::uint64_t size = std::filesystem::file_size(path, ec);
      if (!ec && minimum > size)
        throw Error(ErrorCode::Io, "cannot read '" + path + "': its PLY header declares more data (at least " +
                                       std::to_string(minimum) + " bytes) than the file holds (" +
                                       std::to_string(size) + " bytes)");
      return;
    }
  }
}

}  // namespace roomsense::scanio
