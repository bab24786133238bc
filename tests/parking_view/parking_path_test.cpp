// Paths for drawing: sub-step re-simulation agrees with ParkingSim at every control step (also with
// collisions and 15 Hz recordings), and the interpolated ghost-car pose.
#include "engine/parking_view/parking_path.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_replay.hpp"

namespace sc {
namespace {

ParkingTrial random_trial(std::uint64_t seed, LotVariant variant, int control_hz, int count) {
  Rng rng(seed);
  ParkingTrial trial;
  trial.scenario = sample_parking_scenario(rng, variant);
  trial.control_hz = control_hz;
  for (int i = 0; i < count; ++i) trial.actions.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
  return trial;
}

void expect_matches_replay(const ParkingTrial& trial) {
  const ParkingPath path = simulate_parking_path(trial);
  const ParkingReplay replay = replay_parking_trial(trial);
  ASSERT_EQ(path.control_steps, static_cast<int>(replay.steps.size()));
  ASSERT_EQ(path.samples.size(), 1 + 3 * replay.steps.size());
  ASSERT_EQ(path.rewards.size(), replay.steps.size());
  for (std::size_t k = 0; k < replay.steps.size(); ++k) {
    const VehicleState& a = path.samples[3 * (k + 1)].vehicle;
    const VehicleState& b = replay.steps[k].vehicle;
    // Same functions in the same order: bit-identical, not merely close.
    EXPECT_EQ(a.x, b.x) << "step " << k + 1;
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.heading, b.heading);
    EXPECT_EQ(a.speed, b.speed);
    EXPECT_EQ(path.rewards[k], replay.steps[k].reward);
  }
  EXPECT_EQ(path.success_step, replay.success_step);
  EXPECT_EQ(path.collision, replay.collision);
  EXPECT_NEAR(path.duration(), 0.2 * path.control_steps, 1e-9);
}

TEST(ParkingPath, MatchesParkingSimAtEveryControlStepClassic) {
  for (std::uint64_t seed : {1u, 2u, 3u}) expect_matches_replay(random_trial(seed, LotVariant::Classic, 5, 100));
}

TEST(ParkingPath, MatchesParkingSimWithCollisions) {
  // Full throttle with random steering in the parked lot ends in a wall or a parked car.
  int collided = 0;
  for (std::uint64_t seed = 10; seed < 20; ++seed) {
    ParkingTrial trial = random_trial(seed, LotVariant::Parked, 5, 100);
    for (auto& a : trial.actions) a[0] = 1.0;
    expect_matches_replay(trial);
    collided += simulate_parking_path(trial).collision;
  }
  EXPECT_GT(collided, 0);
}

TEST(ParkingPath, ResponsiveRecordingUsesOneActionPerSubstep) {
  const ParkingTrial trial = random_trial(7, LotVariant::Classic, 15, 300);
  expect_matches_replay(trial);
  // The steering drawn for sub-step i is that of action i.
  const ParkingPath path = simulate_parking_path(trial);
  EXPECT_NEAR(path.samples[2].steering, std::clamp(trial.actions[1][1], -1.0, 1.0) * std::numbers::pi / 4, 1e-12);
}

TEST(ParkingPath, IgnoresActionsAfterTheEpisodeEnds) {
  ParkingTrial trial = random_trial(4, LotVariant::Classic, 5, 140);
  EXPECT_EQ(simulate_parking_path(trial).control_steps, 100);
}

TEST(ParkingPath, RejectsOtherControlRates) {
  const ParkingTrial trial = random_trial(4, LotVariant::Classic, 5, 3);
  EXPECT_THROW(simulate_parking_path(trial.scenario, trial.actions, 10), InputError);
}

TEST(ParkingPath, CarPoseInterpolatesBetweenSubsteps) {
  ParkingPath path;
  path.samples.push_back({0.0, {0, 0, 0, 0}, 0.0});
  path.samples.push_back({0.1, {1, 2, 0.4, 0}, 0.3});
  path.samples.push_back({0.2, {3, 2, 0.6, 0}, -0.2});
  const CarPose mid = car_pose_at(path, 0.05);
  EXPECT_NEAR(mid.center.x, 0.5f, 1e-6f);
  EXPECT_NEAR(mid.center.y, 1.0f, 1e-6f);
  EXPECT_NEAR(mid.heading, 0.2f, 1e-6f);
  EXPECT_NEAR(mid.steering, 0.3f, 1e-6f);
  EXPECT_NEAR(car_pose_at(path, 0.15).center.x, 2.0f, 1e-6f);
  EXPECT_NEAR(car_pose_at(path, -1.0).center.x, 0.0f, 1e-6f);  // clamped to the ends
  EXPECT_NEAR(car_pose_at(path, 9.0).center.x, 3.0f, 1e-6f);
  EXPECT_NEAR(car_pose_at(path, 9.0).steering, -0.2f, 1e-6f);
}

TEST(ParkingPath, HeadingInterpolatesAlongTheShorterArc) {
  // Unwrapped headings 3.1 and -3.1 + 2pi... seen as 3.1 -> -3.1: the short way crosses pi, not zero.
  const CarPose p = interpolate_car_pose({0, 0, 3.1, 0}, {0, 0, -3.1, 0}, 0.0, 0.5);
  EXPECT_NEAR(std::cos(p.heading), -1.0, 1e-3);
}

TEST(ParkingPath, PathPointsAreTheSamplePositions) {
  const ParkingPath path = simulate_parking_path(random_trial(5, LotVariant::Classic, 5, 4));
  const auto points = path_points(path);
  ASSERT_EQ(points.size(), path.samples.size());
  EXPECT_FLOAT_EQ(points.back().x, static_cast<float>(path.samples.back().vehicle.x));
}

}  // namespace
}  // namespace sc
