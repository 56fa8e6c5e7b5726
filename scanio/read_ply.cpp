// PLY by our own lean reader: Debian has no PLY library but assimp, whose reader crashed on bad indices (a
// SIGSEGV for `3 0 1 -1`, an abort for an empty face or missing vertex lines) and needed 6.6 GB for 10M
// vertices. This one validates everything before it stores anything and keeps only positions and triangles.
//
// What is read, in ascii, binary_little_endian and binary_big_endian:
// - element `vertex`: the scalar properties x, y, z, of any numeric type; every other property is skipped.
// - element `face`: the list property `vertex_indices` (or `vertex_index`), of any integer count and item
//   types; polygons are fan-triangulated. Faces of 0 to 2 vertices carry no surface and are skipped, but their
//   indices are checked like any other. Every index must be below the header's vertex count; the first that
//   is not is an error naming the face (numbered from 0, as PLY's elements are) and the index.
// - every other element (edges, materials, tristrips, ...) is skipped.
// - no face element, or none with any triangle: a point cloud, returned without indices. With triangles,
//   vertices no triangle uses are dropped (scan_file.h says why).
// Before reading data, the counts the header declares must fit the bytes left in the stream (where the stream
// can tell its size): a header that claims a billion vertices in a tiny file is refused before anything is
// allocated. In ascii each element is one line, as the format says: a line with too few or too many values
// is an error, so missing vertex lines are caught where they start instead of being read as faces.
#include "roomsense/scanio.h"

