// match_in_order (core/src/areas/list_match.h, internal): each item of a list made again is matched to an equal
// item of the list before, exactly, and every item the two share is matched, whether the lists kept their order
// with runs of items added, gone or replaced (short and long), a block moved, or were shuffled.
#include "../../core/src/areas/list_match.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>

namespace roomsense::detail {
namespace {

using Items = std::vector<std::uint64_t>;

void expect_matched(const Items& before, const Items& now, const std::string& what) {
  SCOPED_TRACE(what);
  const std::vector<std::uint32_t> match = match_in_order(
      std::span<const std::uint64_t>(before), std::span<const std::uint64_t>(now),
      [](std::uint64_t a, std::uint64_t b) { return a == b; }, [](std::uint64_t a) { return a * 0x9e3779b97f4a7c15ull; });
  ASSERT_EQ(match.size(), now.size());
  const std::set<std::uint64_t> in_before(before.begin(), before.end());
  std::set<std::uint32_t> used;
  for (std::size_t j = 0; j < now.size(); ++j) {
    if (match[j] == FirstIndex::kAbsent) {
      EXPECT_FALSE(in_before.contains(now[j])) << "item " << j << " is in the list before, unmatched";
      continue;
    }
    ASSERT_LT(match[j], before.size());
    EXPECT_EQ(before[match[j]], now[j]) << "item " << j;
    EXPECT_TRUE(used.insert(match[j]).second) << "item " << j << " matched to one matched already";
  }
}

TEST(ListMatch, MatchesExactlyEveryItemBothListsShare) {
  std::mt19937_64 random(7);
  std::uint64_t next = 0;
  Items before(3000);
  for (std::uint64_t& item : before) item = next++;
  expect_matched(before, before, "the same list");
  expect_matched({}, before, "nothing before");
  expect_matched(before, {}, "nothing now");
  for (int round = 0; round < 40; ++round) {
    Items now;
    std::size_t i = 0;
    // Runs kept, between runs gone, added or replaced: short ones, and now and then one longer than the window.
    while (i < before.size()) {
      const std::size_t keep = std::size_t(random() % 200);
      now.insert(now.end(), before.begin() + std::ptrdiff_t(i), before.begin() + std::ptrdiff_t(std::min(before.size(), i + keep)));
      i += keep;
      const std::size_t run = random() % 10 == 0 ? 40 + random() % 200 : random() % 12;
      const int kind = int(random() % 3);
      if (kind != 1) i += run;  // gone (or replaced)
      if (kind != 0)
        for (std::size_t k = 0; k < run; ++k) now.push_back(next++);  // added (or replacing)
    }
    if (round % 5 == 3 && now.size() > 600) std::rotate(now.begin() + 100, now.begin() + 300, now.begin() + 600);
    if (round % 10 == 9) std::shuffle(now.begin(), now.end(), random);
    expect_matched(before, now, "round " + std::to_string(round));
    before = now;
  }
}

}  // namespace
}  // namespace roomsense::detail
