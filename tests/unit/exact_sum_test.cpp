// ExactSum (core/src/pipeline/surface_heights.h, internal): the surface heights' sums must come out the same in
// any grouping of their terms, since an IncrementalAnalysis adds up each chunk's sums and must equal one pass
// over the combined scan. Plain double sums do not (checked below on the same terms, so the terms are hard
// enough to tell).
#include "../../core/src/pipeline/surface_heights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using roomsense::detail::ExactSum;

// Terms as the heights sum them: a float height times a float area (exact in a double), of mixed magnitude and
// sign (a floor below the origin).
std::vector<double> terms(unsigned seed, std::size_t n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> height(-3.0f, 3.0f), exponent(-20.0f, 10.0f);
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(double(height(rng)) * double(std::exp2(exponent(rng))));
  return out;
}

TEST(ExactSum, AnyGroupingOfTheTermsGivesTheSameSum) {
  const std::vector<double> t = terms(7, 20000);
  ExactSum in_order;
  for (const double v : t) in_order.add(v);
  ASSERT_TRUE(in_order.exact());
  std::mt19937 rng(11);
  bool plain_differs = false;
  for (int trial = 0; trial < 20; ++trial) {
    // The terms cut into runs (chunks) at random places, in a random order of runs.
    std::vector<std::size_t> cuts{0, t.size()};
    for (int k = 0; k < 30; ++k) cuts.push_back(rng() % t.size());
    std::sort(cuts.begin(), cuts.end());
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) runs.push_back({cuts[k], cuts[k + 1]});
    std::shuffle(runs.begin(), runs.end(), rng);
    ExactSum grouped;
    double plain_grouped = 0.0;
    for (const auto& [b, e] : runs) {
      ExactSum part;
      double plain_part = 0.0;
      for (std::size_t i = b; i < e; ++i) part.add(t[i]), plain_part += t[i];
      grouped += part;
      plain_grouped += plain_part;
    }
    EXPECT_EQ(grouped.value(), in_order.value()) << "trial " << trial;
    double plain = 0.0;
    for (const double v : t) plain += v;
    plain_differs = plain_differs || plain_grouped != plain;
  }
  EXPECT_TRUE(plain_differs) << "the terms do not tell an exact sum from a double one";
}

TEST(ExactSum, IsAsCloseAsItsUnitsAllow) {
  const std::vector<double> t = terms(3, 5000);
  ExactSum sum;
  long double reference = 0.0L;
  for (const double v : t) sum.add(v), reference += (long double)v;
  // Each term loses less than 2^-48; the long double reference itself is off by far less than the tolerance.
  EXPECT_NEAR(sum.value(), double(reference), 5000 * 0x1p-48);
  ExactSum mixed;
  mixed.add(-0.5);
  mixed.add(0.25);
  EXPECT_EQ(mixed.value(), -0.25);
}

TEST(ExactSum, TermsBeyondItsRangeMakeItInexact) {
  ExactSum big;
  big.add(0x1p15);
  EXPECT_FALSE(big.exact());
  ExactSum nan;
  nan.add(NAN);
  EXPECT_FALSE(nan.exact());
  ExactSum fine;
  fine.add(0x1p15 - 1.0);
  EXPECT_TRUE(fine.exact());
  fine += big;
  EXPECT_FALSE(fine.exact());
}

}  // namespace
