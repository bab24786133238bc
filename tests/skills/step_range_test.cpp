#include "teaching/skills/step_range.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

StepSequence counting(int length, int state_dim) {
  StepSequence s;
  s.state_dim = state_dim;
  s.action_dim = 2;
  for (int t = 0; t < length; ++t) {
    for (int d = 0; d < state_dim; ++d) s.states.push_back(static_cast<float>(10 * t + d));
    s.actions.push_back(static_cast<float>(t));
    s.actions.push_back(static_cast<float>(-t));
  }
  return s;
}

TEST(StepRange, TakesTheStatesAndActionsOfTheSteps) {
  const StepSequence part = steps_between(counting(6, 2), 2, 5);
  EXPECT_EQ(part.length(), 3);
  EXPECT_EQ(part.state_dim, 2);
  EXPECT_EQ(part.states, (std::vector<float>{20, 21, 30, 31, 40, 41}));
  EXPECT_EQ(part.actions, (std::vector<float>{2, -2, 3, -3, 4, -4}));
  EXPECT_EQ(steps_between(counting(6, 2), 3, 3).length(), 0);
}

TEST(StepRange, ASequenceWithoutStatesGivesActionsOnly) {
  const StepSequence part = steps_between(counting(4, 0), 1, 4);
  EXPECT_TRUE(part.states.empty());
  EXPECT_EQ(part.actions, (std::vector<float>{1, -1, 2, -2, 3, -3}));
}

TEST(StepRange, ShiftedMovesEverySegment) {
  const Segmentation s = shifted(Segmentation{{{3, 0, 4}, {1, 4, 7}}}, 10);
  EXPECT_EQ(s, (Segmentation{{{3, 10, 14}, {1, 14, 17}}}));
}

}  // namespace
}  // namespace sc
