#include "teaching/students/parking_student_rollout.hpp"

#include <gtest/gtest.h>

#include "engine/core/rng.hpp"

namespace sc {
namespace {

TEST(ParkingStudentRollout, DrivesUntilTheEpisodeEndsAndRecordsEveryStep) {
  const BcPolicy policy(12, 2, 16, 3);  // untrained: wanders until the 100-step horizon
  Rng rng(4);
  const ParkingScenario scenario = sample_parking_scenario(rng, LotVariant::Classic);
  const ParkingTrial t = rollout_parking_student(policy, scenario);
  ASSERT_FALSE(t.actions.empty());
  EXPECT_LE(t.actions.size(), static_cast<std::size_t>(parking::kHorizon));
  EXPECT_EQ(t.states.size(), t.actions.size() + 1);
  EXPECT_EQ(t.rewards.size(), t.actions.size());
  EXPECT_EQ(t.source, "student");
  // The recorded actions replay to the recorded states: nothing is applied that is not in the trial.
  ParkingSim sim(scenario);
  for (std::size_t i = 0; i < t.actions.size(); ++i) {
    EXPECT_EQ(sim.observation(), t.states[i]);
    sim.step(t.actions[i]);
  }
  EXPECT_EQ(sim.succeeded(), t.success.value_or(false));
  EXPECT_EQ(parking_episode_score(t), std::min(t.rewards.back(), 0.0));
  // Deterministic.
  EXPECT_EQ(rollout_parking_student(policy, scenario).actions, t.actions);
}

TEST(ParkingStudentRollout, ScoreAveragesEpisodes) {
  const BcPolicy policy(12, 2, 16, 3);
  Rng rng(4);
  const std::vector<ParkingScenario> scenarios{sample_parking_scenario(rng, LotVariant::Classic),
                                               sample_parking_scenario(rng, LotVariant::Classic)};
  const ParkingScore score = score_parking_student(policy, scenarios);
  const double expected = (parking_episode_score(rollout_parking_student(policy, scenarios[0])) +
                           parking_episode_score(rollout_parking_student(policy, scenarios[1]))) /
                          2.0;
  EXPECT_DOUBLE_EQ(score.mean_reward, expected);
  EXPECT_LE(score.mean_reward, 0.0);
  const double steps = (parking_mean_step_reward(rollout_parking_student(policy, scenarios[0])) +
                        parking_mean_step_reward(rollout_parking_student(policy, scenarios[1]))) /
                       2.0;
  EXPECT_DOUBLE_EQ(score.step_reward, steps);
}

TEST(ParkingStudentRollout, MeanStepRewardAveragesEveryStep) {
  ParkingTrial t;
  t.rewards = {-0.5, -0.25, -0.15};
  EXPECT_DOUBLE_EQ(parking_mean_step_reward(t), -0.3);
  EXPECT_DOUBLE_EQ(parking_episode_score(t), -0.15);
}

}  // namespace
}  // namespace sc
