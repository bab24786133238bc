#include "teaching/tasks/parking_execution.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// A drive of `n` steps from (x0, y0) heading h0, moving `step` m per step and turning `turn` rad per step.
StepSequence drive(int n, double x0, double y0, double h0, double step, double turn) {
  std::vector<ParkingObservation> states;
  std::vector<ParkingAction> actions;
  double x = x0, y = y0, h = h0;
  for (int t = 0; t < n; ++t) {
    states.push_back(make_observation({x, y, h, step * 5.0}, {0.0, 0.0, 0.0}));
    actions.push_back({0.0, 0.0});
    x += step * std::cos(h);
    y += step * std::sin(h);
    h += turn;
  }
  return parking_step_sequence(states, actions);
}

StepAlignment diagonal(int n) {
  StepAlignment path;
  for (int t = 0; t < n; ++t) path.push_back({t, t});
  return path;
}

TEST(ParkingExecution, TheSameMotionFromAnotherStartScoresZero) {
  const StepSequence expert = drive(10, 10.0, 5.0, 0.0, 1.0, 0.1);
  // The learner drifted 3 m off and 0.5 rad round before the segment but then moves alike.
  const StepSequence learner = drive(10, 13.0, 2.0, 0.5, 1.0, 0.1);
  // States are floats (cm-level rounding of x/100) and the reward takes a square root: ~1e-4, not 1e-9.
  EXPECT_NEAR(parking_execution_reward(expert, learner, diagonal(10), 0, 10), 0.0, 1e-3);
  EXPECT_NEAR(parking_execution_reward(expert, expert, diagonal(10), 2, 7), 0.0, 1e-9);
}

TEST(ParkingExecution, ATurnTooWideOrNotMovingScoresBelowZeroTheMoreItDiffers) {
  const StepSequence expert = drive(10, 10.0, 5.0, 0.0, 1.0, 0.2);
  const double wide = parking_execution_reward(expert, drive(10, 10.0, 5.0, 0.0, 1.0, 0.1), diagonal(10), 0, 10);
  const double stopped = parking_execution_reward(expert, drive(10, 10.0, 5.0, 0.0, 0.0, 0.0), diagonal(10), 0, 10);
  EXPECT_LT(wide, -1e-2);
  EXPECT_LT(stopped, wide);
}

TEST(ParkingExecution, TracePointsArePositionAndSignedSpeed) {
  const std::vector<TracePoint3> p = parking_trace_points(drive(3, 10.0, 5.0, 0.0, -1.0, 0.0));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0][0], 10.0, 1e-4);
  EXPECT_NEAR(p[1][0], 9.0, 1e-4);
  EXPECT_NEAR(p[0][1], 5.0, 1e-4);
  EXPECT_NEAR(p[0][2], -5.0, 1e-4);
}

}  // namespace
}  // namespace sc
