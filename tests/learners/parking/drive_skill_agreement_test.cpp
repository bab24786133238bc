#include "teaching/learners/parking/drive_skill_agreement.hpp"

#include <gtest/gtest.h>

#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "tests/support/action_sign_extractor.hpp"

namespace sc {
namespace {

Segmentation segs(std::vector<SkillSegment> s) { return {std::move(s)}; }

TEST(DriveSkillAgreement, SkillPerStepMarksUncoveredStepsWithMinusOne) {
  EXPECT_EQ(skill_per_step(segs({{2, 0, 2}, {5, 3, 4}}), 5), (std::vector<int>{2, 2, -1, 5, -1}));
}

TEST(DriveSkillAgreement, ComparesTheDelayedDriveWithTheCleanOne) {
  const Segmentation clean = segs({{1, 0, 4}, {2, 4, 8}});
  // The driver is two steps late: the same skills, shifted.
  const Segmentation late = segs({{1, 0, 6}, {2, 6, 10}});
  const StepAgreement shifted = step_agreement(clean, 8, late, 10, 2);
  EXPECT_EQ(shifted.steps, 8);
  EXPECT_EQ(shifted.agreed, 8);
  const StepAgreement unshifted = step_agreement(clean, 8, late, 10, 0);
  EXPECT_EQ(unshifted.agreed, 6);  // steps 4 and 5 differ
  EXPECT_DOUBLE_EQ(unshifted.share(), 0.75);
  // A drive that ended early (a collision) only counts the steps it has.
  EXPECT_EQ(step_agreement(clean, 8, late, 5, 2).steps, 3);
}

TEST(DriveSkillAgreement, PresenceCountsTheCleanDrivesDistinctSkillsFoundAnywhereInTheCopy) {
  const Segmentation clean = segs({{1, 0, 4}, {2, 4, 8}, {1, 8, 10}, {3, 10, 12}});
  // Skill 2 moved to the end and 3 replaced: 1 and 2 are present, 3 is not; order and place do not matter.
  const SkillPresence p = skill_presence(clean, segs({{1, 0, 6}, {4, 6, 9}, {2, 9, 12}}));
  EXPECT_EQ(p.skills, 3);
  EXPECT_EQ(p.present, 2);
  EXPECT_DOUBLE_EQ(skill_presence(clean, clean).share(), 1.0);
  EXPECT_EQ(skill_presence(segs({}), clean).skills, 0);
}

TEST(DriveSkillAgreement, StandardConditionsCoverEveryDeviceAndBothRates) {
  bool device[3] = {false, false, false}, five_hz = false, fifteen_hz = false;
  for (const DriveCondition& c : standard_drive_conditions()) {
    device[static_cast<int>(c.profile.device)] = true;
    five_hz |= c.profile.control_hz == 5;
    fifteen_hz |= c.profile.control_hz == 15;
    EXPECT_FALSE(c.name.empty());
  }
  EXPECT_TRUE(device[0] && device[1] && device[2]);
  EXPECT_TRUE(five_hz && fifteen_hz);
}

TEST(DriveSkillAgreement, PathFollowingConditionsAreTheNoisyOrKeyedStandardOnesWithTheLoopClosed) {
  const std::vector<DriveCondition> standard = standard_drive_conditions(), following = path_following_conditions();
  EXPECT_EQ(following.size(), standard.size() - 1);  // all but the noiseless gamepad
  for (const DriveCondition& c : following) {
    EXPECT_TRUE(c.profile.follows_path) << c.name;
    EXPECT_TRUE(c.profile.stick_noise > 0.0 || c.profile.device == DriveDevice::Keyboard) << c.name;
    EXPECT_NE(c.name.find(", follows the path"), std::string::npos) << c.name;
  }
  for (const DriveCondition& c : standard) EXPECT_FALSE(c.profile.follows_path) << c.name;
}

TEST(DriveSkillAgreement, GentleSteeringKeyConditionsAreTheKeyboardRowsWithShift) {
  std::vector<DriveCondition> keyboard;
  for (const DriveCondition& c : standard_drive_conditions())
    if (c.profile.device == DriveDevice::Keyboard) keyboard.push_back(c);
  const std::vector<DriveCondition> gentle = gentle_steering_key_conditions();
  ASSERT_EQ(gentle.size(), keyboard.size());
  ASSERT_FALSE(gentle.empty());
  for (std::size_t i = 0; i < gentle.size(); ++i) {
    EXPECT_TRUE(gentle[i].profile.shift_for_gentle_steering) << gentle[i].name;
    EXPECT_FALSE(keyboard[i].profile.shift_for_gentle_steering) << keyboard[i].name;
    EXPECT_EQ(gentle[i].profile.stick_noise, keyboard[i].profile.stick_noise);
    EXPECT_EQ(gentle[i].profile.reaction_delay_s, keyboard[i].profile.reaction_delay_s);
    EXPECT_EQ(gentle[i].name, "keyboard with Shift" + keyboard[i].name.substr(std::string("keyboard").size()));
  }
}

// Reads the steering's sign (left, straight, right): a model that reads actions.
test::ActionSignExtractor SteeringSignExtractor() { return test::ActionSignExtractor(1); }

TEST(DriveSkillAgreement, KeyedActionsOnTheCleanMotionChangeOnlyWhatAModelReadsFromActions) {
  ParkingTrial drive;
  drive.scenario = parking_pool_scenario(0, 0);
  for (int i = 0; i < 8; ++i) drive.actions.push_back({0.8, -0.3});  // a key is held from 0.5: no steering key
  for (int i = 0; i < 12; ++i) drive.actions.push_back({-0.6, 0.9});
  // The time heuristic never reads actions: every step agrees.
  const StepAgreement time = keyed_action_agreement(TimeHeuristicExtractor(3), {drive});
  EXPECT_EQ(time.steps, 20);
  EXPECT_EQ(time.agreed, 20);
  // The gentle left turn becomes "straight" on the keyboard: 8 of 20 steps change skill.
  const StepAgreement sign = keyed_action_agreement(SteeringSignExtractor(), {drive});
  EXPECT_EQ(sign.steps, 20);
  EXPECT_EQ(sign.agreed, 12);
}

TEST(DriveSkillAgreement, StandingStartConditionsShiftByTheWaitAndTheDelay) {
  // The expert's own motion, later: a model that reads only the steering agrees on every compared step.
  ParkingTrial drive;
  drive.scenario = parking_pool_scenario(0, 0);
  for (int i = 0; i < 8; ++i) drive.actions.push_back({0.8, -0.9});
  for (int i = 0; i < 8; ++i) drive.actions.push_back({-0.8, 0.9});
  const std::vector<DriveCondition> conditions = standing_start_conditions();
  ASSERT_EQ(conditions.size(), 4u);
  EXPECT_EQ(conditions[3].profile.end_wait_s, 5.0);
  EXPECT_EQ(conditions[0].profile.stick_noise, 0.0);
  EXPECT_EQ(conditions[1].profile.start_wait_s, 1.0);
  EXPECT_TRUE(conditions[2].profile.follows_path);
  const std::vector<AgreementRow> rows = measure_drive_agreement(SteeringSignExtractor(), {drive}, {conditions[0]}, 1);
  EXPECT_EQ(rows[0].agreement.steps, 16);
  EXPECT_EQ(rows[0].agreement.agreed, 16);
  DriveCondition waiting = conditions[0];
  waiting.profile.start_wait_s = 1.0;
  const std::vector<AgreementRow> waited = measure_drive_agreement(SteeringSignExtractor(), {drive}, {waiting}, 1);
  EXPECT_EQ(waited[0].agreement.steps, 16);
  EXPECT_EQ(waited[0].agreement.agreed, 16);
}

}  // namespace
}  // namespace sc
