#include "engine/review_view/review_picture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sc::review_view {
namespace {

ReviewPath path() {
  ReviewPath p;
  p.points = {{0, 0}, {10, 0}, {10, 20}};
  const float pi = std::numbers::pi_v<float>;
  p.headings = {0.9f * pi, -0.9f * pi, 0.0f};  // the first step crosses +-pi
  return p;
}

TEST(ReviewPicture, PlayheadInterpolatesBetweenStepsAndClamps) {
  const ReviewPath p = path();
  EXPECT_FLOAT_EQ(position_at(p, 0.5).x, 5.0f);
  EXPECT_FLOAT_EQ(position_at(p, 1.25).y, 5.0f);
  EXPECT_FLOAT_EQ(position_at(p, -3.0).x, 0.0f);
  EXPECT_FLOAT_EQ(position_at(p, 9.0).y, 20.0f);
  EXPECT_FLOAT_EQ(position_at(ReviewPath{}, 1.0).x, 0.0f);
}

TEST(ReviewPicture, HeadingTurnsAlongTheShorterArc) {
  // 0.9 pi -> -0.9 pi is a 0.2 pi turn through pi, not a 1.8 pi spin the other way.
  const float mid = heading_at(path(), 0.5);
  EXPECT_NEAR(std::cos(mid), -1.0, 1e-5);
  EXPECT_NEAR(std::sin(mid), 0.0, 1e-5);
  EXPECT_FLOAT_EQ(heading_at(path(), 5.0), 0.0f);
}

}  // namespace
}  // namespace sc::review_view
