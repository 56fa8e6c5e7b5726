// A found rectangle in voxel coordinates, as the thesis stores it (Eq. 3.26, 3.39, 3.41), and the voxels
// that mark its centre (Eq. 3.42/3.43).
#pragma once
#include "../key_table.h"
#include "roomsense/areas.h"
#include "roomsense/grid.h"

#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <span>
#include <vector>

namespace roomsense::detail {

// Walls: p1 = (x1, y1, z1), p2 = (x2, y1, z2) on the top edge, p3 = (x2, y1 - h, z2), p4 = (x1, y1 - h, z1),
// with x1 <= x2 (Eq. 3.26). Squares: v1, v2, v3, v4 around the square, v1 -> v2 with x1 <= x2 and
// v2 -> v3 = (-(z2 - z1), x2 - x1) (Eq. 3.28), all at one level (Eq. 3.39/3.41).
struct Candidate {
  std::array<glm::ivec3, 4> corners{};
};

// A rectangle as reduction keeps it: corner 1, the edge to corner 2 (level along y), and the side to corner 4,
// which a wall has straight down and a square at a right angle in the plane. 24 bytes in place of 48.
class PackedCandidate {
 public:
  static constexpr std::int32_t kSquare = -1;  // as side: a wall's height is never negative
  PackedCandidate(glm::ivec3 p1, int dx, int dz, int side) : x_(p1.x), y_(p1.y), z_(p1.z), dx_(dx), dz_(dz), side_(side) {}

  // Corner k (0 to 3) of unpack(), without the others. Component by component: built from whole vectors, the
  // corners went through the stack as 32-bit stores read back 64 bits at a time, a store-forwarding stall on
  // every rectangle packing reads.
  glm::ivec3 corner(std::size_t k) const {
    const glm::ivec3 s = side();
    const bool second = k == 1 || k == 2, sided = k >= 2;
    return {x_ + (second ? dx_ : 0) + (sided ? s.x : 0), y_ + (sided ? s.y : 0), z_ + (second ? dz_ : 0) + (sided ? s.z : 0)};
  }
  Candidate unpack() const {
    Candidate c;
    for (std::size_t k = 0; k < 4; ++k) c.corners[k] = corner(k);
    return c;
  }
  // corner_sum(unpack()), without the corners: 4 p1 + 2 (p2 - p1) + 2 side.
  glm::ivec3 corner_sum() const { return 4 * glm::ivec3(x_, y_, z_) + 2 * glm::ivec3(dx_, 0, dz_) + 2 * side(); }
  // Corner 4 - corner 1: a wall's straight down, a square's at a right angle to its first edge in the plane.
  glm::ivec3 side() const { return side_ == kSquare ? glm::ivec3(-dz_, 0, dx_) : glm::ivec3(0, -side_, 0); }
  bool operator==(const PackedCandidate&) const = default;
  // A key of its numbers (equal rectangles, equal keys), for hash tables.
  std::uint64_t hash() const {
    WordHash h;
    for (const std::int32_t v : {x_, y_, z_, dx_, dz_, side_}) h.add(std::uint32_t(v));
    return h.value();
  }

 private:
  std::int32_t x_, y_, z_, dx_, dz_, side_;
};

// A search's rectangles until reduction, 12 bytes each: corner 1's cell, and which of the search's corner offsets
// (its ring, with the wall height or square that goes with each) gives the rest. A large floor's searches find
// millions (issue 19's memory bound). In blocks of 4096: the list grows without a vector's copies.
class Candidates {
 public:
  struct Shape {
    int dx = 0, dz = 0;                     // corner 2 - corner 1
    int side = PackedCandidate::kSquare;    // a wall's height h (Eq. 3.20), or kSquare
  };

  // One candidate as stored: corner 1's cell in bit fields and its shape's index.
  struct Item {
    std::uint32_t cell_lo, cell_hi, shape;
    bool operator==(const Item&) const = default;
  };

  Candidates() = default;
  // Corner 1 lies in the grid's columns, at a level in [0, levels).
  Candidates(const GridSpec& spec, int levels, std::vector<Shape> shapes)
      : layout_(spec, levels), shapes_(std::move(shapes)) {
    if (layout_.y_bits + layout_.z_bits + std::bit_width(unsigned(layout_.limit.x)) > 64)
      throw std::logic_error("a grid too large for the candidates' cells");
  }

