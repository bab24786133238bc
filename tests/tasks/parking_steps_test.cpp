#include "teaching/tasks/parking_steps.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/parking/parking_expert.hpp"

namespace sc {
namespace {

ParkingScenario scenario() {
  ParkingScenario s;
  s.heading0 = 3.346213;
  s.goal_spot = 3;
  return s;
}

TEST(ParkingSteps, StatesComeBeforeTheirActions) {
  ParkingPlan plan = simulate_plan(scenario(), {{0.5, 0.2}, {0.4, -0.1}, {-0.3, 0.0}});
  StepSequence steps = parking_step_sequence(plan.states, plan.actions);
  ASSERT_EQ(steps.length(), static_cast<int>(plan.actions.size()));
  EXPECT_EQ(steps.state_dim, 12);
  for (int t = 0; t < steps.length(); ++t)
    for (int d = 0; d < 12; ++d)
      EXPECT_FLOAT_EQ(steps.states[static_cast<std::size_t>(t * 12 + d)], static_cast<float>(plan.states[t][d]));
  EXPECT_FLOAT_EQ(steps.actions[2], 0.4f);
}

TEST(ParkingSteps, TrialWithoutStatesIsResimulated) {
  ParkingPlan plan = simulate_plan(scenario(), {{0.5, 0.2}, {0.4, -0.1}, {-0.3, 0.0}});
  ParkingTrial bare;
  bare.scenario = scenario();
  bare.actions = plan.actions;
  EXPECT_EQ(parking_step_sequence(bare).states, parking_step_sequence(plan.states, plan.actions).states);
}

TEST(ParkingSteps, ResponsiveTrialIsReducedToControlRate) {
  ParkingTrial trial;
  trial.scenario = scenario();
  trial.control_hz = 15;
  trial.actions = {{0.3, 0.0}, {0.6, 0.3}, {0.9, 0.6}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
  StepSequence steps = parking_step_sequence(trial);
  ASSERT_EQ(steps.length(), 2);
  EXPECT_NEAR(steps.actions[0], 0.6f, 1e-6);
  EXPECT_NEAR(steps.actions[1], 0.3f, 1e-6);
}

TEST(ParkingSteps, VehicleFromObservationInvertsTheObservation) {
  VehicleState v{12.5, -3.0, 2.0, -4.5};
  VehicleState back = vehicle_from_observation(make_observation(v, Pose{}));
  EXPECT_NEAR(back.x, v.x, 1e-9);
  EXPECT_NEAR(back.y, v.y, 1e-9);
  EXPECT_NEAR(back.heading, v.heading, 1e-9);
  EXPECT_NEAR(back.speed, v.speed, 1e-9);
}

}  // namespace
}  // namespace sc
