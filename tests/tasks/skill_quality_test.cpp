#include "teaching/tasks/skill_quality.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

using test::segments_of;

SkillDemo word_demo(int length, std::vector<int> boundaries) {
  SkillDemo d;
  d.steps.action_dim = 2;
  d.steps.actions.assign(static_cast<std::size_t>(2 * length), 1.0f);
  d.true_boundaries = std::move(boundaries);
  return d;
}

TEST(WritingBoundaryScore, ToleranceIsFivePercentOfEachWordsLength) {
  // 1000 steps -> +-50; 200 steps -> +-10.
  const std::vector<SkillDemo> demos = {word_demo(1000, {300, 600}), word_demo(200, {100})};
  const std::vector<Segmentation> predicted = {segments_of({{0, 350}, {1, 251}, {2, 399}}),  // 350 ok, 601 ok
                                               segments_of({{0, 111}, {1, 89}})};            // 111 misses 100
  const BoundaryScore s = writing_boundary_score(predicted, demos);
  EXPECT_EQ(s.true_positives, 2);
  EXPECT_EQ(s.false_positives, 1);
  EXPECT_EQ(s.false_negatives, 1);
  EXPECT_DOUBLE_EQ(s.f1(), 2.0 / 3.0);
}

TEST(WritingBoundaryScore, OnePredictionMatchesOneTrueBoundaryOnly) {
  const BoundaryScore s = writing_boundary_score({segments_of({{0, 500}, {1, 500}})}, {word_demo(1000, {480, 520})});
  EXPECT_EQ(s.true_positives, 1);
  EXPECT_EQ(s.false_negatives, 1);
}

TEST(WritingSymbolPurity, CountsEachSkillsStepsByTheTrueSymbolUnderThem) {
  // "ab-": a = [0, 10), b = [10, 20), - = [20, 24). Skill 3 draws a and half of b, skill 5 the rest.
  SkillDemo demo = word_demo(24, {10, 20});
  demo.label = "ab-";
  const WritingSymbolReport r = writing_symbol_purity({segments_of({{3, 15}, {5, 9}})}, {demo});
  ASSERT_EQ(r.skills.size(), 2u);
  EXPECT_EQ(r.skills[0].skill, 3);
  EXPECT_EQ(r.skills[0].majority(), 'a');
  EXPECT_DOUBLE_EQ(r.skills[0].purity(), 10.0 / 15.0);
  EXPECT_EQ(r.skills[1].majority(), 'b');  // 5 steps of b, 4 of -
  EXPECT_DOUBLE_EQ(r.purity, (10.0 + 5.0) / 24.0);
  EXPECT_EQ(r.symbol_skill.at('a'), 3);
  EXPECT_EQ(r.symbol_skill.at('b'), 3);  // 5 steps each: the smaller skill id
  EXPECT_EQ(r.symbol_skill.at('-'), 5);
}

TEST(WritingSymbolPurity, SkipsDemosWhoseLabelIsNotOneCharacterPerSymbol) {
  SkillDemo demo = word_demo(24, {10, 20});
  demo.label = "trial-07.json";
  EXPECT_TRUE(writing_symbol_purity({segments_of({{0, 24}})}, {demo}).skills.empty());
}

// A 12-D parking step sequence whose car drives with the given signed speeds (heading along +x).
StepSequence parking_steps(const std::vector<double>& speeds, const std::vector<double>& steering) {
  StepSequence s;
  s.state_dim = kParkingStateDim;
  s.action_dim = kParkingActionDim;
  for (std::size_t t = 0; t < speeds.size(); ++t) {
    std::vector<float> o(kParkingStateDim, 0.0f);
    o[2] = static_cast<float>(speeds[t] / 5.0);  // vx / 5
    o[4] = 1.0f;                                 // cos(heading)
    s.states.insert(s.states.end(), o.begin(), o.end());
    s.actions.push_back(0.0f);
    s.actions.push_back(static_cast<float>(steering[t]));
  }
  return s;
}

