// What every scan reader shares: the one shape of their error line and of a word it quotes, a number's sign,
// opening a path only when it is a regular file, and dropping the vertices no face uses. A FIFO would block the
// open, /dev/zero would never end and a directory "opens" on some systems, so the kind of file is checked first
// and named in the message.
#pragma once
#include "roomsense/scan.h"

#include <charconv>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace roomsense::scanio {

// Throws Error(ErrorCode::Io, "cannot read '<name>': <what>").
[[noreturn]] void throw_read_error(const std::string& name, const std::string& what);

// A word of the file as an error message quotes it: its first 32 bytes in single quotes, control bytes (a NUL, a
// tab, an escape) as '?', so that the message stays one printable line whatever the file holds.
std::string quoted(std::string_view word);

// A whole word of the file as a number of type T (std::from_chars); nothing where the word is no such number, or
// one out of T's range. from_chars takes no '+': a leading one is read once, and never before another sign, so
// that "+1.5" is 1.5 and "+-1", "++1" are no numbers (rather than -1).
template <class T>
std::optional<T> number_word(std::string_view word) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '+' && word[1] != '-') word.remove_prefix(1);
  T value{};
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

// Opens `path` for binary reading; throws the read error above when it does not exist, is a directory, a
// FIFO, a device or anything else that is not a regular file, or cannot be opened.
std::ifstream open_scan_file(const std::string& path);

// The first bytes of a regular file (fewer when it is shorter), for telling formats apart by content.
std::string file_head(const std::string& path, std::size_t bytes);

// For a mesh with triangles, keeps only the vertices some triangle uses, in file order, and renumbers the
// indices; a point cloud (no indices) is left alone. Stray points in a mesh file are no surface, and assimp,
// which read these files before, dropped them too: real scans carry some (the HoloLens apartment has 1777),
// and they move levels and storeys in the analysis.
void drop_unreferenced_vertices(Scan& scan);

}  // namespace roomsense::scanio
