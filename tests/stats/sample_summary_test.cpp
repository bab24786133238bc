// Mean, standard deviation (n - 1), standard error and type-7 quartiles, worked by hand.
#include "teaching/stats/sample_summary.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace sc::stats {
namespace {

TEST(SampleSummary, MeanSdSeAndQuartiles) {
  // mean 2.5; squared deviations 2.25 + 0.25 + 0.25 + 2.25 = 5, sd = sqrt(5/3), se = sd / 2;
  // quartile positions 0.75, 1.5, 2.25 between the sorted values 1 2 3 4 -> 1.75, 2.5, 3.25.
  const std::vector<double> v{4, 1, 3, 2};
  const SampleSummary s = summarise(v);
  EXPECT_EQ(s.n, 4);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.sd, std::sqrt(5.0 / 3.0), 1e-15);
  EXPECT_NEAR(s.se, std::sqrt(5.0 / 3.0) / 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.q1, 1.75);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.q3, 3.25);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.1), 1.3);  // position 0.3
  EXPECT_DOUBLE_EQ(s.whisker_low, 1.0);
  EXPECT_DOUBLE_EQ(s.whisker_high, 4.0);
}

TEST(SampleSummary, WhiskersStopAtTheLastValueWithinOneAndAHalfBoxes) {
  // 1..8 and 30: q1 = 3, q3 = 7 (positions 2 and 6), IQR 4, reach 6: whiskers 1 and 8 (30 > 13 is an outlier).
  const std::vector<double> v{1, 2, 3, 4, 5, 6, 7, 8, 30};
  const SampleSummary s = summarise(v);
  EXPECT_DOUBLE_EQ(s.q1, 3.0);
  EXPECT_DOUBLE_EQ(s.q3, 7.0);
  EXPECT_DOUBLE_EQ(s.whisker_low, 1.0);
  EXPECT_DOUBLE_EQ(s.whisker_high, 8.0);
  EXPECT_DOUBLE_EQ(s.max, 30.0);
}

TEST(SampleSummary, OneValueHasNoSpreadAndNoneHasNothing) {
  const std::vector<double> one{-0.7};
  const SampleSummary s = summarise(one);
  EXPECT_EQ(s.n, 1);
  EXPECT_DOUBLE_EQ(s.mean, -0.7);
  EXPECT_TRUE(std::isnan(s.sd));
  EXPECT_TRUE(std::isnan(s.se));
  EXPECT_DOUBLE_EQ(s.median, -0.7);
  const SampleSummary none = summarise(std::vector<double>{});
  EXPECT_EQ(none.n, 0);
  EXPECT_TRUE(std::isnan(none.mean));
}

}  // namespace
}  // namespace sc::stats
