#include "teaching/expertise/execution_reference.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(ExecutionReference, TheLearnersAlignmentIsCarriedToTheReferenceThroughTheExpertsSteps) {
  ExecutionReference r;
  // Expert steps 0..3; the reference does step 1 in two steps (1, 2) and step 3 as its step 4.
  r.from_expert = {{0, 0}, {1, 1}, {1, 2}, {2, 3}, {3, 4}};
  const StepAlignment learner = {{0, 0}, {1, 1}, {2, 2}, {2, 3}, {3, 4}};
  EXPECT_EQ(through_reference(r, learner, 1, 3), (StepAlignment{{1, 1}, {2, 1}, {3, 2}, {3, 3}}));
  EXPECT_EQ(through_reference(r, learner, 0, 4), (StepAlignment{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {3, 3}, {4, 4}}));
  EXPECT_TRUE(through_reference(r, learner, 4, 6).empty());
}

TEST(ExecutionReference, ExpertStepsTheOtherAlignmentLacksCarryNothing) {
  ExecutionReference r;
  r.from_expert = {{0, 0}, {2, 1}};
  EXPECT_EQ(through_reference(r, {{0, 5}, {1, 6}, {2, 7}}, 0, 3), (StepAlignment{{0, 5}, {1, 7}}));
  EXPECT_TRUE(through_reference(r, {{1, 6}}, 0, 3).empty());
}

}  // namespace
}  // namespace sc
