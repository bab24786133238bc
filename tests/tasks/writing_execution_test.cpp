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

TEST(WritingExecution, InkWithinTheToleranceScoresZeroAndBeyondTheCutoffMinusOne) {
  const StepSequence expert = pen_line(20, 50.0);
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, expert, writing_diagonal(20), 5, 15), 0.0);
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, pen_line(20, 52.0), writing_diagonal(20), 5, 15),
                   0.0);  // 2 px <= 3
  EXPECT_DOUBLE_EQ(writing_execution_reward(expert, pen_line(20, 60.0), writing_diagonal(20), 5, 15),
                   -1.0);  // 10 px >= 8
  const double half =
      writing_execution_reward(expert, pen_line(20, 55.5), writing_diagonal(20), 5, 15);  // 5.5 px: credit 1/2
  EXPECT_NEAR(half, 0.25 - 1.0, 1e-6);
}

}  // namespace
}  // namespace sc
