#include "engine/writing_view/score_badge.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sc::writing_view {
namespace {

TEST(ScoreBadge, PointsAreTheScoreWithAPositiveOffset) {
  EXPECT_EQ(score_points(0.0), 100);
  EXPECT_EQ(score_points(-0.134), 87);
  EXPECT_EQ(score_points(-1.0), 0);
  EXPECT_EQ(score_points(-3.0), 0);  // clamped to the score's range
  writing::WritingScore score;
  score.score = -0.134;
  score.recall = 0.91;
  score.precision = 0.952;
  EXPECT_EQ(score_headline(score), "87 points");
  EXPECT_EQ(score_details(score), "score -0.134 \xc2\xb7 recall 0.91 \xc2\xb7 precision 0.95");
  score.score = -0.993;
  EXPECT_EQ(score_headline(score), "1 point");
}

TEST(ScoreBadge, APerfectScoreNeverPrintsANegativeZero) {
  writing::WritingScore score;
  score.score = -0.0001;
  score.recall = 1.0;
  score.precision = 1.0;
  EXPECT_EQ(score_details(score), "score 0.000 \xc2\xb7 recall 1.00 \xc2\xb7 precision 1.00");
  EXPECT_FALSE(std::signbit(rounded_score(-0.0)));
}

}  // namespace
}  // namespace sc::writing_view
