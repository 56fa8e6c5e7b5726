// OBJ through Debian's tinyobjloader, by its streaming callback API: only positions and triangle indices are
// kept. Its other API stores normals, texture coordinates and a heap vector per face, several times the
// memory of what the pipeline needs (assimp, before, peaked at 6.6 GB for 10M vertices).
//
// What is read: `v` lines (a w is ignored) and `f` lines in every form (i, i/j, i//k, i/j/k), with negative
// indices relative to the vertices read so far. Polygons are fan-triangulated; faces of one or two vertices
// carry no surface and are skipped, but their indices are checked like any other. A face may refer to a
// vertex defined later in the file (as assimp allowed); every index is checked once the file is read. The
// first bad index is an error naming the face (numbered from 1, in file order, like OBJ's vertices) and the
// index as written. Lines tinyobjloader does not know (l, p, curves, mtllib, ...) are ignored. In a file with
// triangles, vertices no triangle uses are dropped (scan_file.h says why); one without keeps them as points.
// A vertex's three coordinates are checked as the file is read (CheckedVertexLines): tinyobjloader alone reads
// "nan", "inf", "1,5" or a missing coordinate as 0 without a word.
#include "roomsense/scanio.h"

#include "scan_file.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <istream>
#include <limits>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>

namespace roomsense::scanio {
namespace {

// Whether `token` is a number as tinyobjloader's parser reads it whole: [+-] digits [. digits] [e [+-] digits], or
// [+-] . digits [e [+-] digits]. Its value is then tinyobjloader's.
bool plain_number(std::string_view token) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < token.size() && token[i] >= '0' && token[i] <= '9') ++i;
    return i - from;
  };
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < token.size() && token[i] == '.') ++i, mantissa += digits();
  if (mantissa == 0) return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == token.size();
}

// The file as tinyobjloader reads it, in blocks of whole lines, each `v` line's coordinates checked on the way:
// three of them, each a number. A coordinate that is not plain_number but a value that is not finite ("nan", "inf",
// "-infinity", as std::from_chars reads them, whatever the locale) keeps that value, where tinyobjloader reads 0:
// the pipeline skips a vertex that is not finite and says how many it skipped, as for PLY. Anything else ("1,5",
// "1.5e", a missing coordinate) ends the stream and is the read's error, naming the line.
class CheckedVertexLines : public std::streambuf {
 public:
  explicit CheckedVertexLines(std::streambuf& source) : source_(source) {}
  // The vertex tinyobjloader reports next (in the `v` lines' order), as it read it: with the values of the
  // coordinates it read as 0.
  glm::vec3 vertex(glm::vec3 read) {
    ++vertices_taken_;
    if (replaced_.empty() || replaced_.front().vertex != vertices_taken_) return read;
    const Replaced r = replaced_.front();
    replaced_.pop_front();
    for (int axis = 0; axis < 3; ++axis)
      if (r.axes[axis]) read[axis] = r.value[axis];
    return read;
  }
  const std::string& error() const { return error_; }

 protected:
  // The next block of whole lines, each checked; the last line left for the next block where it may go on. Read in
  // 64 KiB blocks and scanned by hand: a line at a time, through std::string's find_first_of, cost 20-40 % more than
  // tinyobjloader's own reading, this about 5 % (a 4.9 MB scan: 43.5 -> 45.6 ms).
  int_type underflow() override {
    constexpr std::size_t kBlock = 1 << 16;
    if (!error_.empty()) return traits_type::eof();
    buffer_.erase(0, exposed_);  // what tinyobjloader has read; the rest is the start of a line
    exposed_ = 0;
    std::size_t end = std::string::npos;  // past the last terminator whose line is whole
    bool at_eof = false;
    while (end == std::string::npos && !at_eof) {
      const std::size_t before = buffer_.size();
      buffer_.resize(before + kBlock);
      const std::streamsize got = source_.sgetn(buffer_.data() + before, std::streamsize(kBlock));
      buffer_.resize(before + std::size_t(std::max<std::streamsize>(got, 0)));
      at_eof = got <= 0;
      // A \r at the very end may be the first half of \r\n: its line ends in the next block.
      for (std::size_t i = buffer_.size(); i > before && end == std::string::npos; --i) {
        const char c = buffer_[i - 1];
        if (c == '\n' || (c == '\r' && i < buffer_.size())) end = i;
      }
    }
    if (end == std::string::npos) end = buffer_.size();  // the file's last line, without a terminator
    if (end == 0) return traits_type::eof();
    for (std::size_t from = 0; from < end && error_.empty();) {
      std::size_t to = from;
      while (to < end && buffer_[to] != '\n' && buffer_[to] != '\r') ++to;
      ++line_number_;
      check(std::string_view(buffer_).substr(from, to - from));
      from = to + (to + 1 < buffer_.size() && buffer_[to] == '\r' && buffer_[to + 1] == '\n' ? 2 : 1);
    }
    if (!error_.empty()) return traits_type::eof();
    exposed_ = end;
    setg(buffer_.data(), buffer_.data(), buffer_.data() + end);
    return traits_type::to_int_type(buffer_[0]);
  }

