// Live driving at sub-step resolution: what is shown is what ParkingSim computes, and the recorded trial
// replays to exactly the same episode in both input timings.
#include "engine/parking_view/live_parking_drive.hpp"

#include <gtest/gtest.h>

#include "engine/core/rng.hpp"
#include "engine/parking/parking_replay.hpp"
#include "engine/parking/parking_sim.hpp"

namespace sc {
namespace {

// A live input that changes at every sub-step, like a real stick (the latch decides what reaches the car).
input::DriveAction wobbly_input(Rng& rng) { return {rng.uniform(-0.3, 1.0), rng.uniform(-1.0, 1.0)}; }

void expect_replays_exactly(input::ActionTiming timing, LotVariant variant, std::uint64_t seed) {
  Rng rng(seed);
  LiveParkingDrive drive(sample_parking_scenario(rng, variant), timing);
  for (int i = 0; i < 3 * 40 + 2 && !drive.done(); ++i) drive.substep(wobbly_input(rng));
  const ParkingTrial trial = drive.to_trial("learner", "test");
  EXPECT_EQ(trial.control_hz, timing == input::ActionTiming::Latched ? 5 : 15);
  const ParkingReplay replay = replay_parking_trial(trial);
  ASSERT_EQ(static_cast<int>(replay.steps.size()), drive.control_steps());
  EXPECT_EQ(replay.ignored_actions, 0);
  for (std::size_t k = 0; k < replay.steps.size(); ++k) EXPECT_EQ(replay.steps[k].reward, drive.rewards()[k]);
  if (drive.done()) {
    EXPECT_EQ(replay.steps.back().vehicle.x, drive.current().x);
    EXPECT_EQ(replay.steps.back().vehicle.heading, drive.current().heading);
  }
  EXPECT_EQ(trial.states.size(), trial.rewards.size() + 1);
}

TEST(LiveParkingDrive, LatchedRecordingReplaysExactly) {
  for (std::uint64_t seed : {1u, 2u}) expect_replays_exactly(input::ActionTiming::Latched, LotVariant::Classic, seed);
}

TEST(LiveParkingDrive, ResponsiveRecordingReplaysExactly) {
  for (std::uint64_t seed : {3u, 4u})
    expect_replays_exactly(input::ActionTiming::Responsive, LotVariant::Classic, seed);
}

TEST(LiveParkingDrive, ParkedLotRecordingReplaysExactly) {
  for (std::uint64_t seed : {5u, 6u, 7u})
    expect_replays_exactly(input::ActionTiming::Latched, LotVariant::Parked, seed);
}

TEST(LiveParkingDrive, SubstepStatesMatchParkingSimAtControlSteps) {
  Rng rng(11);
  const ParkingScenario scenario = sample_parking_scenario(rng, LotVariant::Classic);
  LiveParkingDrive drive(scenario);
  ParkingSim sim(scenario);
  for (int step = 0; step < 10; ++step) {
    const input::DriveAction live{0.6, step < 5 ? 0.8 : -0.5};
    for (int k = 0; k < 3; ++k) {
      const VehicleState before = drive.current();
      drive.substep(live);
      EXPECT_EQ(drive.previous().x, before.x);  // previous() is the state the sub-step started from
    }
    sim.step({live.accel, live.steer});
    EXPECT_EQ(drive.current().x, sim.vehicle().x);
    EXPECT_EQ(drive.current().y, sim.vehicle().y);
    EXPECT_EQ(drive.control_steps(), sim.steps());
  }
  EXPECT_EQ(drive.trail().size(), 31u);  // the start and every sub-step
  EXPECT_NEAR(drive.time_seconds(), 2.0, 1e-12);
}

TEST(LiveParkingDrive, LatchedInputOnlyReachesTheCarAtControlSteps) {
  LiveParkingDrive drive(ParkingScenario{});
  drive.substep({1.0, 0.0});
  drive.substep({-1.0, 1.0});  // mid-step: ignored until the next control step
  EXPECT_EQ(drive.applied_action(), (input::DriveAction{1.0, 0.0}));
  drive.substep({-1.0, 1.0});
  drive.substep({-1.0, 1.0});
  EXPECT_EQ(drive.applied_action(), (input::DriveAction{-1.0, 1.0}));
}

TEST(LiveParkingDrive, StopsAtTheEndOfTheEpisode) {
  LiveParkingDrive drive(ParkingScenario{});
  for (int i = 0; i < 400; ++i) drive.substep({0.0, 0.0});
  EXPECT_TRUE(drive.done());
  EXPECT_EQ(drive.control_steps(), parking::kHorizon);
  EXPECT_EQ(drive.substeps(), 3 * parking::kHorizon);
  EXPECT_FALSE(drive.succeeded());
}

TEST(LiveParkingDrive, LiveRewardFollowsTheCarBetweenControlSteps) {
  ParkingScenario scenario;
  scenario.heading0 = 1.5707963267948966;  // facing the lower row
  scenario.goal_spot = 7;                  // straight ahead at (2, 14)
  LiveParkingDrive drive(scenario);
  const double at_start = drive.live_reward();
  drive.substep({1.0, 0.0});
  drive.substep({1.0, 0.0});
  EXPECT_GT(drive.live_reward(), at_start);  // closer to the goal after two sub-steps
  EXPECT_TRUE(drive.rewards().empty());      // no control step completed yet
}

}  // namespace
}  // namespace sc
