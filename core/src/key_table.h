// A hash table from 63-bit keys to a 32-bit value: growth's sample owners by packed cell key (candidate.h's
// pack_key; world positions, unbounded: packing's bounded boxes use sample_raster.h), and under FirstIndex the
// first index of each value of a list (reach's wall footprints, growth's matching, the bounds' mesh vertices).
// Open addressing with linear probing, so a lookup is a multiply and a probe or two, and an insert allocates only
// when the table doubles (std::unordered_map allocated a node per entry).
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace roomsense::detail {

class KeyTable {
 public:
  static constexpr std::uint32_t kAbsent = ~std::uint32_t{0};

  // The value stored for key, or kAbsent.
  std::uint32_t find(std::uint64_t key) const {
    if (keys_.empty()) return kAbsent;
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == kEmpty) return kAbsent;
    }
  }

  // Stores value for key unless key is there already (as std::unordered_map::emplace). Returns whether it
  // stored.
  bool insert(std::uint64_t key, std::uint32_t value = 0) {
    if (4 * (size_ + 1) > 3 * keys_.size()) grow();  // at most three quarters full
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return false;
      if (keys_[i] == kEmpty) {
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        return true;
      }
    }
  }

  std::size_t size() const { return size_; }
  // No key, its slots kept: a table made again each update (the bounds mesh's vertices) allocates no fresh pages.
  void clear() {
    std::fill(keys_.begin(), keys_.end(), kEmpty);
    size_ = 0;
  }
  // Room for n keys without growing.
  void reserve(std::size_t n) {
    std::size_t slots = keys_.empty() ? 1024 : keys_.size();
    while (4 * n > 3 * slots) slots *= 2;
    if (slots != keys_.size()) rehash(slots);
  }

 private:
  // Keys use 63 bits (pack_key's, FirstIndex's), so none is this.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  std::size_t home(std::uint64_t key) const {
    // The finaliser of splitmix64: neighbouring cells' keys differ in their low bits of each axis.
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ull;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebull;
    key ^= key >> 31;
    return std::size_t(key) & mask_;
  }

  void grow() { rehash(keys_.empty() ? 1024 : 2 * keys_.size()); }
  void rehash(std::size_t slots) {  // a power of two
    const std::vector<std::uint64_t> old_keys = std::move(keys_);
    const std::vector<std::uint32_t> old_values = std::move(values_);
    keys_.assign(slots, kEmpty);
    values_.assign(slots, 0);
    mask_ = keys_.size() - 1;
    size_ = 0;
    for (std::size_t i = 0; i < old_keys.size(); ++i)
      if (old_keys[i] != kEmpty) insert(old_keys[i], old_values[i]);
  }

  // Keys and values apart: 12 bytes a slot, not a padded 16 (a 50 x 50 m floor has millions of samples).
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0, size_ = 0;
};

// FNV-1a over 32-bit words (a float's bits): the hash of what FirstIndex finds.
class WordHash {
 public:
  WordHash& add(std::uint32_t word) {
    value_ = (value_ ^ word) * 0x100000001b3ull;
    return *this;
  }
  WordHash& add(float v) { return add(std::bit_cast<std::uint32_t>(v)); }
  std::uint64_t value() const { return value_; }

 private:
  std::uint64_t value_ = 0xcbf29ce484222325ull;
};

// The first index of each value of a list, found by a hash of the value and its equality (told by `is`, a
// predicate on an index): a KeyTable whose key two unequal values share moves the later one on to the next key.
class FirstIndex {
 public:
  static constexpr std::uint32_t kAbsent = KeyTable::kAbsent;

  void reserve(std::size_t n) { table_.reserve(n); }
  void clear() { table_.clear(); }
  bool empty() const { return table_.size() == 0; }
  // The first index of the value `is` tells equal, whose hash is `hash`; kAbsent where there is none.
  template <class Is>
  std::uint32_t find(std::uint64_t hash, Is is) const {
    for (std::uint64_t key = hash >> 1;; key = next(key)) {
      const std::uint32_t j = table_.find(key);
      if (j == kAbsent || is(j)) return j;
    }
  }
  // Index i of a value whose hash is `hash`, unless the index of an equal value (`is`) is there: returns the
  // first index of the value.
  template <class Is>
  std::uint32_t insert(std::uint64_t hash, std::uint32_t i, Is is) {
    for (std::uint64_t key = hash >> 1;; key = next(key)) {
      const std::uint32_t j = table_.find(key);
      if (j == kAbsent) {
        table_.insert(key, i);
        return i;
      }
      if (is(j)) return j;
    }
  }

 private:
  static std::uint64_t next(std::uint64_t key) { return (key + 1) & (~std::uint64_t{0} >> 1); }  // 63 bits
  KeyTable table_;
};

}  // namespace roomsense::detail
