// Which area holds each sample cell of growth (grow.cpp): cells grouped in tiles, a tile's owners in one block of
// 32-bit values, the tiles found through a KeyTable. A floor's samples fill their tiles, so a sample costs about
// four bytes instead of a hash slot's twelve at three quarters full (a 50 x 50 m floor has millions).
#pragma once
#include "candidate.h"
#include "../key_table.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace roomsense::detail {

class SampleOwners {
 public:
  static constexpr std::uint32_t kAbsent = KeyTable::kAbsent;

  // Tiles of 2^shift cells along each axis: flat ones for horizontal areas, cubes for walls.
  explicit SampleOwners(glm::ivec3 shift)
      : shift_(shift), mask_((1 << shift.x) - 1, (1 << shift.y) - 1, (1 << shift.z) - 1),
        cells_(std::size_t(1) << (shift.x + shift.y + shift.z)) {}

  // Room for `tiles` tiles without the copies of growing to them.
  void reserve(std::size_t tiles) {
    owners_.reserve(tiles * cells_);
    tiles_.reserve(tiles);
  }

  // The owner of cell, or kAbsent.
  std::uint32_t find(glm::ivec3 cell) const {
    const std::uint32_t tile = tile_of(tile_key(cell));
    return tile == KeyTable::kAbsent ? kAbsent : owners_[std::size_t(tile) * cells_ + offset(cell)];
  }

  // Makes value the owner of cell unless it has one (as KeyTable::insert).
  void insert(glm::ivec3 cell, std::uint32_t value) {
    const std::uint64_t key = tile_key(cell);
    std::uint32_t tile = tile_of(key);
    if (tile == KeyTable::kAbsent) {
      tile = std::uint32_t(owners_.size() / cells_);
      tiles_.insert(key, tile);
      owners_.resize(owners_.size() + cells_, kAbsent);
      last_tile_ = tile;
    }
    std::uint32_t& owner = owners_[std::size_t(tile) * cells_ + offset(cell)];
    if (owner == kAbsent) owner = value;
  }

 private:
  // Cells as pack_key sees them (21 bits an axis), so that two cells are one exactly when their keys are.
  static glm::ivec3 wrapped(glm::ivec3 c) { return c & glm::ivec3(0x1FFFFF); }
  std::uint64_t tile_key(glm::ivec3 cell) const {
    const glm::ivec3 c = wrapped(cell);
    return pack_key(c.x >> shift_.x, c.y >> shift_.y, c.z >> shift_.z);
  }
  std::size_t offset(glm::ivec3 cell) const {
    const glm::ivec3 c = wrapped(cell) & mask_;
    return (std::size_t(c.x) << (shift_.y + shift_.z)) | (std::size_t(c.y) << shift_.z) | std::size_t(c.z);
  }

  // The tile of a key, the last one asked for remembered (so one thread at a time reads a SampleOwners): a
  // strip's samples mostly share their tile.
  std::uint32_t tile_of(std::uint64_t key) const {
    if (key != last_key_) last_key_ = key, last_tile_ = tiles_.find(key);
    return last_tile_;
  }

  glm::ivec3 shift_, mask_;
  std::size_t cells_;
  mutable std::uint64_t last_key_ = ~std::uint64_t{0};  // no tile's: pack_key uses 63 bits
  mutable std::uint32_t last_tile_ = KeyTable::kAbsent;
  KeyTable tiles_;
  std::vector<std::uint32_t> owners_;
};

}  // namespace roomsense::detail
