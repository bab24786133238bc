#include "teaching/skills/restart_choice.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sc {
namespace {

TEST(RestartChoice, LowestValidationNllWithoutUnits) {
  EXPECT_EQ(choose_restart({{75.0, NAN}, {49.6, NAN}}), 1u);
  EXPECT_EQ(choose_restart({{49.6, NAN}, {75.0, NAN}, {60.0, NAN}}), 0u);
}

TEST(RestartChoice, TiesAndMissingValidationGoToTheLowerIndex) {
  EXPECT_EQ(choose_restart({{5.0, NAN}, {5.0, NAN}}), 0u);
  EXPECT_EQ(choose_restart({{NAN, NAN}, {NAN, NAN}}), 0u);
  EXPECT_EQ(choose_restart({{NAN, 0.7}, {NAN, 0.8}}), 0u);
}

// The 333 x 2 writing run of docs/skills.md: the restart with the lower NLL had not separated its units.
TEST(RestartChoice, ARestartWhoseUnitsStayedMergedIsNotKeptForItsNll) {
  EXPECT_EQ(choose_restart({{50.0, 3.13}, {75.0, 0.72}}), 1u);
  EXPECT_EQ(choose_restart({{75.0, 0.72}, {50.0, 3.13}}), 0u);
}

TEST(RestartChoice, UnitTermsWithinTheSlackLeaveTheChoiceToTheNll) {
  EXPECT_EQ(choose_restart({{75.0, 0.70}, {49.6, 0.76}}), 1u);
  EXPECT_EQ(choose_restart({{75.0, 0.70}, {49.6, 0.70 + kUnitTermSlack}}), 1u);
  EXPECT_EQ(choose_restart({{75.0, 0.70}, {49.6, 0.71 + kUnitTermSlack}}), 0u);
}

TEST(RestartChoice, UnitTermsAreComparedOnlyWhenEveryRunHasOne) {
  EXPECT_EQ(choose_restart({{75.0, 0.7}, {49.6, NAN}}), 1u);
}

TEST(RestartChoice, AScoreOnEveryCandidateDecidesBeforeTheNll) {
  EXPECT_EQ(choose_restart({{49.6, NAN, 0.60}, {75.0, NAN, 0.85}}), 1u);
  EXPECT_EQ(choose_restart({{49.6, 0.70, 0.85}, {75.0, 0.72, 0.60}}), 0u);
  // Equal scores: the NLL, then the index.
  EXPECT_EQ(choose_restart({{75.0, NAN, 0.8}, {49.6, NAN, 0.8}}), 1u);
  EXPECT_EQ(choose_restart({{49.6, NAN, 0.8}, {49.6, NAN, 0.8}}), 0u);
}

TEST(RestartChoice, AScoreMissingOnACandidateLeavesTheChoiceToTheNll) {
  EXPECT_EQ(choose_restart({{49.6, NAN, NAN}, {75.0, NAN, 0.85}}), 0u);
}

// A restart that merged its units is no candidate however consistent it looks; scores of non-candidates
// (even NaN) do not matter.
TEST(RestartChoice, AScoreNeverBringsBackARestartWhoseUnitsStayedMerged) {
  EXPECT_EQ(choose_restart({{75.0, 0.72, 0.60}, {50.0, 3.13, 0.99}}), 0u);
  EXPECT_EQ(choose_restart({{75.0, 0.72, 0.60}, {50.0, 3.13, NAN}, {80.0, 0.70, 0.70}}), 2u);
}

}  // namespace
}  // namespace sc
