#include "teaching/learners/parking/realistic_driver.hpp"

#include <cmath>
#include <initializer_list>
#include <utility>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/parking/parking_sim.hpp"
#include "teaching/learners/parking/path_follower.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

// An expert drive in pool scenario 0 of `steps` control steps of each action in turn.
ParkingTrial hand_made_drive(std::initializer_list<std::pair<int, ParkingAction>> runs) {
  ParkingTrial t;
  t.scenario = parking_pool_scenario(0, 0);
  for (const auto& [steps, action] : runs) t.actions.insert(t.actions.end(), static_cast<std::size_t>(steps), action);
  t.source = "expert";
  return t;
}

// Forward with a left turn, a hard stop, then reversing with right lock.
ParkingTrial expert_drive() { return hand_made_drive({{8, {0.8, -0.3}}, {4, {-0.9, 0.0}}, {8, {-0.6, 0.9}}}); }

RealisticDriverProfile clean(DriveDevice device, int hz) {
  RealisticDriverProfile p;
  p.device = device;
  p.control_hz = hz;
  p.stick_noise = 0.0;
  p.reaction_delay_s = 0.0;
  return p;
}

double speed_of(const ParkingObservation& o) { return vehicle_from_observation(o).speed; }

// The hand-made expert drive as `p` drives it, each time from the same seed: drives that differ only by the profile.
ParkingTrial drive_as(const RealisticDriverProfile& p) {
  Rng rng(1);
  return realistic_drive(expert_drive(), p, rng);
}

TEST(RealisticDriver, SameSeedSameDriveOtherSeedAnotherDrive) {
  RealisticDriverProfile p;
  Rng a(7), b(7), c(8);
  const ParkingTrial x = realistic_drive(expert_drive(), p, a);
  EXPECT_EQ(parking_trial_to_json(x), parking_trial_to_json(realistic_drive(expert_drive(), p, b)));
  EXPECT_NE(x.actions, realistic_drive(expert_drive(), p, c).actions);
  EXPECT_EQ(x.device, "gamepad");
  EXPECT_EQ(x.source, "learner");
}

TEST(RealisticDriver, MouseWithoutNoiseOrDelayAtTheControlRateRepeatsTheExpert) {
  Rng rng(1);
  const ParkingTrial e = expert_drive();
  const ParkingTrial d = realistic_drive(e, clean(DriveDevice::MouseJoystick, 5), rng);
  ASSERT_EQ(d.actions.size(), e.actions.size());
  for (std::size_t t = 0; t < e.actions.size(); ++t) {
    EXPECT_NEAR(d.actions[t][0], e.actions[t][0], 1e-9) << t;
    EXPECT_NEAR(d.actions[t][1], e.actions[t][1], 1e-9) << t;
  }
}

TEST(RealisticDriver, GamepadDeadZoneSilencesSmallIntents) {
  ParkingTrial e = expert_drive();
  e.actions.assign(5, {0.05, -0.05});  // inside the stick's 0.12 dead zone
  Rng rng(1);
  for (const ParkingAction& u : realistic_drive(e, clean(DriveDevice::Gamepad, 5), rng).actions) {
    EXPECT_EQ(u[0], 0.0);
    EXPECT_EQ(u[1], 0.0);
  }
}

TEST(RealisticDriver, KeyboardGivesOnlyKeyActionsAt15Hz) {
  RealisticDriverProfile p = clean(DriveDevice::Keyboard, 15);
  p.stick_noise = 0.2;
  Rng rng(3);
  const ParkingTrial d = realistic_drive(expert_drive(), p, rng);
  EXPECT_EQ(d.control_hz, 15);
  ASSERT_FALSE(d.rewards.empty());
  EXPECT_EQ(d.actions.size(), 3 * d.rewards.size());
  EXPECT_EQ(d.states.size(), d.rewards.size() + 1);
  int held = 0;
  for (const ParkingAction& u : d.actions)
    for (double v : u) {
      EXPECT_TRUE(v == 0.0 || std::abs(v) == 1.0) << v;
      held += v != 0.0;
    }
  EXPECT_GT(held, 0);
}

TEST(RealisticDriver, ReactionDelayShiftsTheExpertsActions) {
  RealisticDriverProfile p = clean(DriveDevice::MouseJoystick, 5);
  p.reaction_delay_s = 0.4;  // two control steps
  Rng rng(1);
  const ParkingTrial e = expert_drive();
  const ParkingTrial d = realistic_drive(e, p, rng);
  ASSERT_EQ(d.actions.size(), e.actions.size() + 2);
  EXPECT_EQ(d.actions[0], (ParkingAction{0.0, 0.0}));
  EXPECT_EQ(d.actions[1], (ParkingAction{0.0, 0.0}));
  for (std::size_t t = 2; t < d.actions.size(); ++t) EXPECT_NEAR(d.actions[t][0], e.actions[t - 2][0], 1e-9) << t;
}

