#include "engine/writing_view/ghost_pen.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sc::writing_view {
namespace {

using writing::TracePoint;

// 200 one-pixel steps right, then a 50-step pen-up move, then 50 inked steps.
std::vector<TracePoint> path_with_a_lift() {
  std::vector<TracePoint> path{{0, 150, true}};
  for (int i = 1; i <= 200; ++i) path.push_back({static_cast<double>(i), 150, true});
  for (int i = 1; i <= 50; ++i) path.push_back({200, 150.0 - i, false});
  for (int i = 1; i <= 50; ++i) path.push_back({200.0 + i, 100, true});
  return path;
}

TEST(GhostPen, MovesAtTheExpertsWritingSpeed) {
  const auto path = path_with_a_lift();
  EXPECT_DOUBLE_EQ(ghost_pen_duration(path.size()), 300.0 / writing::kExpertStepsPerSecond);
  // After half a second at 200 steps/s the pen has made 100 steps: x = 100.
  const GhostPenFrame half = ghost_pen_at(path, 0.5);
  EXPECT_FLOAT_EQ(half.tip.x, 100.0f);
  EXPECT_TRUE(half.pen_down);
  EXPECT_FALSE(half.finished);
  EXPECT_NEAR(half.progress, 100.0 / 300.0, 1e-12);
  EXPECT_EQ(half.written.size(), 101u);
  // Between two points the tip is interpolated and the written part ends at the tip.
  const GhostPenFrame between = ghost_pen_at(path, 0.5 + 0.5 / writing::kExpertStepsPerSecond);
  EXPECT_FLOAT_EQ(between.tip.x, 100.5f);
  EXPECT_EQ(between.written.size(), 102u);
  EXPECT_DOUBLE_EQ(between.written.back().x, 100.5);
}

TEST(GhostPen, IsLiftedDuringPenUpMovesAndRestsAtTheEnds) {
  const auto path = path_with_a_lift();
  const GhostPenFrame lifted = ghost_pen_at(path, 225.3 / writing::kExpertStepsPerSecond);
  EXPECT_FALSE(lifted.pen_down);
  EXPECT_FLOAT_EQ(lifted.tip.x, 200.0f);
  const GhostPenFrame before = ghost_pen_at(path, -1.0);
  EXPECT_EQ(before.written.size(), 1u);
  EXPECT_FLOAT_EQ(before.tip.x, 0.0f);
  EXPECT_DOUBLE_EQ(before.progress, 0.0);
  const GhostPenFrame after = ghost_pen_at(path, 100.0);
  EXPECT_TRUE(after.finished);
  EXPECT_DOUBLE_EQ(after.progress, 1.0);
  EXPECT_EQ(after.written.size(), path.size());
  EXPECT_FLOAT_EQ(after.tip.x, 250.0f);
  EXPECT_TRUE(ghost_pen_at({}, 1.0).finished);
}

TEST(GhostPen, SpeedIsAParameter) {
  const auto path = path_with_a_lift();
  EXPECT_FLOAT_EQ(ghost_pen_at(path, 1.0, 50.0).tip.x, 50.0f);
  EXPECT_DOUBLE_EQ(ghost_pen_duration(path.size(), 100.0), 3.0);
}

}  // namespace
}  // namespace sc::writing_view