 private:
  void check(std::string_view line) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    const auto skip_blanks = [&] {
      while (!line.empty() && blank(line.front())) line.remove_prefix(1);
    };
    skip_blanks();
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) return;
    line.remove_prefix(2);
    ++vertex_lines_;
    Replaced r{vertex_lines_, glm::vec3(0.0f), glm::bvec3(false)};
    for (int axis = 0; axis < 3; ++axis) {
      skip_blanks();
      std::size_t length = 0;
      while (length < line.size() && !blank(line[length])) ++length;
      const std::string_view token = line.substr(0, length);
      line.remove_prefix(token.size());
      if (token.empty() || token[0] == '#') {
        fail("a vertex needs three coordinates");
        return;
      }
      if (plain_number(token)) continue;
      const std::optional<float> value = number_word<float>(token);
      if (!value || std::isfinite(*value)) {
        fail("vertex coordinate " + quoted(token) + " is not a number");
        return;
      }
      r.value[axis] = *value, r.axes[axis] = true;
    }
    if (r.axes.x || r.axes.y || r.axes.z) replaced_.push_back(r);
  }
  void fail(const std::string& what) { error_ = "line " + std::to_string(line_number_) + ": " + what; }

  std::streambuf& source_;
  std::string buffer_;         // lines read from source_: those before exposed_ given to tinyobjloader
  std::size_t exposed_ = 0;
  std::uint64_t line_number_ = 0, vertex_lines_ = 0, vertices_taken_ = 0;
  struct Replaced {
    std::uint64_t vertex;  // its number, from 1
    glm::vec3 value;       // on `axes`
    glm::bvec3 axes;
  };
  std::deque<Replaced> replaced_;  // in order; those tinyobjloader has not reported yet
  std::string error_;
};

struct ObjReader {
  const std::string& name;
  CheckedVertexLines& lines;
  Scan scan;
  std::uint64_t faces = 0;
  // The largest 1-based index seen and the face it is in: checked against the vertex count at the end.
  std::uint64_t max_index = 0;
  std::uint64_t max_index_face = 0;

  void vertex(float x, float y, float z) {
    if (scan.vertices.size() >= std::numeric_limits<std::uint32_t>::max())
      throw_read_error(name, "it has more vertices than 32-bit indices can address");
    scan.vertices.push_back(lines.vertex(glm::vec3(x, y, z)));
  }

  // Raw OBJ index (1-based, negative = relative, 0 = none) to a 0-based vertex index.
  std::uint32_t resolve(int raw) {
    const std::uint64_t defined = scan.vertices.size();
    if (raw > 0) {
      const auto one_based = std::uint64_t(raw);
      if (one_based > max_index) max_index = one_based, max_index_face = faces;
      return std::uint32_t(one_based - 1);
    }
    if (raw == 0) throw_read_error(name, "face " + std::to_string(faces) + " has a missing or zero vertex index");
    const std::uint64_t back = std::uint64_t(-std::int64_t(raw));
    if (back > defined)
      throw_read_error(name, "face " + std::to_string(faces) + " refers to vertex " + std::to_string(raw) +
                                 ", but only " + std::to_string(defined) + " vertices precede it");
    return std::uint32_t(defined - back);
  }

  void face(const tinyobj::index_t* indices, int count) {
    ++faces;
    if (count < 3) {
      for (int k = 0; k < count; ++k) resolve(indices[k].vertex_index);
      return;
    }
    const std::uint32_t first = resolve(indices[0].vertex_index);
    std::uint32_t previous = resolve(indices[1].vertex_index);
    for (int k = 2; k < count; ++k) {
      const std::uint32_t current = resolve(indices[k].vertex_index);
      scan.indices.insert(scan.indices.end(), {first, previous, current});
      previous = current;
    }
  }
};

}  // namespace

Scan read_obj(std::istream& in, const std::string& name) {
  if (in.rdbuf() == nullptr) throw_read_error(name, "reading it failed");
  CheckedVertexLines lines(*in.rdbuf());
  std::istream checked(&lines);
  ObjReader reader{name, lines, {}};
  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
    static_cast<ObjReader*>(self)->vertex(x, y, z);
  };
  callbacks.index_cb = [](void* self, tinyobj::index_t* indices, int count) {
    static_cast<ObjReader*>(self)->face(indices, count);
  };
  std::string warnings, errors;
  // Our callbacks throw Error (and std::bad_alloc may come from anywhere): tinyobjloader holds only standard
  // containers while it parses, so the exceptions unwind through it cleanly.
  const bool ok = tinyobj::LoadObjWithCallback(checked, callbacks, &reader, nullptr, &warnings, &errors);
  if (!lines.error().empty()) throw_read_error(name, lines.error());
  if (!ok) throw_read_error(name, errors.empty() ? "it is not a valid OBJ file" : errors.substr(0, errors.find('\n')));
  if (in.bad() || checked.bad()) throw_read_error(name, "reading it failed");  // checked: a source that threw
  if (reader.scan.vertices.empty()) throw_read_error(name, "it holds no vertices");
  if (reader.max_index > reader.scan.vertices.size())
    throw_read_error(name, "face " + std::to_string(reader.max_index_face) + " refers to vertex " +
                               std::to_string(reader.max_index) + ", but the file has " +
                               std::to_string(reader.scan.vertices.size()) + " vertices");
  drop_unreferenced_vertices(reader.scan);
  return std::move(reader.scan);
}

}  // namespace roomsense::scanio
