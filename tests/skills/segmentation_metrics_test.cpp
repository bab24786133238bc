#include "teaching/skills/segmentation_metrics.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(SegmentationMetrics, MatchesOneToOneWithinTolerance) {
  // 10 matches 11; 20 and 21 both near 20 but only one may match; 40 has no partner.
  const BoundaryScore s = score_boundaries({10, 20, 21, 40}, {11, 20, 30}, 1);
  EXPECT_EQ(s.true_positives, 2);
  EXPECT_EQ(s.false_positives, 2);
  EXPECT_EQ(s.false_negatives, 1);
  EXPECT_DOUBLE_EQ(s.precision(), 0.5);
  EXPECT_NEAR(s.recall(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.f1(), 4.0 / 7.0, 1e-12);
  EXPECT_EQ(interior_boundaries(Segmentation{{{0, 0, 4}, {1, 4, 9}, {0, 9, 12}}}), (std::vector<int>{4, 9}));
}

}  // namespace
}  // namespace sc