TEST(RealisticDriver, AStartWaitStandsStillFirstThenDrivesTheSameMotion) {
  RealisticDriverProfile p = clean(DriveDevice::Gamepad, 15);
  p.reaction_delay_s = 0.2;
  const ParkingTrial late = drive_as(p);
  p.start_wait_s = 1.0;  // five more control steps
  const ParkingTrial waited = drive_as(p);
  ASSERT_EQ(waited.states.size(), late.states.size() + 5);
  for (std::size_t t = 0; t <= 5; ++t) EXPECT_EQ(waited.states[t], late.states[0]) << t;
  for (std::size_t t = 0; t < late.states.size(); ++t)
    for (std::size_t d = 0; d < 6; ++d) EXPECT_NEAR(waited.states[t + 5][d], late.states[t][d], 1e-12) << t;
  p.start_wait_s = -1.0;
  EXPECT_THROW(drive_as(p), InputError);
}

TEST(RealisticDriver, AnEndWaitBrakesToAStandstillAndStands) {
  RealisticDriverProfile p = clean(DriveDevice::MouseJoystick, 15);
  const ParkingTrial plain = drive_as(p);
  p.end_wait_s = 1.0;  // five more control steps
  const ParkingTrial waited = drive_as(p);
  ASSERT_EQ(waited.states.size(), plain.states.size() + 5);
  for (std::size_t t = 0; t < plain.states.size(); ++t) EXPECT_EQ(waited.states[t], plain.states[t]) << t;
  EXPECT_GT(std::abs(speed_of(plain.states.back())), 1.0);  // the expert's drive ends moving
  for (std::size_t t = plain.states.size() + 1; t < waited.states.size(); ++t)
    EXPECT_NEAR(speed_of(waited.states[t]), 0.0, 1e-9) << t;
  p.end_wait_s = std::nan("");
  EXPECT_THROW(drive_as(p), InputError);
}

TEST(RealisticDriver, OneWhoKeepsTryingDrivesOnTowardsTheExpertsEndUntilItsTime) {
  RealisticDriverProfile p = clean(DriveDevice::Gamepad, 15);
  const ParkingTrial plain = drive_as(p);
  p.keeps_trying_until_s = 8.0;  // 40 control steps, twice the plan's
  const ParkingTrial trying = drive_as(p);
  ASSERT_EQ(trying.states.size(), 41u);
  for (std::size_t t = 0; t < plain.states.size(); ++t) EXPECT_EQ(trying.states[t], plain.states[t]) << t;
  // The plan leaves the car rolling; left alone it would roll on for 4 s. Trying, the learner acts on every step
  // and stays within a car length of where the expert's drive ended.
  EXPECT_GT(std::abs(speed_of(plain.states.back())), 1.0);
  for (std::size_t t = plain.actions.size(); t < trying.actions.size(); t += 3)
    EXPECT_NE(trying.actions[t], (ParkingAction{0.0, 0.0})) << t;
  const PathFollower follower(expert_drive());
  const VehicleState end = follower.expert_state(follower.substeps());
  const VehicleState last = vehicle_from_observation(trying.states.back());
  EXPECT_LT(std::hypot(last.x - end.x, last.y - end.y), parking::kCarLength);
  // Standing at the end comes first: one who gives up does not keep trying.
  p.end_wait_s = 1.0;
  EXPECT_EQ(drive_as(p).states.size(), plain.states.size() + 5);
}

TEST(RealisticDriver, PlantedDeficitsShowInTheActions) {
  const ParkingTrial e = expert_drive();
  RealisticDriverProfile p = clean(DriveDevice::MouseJoystick, 15);
  p.stick_noise = 0.1;
  p.deficit = PlantedDeficit::NeverReversing;
  Rng r1(2);
  for (const ParkingObservation& o : realistic_drive(e, p, r1).states) EXPECT_GE(speed_of(o), -1e-9);
  p.deficit = PlantedDeficit::WeakSteering;
  Rng r2(2);
  for (const ParkingAction& u : realistic_drive(e, p, r2).actions) EXPECT_LE(std::abs(u[1]), kWeakSteering);
  // Late braking: the expert's braking run starts at step 8 (u0 -0.9 against forward motion); the driver
  // coasts through its first kLateBrakingSeconds (3 control steps) and brakes from the 4th.
  const std::vector<bool> braking = expert_braking_steps(e);
  ASSERT_TRUE(braking[8]);
  EXPECT_FALSE(braking[7]);
  RealisticDriverProfile late = clean(DriveDevice::MouseJoystick, 5);
  late.deficit = PlantedDeficit::LateBraking;
  Rng r3(2);
  const ParkingTrial d = realistic_drive(e, late, r3);
  for (std::size_t t = 8; t < 11; ++t) EXPECT_EQ(d.actions[t][0], 0.0) << t;
  EXPECT_NEAR(d.actions[11][0], -0.9, 1e-9);
}