  // Inlined into the searches, which call it once per candidate found: called, its ivec3 went to the registers
  // through the stack, and that load stalled on the two stores before it (perf put 8-10 % of the searches'
  // samples on the next instruction).
  [[gnu::always_inline]] void push_back(glm::ivec3 first, std::uint32_t shape) {
    if (glm::any(glm::lessThan(first, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(first, layout_.limit)))
      throw std::logic_error("a candidate outside its search's grid");
    const std::uint64_t cell =
        (((std::uint64_t(first.x) << layout_.z_bits) | std::uint64_t(first.z)) << layout_.y_bits) | std::uint64_t(first.y);
    push_item({std::uint32_t(cell), std::uint32_t(cell >> 32), shape});
  }
  // An item of a Candidates made with the same grid, levels and shapes (SearchCache's kept pieces).
  void push_item(const Item& item) {
    if (item.shape >= shapes_.size()) throw std::logic_error("a candidate outside its search's shapes");
    if (size_ % kBlock == 0) blocks_.push_back(std::make_unique<Item[]>(kBlock));
    blocks_.back()[size_ % kBlock] = item;
    ++size_;
  }
  // Items of a Candidates made with the same grid, levels and shapes, checked as push_item checks them.
  void push_items(std::span<const Item> items) {
    for (const Item& item : items)
      if (item.shape >= shapes_.size()) throw std::logic_error("a candidate outside its search's shapes");
    while (!items.empty()) {
      if (size_ % kBlock == 0) blocks_.push_back(std::make_unique<Item[]>(kBlock));
      const std::size_t n = std::min(items.size(), kBlock - size_ % kBlock);
      std::copy_n(items.begin(), n, blocks_.back().get() + size_ % kBlock);
      size_ += n;
      items = items.subspan(n);
    }
  }
  const Item& item(std::size_t i) const { return blocks_[i / kBlock][i % kBlock]; }
  std::span<const Shape> shapes() const { return shapes_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  static constexpr std::size_t kBytesEach = 12;  // what one candidate takes
  // The same grid, levels and shapes, without rectangles.
  Candidates empty_like() const {
    Candidates c;
    c.layout_ = layout_, c.shapes_ = shapes_;
    return c;
  }
  PackedCandidate operator[](std::size_t i) const { return decode(item(i)); }
  PackedCandidate decode(const Item& item) const {
    const std::uint64_t cell = (std::uint64_t(item.cell_hi) << 32) | item.cell_lo;
    const Shape& s = shapes_[item.shape];
    const Layout& l = layout_;
    return {glm::ivec3(int(cell >> (l.y_bits + l.z_bits)), int(cell & l.y_mask), int((cell >> l.y_bits) & l.z_mask)),
            s.dx, s.dz, s.side};
  }
  PackedCandidate at(std::size_t i) const {
    if (i >= size()) throw std::out_of_range("Candidates::at");
    return (*this)[i];
  }

 private:
  // A cell is x, z, y in bit fields; corner 1 lies below `limit` on each axis.
  struct Layout {
    Layout() = default;
    Layout(const GridSpec& spec, int levels)
        : y_bits(std::bit_width(unsigned(std::max(levels, 1)))), z_bits(std::bit_width(unsigned(std::max(spec.nz, 1)))),
          y_mask((std::uint64_t{1} << y_bits) - 1), z_mask((std::uint64_t{1} << z_bits) - 1),
          limit(std::max(spec.nx, 1), std::max(levels, 1), std::max(spec.nz, 1)) {}
    int y_bits = 0, z_bits = 0;
    std::uint64_t y_mask = 0, z_mask = 0;  // the fields' low bits: decode's most frequent work, found once
    glm::ivec3 limit{0};
  } layout_;
  static_assert(sizeof(Item) == kBytesEach);
  static constexpr std::size_t kBlock = 4096;
  std::vector<Shape> shapes_;
  std::vector<std::unique_ptr<Item[]>> blocks_;
  std::size_t size_ = 0;
};

// 4 x the centre of Eq. 3.42, exact in integers.
inline glm::ivec3 corner_sum(const Candidate& c) {
  return c.corners[0] + c.corners[1] + c.corners[2] + c.corners[3];
}

// The voxel indices along one axis that Eq. 3.43 marks for a centre of sum / 4: one voxel, or two when the
// centre lies exactly between them. Returns how many (1 or 2) and writes them to out.
inline int centre_voxels(int sum, int out[2]) {
  const int base = sum >= 0 ? sum / 4 : -((-sum + 3) / 4);  // floor(sum / 4)
  switch (sum - 4 * base) {
    case 2:
      out[0] = base;
      out[1] = base + 1;
      return 2;
    case 3:
      out[0] = base + 1;
      return 1;
    default:
      out[0] = base;
      return 1;
  }
}

// Sizes in voxels for one of the three size classes (§3.3.1/3.3.2): d must lie in [min_d, max_d].
struct SizeRange {
  double min_d = 0, max_d = 0;
  double height_ratio = 0.5;  // walls: h = ⌊d · ratio⌋ (Eq. 3.20 has ratio 1/2)
  // Eq. 3.20: the height in voxels of a wall rectangle whose corners lie d voxels apart.
  int wall_height(double d) const { return int(std::floor(d * height_ratio + 1e-9)); }
};

inline SizeRange size_range(float width, float height, float tolerance, float voxel_size) {
  return {double(width - tolerance) / voxel_size, double(width + tolerance) / voxel_size, double(height / width)};
}

// A fixed-size set of bits, for the centres a search has found.
class BitSet {
 public:
  explicit BitSet(std::size_t size) : words_((size + 63) / 64, 0) {}
  bool test(std::size_t i) const { return (words_[i / 64] >> (i % 64)) & 1u; }
  void set(std::size_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }
  void reset(std::size_t i) { words_[i / 64] &= ~(std::uint64_t{1} << (i % 64)); }
  void reset(std::size_t from, std::size_t to) {  // bits [from, to)
    if (from >= to) return;
    const std::size_t first = from / 64, last = (to - 1) / 64;
    const std::uint64_t head = ~std::uint64_t{0} << (from % 64), tail = ~std::uint64_t{0} >> (63 - (to - 1) % 64);
    if (first == last) {
      words_[first] &= ~(head & tail);
      return;
    }
    words_[first] &= ~head;
    std::fill(words_.begin() + std::ptrdiff_t(first + 1), words_.begin() + std::ptrdiff_t(last), std::uint64_t{0});
    words_[last] &= ~tail;
  }

 private:
  std::vector<std::uint64_t> words_;
};

// The centre-voxel keys are packed into 64 bits; grids are far smaller than 2^20 per axis.
inline std::uint64_t pack_key(int x, int y, int z) {
  return (std::uint64_t(std::uint32_t(x) & 0x1FFFFF) << 42) | (std::uint64_t(std::uint32_t(y) & 0x1FFFFF) << 21) |
         std::uint64_t(std::uint32_t(z) & 0x1FFFFF);
}

}  // namespace roomsense::detail
