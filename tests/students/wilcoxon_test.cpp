#include "teaching/students/wilcoxon.hpp"

#include <gtest/gtest.h>

namespace sc {

// Reference values from scipy.stats.wilcoxon (exact mode) and R's wilcox.test(paired = TRUE).
TEST(Wilcoxon, ExactSmallSample) {
  // Differences 1..6 all positive: W- = 0, p = 2 / 2^6 = 0.03125.
  std::vector<double> a{2, 3, 4, 5, 6, 7}, b{1, 1, 1, 1, 1, 1};
  auto r = wilcoxon_signed_rank(a, b);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.n, 6);
  EXPECT_DOUBLE_EQ(r.w_plus, 21.0);
  EXPECT_DOUBLE_EQ(r.w_minus, 0.0);
  EXPECT_NEAR(r.p_two_sided, 0.03125, 1e-12);
}

TEST(Wilcoxon, MixedSignsExact) {
  // d = {1,-2,3,4,-5,6,7,8}: W- = 7, n = 8; 19 of the 256 sign patterns give W <= 7 -> p = 38/256.
  std::vector<double> d{1, -2, 3, 4, -5, 6, 7, 8};
  std::vector<double> zero(d.size(), 0.0);
  auto r = wilcoxon_signed_rank(d, zero);
  EXPECT_DOUBLE_EQ(r.w_minus, 7.0);
  EXPECT_NEAR(r.p_two_sided, 0.1484375, 1e-12);
}

TEST(Wilcoxon, IdenticalSamplesGiveNoEvidence) {
  std::vector<double> a{1, 2, 3};
  auto r = wilcoxon_signed_rank(a, a);
  EXPECT_EQ(r.n, 0);
  EXPECT_DOUBLE_EQ(r.p_two_sided, 1.0);
}

TEST(Wilcoxon, TiesUseNormalApproximation) {
  std::vector<double> a{1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, b(10, 0.0);
  auto r = wilcoxon_signed_rank(a, b);
  EXPECT_FALSE(r.exact);
  // All ranks tied at 5.5: W- = 0, mean 27.5, var = 96.25 - 990/48 = 75.625; z = 27/8.696 = 3.105.
  EXPECT_NEAR(r.p_two_sided, 0.0019, 2e-4);
}

}  // namespace sc
