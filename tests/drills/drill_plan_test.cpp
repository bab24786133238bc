#include "teaching/drills/drill_plan.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc {
namespace {

// Expert e: state t = (100e + t, -t), action t = (e, t), for T steps.
StepSequence expert(int e, int steps) {
  StepSequence s;
  s.state_dim = 2;
  s.action_dim = 2;
  for (int t = 0; t < steps; ++t) {
    s.states.insert(s.states.end(), {static_cast<float>(100 * e + t), static_cast<float>(-t)});
    s.actions.insert(s.actions.end(), {static_cast<float>(e), static_cast<float>(t)});
  }
  return s;
}

DrillPlan two_segment_plan() {
  DrillPlan plan;
  plan.target_skill = 4;
  plan.ngram = {4, 9};
  plan.segments = {{4, 1, 2, 5}, {9, 0, 6, 8}};
  return plan;
}

TEST(DrillPlan, LengthsStartsAndSegmentation) {
  const DrillPlan plan = two_segment_plan();
  EXPECT_EQ(plan.length(), 5);
  EXPECT_EQ(plan.skills(), (std::vector<int>{4, 9}));
  EXPECT_EQ(plan.segment_starts(), (std::vector<int>{0, 3}));
  const Segmentation seg = plan_segmentation(plan);
  ASSERT_EQ(seg.segments.size(), 2u);
  EXPECT_EQ(seg.segments[0], (SkillSegment{4, 0, 3}));
  EXPECT_EQ(seg.segments[1], (SkillSegment{9, 3, 5}));
}

TEST(DrillPlan, ConcatenatesExpertStepsAndStartsAtTheFirstSegment) {
  const std::vector<StepSequence> experts = {expert(0, 10), expert(1, 6)};
  const DrillPlan plan = two_segment_plan();
  EXPECT_EQ(drill_initial_state(plan, experts), (std::vector<float>{102.0f, -2.0f}));
  const StepSequence steps = concatenate_expert_steps(plan, experts);
  EXPECT_EQ(steps.length(), 5);
  EXPECT_EQ(steps.states, (std::vector<float>{102, -2, 103, -3, 104, -4, 6, -6, 7, -7}));
  EXPECT_EQ(steps.actions, (std::vector<float>{1, 2, 1, 3, 1, 4, 0, 6, 0, 7}));
}

TEST(DrillPlan, RejectsSegmentsOutsideTheExperts) {
  const std::vector<StepSequence> experts = {expert(0, 10), expert(1, 4)};
  DrillPlan plan = two_segment_plan();  // segment 0 asks expert 1 for [2, 5) but it has 4 steps
  EXPECT_THROW(concatenate_expert_steps(plan, experts), InputError);
  plan.segments[0].expert = 7;
  EXPECT_THROW(drill_initial_state(plan, experts), InputError);
  EXPECT_THROW(concatenate_expert_steps(DrillPlan{}, experts), InputError);
}

}  // namespace
}  // namespace sc
