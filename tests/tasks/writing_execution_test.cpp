#include "teaching/tasks/writing_execution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace sc {
namespace {

// Pen steps along y = y0 from x = 0, one px apart (13-float states: x, y, timer, goal).
StepSequence pen_line(int n, double y0) {
  StepSequence s;
  s.state_dim = 13;
  s.action_dim = 2;
  for (int t = 0; t < n; ++t) {
    std::vector<float> state(13, 0.0f);
    state[0] = static_cast<float>(t);
    state[1] = static_cast<float>(y0);
    s.states.insert(s.states.end(), state.begin(), state.end());
    s.actions.insert(s.actions.end(), {1.0f, 0.0f});
  }
  return s;
}

StepAlignment writing_diagonal(int n) {
  StepAlignment path;
  for (int t = 0; t < n; ++t) path.push_back({t, t});
  return path;
}

// A learner line bent at step `knee` by `rise` px per step (a different shape from the expert's line).
StepSequence bent_line(int n, double y0, int knee, double rise) {
  StepSequence s = pen_line(n, y0);
  for (int t = knee; t < n; ++t)
    s.states[static_cast<std::size_t>(t) * 13 + 1] += static_cast<float>(rise * (t - knee));
  return s;
}

// Pen steps through the given points (x, y px).
StepSequence pen_path(const std::vector<std::pair<double, double>>& points) {
  StepSequence s = pen_line(static_cast<int>(points.size()), 0.0);
  for (std::size_t t = 0; t < points.size(); ++t) {
    s.states[t * 13] = static_cast<float>(points[t].first);
    s.states[t * 13 + 1] = static_cast<float>(points[t].second);
  }
  return s;
}

// A letter-like loop: a circle of `rx` by `ry` px about (cx, cy), 40 pen steps.
StepSequence pen_loop(double cx, double cy, double rx, double ry) {
  std::vector<std::pair<double, double>> points;
  for (int t = 0; t < 40; ++t) {
    const double a = 2.0 * 3.14159265358979 * t / 40.0;
    points.emplace_back(cx + rx * std::cos(a), cy + ry * std::sin(a));
  }
  return pen_path(points);
}

TEST(WritingExecution, TheSameShapeAnywhereScoresZero) {
  const StepSequence expert = pen_line(20, 50.0);
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, expert, writing_diagonal(20), 5, 15), 0.0);
  // Moved by 10 px (beyond the 8 px cutoff), e.g. by an earlier letter's drift: the segment's shape is right.
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, pen_line(20, 60.0), writing_diagonal(20), 5, 15), 0.0);
}

// A 40 px stroke (about a letter's size; the learner's points are fitted to its place and size first).
TEST(WritingExecution, InkOffTheShapeLosesCreditBetweenTheToleranceAndTheCutoff) {
  const StepSequence expert = pen_line(40, 50.0);
  // Half the points 11 px off the line: fitted to the centroid (and shrunk to the expert's spread, by 0.9) each
  // half lies about 5 px from the other's line, between the 3 px tolerance and the 8 px cutoff.
  StepSequence step = pen_line(40, 50.0);
  for (int t = 20; t < 40; ++t) step.states[static_cast<std::size_t>(t) * 13 + 1] = 61.0f;
  const double stepped = writing_execution_reward(expert, step, writing_diagonal(40), 0, 40);
  EXPECT_LT(stepped, -0.3);
  EXPECT_GT(stepped, -0.9);
  // A line that bends away by 2 px per step halfway: its far end is well beyond the cutoff.
  EXPECT_LT(writing_execution_reward(expert, bent_line(40, 50.0, 20, 2.0), writing_diagonal(40), 0, 40), -0.4);
  // A slight bend within the tolerance costs nothing.
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, bent_line(40, 50.0, 20, 0.1), writing_diagonal(40), 0, 40), 0.0);
}

// A learner tracing a letter larger or smaller than the guide has the letter's shape.
TEST(WritingExecution, TheSameShapeAtAnotherSizeScoresZero) {
  const StepSequence expert = pen_loop(100, 100, 20, 20);
  EXPECT_NEAR(writing_execution_reward(expert, pen_loop(160, 90, 30, 30), writing_diagonal(40), 0, 40), 0.0, 1e-12);
  EXPECT_NEAR(writing_execution_reward(expert, pen_loop(60, 120, 12, 12), writing_diagonal(40), 0, 40), 0.0, 1e-12);
  // Before 2026-12-05 the size was scored: the 1.5 times larger loop lies 10 px off, beyond the cutoff.
}

// What a size does not explain still counts: a loop squashed to half its height, a straight line for it, and a
// loop more than twice the size (rescaled by at most kMaxSizeRatio).
TEST(WritingExecution, ASquashedLetterALineOrAFarLargerLetterStillScoresBadly) {
  const StepSequence expert = pen_loop(100, 100, 20, 20);
  const double squashed = writing_execution_reward(expert, pen_loop(100, 100, 20, 10), writing_diagonal(40), 0, 40);
  const double line = writing_execution_reward(expert, pen_loop(100, 100, 20, 0), writing_diagonal(40), 0, 40);
  const double far_larger = writing_execution_reward(expert, pen_loop(100, 100, 60, 60), writing_diagonal(40), 0, 40);
  EXPECT_LT(squashed, -0.3);
  EXPECT_LT(line, -0.6);
  EXPECT_LT(far_larger, -0.9);
  // Twice the size is the most that is undone.
  EXPECT_NEAR(writing_execution_reward(expert, pen_loop(100, 100, 40, 40), writing_diagonal(40), 0, 40), 0.0, 1e-12);
}

}  // namespace
}  // namespace sc