TEST(RealisticDriver, RefusesAnExpertAtTheSimulationRateAndBadProfiles) {
  ParkingTrial e = expert_drive();
  Rng rng(1);
  RealisticDriverProfile p;
  p.control_hz = 7;
  EXPECT_THROW(realistic_drive(e, p, rng), InputError);
  p = {};
  p.stick_noise = -0.1;
  EXPECT_THROW(realistic_drive(e, p, rng), InputError);
  e.control_hz = 15;
  EXPECT_THROW(realistic_drive(e, {}, rng), InputError);
}

TEST(RealisticDriver, NoviceProfilesStayInTheirDocumentedRanges) {
  Rng rng(5);
  for (int i = 0; i < 50; ++i) {
    const RealisticDriverProfile p = sample_novice_profile(DriveDevice::Keyboard, rng);
    EXPECT_EQ(p.device, DriveDevice::Keyboard);
    EXPECT_EQ(p.control_hz, 15);
    EXPECT_GE(p.stick_noise, 0.05);
    EXPECT_LT(p.stick_noise, 0.2);
    EXPECT_GE(p.reaction_delay_s, 0.1);
    EXPECT_LT(p.reaction_delay_s, 0.3);
  }
}

TEST(RealisticDriver, KeyboardKeysAreHeldFromHalfTheKeyAction) {
  EXPECT_EQ(keyboard_keys({0.8, -0.3}), (ParkingAction{1.0, 0.0}));
  EXPECT_EQ(keyboard_keys({-0.5, 0.51}), (ParkingAction{-1.0, 1.0}));
  EXPECT_EQ(keyboard_keys({0.49, -0.49}), (ParkingAction{0.0, 0.0}));
}

TEST(RealisticDriver, WithShiftTheSteeringIsTheNearestOfStraightHalfAndFullLock) {
  EXPECT_EQ(keyboard_keys({0.4, 0.24}, true), (ParkingAction{0.0, 0.0}));
  EXPECT_EQ(keyboard_keys({0.6, -0.25}, true), (ParkingAction{1.0, -0.5}));
  EXPECT_EQ(keyboard_keys({-0.6, 0.74}, true), (ParkingAction{-1.0, 0.5}));
  EXPECT_EQ(keyboard_keys({0.0, -0.75}, true), (ParkingAction{0.0, -1.0}));
  EXPECT_EQ(keyboard_keys({0.0, 0.6}, false), (ParkingAction{0.0, 1.0}));
  RealisticDriverProfile p = clean(DriveDevice::Keyboard, 5);
  p.shift_for_gentle_steering = true;
  const ParkingTrial d = drive_as(p);  // the hand-made drive steers at -0.3 and +0.9
  ASSERT_GE(d.actions.size(), 20u);
  EXPECT_EQ(d.actions[0], (ParkingAction{1.0, -0.5}));
  EXPECT_EQ(d.actions[19], (ParkingAction{-1.0, 1.0}));
}

// The expert drives with the pedal at its limit, so the keys must reach it: a drive of full-deflection and neutral
// actions is one a keyboard reproduces exactly, motion and all.
TEST(RealisticDriver, KeyboardReproducesADriveAtFullDeflectionExactly) {
  const ParkingTrial e = hand_made_drive({{6, {1.0, -1.0}}, {3, {-1.0, 0.0}}, {6, {-1.0, 1.0}}});
  Rng rng(1);
  const ParkingTrial d = realistic_drive(e, clean(DriveDevice::Keyboard, 5), rng);
  ASSERT_EQ(d.actions.size(), e.actions.size());
  EXPECT_EQ(d.actions, e.actions);
  ParkingSim sim(e.scenario);
  for (const ParkingAction& u : e.actions) sim.step(u);
  EXPECT_EQ(d.states.back(), sim.observation());
}

}  // namespace
}  // namespace sc
