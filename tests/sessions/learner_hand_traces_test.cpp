#include "teaching/sessions/learner_hand_traces.hpp"

#include <gtest/gtest.h>

#include "tests/sessions/toy_task_kit.hpp"

namespace sc::test {
namespace {

std::vector<std::pair<double, double>> xy(const TaskKit& kit, const StepSequence& steps) {
  std::vector<std::pair<double, double>> out;
  for (const TracePoint3& p : kit.trace_points(steps)) out.emplace_back(p[0], p[1]);
  return out;
}

TEST(LearnerHandTraces, TheLearnersTrialTheGuideAndTheNamedHandInTheTasksCoordinates) {
  ToyTaskKit kit(4, ExpertiseMode::QualityAware);
  kit.give_references = true;
  const ExpertDemo& expert = kit.expert_pool()[1];
  const Json trial = toy_trial(1, toy_learner_gestures(1, 2, 3));
  const auto traces = learner_hand_traces(kit, expert.scenario, expert.steps, trial, "the double-length hand");
  ASSERT_TRUE(traces.has_value());
  EXPECT_EQ(traces->learner, xy(kit, kit.steps_of(trial)));
  EXPECT_EQ(traces->guide, xy(kit, expert.steps));
  EXPECT_EQ(traces->hand, xy(kit, kit.execution_references(expert.scenario, expert.steps).front().steps));
  EXPECT_NE(traces->hand, traces->guide);
}

TEST(LearnerHandTraces, NoHandOrAnUnknownHandGivesNoTraces) {
  ToyTaskKit kit(4, ExpertiseMode::QualityAware);
  kit.give_references = true;
  const ExpertDemo& expert = kit.expert_pool()[0];
  const Json trial = toy_trial(0, toy_expert_gestures(0));
  EXPECT_FALSE(learner_hand_traces(kit, expert.scenario, expert.steps, trial, "").has_value());
  EXPECT_FALSE(learner_hand_traces(kit, expert.scenario, expert.steps, trial, "another hand").has_value());
  kit.give_references = false;
  EXPECT_FALSE(learner_hand_traces(kit, expert.scenario, expert.steps, trial, "the double-length hand").has_value());
}

}  // namespace
}  // namespace sc::test
