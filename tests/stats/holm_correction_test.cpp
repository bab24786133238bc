// Holm's adjusted p-values, worked by hand: sort, multiply the i-th smallest by m - i + 1, carry the
// running maximum, cap at 1, and put them back in the input order.
#include "teaching/stats/holm_correction.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace sc::stats {
namespace {

TEST(HolmCorrection, StepDownWithRunningMaximum) {
  // sorted 0.01, 0.03, 0.04 -> 3 x 0.01 = 0.03, 2 x 0.03 = 0.06, max(0.06, 1 x 0.04) = 0.06.
  const std::vector<double> p{0.01, 0.04, 0.03};
  const auto adjusted = holm_adjusted(p);
  ASSERT_EQ(adjusted.size(), 3u);
  EXPECT_NEAR(adjusted[0], 0.03, 1e-15);
  EXPECT_NEAR(adjusted[1], 0.06, 1e-15);
  EXPECT_NEAR(adjusted[2], 0.06, 1e-15);
}

TEST(HolmCorrection, CapsAtOneAndLeavesASingleTestAlone) {
  const std::vector<double> p{0.5, 0.01, 0.7};
  // sorted 0.01, 0.5, 0.7 -> 0.03, min(1, 1.0) = 1, max(1, 0.7) = 1.
  const auto adjusted = holm_adjusted(p);
  EXPECT_NEAR(adjusted[0], 1.0, 1e-15);
  EXPECT_NEAR(adjusted[1], 0.03, 1e-15);
  EXPECT_NEAR(adjusted[2], 1.0, 1e-15);
  const std::vector<double> one{0.04};
  EXPECT_DOUBLE_EQ(holm_adjusted(one)[0], 0.04);
  EXPECT_TRUE(holm_adjusted(std::vector<double>{}).empty());
}

TEST(HolmCorrection, RejectsExactlyWhatTheSequentialProcedureRejects) {
  // Holm at alpha = 0.05 with m = 4: 0.012 <= 0.05/4, 0.015 <= 0.05/3, 0.03 > 0.05/2 -> stop: the two
  // smallest are rejected, the others not (adjusted: 0.048, max(0.048, 0.045), 0.06, 0.2).
  const std::vector<double> p{0.03, 0.012, 0.2, 0.015};
  const auto adjusted = holm_adjusted(p);
  EXPECT_GT(adjusted[0], 0.05);
  EXPECT_LE(adjusted[1], 0.05);
  EXPECT_GT(adjusted[2], 0.05);
  EXPECT_LE(adjusted[3], 0.05);
  EXPECT_NEAR(adjusted[3], 0.048, 1e-15);
}

}  // namespace
}  // namespace sc::stats
