// Ghost-path runs: forward and reversing stretches are split where the car changes direction; a tiny creep
// is not a manoeuvre.
#include "engine/parking_view/teaching_overlays.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

// A straight path along +x (heading 0) through the given x positions, 1/15 s apart.
ParkingPath straight_path(std::initializer_list<double> xs) {
  ParkingPath path;
  double t = 0.0;
  for (double x : xs) {
    path.samples.push_back({t, {x, 0.0, 0.0, 0.0}, 0.0});
    t += parking::kDt;
  }
  return path;
}

TEST(SplitByDirection, ForwardThenReverse) {
  const ParkingPath path = straight_path({0, 1, 2, 3, 2.5, 1.5, 0.5});
  const auto runs = split_by_direction(path);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_FALSE(runs[0].reversing);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 3u);
  EXPECT_TRUE(runs[1].reversing);
  EXPECT_EQ(runs[1].first, 3u);  // shares the turning point, so the ribbon has no gap
  EXPECT_EQ(runs[1].last, 6u);
}

TEST(SplitByDirection, ReversingIsRelativeToTheHeading) {
  // Heading pi: moving toward -x is forward.
  ParkingPath path;
  for (int i = 0; i < 4; ++i) path.samples.push_back({i * parking::kDt, {-1.0 * i, 0, 3.14159265, 0}, 0});
  const auto runs = split_by_direction(path);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_FALSE(runs[0].reversing);
}

TEST(SplitByDirection, StopsJoinTheRunTheyEnd) {
  const ParkingPath path = straight_path({0, 1, 2, 2, 2, 1, 0});
  const auto runs = split_by_direction(path);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].last, 4u);
  EXPECT_TRUE(runs[1].reversing);
}

TEST(SplitByDirection, ShortCreepIsMerged) {
  const ParkingPath path = straight_path({0, 1, 2, 3, 2.95, 2.9, 2.9});
  const auto runs = split_by_direction(path, 0.3);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].last, 6u);
  EXPECT_EQ(split_by_direction(path, 0.05).size(), 2u);
}

TEST(SplitByDirection, EmptyAndSinglePointPaths) {
  EXPECT_TRUE(split_by_direction(ParkingPath{}).empty());
  EXPECT_TRUE(split_by_direction(straight_path({1})).empty());
}

}  // namespace
}  // namespace sc
