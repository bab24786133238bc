#include "engine/writing_view/canvas_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sc::writing_view {
namespace {

using writing::TracePoint;

TEST(CanvasCamera, FitsTheCanvasWithItsMarginAndKeepsTheAspect) {
  // 1000 x 600 pixels for 524 x 324 canvas px: the height limits, so the scale is 600 / 324.
  const Camera2D camera = writing_canvas_camera({0, 0, 1000, 600});
  EXPECT_NEAR(camera.pixels_per_unit(), 600.0f / 324.0f, 1e-4f);
  const Vec2f top_left = camera.world_to_pixel({-kCanvasMargin, -kCanvasMargin});
  const Vec2f bottom_right = camera.world_to_pixel({500 + kCanvasMargin, 300 + kCanvasMargin});
  EXPECT_NEAR(top_left.y, 0.0f, 1e-3f);
  EXPECT_NEAR(bottom_right.y, 600.0f, 1e-3f);
  EXPECT_NEAR(top_left.x + bottom_right.x, 1000.0f, 1e-3f);  // centred horizontally
  // y points down on the canvas, as on screen.
  EXPECT_GT(camera.world_to_pixel({0, 300}).y, camera.world_to_pixel({0, 0}).y);
}

TEST(SplitInk, SeparatesInkRunsDotsAndPenUpHops) {
  const std::vector<TracePoint> trace{{0, 0, true},  {1, 0, true},  {2, 0, true},    // a run of two segments
                                      {5, 5, false}, {8, 5, false},                  // a pen-up hop
                                      {8, 5, true},                                  // a tap: ink that does not move
                                      {9, 9, false},                                 // another hop
                                      {10, 9, true}, {10, 9, true}, {11, 9, true}};  // a run with a repeated point
  const InkPaths paths = split_ink(trace);
  ASSERT_EQ(paths.runs.size(), 2u);
  EXPECT_EQ(paths.runs[0].size(), 3u);
  EXPECT_EQ(paths.runs[1].size(), 3u);  // 9,9 -> 10,9 -> 11,9: the repeated point is dropped
  EXPECT_FLOAT_EQ(paths.runs[1].front().x, 9.0f);
  ASSERT_EQ(paths.dots.size(), 1u);
  EXPECT_FLOAT_EQ(paths.dots[0].x, 8.0f);
  ASSERT_EQ(paths.hops.size(), 2u);
  EXPECT_EQ(paths.hops[0].size(), 3u);  // from the run's end (2,0) via (5,5) to (8,5)
  EXPECT_FLOAT_EQ(paths.hops[0].front().x, 2.0f);
  EXPECT_FLOAT_EQ(paths.hops[0].back().x, 8.0f);
}

TEST(SplitInk, FirstPointsPenFlagIsIgnoredAndEmptyTracesDrawNothing) {
  const std::vector<TracePoint> trace{{0, 0, false}, {3, 4, true}};
  const InkPaths paths = split_ink(trace);
  ASSERT_EQ(paths.runs.size(), 1u);
  EXPECT_TRUE(paths.hops.empty());
  EXPECT_TRUE(split_ink({}).runs.empty());
  const std::vector<TracePoint> one{{1, 1, true}};
  EXPECT_TRUE(split_ink(one).runs.empty());
  EXPECT_TRUE(split_ink(one).dots.empty());
}

TEST(PathLength, PointAtLengthInterpolatesAndClamps) {
  const std::vector<Vec2f> path{{0, 0}, {3, 4}, {3, 10}};
  EXPECT_FLOAT_EQ(path_length(path), 11.0f);
  const Vec2f mid = point_at_length(path, 2.5f);
  EXPECT_NEAR(mid.x, 1.5f, 1e-5f);
  EXPECT_NEAR(mid.y, 2.0f, 1e-5f);
  EXPECT_FLOAT_EQ(point_at_length(path, 8.0f).y, 7.0f);
  EXPECT_FLOAT_EQ(point_at_length(path, 100.0f).y, 10.0f);
  EXPECT_FLOAT_EQ(point_at_length(path, -1.0f).x, 0.0f);
}

TEST(DirectionMarks, AreSpacedAlongTheArcAndPointTheWayThePathGoes) {
  // An L: 100 px right, then 100 px down, in 1 px steps like an infilled trace.
  std::vector<Vec2f> path;
  for (int i = 0; i <= 100; ++i) path.push_back({static_cast<float>(i), 0});
  for (int i = 1; i <= 100; ++i) path.push_back({100, static_cast<float>(i)});
  const auto marks = direction_marks(path, 40.0f, 10.0f);
  ASSERT_EQ(marks.size(), 5u);  // at 20, 60, 100, 140, 180 px
  EXPECT_NEAR((marks[0].from.x + marks[0].to.x) * 0.5f, 20.0f, 1e-4f);
  EXPECT_GT(marks[0].to.x, marks[0].from.x);  // rightwards
  EXPECT_NEAR(marks[0].to.y, marks[0].from.y, 1e-4f);
  EXPECT_GT(marks[4].to.y, marks[4].from.y);  // downwards on the second leg
  EXPECT_NEAR(marks[4].to.x, marks[4].from.x, 1e-4f);
  for (const auto& m : marks) EXPECT_NEAR(std::hypot(m.to.x - m.from.x, m.to.y - m.from.y), 10.0f, 1e-3f);
  EXPECT_TRUE(direction_marks(std::vector<Vec2f>{{0, 0}, {5, 0}}, 40.0f, 10.0f).empty());  // shorter than 20
}

}  // namespace
}  // namespace sc::writing_view
