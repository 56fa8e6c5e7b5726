#include "scan_file.h"

#include "roomsense/error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

namespace roomsense::scanio {
namespace {

std::string what_it_is(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::not_found: return "no such file";
    case std::filesystem::file_type::directory: return "it is a directory";
    case std::filesystem::file_type::fifo: return "it is not a regular file (a FIFO)";
    case std::filesystem::file_type::character: return "it is not a regular file (a character device)";
    case std::filesystem::file_type::block: return "it is not a regular file (a block device)";
    case std::filesystem::file_type::socket: return "it is not a regular file (a socket)";
    default: return "it is not a regular file";
  }
}

}  // namespace

void throw_read_error(const std::string& name, const std::string& what) {
  throw Error(ErrorCode::Io, "cannot read '" + name + "': " + what);
}

std::string quoted(std::string_view word) {
  std::string out(1, '\'');
  for (const char c : word.substr(0, 32)) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  out += '\'';
  return out;
}

std::ifstream open_scan_file(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);  // follows symlinks
  if (ec && status.type() != std::filesystem::file_type::not_found) throw_read_error(path, ec.message());
  if (status.type() != std::filesystem::file_type::regular) throw_read_error(path, what_it_is(status.type()));
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_read_error(path, errno != 0 ? std::strerror(errno) : "it cannot be opened");
  return in;
}

std::string file_head(const std::string& path, std::size_t bytes) {
  std::ifstream in = open_scan_file(path);
  std::string head(bytes, '\0');
  in.read(head.data(), std::streamsize(bytes));
  head.resize(std::size_t(in.gcount()));
  return head;
}

void drop_unreferenced_vertices(Scan& scan) {
  if (scan.indices.empty()) return;
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> new_index(scan.vertices.size(), kUnused);
  for (const std::uint32_t i : scan.indices) new_index[i] = 0;
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < scan.vertices.size(); ++v)
    if (new_index[v] != kUnused) {
      new_index[v] = kept;
      scan.vertices[kept++] = scan.vertices[v];  // kept <= v: moving down in place is safe
    }
  if (kept == scan.vertices.size()) return;
  scan.vertices.resize(kept);
  for (std::uint32_t& i : scan.indices) i = new_index[i];
}

}  // namespace roomsense::scanio
