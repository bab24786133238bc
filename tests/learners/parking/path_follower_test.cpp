#include "teaching/learners/parking/path_follower.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "teaching/learners/parking/realistic_driver.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// A hand-made drive well inside the actuators' limits: forward with a gentle left turn, a stop, then
// reversing with some right lock. A driver has room to correct on both axes.
ParkingTrial moderate_drive() {
  ParkingTrial t;
  t.scenario = parking_pool_scenario(0, 0);
  for (int i = 0; i < 10; ++i) t.actions.push_back({0.4, -0.3});
  for (int i = 0; i < 4; ++i) t.actions.push_back({-0.5, 0.0});
  for (int i = 0; i < 10; ++i) t.actions.push_back({-0.3, 0.4});
  t.source = "expert";
  return t;
}

double end_error(const ParkingTrial& drive, const PathFollower& follower, int delay_steps) {
  const VehicleState car = vehicle_from_observation(drive.states.back());
  const int expert_step = static_cast<int>(drive.states.size()) - 1 - delay_steps;
  const VehicleState& e = follower.expert_state(expert_step * parking::kSubstepsPerAction);
  return std::hypot(car.x - e.x, car.y - e.y);
}

TEST(PathFollower, ACarOnThePathKeepsTheExpertsAction) {
  const PathFollower f(moderate_drive());
  ASSERT_EQ(f.substeps(), 24 * parking::kSubstepsPerAction);
  for (int j = 0; j < f.substeps(); j += 5) {
    const ParkingAction d = f.correction(f.expert_state(j), j);
    EXPECT_EQ(d[0], 0.0) << j;
    EXPECT_EQ(d[1], 0.0) << j;
  }
}

TEST(PathFollower, ACarBehindSpeedsUpAndACarOffToOneSideSteersBack) {
  const PathFollower f(moderate_drive());
  const int j = 15;  // driving forward at about 1 m/s
  VehicleState slow = f.expert_state(j);
  slow.speed *= 0.5;
  EXPECT_GT(f.correction(slow, j)[0], 0.0);
  // Moved to the car's left (heading + 90 degrees): steering right (u1 > 0 turns left in this model, so < 0).
  VehicleState left = f.expert_state(j);
  left.x += 0.8 * std::cos(left.heading + std::numbers::pi / 2);
  left.y += 0.8 * std::sin(left.heading + std::numbers::pi / 2);
  VehicleState right = f.expert_state(j);
  right.x -= 0.8 * std::cos(right.heading + std::numbers::pi / 2);
  right.y -= 0.8 * std::sin(right.heading + std::numbers::pi / 2);
  const double to_left = f.correction(left, j)[1], to_right = f.correction(right, j)[1];
  EXPECT_NE(to_left, 0.0);
  EXPECT_LT(to_left * to_right, 0.0) << "the two sides must be corrected in opposite directions";
}

TEST(PathFollower, ANoisyDriverWhoFollowsThePathStaysCloserThanOneWhoDoesNot) {
  const ParkingTrial e = moderate_drive();
  const PathFollower f(e);
  RealisticDriverProfile p;
  p.device = DriveDevice::Gamepad;
  p.stick_noise = 0.2;
  p.reaction_delay_s = 0.2;
  double open = 0.0, closed = 0.0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng a(seed), b(seed);
    p.follows_path = false;
    open += end_error(realistic_drive(e, p, a), f, 1);
    p.follows_path = true;
    closed += end_error(realistic_drive(e, p, b), f, 1);
  }
  std::printf("mean distance from the expert's end: open loop %.2f m, following the path %.2f m\n", open / 10,
              closed / 10);
  EXPECT_LT(closed, 0.5 * open);
}

TEST(PathFollower, WithoutNoiseOrDelayAFollowerRepeatsTheExpert) {
  const ParkingTrial e = moderate_drive();
  RealisticDriverProfile p;
  p.device = DriveDevice::MouseJoystick;
  p.control_hz = 5;
  p.stick_noise = 0.0;
  p.reaction_delay_s = 0.0;
  p.follows_path = true;
  Rng rng(1);
  const ParkingTrial d = realistic_drive(e, p, rng);
  ASSERT_EQ(d.actions.size(), e.actions.size());
  for (std::size_t t = 0; t < e.actions.size(); ++t) {
    EXPECT_NEAR(d.actions[t][0], e.actions[t][0], 1e-9) << t;
    EXPECT_NEAR(d.actions[t][1], e.actions[t][1], 1e-9) << t;
  }
}

TEST(PathFollower, FollowingDrawsNoRandomNumbersOfItsOwn) {
  RealisticDriverProfile p;
  p.follows_path = true;
  Rng a(4), b(4);
  (void)realistic_drive(moderate_drive(), p, a);
  p.follows_path = false;
  (void)realistic_drive(moderate_drive(), p, b);
  EXPECT_EQ(a.next_u64(), b.next_u64());
}

}  // namespace
}  // namespace sc
