#include "teaching/tasks/writing_execution.hpp"

#include <gtest/gtest.h>

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

TEST(WritingExecution, TheSameShapeAnywhereScoresZero) {
  const StepSequence expert = pen_line(20, 50.0);
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, expert, writing_diagonal(20), 5, 15), 0.0);
  // Moved by 10 px (beyond the 8 px cutoff), e.g. by an earlier letter's drift: the segment's shape is right.
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, pen_line(20, 60.0), writing_diagonal(20), 5, 15), 0.0);
}

TEST(WritingExecution, InkOffTheShapeLosesCreditBetweenTheToleranceAndTheCutoff) {
  const StepSequence expert = pen_line(20, 50.0);
  // Half the segment's points 11 px off the line's direction, half on it: the mean offset (moved away) is
  // 5.5 px, so each half lies 5.5 px from the other: credit 1/2 everywhere.
  StepSequence step = pen_line(20, 50.0);
  for (int t = 10; t < 20; ++t) step.states[static_cast<std::size_t>(t) * 13 + 1] = 61.0f;
  EXPECT_NEAR(writing_execution_reward(expert, step, writing_diagonal(20), 5, 15), 0.25 - 1.0, 0.05);
  // A line that bends away by 2 px per step: its far end is well beyond the cutoff.
  EXPECT_LT(writing_execution_reward(expert, bent_line(20, 50.0, 5, 2.0), writing_diagonal(20), 5, 15), -0.4);
  // A slight bend within the tolerance costs nothing.
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, bent_line(20, 50.0, 5, 0.2), writing_diagonal(20), 5, 15), 0.0);
}

}  // namespace
}  // namespace sc