TEST(ParkingStepKind, ReversingReadsTheSpeedAfterTheStepAndTurnTheSteering) {
  const StepSequence s = parking_steps({0.0, -2.0, -1.0, 3.0}, {0.5, -0.5, 0.05, 0.0});
  EXPECT_TRUE(classify_parking_step(s, 0).reversing);  // speed after step 0 is -2
  EXPECT_EQ(classify_parking_step(s, 0).turn, 1);
  EXPECT_EQ(classify_parking_step(s, 1).turn, -1);
  EXPECT_EQ(classify_parking_step(s, 2).turn, 0);
  EXPECT_FALSE(classify_parking_step(s, 2).reversing);  // speed after step 2 is +3
  EXPECT_FALSE(classify_parking_step(s, 3).reversing);  // last step: its own state
}

TEST(ParkingSkillPurity, SharesPerSkillAndStepWeightedPurity) {
  // Speeds after each step: steps 0-3 forward and straight, steps 4-7 reversing and steering left.
  const std::vector<double> speeds = {0, 1, 1, 1, 1, -1, -1, -1};
  const std::vector<double> steer = {0, 0, 0, 0, 0.8, 0.8, 0.8, 0.8};
  const StepSequence s = parking_steps(speeds, steer);
  const ParkingPurityReport pure = parking_skill_purity({segments_of({{0, 4}, {1, 4}})}, {s});
  ASSERT_EQ(pure.skills.size(), 2u);
  EXPECT_DOUBLE_EQ(pure.skills[1].reversing, 1.0);
  EXPECT_DOUBLE_EQ(pure.skills[1].left, 1.0);
  EXPECT_DOUBLE_EQ(pure.skills[0].forward, 1.0);
  EXPECT_DOUBLE_EQ(pure.skills[0].straight, 1.0);
  EXPECT_DOUBLE_EQ(pure.direction_purity, 1.0);
  EXPECT_DOUBLE_EQ(pure.turn_purity, 1.0);
  // One skill over everything mixes both; a third of it split differently gives the weighted mean.
  const ParkingPurityReport mixed = parking_skill_purity({segments_of({{3, 8}})}, {s});
  ASSERT_EQ(mixed.skills.size(), 1u);
  EXPECT_DOUBLE_EQ(mixed.skills[0].reversing, 0.5);
  EXPECT_DOUBLE_EQ(mixed.skills[0].left, 0.5);
  EXPECT_DOUBLE_EQ(mixed.direction_purity, 0.5);
  const ParkingPurityReport weighted = parking_skill_purity({segments_of({{0, 2}, {1, 6}})}, {s});
  EXPECT_DOUBLE_EQ(weighted.direction_purity, (2 * 1.0 + 6 * (4.0 / 6.0)) / 8.0);
}

TEST(ParkingSkillPurity, RefusesStepsThatAreNotParkingShaped) {
  StepSequence writing;
  writing.state_dim = 13;
  writing.action_dim = 2;
  writing.states.assign(13, 0.0f);
  writing.actions.assign(2, 0.0f);
  EXPECT_THROW(parking_skill_purity({segments_of({{0, 1}})}, {writing}), InputError);
}

TEST(SkillQualityReport, WritingHasBoundariesAndParkingHasPurity) {
  SkillDataSet words{"writing", "two words", {word_demo(100, {50}), word_demo(100, {40})}, {}, {}};
  const Json w = skill_quality_report(words, {segments_of({{0, 50}, {1, 50}}), segments_of({{0, 100}})});
  EXPECT_EQ(w.at("boundaries").at("true_positives"), 1);
  EXPECT_EQ(w.at("boundaries").at("false_negatives"), 1);
  EXPECT_EQ(w.at("usage").at("skills_used"), 2);
  EXPECT_FALSE(w.contains("purity"));
  SkillDataSet lots{"parking", "one plan", {{"p", parking_steps({1, 1}, {0, 0}), {}}}, {}, {}};
  const Json p = skill_quality_report(lots, {segments_of({{0, 2}})});
  EXPECT_TRUE(p.contains("purity"));
  EXPECT_FALSE(p.contains("boundaries"));
  EXPECT_THROW(skill_quality_report(lots, {}), InputError);
}

}  // namespace
}  // namespace sc
