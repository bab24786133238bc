// The planning expert on a fixed set of scenarios: success, no collisions, smooth actions, determinism.
#include "engine/parking/parking_expert.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/rng.hpp"

namespace sc {
namespace {

// Largest change of each action channel between consecutive steps.
std::array<double, 2> largest_change(const std::vector<ParkingAction>& actions) {
  std::array<double, 2> m{0.0, 0.0};
  for (std::size_t t = 1; t < actions.size(); ++t)
    for (int c = 0; c < 2; ++c) m[c] = std::max(m[c], std::fabs(actions[t][c] - actions[t - 1][c]));
  return m;
}

void expect_clean_smooth_plan(const ParkingScenario& s, const ParkingPlan& plan) {
  SCOPED_TRACE("heading0 " + std::to_string(s.heading0) + " spot " + std::to_string(s.goal_spot) + " " +
               std::string(to_string(s.variant)) + (s.reverse_in ? " reverse-in" : ""));
  EXPECT_TRUE(plan.success);
  EXPECT_FALSE(plan.collision);
  ASSERT_EQ(plan.success_step, static_cast<int>(plan.actions.size()));
  ASSERT_EQ(plan.states.size(), plan.actions.size() + 1);
  ASSERT_EQ(plan.rewards.size(), plan.actions.size());
  EXPECT_TRUE(is_success_reward(plan.rewards.back()));
  for (const auto& a : plan.actions) {
    EXPECT_LE(std::fabs(a[0]), 1.0);
    EXPECT_LE(std::fabs(a[1]), 1.0);
  }
  // A careful driver: no chattering between full left and full right (a change of 2 in 0.2 s). The
  // largest steering change measured over 1000 random classic scenarios is 1.11 (a lock-to-lock switch
  // at a change of direction, spread over two steps); on this fixed set it is below 0.9.
  const auto change = largest_change(plan.actions);
  EXPECT_LE(change[1], 1.2);
  // The plan is exactly what ParkingSim does with its actions.
  const ParkingPlan replayed = simulate_plan(s, plan.actions);
  EXPECT_EQ(replayed.states, plan.states);
  EXPECT_EQ(replayed.rewards, plan.rewards);
}

TEST(ParkingExpert, ClassicScenarios) {
  const ParkingExpert expert;
  Rng rng(20240501);
  int total_steps = 0;
  for (int i = 0; i < 18; ++i) {
    const ParkingScenario s = sample_parking_scenario(rng, LotVariant::Classic);
    const ParkingPlan plan = expert.plan(s);
    expect_clean_smooth_plan(s, plan);
    total_steps += plan.success_step;
  }
  EXPECT_LE(total_steps / 18.0, 19.0);  // the paper's SAC expert: 18.6
}

TEST(ParkingExpert, ParkedCarScenariosWithoutCollisions) {
  const ParkingExpert expert;
  Rng rng(77);
  for (int i = 0; i < 8; ++i) {
    const ParkingScenario s = sample_parking_scenario(rng, LotVariant::Parked);
    expect_clean_smooth_plan(s, expert.plan(s));
  }
}

TEST(ParkingExpert, ReverseInGoals) {
  const ParkingExpert expert;
  Rng rng(5);
  for (int i = 0; i < 4; ++i) {
    const ParkingScenario s = sample_parking_scenario(rng, i < 2 ? LotVariant::Classic : LotVariant::Parked, 1.0);
    ASSERT_TRUE(s.reverse_in);
    const ParkingPlan plan = expert.plan(s);
    expect_clean_smooth_plan(s, plan);
    // Backed in: the car ends nose-out, so its last move into the spot is in reverse.
    EXPECT_LT(plan.states.back()[3] * plan.states.back()[11], 0.0);
  }
}

TEST(ParkingExpert, GoldenScenarioAndDeterminism) {
  // The reference's golden episode (SAC expert: success at step 16).
  ParkingScenario s;
  s.heading0 = 3.346213;
  s.goal_spot = 3;
  const ParkingExpert expert;
  const ParkingPlan a = expert.plan(s);
  const ParkingPlan b = expert.plan(s);
  expect_clean_smooth_plan(s, a);
  EXPECT_LE(a.success_step, 16);
  EXPECT_EQ(a.actions, b.actions);
  EXPECT_GT(a.planning_ms, 0.0);
}

TEST(ParkingExpert, PlanConvertsToAnExpertTrial) {
  ParkingScenario s;
  s.heading0 = 1.0;
  s.goal_spot = 20;
  const ParkingPlan plan = ParkingExpert().plan(s);
  const ParkingTrial trial = plan.to_trial(s);
  EXPECT_EQ(trial.source, "expert");
  EXPECT_EQ(trial.scenario, s);
  EXPECT_EQ(trial.actions, plan.actions);
  EXPECT_EQ(trial.success, std::optional<bool>(true));
  const ParkingTrial back = parse_parking_trial(parking_trial_to_json(trial), "mem");
  EXPECT_EQ(back.states, plan.states);
}

}  // namespace
}  // namespace sc
