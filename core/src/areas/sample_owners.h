// Which area holds each sample cell of growth (grow.cpp): cells grouped in tiles, a tile's owners in one run of
// 32-bit values, the tiles found through a KeyTable. A floor's samples fill their tiles, so a sample costs about
// four bytes instead of a hash slot's twelve at three quarters full (a 50 x 50 m floor has millions). The tiles
// lie in blocks of a fixed count, never moved: as the areas grow past the tiles reserved for them, a block is
// added, where one array would double and copy (a 90 x 90 m floor's growth held 26 MB of owners for 13 MB used,
// and 39 MB while it copied).
#pragma once
#include "candidate.h"
#include "../key_table.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <vector>

namespace roomsense::detail {

class SampleOwners {
 public:
  static constexpr std::uint32_t kAbsent = KeyTable::kAbsent;

  // Tiles of 2^shift cells along each axis: flat ones for horizontal areas, cubes for walls.
  explicit SampleOwners(glm::ivec3 shift)
      : shift_(shift), mask_((1 << shift.x) - 1, (1 << shift.y) - 1, (1 << shift.z) - 1),
        cells_(std::size_t(1) << (shift.x + shift.y + shift.z)) {}

  // Expects about `tiles` tiles: blocks of a sixteenth to an eighth of them (at least 16 tiles), their table sized
  // for them. The block size is set before the first insert only (the tiles already placed depend on it).
  void reserve(std::size_t tiles) {
    if (tile_count_ == 0) block_shift_ = std::max(4, int(std::bit_width(tiles / 16)));
    tiles_.reserve(tiles);
  }

  // The tile a run of reads last read: a strip's samples mostly share their tile. Growth reads a strip's samples at
  // several depths in turn and keeps one cursor per depth (find(cell, cursor)); one remembered tile for all of them
  // missed at every read (three table probes a wall's sample).
  struct Cursor {
    std::uint64_t key = ~std::uint64_t{0};  // no tile's (pack_key uses 63 bits)
    std::uint32_t tile = KeyTable::kAbsent;
    std::uint32_t tiles = 0;  // tile_count_ when a missing tile was remembered: a tile made since may be it
  };

  // The owner of cell, or kAbsent: through this SampleOwners' own cursor, or the caller's.
  std::uint32_t find(glm::ivec3 cell) const { return find(cell, last_); }
  std::uint32_t find(glm::ivec3 cell, Cursor& at) const {
    const std::uint32_t tile = tile_of(tile_key(cell), at);
    return tile == KeyTable::kAbsent ? kAbsent : owners(tile)[offset(cell)];
  }

  // Makes value the owner of cell unless it has one (as KeyTable::insert).
  void insert(glm::ivec3 cell, std::uint32_t value) {
    std::uint32_t& owner = slot(cell);
    if (owner == kAbsent) owner = value;
  }
  // Makes value the owner of cell unless it has a lower one: values inserted in any order leave the owners that
  // inserting them in ascending order would.
  void lower(glm::ivec3 cell, std::uint32_t value) {
    std::uint32_t& owner = slot(cell);
    owner = std::min(owner, value);  // kAbsent is the highest value
  }
  // lower() of every cell of the box [lo, hi] (inclusive), tile by tile: an area along the grid's axes is such a
  // box, and cell by cell its samples were 3 % of a whole analysis of thesis-room1.
  void lower_box(glm::ivec3 lo, glm::ivec3 hi, std::uint32_t value) {
    const glm::ivec3 first = lo >> shift_, last = hi >> shift_;  // tiles: arithmetic shifts, below zero too
    const glm::ivec3 side = glm::ivec3(1) << shift_;                // a tile's cells a side (no shift of a negative)
    for (int tx = first.x; tx <= last.x; ++tx)
      for (int ty = first.y; ty <= last.y; ++ty)
        for (int tz = first.z; tz <= last.z; ++tz) {
          const glm::ivec3 tile(tx, ty, tz);
          const glm::ivec3 from = glm::max(lo, tile * side), to = glm::min(hi, (tile + 1) * side - 1);
          std::uint32_t* const owners = tile_owners(from);
          for (int x = from.x; x <= to.x; ++x)
            for (int y = from.y; y <= to.y; ++y) {
              std::uint32_t* const row = owners + offset(glm::ivec3(x, y, 0));  // z runs along a tile's owners
              for (int z = from.z & mask_.z; z <= (to.z & mask_.z); ++z) row[z] = std::min(row[z], value);
            }
        }
  }

 private:
  // The owner of cell, kAbsent where it has none; its tile made where it has none.
  std::uint32_t& slot(glm::ivec3 cell) { return tile_owners(cell)[offset(cell)]; }
  // The first of the owners of cell's tile, made where it has none.
  std::uint32_t* tile_owners(glm::ivec3 cell) {
    const std::uint64_t key = tile_key(cell);
    std::uint32_t tile = tile_of(key, last_);
    if (tile == KeyTable::kAbsent) {
      tile = tile_count_++;
      if ((tile & block_mask()) == 0) blocks_.push_back(std::make_unique_for_overwrite<std::uint32_t[]>(cells_ << block_shift_));
      tiles_.insert(key, tile);
      std::fill_n(owners(tile), cells_, kAbsent);
      last_ = {key, tile, tile_count_};
    }
    return owners(tile);
  }

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

  std::uint32_t block_mask() const { return (std::uint32_t{1} << block_shift_) - 1; }
  // The first of a tile's owners.
  std::uint32_t* owners(std::uint32_t tile) const {
    return blocks_[tile >> block_shift_].get() + std::size_t(tile & block_mask()) * cells_;
  }

  // The tile of a key (kAbsent: none), remembered in `at`; a missing one is looked up again once tiles were made.
  std::uint32_t tile_of(std::uint64_t key, Cursor& at) const {
    if (key != at.key || (at.tile == KeyTable::kAbsent && at.tiles != tile_count_)) at = {key, tiles_.find(key), tile_count_};
    return at.tile;
  }

  glm::ivec3 shift_, mask_;
  std::size_t cells_;
  mutable Cursor last_;  // find's and insert's own (so one thread at a time reads a SampleOwners)
  KeyTable tiles_;
  int block_shift_ = 4;  // 2^block_shift_ tiles a block
  std::uint32_t tile_count_ = 0;
  std::vector<std::unique_ptr<std::uint32_t[]>> blocks_;
};

}  // namespace roomsense::detail