#include "scan_file.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roomsense::scanio {
namespace {

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> parse_type(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, Type>, 16> names = {{
      {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},   {"uint8", Type::UInt8},
      {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16}, {"uint16", Type::UInt16},
      {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},   {"uint32", Type::UInt32},
      {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64},
  }};
  for (const auto& [n, t] : names)
    if (n == name) return t;
  return std::nullopt;
}

std::size_t type_size(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  Type type = Type::Float32;  // of the value, or of a list's items
  bool list = false;
  Type count_type = Type::UInt8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

// A coordinate as float; beyond float's range it is infinite (the pipeline skips such vertices), never a
// conversion with undefined behaviour.
float to_float(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

// Which property of an element plays which role.
enum class Role : std::uint8_t { Skip, X, Y, Z, Indices };

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}
std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
  return a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a ? std::numeric_limits<std::uint64_t>::max() : a * b;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

// A buffered view of the stream: whole lines for the header and ascii data, fixed-size runs for binary.
class Input {
 public:
  explicit Input(std::istream& in) : in_(in), buffer_(std::size_t{1} << 20) {
    const std::istream::pos_type start = in_.tellg();
    if (start != std::istream::pos_type(-1) && in_.seekg(0, std::ios::end)) {
      const std::istream::pos_type end = in_.tellg();
      if (end != std::istream::pos_type(-1) && end >= start) size_ = std::uint64_t(end - start);
      in_.seekg(start);
    }
    in_.clear();
  }

  // Bytes of the stream not yet consumed, where the stream can say.
  std::optional<std::uint64_t> remaining() const {
    if (!size_) return std::nullopt;
    const std::uint64_t used = consumed();
    return used <= *size_ ? *size_ - used : 0;
  }
  std::uint64_t consumed() const { return read_ - (end_ - pos_); }
  bool bad() const { return in_.bad(); }

  // At least n bytes at data(); false at the end of the stream.
  bool ensure(std::size_t n) {
    if (end_ - pos_ >= n) return true;
    if (n > buffer_.size()) buffer_.resize(std::max(n, buffer_.size() * 2));
    std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
    while (end_ < n && !eof_) {
      in_.read(buffer_.data() + end_, std::streamsize(buffer_.size() - end_));
      const auto got = std::size_t(in_.gcount());
      if (got < buffer_.size() - end_) eof_ = true;
      end_ += got;
      read_ += got;
    }
    return end_ - pos_ >= n;
  }
  const char* data() const { return buffer_.data() + pos_; }
  void skip(std::size_t n) { pos_ += n; }

  // The next line without its '\n' (and '\r'), or nothing at the end of the stream. A line longer than
  // max_length is reported as too long.
  std::optional<std::string_view> line(std::size_t max_length, bool& too_long) {
    too_long = false;
    std::size_t scanned = 0;
    for (;;) {
      const char* begin = buffer_.data() + pos_;
      if (const void* nl = std::memchr(begin + scanned, '\n', end_ - pos_ - scanned); nl != nullptr) {
        const std::size_t length = std::size_t(static_cast<const char*>(nl) - begin);
        pos_ += length + 1;
        std::string_view text(begin, length);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
      }
      scanned = end_ - pos_;
      if (scanned > max_length) {
        too_long = true;
        return std::nullopt;
      }
      if (eof_) {
        if (scanned == 0) return std::nullopt;
        const std::string_view text(begin, scanned);
        pos_ = end_;
        return text.back() == '\r' ? text.substr(0, text.size() - 1) : text;
      }
      ensure(scanned + 1);  // moves the partial line to the front, grows the buffer when it is full
    }
  }

 private:
  std::istream& in_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0;
  std::uint64_t read_ = 0;
  bool eof_ = false;
  std::optional<std::uint64_t> size_;
};

class PlyReader {
 public:
  PlyReader(std::istream& in, const std::string& name) : input_(in), name_(name) {}

  Scan read() {
    read_header();
    check_sizes();
    Scan scan;
    if (const std::optional<std::uint64_t> left = input_.remaining()) {
      // The vertex count fits the stream (check_sizes): reserving it is safe. Faces may be empty, so only as
      // many triangles as the bytes left could hold (4 each at the least) are reserved: at most 3x the file.
      scan.vertices.reserve(std::size_t(vertex_count_));
      if (face_element_ != nullptr)
        scan.indices.reserve(std::size_t(std::min(face_element_->count, *left / 4) * 3));
    }
    for (const Element& element : elements_) {
      if (&element == vertex_element_) read_element(element, vertex_roles_, scan);
      else if (&element == face_element_) read_element(element, face_roles_, scan);
      else read_element(element, std::vector<Role>(element.properties.size(), Role::Skip), scan);
    }
    if (input_.bad()) fail("reading it failed");
    if (scan.vertices.empty()) fail("it holds no vertices");
    drop_unreferenced_vertices(scan);
    return scan;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw_read_error(name_, what); }

  // The next line, or nothing at the end of the stream.
  std::optional<std::string_view> next_line(std::size_t max_length) {
    bool too_long = false;
    const std::optional<std::string_view> text = input_.line(max_length, too_long);
    if (too_long) fail("line " + std::to_string(line_number_ + 1) + " is longer than " + std::to_string(max_length >> 20) + " MiB");
    if (text) ++line_number_;
    return text;
  }

  void read_header() {
    bool too_long = false;
    const std::optional<std::string_view> magic = input_.line(16, too_long);
    if (!magic || split_words(*magic) != std::vector<std::string_view>{"ply"})
      fail("it is not a PLY file (it does not start with 'ply')");
    line_number_ = 1;
    bool have_format = false;
    for (;;) {
      const std::optional<std::string_view> text = next_line(kMaxHeader);
      if (!text) fail("the file ends inside its PLY header (no end_header)");
      if (input_.consumed() > kMaxHeader) fail("its PLY header is longer than 1 MiB");
      const std::vector<std::string_view> words = split_words(*text);
      const std::string where = "header line " + std::to_string(line_number_);
      if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
      if (words[0] == "end_header") break;
      if (words[0] == "format") {
        if (words.size() < 2) fail(where + " names no format");
        if (words[1] == "ascii") format_ = Format::Ascii;
        else if (words[1] == "binary_little_endian") format_ = Format::BinaryLittleEndian;
        else if (words[1] == "binary_big_endian") format_ = Format::BinaryBigEndian;
        else fail(where + ": unknown format " + quoted(words[1]));
        have_format = true;
      } else if (words[0] == "element") {
        if (words.size() != 3) fail(where + " is not 'element NAME COUNT'");
        Element element;
        element.name = std::string(words[1].substr(0, 64));
        const auto [end, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
        if (ec != std::errc() || end != words[2].data() + words[2].size())
          fail(where + ": the count of element '" + element.name + "' is not a whole number");
        elements_.push_back(std::move(element));
      } else if (words[0] == "property") {
        if (elements_.empty()) fail(where + ": a property before any element");
        Property property;
        if (words.size() == 5 && words[1] == "list") {
          const auto count_type = parse_type(words[2]);
          const auto item_type = parse_type(words[3]);
          if (!count_type || !item_type) fail(where + ": unknown property type");
          if (!is_integer(*count_type)) fail(where + ": a list count must be of an integer type");
          property = {std::string(words[4].substr(0, 64)), *item_type, true, *count_type};
        } else if (words.size() == 3) {
          const auto type = parse_type(words[1]);
          if (!type) fail(where + ": unknown property type " + quoted(words[1]));
          property = {std::string(words[2].substr(0, 64)), *type, false, Type::UInt8};
        } else {
          fail(where + " is not 'property TYPE NAME' or 'property list TYPE TYPE NAME'");
        }
        elements_.back().properties.push_back(std::move(property));
      } else {
        fail(where + " is not a PLY header line");
      }
    }
    if (!have_format) fail("its PLY header has no format line");
    assign_roles();
  }

  void assign_roles() {
    for (const Element& element : elements_) {
      if (element.name == "vertex" && vertex_element_ == nullptr) vertex_element_ = &element;
      else if (element.name == "face" && face_element_ == nullptr) face_element_ = &element;
    }
    if (vertex_element_ == nullptr) fail("its PLY header declares no vertex element");
    if (vertex_element_->count > std::numeric_limits<std::uint32_t>::max())
      fail("it declares " + std::to_string(vertex_element_->count) +
           " vertices, more than 32-bit indices can address");
    vertex_count_ = vertex_element_->count;
    vertex_roles_.assign(vertex_element_->properties.size(), Role::Skip);
    std::array<bool, 3> found{};
    for (std::size_t p = 0; p < vertex_element_->properties.size(); ++p) {
      const Property& property = vertex_element_->properties[p];
      const int axis = property.name == "x" ? 0 : property.name == "y" ? 1 : property.name == "z" ? 2 : -1;
      if (axis < 0 || found[std::size_t(axis)]) continue;
      if (property.list) fail("its vertex property '" + property.name + "' is a list, not a number");
      vertex_roles_[p] = axis == 0 ? Role::X : axis == 1 ? Role::Y : Role::Z;
      found[std::size_t(axis)] = true;
    }
    if (!found[0] || !found[1] || !found[2]) fail("its vertex element lacks an x, y or z property");
    if (face_element_ != nullptr) {
      face_roles_.assign(face_element_->properties.size(), Role::Skip);
      bool have_indices = false;
      for (std::size_t p = 0; p < face_element_->properties.size() && !have_indices; ++p) {
        const Property& property = face_element_->properties[p];
        if (property.name != "vertex_indices" && property.name != "vertex_index") continue;
        if (!property.list) fail("its face property '" + property.name + "' is not a list");
        if (!is_integer(property.type)) fail("its face property '" + property.name + "' holds no integers");
        face_roles_[p] = Role::Indices;
        have_indices = true;
      }
      if (!have_indices) fail("its face element has no vertex_indices list");
    }
  }

  // The declared elements need at least this many bytes: in binary every scalar's size and every list's
  // count; in ascii a digit and a separator per scalar and list count.
  void check_sizes() {
    const std::optional<std::uint64_t> left = input_.remaining();
    if (!left) return;
    std::uint64_t minimum = 0;
    for (const Element& element : elements_) {
      std::uint64_t per_element = 0;
      for (const Property& property : element.properties)
        per_element += format_ == Format::Ascii ? 2 : type_size(property.list ? property.count_type : property.type);
      minimum = saturating_add(minimum, saturating_mul(element.count, per_element));
    }
    if (minimum > *left)
      fail("its PLY header declares more data (at least " + std::to_string(minimum) + " bytes) than the file holds (" +
           std::to_string(*left) + " bytes after the header)");
  }

  void read_element(const Element& element, const std::vector<Role>& roles, Scan& scan) {
    if (format_ == Format::Ascii) read_ascii(element, roles, scan);
    else read_binary(element, roles, scan);
  }

  // --- indices, shared by both encodings -----------------------------------------------------------------

  void begin_face(std::uint64_t count) {
    polygon_size_ = count;
    polygon_seen_ = 0;
  }
  void face_index(std::int64_t index, Scan& scan) {
    if (index < 0 || std::uint64_t(index) >= vertex_count_)
      fail("face " + std::to_string(record_) + " refers to vertex " + std::to_string(index) + ", but the file has " +
           std::to_string(vertex_count_) + " vertices");
    const auto v = std::uint32_t(index);
    if (polygon_size_ >= 3) {
      if (polygon_seen_ == 0) first_ = v;
      else if (polygon_seen_ >= 2) scan.indices.insert(scan.indices.end(), {first_, previous_, v});
      previous_ = v;
    }
    ++polygon_seen_;
  }

  // --- ascii -----------------------------------------------------------------------------------------------

  void read_ascii(const Element& element, const std::vector<Role>& roles, Scan& scan) {
    const std::string what = element.name == "vertex" ? "vertex" : element.name == "face" ? "face" : element.name;
    for (record_ = 0; record_ < element.count; ++record_) {
      std::optional<std::string_view> line;
      do {
        line = next_line(kMaxLine);
        if (!line)
          fail("the file ends after " + std::to_string(record_) + " of its " + std::to_string(element.count) + " " +
               what + " lines");
      } while (line->find_first_not_of(" \t\r") == std::string_view::npos);
      const std::string_view text = *line;
      const char* p = text.data();
      const char* const end = text.data() + text.size();
      const auto where = [&] { return what + " " + std::to_string(record_) + " (line " + std::to_string(line_number_) + ")"; };
      const auto token = [&]() -> std::string_view {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
        const char* start = p;
        while (p < end && *p != ' ' && *p != '\t' && *p != '\r') ++p;
        if (start == p) fail(where() + " has fewer values than its element declares");
        return {start, std::size_t(p - start)};
      };
      const auto integer = [&](std::string_view t) {
        const std::optional<std::int64_t> v = number_word<std::int64_t>(t);
        if (!v) fail(where() + ": " + quoted(t) + " is not an integer");
        return *v;
      };
      glm::vec3 position(0.0f);
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& property = element.properties[k];
        if (!property.list) {
          const std::string_view t = token();
          if (roles[k] == Role::Skip) continue;
          const std::optional<double> v = number_word<double>(t);
          if (!v) fail(where() + ": " + quoted(t) + " is not a number");
          position[roles[k] == Role::X ? 0 : roles[k] == Role::Y ? 1 : 2] = to_float(*v);
          continue;
        }
        const std::int64_t count = integer(token());
        if (count < 0) fail(where() + " has a negative list count");
        if (roles[k] == Role::Indices) begin_face(std::uint64_t(count));
        for (std::int64_t i = 0; i < count; ++i) {
          const std::string_view t = token();
          if (roles[k] == Role::Indices) face_index(integer(t), scan);
        }
      }
      while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
      if (p != end)
        fail(where() + " has more values than its element declares" +
             (what == "vertex" ? " (are vertex lines missing?)" : ""));
      if (&element == vertex_element_) scan.vertices.push_back(position);
    }
  }

  // --- binary ----------------------------------------------------------------------------------------------

  template <class T>
  T load(const char* p) const {
    std::array<char, sizeof(T)> bytes;
    std::memcpy(bytes.data(), p, sizeof(T));
    if ((format_ == Format::BinaryBigEndian) == (std::endian::native == std::endian::little))
      std::reverse(bytes.begin(), bytes.end());
    T v;
    std::memcpy(&v, bytes.data(), sizeof(T));
    return v;
  }

  double number(Type t, const char* p) const {
    switch (t) {
      case Type::Int8: return load<std::int8_t>(p);
      case Type::UInt8: return load<std::uint8_t>(p);
      case Type::Int16: return load<std::int16_t>(p);
      case Type::UInt16: return load<std::uint16_t>(p);
      case Type::Int32: return load<std::int32_t>(p);
      case Type::UInt32: return load<std::uint32_t>(p);
      case Type::Float32: return load<float>(p);
      case Type::Float64: return load<double>(p);
    }
    return 0;
  }

  // Every 32-bit integer is exact in a double; lists of floats are refused in the header.
  std::int64_t integer(Type t, const char* p) const {
    return t == Type::Float32 || t == Type::Float64 ? 0 : std::int64_t(number(t, p));
  }

  const char* take(std::size_t bytes, const Element& element) {
    if (!input_.ensure(bytes))
      fail("the file ends in " + element.name + " " + std::to_string(record_) + " of " + std::to_string(element.count));
    const char* p = input_.data();
    input_.skip(bytes);
    return p;
  }

  void read_binary(const Element& element, const std::vector<Role>& roles, Scan& scan) {
    const bool fixed = std::none_of(element.properties.begin(), element.properties.end(), [](const Property& p) { return p.list; });
    const bool wanted = std::any_of(roles.begin(), roles.end(), [](Role r) { return r != Role::Skip; });
    std::size_t record_size = 0;
    for (const Property& property : element.properties) record_size += type_size(property.type);
    if (fixed && !wanted) {  // an element we skip whole: no need to look at its records
      for (std::uint64_t left = saturating_mul(element.count, record_size); left > 0;) {
        const std::size_t step = std::size_t(std::min<std::uint64_t>(left, std::uint64_t{1} << 20));
        record_ = (saturating_mul(element.count, record_size) - left) / std::max<std::size_t>(record_size, 1);
        take(step, element);
        left -= step;
      }
      return;
    }
    for (record_ = 0; record_ < element.count; ++record_) {
      glm::vec3 position(0.0f);
      if (fixed) {
        const char* p = take(record_size, element);
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
          const Type type = element.properties[k].type;
          if (roles[k] != Role::Skip) position[roles[k] == Role::X ? 0 : roles[k] == Role::Y ? 1 : 2] = to_float(number(type, p));
          p += type_size(type);
        }
      } else {
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
          const Property& property = element.properties[k];
          if (!property.list) {
            const char* p = take(type_size(property.type), element);
            if (roles[k] != Role::Skip) position[roles[k] == Role::X ? 0 : roles[k] == Role::Y ? 1 : 2] = to_float(number(property.type, p));
            continue;
          }
          const std::int64_t count = integer(property.count_type, take(type_size(property.count_type), element));
          if (count < 0) fail(element.name + " " + std::to_string(record_) + " has a negative list count");
          const std::size_t item = type_size(property.type);
          if (roles[k] != Role::Indices) {  // skipped in runs, so a huge count cannot make a huge request
            for (std::uint64_t left = saturating_mul(std::uint64_t(count), item); left > 0;) {
              const std::size_t step = std::size_t(std::min<std::uint64_t>(left, std::uint64_t{1} << 20));
              take(step, element);
              left -= step;
            }
            continue;
          }
          begin_face(std::uint64_t(count));
          for (std::int64_t i = 0; i < count; ++i) face_index(integer(property.type, take(item, element)), scan);
        }
      }
      if (&element == vertex_element_) scan.vertices.push_back(position);
    }
  }

  static constexpr std::size_t kMaxLine = std::size_t{64} << 20;
  static constexpr std::uint64_t kMaxHeader = std::uint64_t{1} << 20;

  Input input_;
  const std::string& name_;
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  const Element* vertex_element_ = nullptr;
  const Element* face_element_ = nullptr;
  std::vector<Role> vertex_roles_, face_roles_;
  std::uint64_t vertex_count_ = 0;
  std::uint64_t line_number_ = 0;
  std::uint64_t record_ = 0;  // the element record being read, for messages
  std::uint64_t polygon_size_ = 0, polygon_seen_ = 0;
  std::uint32_t first_ = 0, previous_ = 0;
};

}  // namespace

Scan read_ply(std::istream& in, const std::string& name) { return PlyReader(in, name).read(); }

}  // namespace roomsense::scanio
