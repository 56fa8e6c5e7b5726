// Beyond the thesis (issue 19): which items of a list an analysis made again were in the list the analysis before
// made, where the two keep the order of the items they share: a change moves the items near it alone (V_Floor
// and V_Wall for reach: an added object changes the squares of each size near it, a few runs of items apart).
#pragma once
#include "../key_table.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::detail {

// For each item of `now`, the index in `before` of an item `equal` to it, or FirstIndex::kAbsent. The lists are
// walked side by side; at an item that differs, the next `window` items of each are searched for the other's, so a
// run of up to that many items added, gone or both costs that many comparisons an item. Where neither is found the
// two are taken for an item replaced; after `window` of those in a row the walk stops. Then the items of `now` left
// unmatched are looked up in an index (by `hash`, a 64-bit hash of an item) of those of `before` left unmatched: a
// few where a change moved a few items, rather than an index of the whole list each update (reach's view and the
// placing of its floors, which built those, held 5 % of an added object's update's time on thesis-room1). Every item
// is matched that is equal to one of `before` not matched to another.
template <class T, class Equal, class Hash>
std::vector<std::uint32_t> match_in_order(std::span<const T> before, std::span<const T> now, Equal equal, Hash hash,
                                          std::size_t window = 32) {
  constexpr std::uint32_t kAbsent = FirstIndex::kAbsent;
  std::vector<std::uint32_t> match(now.size(), kAbsent);
  std::vector<std::uint8_t> matched(before.size(), 0);
  const auto pair = [&](std::size_t j, std::size_t i) { match[j] = std::uint32_t(i), matched[i] = 1; };
  // The first index in [from, min(from + window, end)) where at(k) holds, or `end`.
  const auto ahead = [window](std::size_t from, std::size_t end, const auto& at) {
    for (std::size_t k = from; k < end && k < from + window; ++k)
      if (at(k)) return k;
    return end;
  };
  std::size_t i = 0, j = 0, replaced = 0;
  while (j < now.size() && i < before.size() && replaced <= window) {
    if (equal(before[i], now[j])) {
      pair(j++, i++), replaced = 0;
      continue;
    }
    // now[j] further on in `before` (those before it gone), or before[i] further on in `now` (those before it added).
    const std::size_t k = ahead(i + 1, before.size(), [&](std::size_t k) { return equal(before[k], now[j]); });
    if (k < before.size()) {
      pair(j++, k), i = k + 1, replaced = 0;
      continue;
    }
    const std::size_t l = ahead(j + 1, now.size(), [&](std::size_t l) { return equal(before[i], now[l]); });
    if (l < now.size()) {
      j = l;  // now[j, l) added; before[i] matches now[l] next
      continue;
    }
    ++j, ++i, ++replaced;
  }
  FirstIndex left;
  for (std::size_t k = 0; k < before.size(); ++k)
    if (!matched[k])
      left.insert(hash(before[k]), std::uint32_t(k), [&](std::uint32_t at) { return equal(before[at], before[k]); });
  if (left.empty()) return match;
  for (std::size_t k = 0; k < now.size(); ++k)
    if (match[k] == kAbsent)
      match[k] = left.find(hash(now[k]), [&](std::uint32_t at) { return equal(before[at], now[k]); });
  return match;
}

}  // namespace roomsense::detail
