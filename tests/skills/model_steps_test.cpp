#include "teaching/skills/model_steps.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

StepSequence straight(int t, float dx) {
  StepSequence s;
  s.action_dim = 2;
  s.state_dim = 1;
  for (int i = 0; i < t; ++i) {
    s.actions.push_back(dx);
    s.actions.push_back(0.0f);
    s.states.push_back(static_cast<float>(i));
  }
  return s;
}

TEST(ModelSteps, ZeroStepIsIdentity) {
  const StepSequence s = straight(7, 1.0f);
  const ModelSteps m = to_model_steps(s, 0.0);
  EXPECT_EQ(m.steps.actions, s.actions);
  ASSERT_EQ(m.original_begin.size(), 8u);
  EXPECT_EQ(m.original_begin.back(), 7);
}

TEST(ModelSteps, APhaseShortensOnlyTheFirstGroup) {
  // 23 one-unit steps at 5 units per model step, read 2 units into the first group: 3, then 5s, then 0.
  const ModelSteps m = to_model_steps(straight(23, 1.0f), 5.0, 2.0);
  EXPECT_EQ(m.original_begin, (std::vector<int>{0, 3, 8, 13, 18, 23}));
  EXPECT_FLOAT_EQ(m.steps.actions[0], 1.0f);  // still a unit direction: the phase is not path walked
  EXPECT_EQ(to_model_steps(straight(23, 1.0f), 5.0, 0.0).original_begin, (std::vector<int>{0, 5, 10, 15, 20, 23}));
}

TEST(ModelSteps, ResamplesByArcLengthAndMapsBoundariesBack) {
  // 23 one-unit steps at 5 units per model step: groups of 5, 5, 5, 5 and a remainder of 3.
  const StepSequence s = straight(23, 1.0f);
  const ModelSteps m = to_model_steps(s, 5.0);
  ASSERT_EQ(m.steps.length(), 5);
  EXPECT_EQ(m.original_begin, (std::vector<int>{0, 5, 10, 15, 20, 23}));
  EXPECT_FLOAT_EQ(m.steps.actions[0], 1.0f);  // mean unit direction, not the 5-unit displacement
  EXPECT_FLOAT_EQ(m.steps.states[2], 10.0f);  // state before the group's first action
  const Segmentation model{{{3, 0, 2}, {1, 2, 5}}};
  const Segmentation original = to_original_indices(model, m);
  EXPECT_EQ(original, (Segmentation{{{3, 0, 10}, {1, 10, 23}}}));
}

TEST(ModelSteps, ReadoutDropsEmptyAndOutOfOrderSegments) {
  // Boundaries 6, 4 (before the previous one: empty), 6 (empty), last = length.
  const Segmentation seg = segments_from_boundaries({6, 4, 6, 0}, {2, 5, 7, 1}, 10);
  EXPECT_EQ(seg, (Segmentation{{{2, 0, 6}, {1, 6, 10}}}));
  const Segmentation all_first = segments_from_boundaries({10, 10, 10}, {0, 1, 2}, 10);
  EXPECT_EQ(all_first, (Segmentation{{{0, 0, 10}}}));
}

}  // namespace
}  // namespace sc
