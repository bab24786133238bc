// The Mann-Whitney U test against values worked out independently of the code (by hand, below each case,
// and by enumerating every split of the pooled ranks), and against the figures scipy's documentation prints
// for its own example.
#include "teaching/stats/mann_whitney.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace sc::stats {
namespace {

TEST(MannWhitney, SeparatedSamplesOfThreeGiveTheSmallestExactP) {
  // U of x is 0 (no x beats a y). Of the C(6,3) = 20 equally likely rank splits exactly one gives U = 0 and
  // one gives U = 9, so p = 2 * 1/20 = 0.1.
  const std::vector<double> x{1, 2, 3}, y{4, 5, 6};
  const auto r = mann_whitney_u(x, y);
  EXPECT_EQ(r.method, MannWhitneyMethod::Exact);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_NEAR(r.p, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(r.effect, 0.0);
  EXPECT_DOUBLE_EQ(mann_whitney_u(y, x).u, 9.0);  // U1 + U2 = n1 n2
}

TEST(MannWhitney, ScipyDocumentationExample) {
  // scipy.stats.mannwhitneyu's example (ages of males and females): statistic 17.0, exact p 0.1111111111111111,
  // asymptotic p 0.11134688653314041. By hand: P(U >= 17) = P(U <= 3) = (1 + 1 + 2 + 3) / C(9,4) = 7/126;
  // z = (17 - 10 - 0.5) / sqrt(20/12 * 10) = 1.5921683.
  const std::vector<double> males{19, 22, 16, 29, 24}, females{20, 11, 17, 12};
  const auto exact = mann_whitney_u(males, females);
  EXPECT_EQ(exact.method, MannWhitneyMethod::Exact);
  EXPECT_DOUBLE_EQ(exact.u, 17.0);
  EXPECT_NEAR(exact.p, 0.1111111111111111, 1e-12);
  const auto normal = mann_whitney_u(males, females, MannWhitneyMethod::Asymptotic);
  EXPECT_DOUBLE_EQ(normal.u, 17.0);
  EXPECT_NEAR(normal.z, 1.5921683, 1e-6);
  EXPECT_NEAR(normal.p, 0.11134688653314041, 1e-12);
}

TEST(MannWhitney, TiesUseTheTieCorrectedNormalApproximation) {
  // Pooled: 2 3 5 6 7 8 8 9 10 11 12 15; the 8s share rank 6.5. x's ranks 5+2+4+1+6.5+3 = 21.5, U1 = 0.5,
  // U2 = 35.5. sigma^2 = 36/12 (13 - 6/132) = 38.863636; z = (35.5 - 18 - 0.5)/6.2340706 = 2.7269502;
  // p = erfc(z / sqrt 2) = 0.0063923.
  const std::vector<double> control{7, 3, 6, 2, 8, 5}, treated{9, 12, 8, 11, 15, 10};
  const auto r = mann_whitney_u(control, treated);
  EXPECT_TRUE(r.ties);
  EXPECT_EQ(r.method, MannWhitneyMethod::Asymptotic);  // small samples, but tied
  EXPECT_DOUBLE_EQ(r.u, 0.5);
  EXPECT_NEAR(r.z, 2.7269502, 1e-6);
  EXPECT_NEAR(r.p, 0.0063923, 1e-6);
  EXPECT_NEAR(r.effect, 0.5 / 36.0, 1e-15);
}

TEST(MannWhitney, LargeSamplesUseTheNormalApproximationWithoutTies) {
  std::vector<double> x, y;
  for (int i = 0; i < 9; ++i) {
    x.push_back(2.0 * i);
    y.push_back(2.0 * i + 3.0);
  }
  // x beats y in pairs (i, j) with 2i > 2j + 3: j <= i - 2, i.e. sum over i of max(0, i - 1) = 28.
  // sigma^2 = 81/12 * 19 = 128.25; z = (81 - 28 - 40.5 - 0.5)/11.324751 = 1.0596258.
  const auto r = mann_whitney_u(x, y);
  EXPECT_EQ(r.method, MannWhitneyMethod::Asymptotic);
  EXPECT_DOUBLE_EQ(r.u, 28.0);
  EXPECT_NEAR(r.z, 1.0596258, 1e-6);
  EXPECT_NEAR(r.p, std::erfc(1.0596258 / std::sqrt(2.0)), 1e-6);
  // One sample of 8 or fewer: exact, as scipy's "auto".
  x.pop_back();
  EXPECT_EQ(mann_whitney_u(x, y).method, MannWhitneyMethod::Exact);
}

// Independent of exact_u_upper_tail's recurrence: every choice of n1 of the n pooled ranks, counted.
double enumerated_upper_tail(int n1, int n2, double u) {
  const int n = n1 + n2;
  long total = 0, tail = 0;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    if (__builtin_popcount(mask) != n1) continue;
    int rank_sum = 0;
    for (int r = 0; r < n; ++r) rank_sum += (mask >> r & 1u) ? r + 1 : 0;
    ++total;
    if (rank_sum - n1 * (n1 + 1) / 2 >= u) ++tail;
  }
  return static_cast<double>(tail) / static_cast<double>(total);
}

TEST(MannWhitney, ExactTailMatchesEnumerationOfEverySplit) {
  for (auto [n1, n2] : {std::pair{1, 1}, {2, 5}, {4, 5}, {6, 6}, {3, 9}})
    for (int u = 0; u <= n1 * n2; ++u)
      EXPECT_NEAR(exact_u_upper_tail(n1, n2, u), enumerated_upper_tail(n1, n2, u), 1e-12)
          << n1 << " x " << n2 << " U >= " << u;
}

TEST(MannWhitney, AllValuesEqualGiveP1AndEmptySamplesAreRefused) {
  const std::vector<double> same{1, 1, 1}, empty;
  EXPECT_DOUBLE_EQ(mann_whitney_u(same, same).p, 1.0);
  EXPECT_THROW(mann_whitney_u(empty, same), std::invalid_argument);
  const std::vector<double> bad{1, NAN};
  EXPECT_THROW(mann_whitney_u(bad, same), std::invalid_argument);
}

}  // namespace
}  // namespace sc::stats
