#include "teaching/expertise/execution_expertise.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc {
namespace {

// Expert: skills 0, 1, 2 in order. The learner shows 0 and 1 (1 badly) and misses 2; reward -0.3.
ExecutionTrial trial() {
  ExecutionTrial t;
  t.trial.expert = {{{0, 0, 10}, {1, 10, 20}, {2, 20, 30}}};
  t.trial.student = {{{0, 0, 12}, {1, 12, 25}}};
  t.trial.student_reward = -0.3;
  t.segments = {{-0.01, 0, 12}, {-0.9, 12, 25}, {-0.2, 25, 30}};
  return t;
}

TEST(ExecutionExpertise, Alg2ModeIsAlg2Exactly) {
  const ExecutionExpertise e = estimate_execution_expertise({trial()}, 3, 2, ExpertiseMode::Alg2);
  const ExpertiseEstimate plain = estimate_expertise({trial().trial}, 3, 2);
  EXPECT_EQ(e.estimate.expertise, plain.expertise);
  EXPECT_EQ(e.estimate.targets, plain.targets);
  ASSERT_EQ(e.why.size(), 2u);
  EXPECT_EQ(e.why[0].skill, 2);
  EXPECT_EQ(e.why[0].reason, TargetReason::Missing);
  EXPECT_EQ(e.why[0].position, 3);
  // Skill 0 and 1 were shown: Alg. 2 has no penalty for the second target.
  EXPECT_EQ(e.why[1].reason, TargetReason::NoMistake);
  EXPECT_EQ(e.why[1].delta, 0.0);
}

// The same learner doing two more trials with nothing missing and an ordinary hand's scatter.
std::vector<ExecutionTrial> three_trials() {
  ExecutionTrial shown = trial();
  shown.trial.student = shown.trial.expert;
  shown.trial.student_reward = -0.2;
  ExecutionTrial b = shown, c = shown;
  b.segments = {{-0.15, 0, 10}, {-0.20, 10, 20}, {-0.25, 20, 30}};
  c.segments = {{-0.20, 0, 10}, {-0.10, 10, 20}, {-0.15, 20, 30}};
  ExecutionTrial a = trial();
  a.segments = {{-0.10, 0, 12}, {-0.90, 12, 25}, {-0.20, 25, 30}};
  return {a, b, c};
}

TEST(ExecutionExpertise, QualityAwareChargesASegmentByHowFarItFallsBeyondTheLearnersOutlierCut) {
  const ExecutionExpertise e = estimate_execution_expertise(three_trials(), 3, 2, ExpertiseMode::QualityAware);
  // The nine segment rewards have median -0.2 and median absolute deviation 0.05.
  const double cut = -0.2 - kOutlierCut * kMadToStandardDeviation * 0.05;
  EXPECT_DOUBLE_EQ(e.estimate.expertise[0], 0.0);
  EXPECT_NEAR(e.estimate.expertise[1], (-0.9 - cut) / 2, 1e-12);
  EXPECT_DOUBLE_EQ(e.estimate.expertise[2], -0.3 / 3);  // Alg. 2's: missing in the first trial
  // Skill 1 was shown (Alg. 2 never sees it) but done with a large error: now the first target.
  ASSERT_EQ(e.estimate.targets, (std::vector<int>{1, 2}));
  EXPECT_EQ(e.why[0].reason, TargetReason::LargeError);
  EXPECT_EQ(e.why[0].trial, 0);
  EXPECT_EQ(e.why[0].expert_begin, 10);
  EXPECT_EQ(e.why[0].learner_begin, 12);
  EXPECT_EQ(e.why[0].learner_end, 25);
  EXPECT_EQ(e.why[1].reason, TargetReason::Missing);
  EXPECT_STREQ(target_reason_words(e.why[0].reason), "done with a large error here");
}

TEST(ExecutionExpertise, AHandsOrdinaryScatterIsChargedNothing) {
  std::vector<ExecutionTrial> trials = three_trials();
  trials[0].segments[1].reward = -0.4;  // worse than the median, not an outlier
  const ExecutionExpertise e = estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware);
  std::vector<ExpertiseTrial> plain;
  for (const ExecutionTrial& t : trials) plain.push_back(t.trial);
  EXPECT_EQ(e.estimate.expertise, estimate_expertise(plain, 3, 2).expertise);
}

TEST(ExecutionExpertise, AHandThatDoesEverySkillEquallyBadlyIsChargedNoExecutionPenalty) {
  ExecutionTrial t = trial();
  t.trial.student = t.trial.expert;  // nothing missing
  for (SegmentExecution& s : t.segments) s.reward = -0.6;
  ExecutionTrial other = t;
  other.segments[2].reward = -0.95;  // one skill done worse than the rest
  const ExecutionExpertise even = estimate_execution_expertise({t, t}, 3, 2, ExpertiseMode::QualityAware);
  for (double e : even.estimate.expertise) EXPECT_DOUBLE_EQ(e, 0.0);
  const ExecutionExpertise uneven = estimate_execution_expertise({t, other}, 3, 2, ExpertiseMode::QualityAware);
  EXPECT_DOUBLE_EQ(uneven.estimate.expertise[2], -0.35 / 3);
  EXPECT_EQ(uneven.estimate.targets.front(), 2);
  EXPECT_EQ(uneven.why.front().reason, TargetReason::LargeError);
  EXPECT_EQ(uneven.why.front().trial, 1);
}

// trial(): skill 2 is missing from the segmentation, yet the learner's part aligned with it scores -0.2.
TEST(ExecutionExpertise, ANoiseFloorWaivesAMissingSkillDoneAsWellAsNoiseAllows) {
  const ExecutionExpertise waived = estimate_execution_expertise({trial()}, 3, 2, ExpertiseMode::QualityAware, -0.5);
  EXPECT_EQ(waived.estimate.expertise[2], 0.0);  // exactly: a waived skill is not "penalised" by a residue
  EXPECT_FALSE(waived.estimate.penalised(2));
  EXPECT_TRUE(waived.estimate.contributions[2].empty());
  for (const TargetWhy& w : waived.why) EXPECT_NE(w.reason, TargetReason::Missing);
  // Scoring worse than the floor, the miss is charged as Alg. 2 charges it.
  const ExecutionExpertise charged = estimate_execution_expertise({trial()}, 3, 2, ExpertiseMode::QualityAware, -0.1);
  EXPECT_DOUBLE_EQ(charged.estimate.expertise[2], -0.3 / 3);
  EXPECT_EQ(charged.why.front().skill, 2);
  EXPECT_EQ(charged.why.front().reason, TargetReason::Missing);
  // Alg. 2 mode ignores the floor; without one every miss is charged.
  EXPECT_DOUBLE_EQ(estimate_execution_expertise({trial()}, 3, 2, ExpertiseMode::Alg2, -0.5).estimate.expertise[2],
                   -0.3 / 3);
  EXPECT_DOUBLE_EQ(estimate_execution_expertise({trial()}, 3, 2, ExpertiseMode::QualityAware).estimate.expertise[2],
                   -0.3 / 3);
}

// A tidy learner: every segment within the tolerance but one slight wobble. The spread is 0, so the outlier
// cut alone charges the wobble; with a floor only what is worse than noise makes counts.
TEST(ExecutionExpertise, ANoiseFloorChargesOnlyWhatIsWorseThanNoiseMakes) {
  ExecutionTrial t = trial();
  t.trial.student = t.trial.expert;
  t.segments = {{0.0, 0, 10}, {-0.1, 10, 20}, {0.0, 20, 30}};
  ExecutionTrial tidy = t;
  tidy.segments[1].reward = 0.0;
  const std::vector<ExecutionTrial> wobble{t, tidy, tidy};
  EXPECT_DOUBLE_EQ(estimate_execution_expertise(wobble, 3, 2, ExpertiseMode::QualityAware).estimate.expertise[1],
                   -0.1 / 2);
  for (double e : estimate_execution_expertise(wobble, 3, 2, ExpertiseMode::QualityAware, -0.5).estimate.expertise)
    EXPECT_DOUBLE_EQ(e, 0.0);
  std::vector<ExecutionTrial> bad = wobble;
  bad[0].segments[1].reward = -0.8;
  const ExecutionExpertise e = estimate_execution_expertise(bad, 3, 2, ExpertiseMode::QualityAware, -0.5);
  EXPECT_NEAR(e.estimate.expertise[1], (-0.8 + 0.5) / 2, 1e-12);
  EXPECT_EQ(e.why.front().reason, TargetReason::LargeError);
  EXPECT_THROW(estimate_execution_expertise(bad, 3, 2, ExpertiseMode::QualityAware, 0.1), InputError);
}

TEST(ExecutionExpertise, RefusesScoresNotParallelToTheExpertOrPositive) {
  ExecutionTrial t = trial();
  t.segments.pop_back();
  EXPECT_THROW(estimate_execution_expertise({t}, 3, 2, ExpertiseMode::QualityAware), InputError);
  t = trial();
  t.segments[0].reward = 0.1;
  EXPECT_THROW(estimate_execution_expertise({t}, 3, 2, ExpertiseMode::QualityAware), InputError);
}

// Three trials, skills 0, 1, 2 all shown; each segment's score against the expert and against two references.
// The learner writes in a hand of its own: close to reference 0 except skill 2, which it does badly in every
// trial; against the expert, skill 1 (a shape the learner's hand does differently) looks worst.
std::vector<ExecutionTrial> own_hand_trials(double expert1, double ref0_of_skill2) {
  std::vector<ExecutionTrial> out;
  for (int t = 0; t < 3; ++t) {
    ExecutionTrial et;
    et.trial.expert = {{{0, 0, 10}, {1, 10, 20}, {2, 20, 30}}};
    et.trial.student = et.trial.expert;
    et.trial.student_reward = -0.2;
    const double scatter = 0.01 * t;
    et.segments = {{-0.1 - scatter, 0, 10, {-0.05 - scatter, -0.7}},
                   {expert1 - scatter, 10, 20, {-0.02 - scatter, -0.7}},
                   {-0.5 - scatter, 20, 30, {ref0_of_skill2 - scatter, -0.7}}};
    et.reference_names = {"hand 0", "hand 1"};
    out.push_back(et);
  }
  return out;
}

std::vector<ExecutionTrial> without_references(std::vector<ExecutionTrial> trials) {
  for (ExecutionTrial& t : trials) {
    t.reference_names.clear();
    for (SegmentExecution& s : t.segments) s.reference_rewards.clear();
  }
  return trials;
}

TEST(ExecutionExpertise, ALearnersOwnHandIsTheYardstickAndTheSkillDoneBadlyInItIsCharged) {
  const std::vector<ExecutionTrial> trials = own_hand_trials(-0.8, -0.5);
  const ExecutionExpertise mine = estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware);
  EXPECT_EQ(mine.learner_hands, std::vector<int>{0});
  EXPECT_EQ(mine.estimate.learner_hand, "hand 0");
  ASSERT_FALSE(mine.estimate.targets.empty());
  EXPECT_EQ(mine.estimate.targets[0], 2);
  EXPECT_EQ(mine.why[0].reason, TargetReason::LargeError);
  EXPECT_LT(mine.estimate.expertise[2], -0.1);
  EXPECT_EQ(mine.estimate.expertise[1], 0.0);  // the hand's own shape of skill 1 is not an error
  // Against the expert alone the scores scatter so widely (-0.1 / -0.8 / -0.5) that nothing stands out.
  const ExecutionExpertise expert_only =
      estimate_execution_expertise(without_references(trials), 3, 2, ExpertiseMode::QualityAware);
  EXPECT_TRUE(expert_only.learner_hands.empty());
  EXPECT_EQ(expert_only.estimate.learner_hand, "");
  EXPECT_EQ(expert_only.estimate.expertise[2], 0.0);
  // Alg. 2 never looks at the references.
  EXPECT_TRUE(estimate_execution_expertise(trials, 3, 2, ExpertiseMode::Alg2).learner_hands.empty());
}

TEST(ExecutionExpertise, NoHandIsTakenWhenTheExpertsOwnFitsBetterSoAnotherShapeOfOneSkillStaysAnError) {
  // A learner writing the expert's shapes (close to the expert) except skill 2, which matches reference 0.
  std::vector<ExecutionTrial> trials = own_hand_trials(-0.02, -0.01);
  for (ExecutionTrial& t : trials) {
    t.segments[0].reward = -0.01, t.segments[1].reward = -0.02;
    t.segments[0].reference_rewards[0] = -0.6, t.segments[1].reference_rewards[0] = -0.7;
  }
  const ExecutionExpertise e = estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware);
  EXPECT_TRUE(e.learner_hands.empty());
  ASSERT_FALSE(e.estimate.targets.empty());
  EXPECT_EQ(e.estimate.targets[0], 2);
  EXPECT_LT(e.estimate.expertise[2], -0.1);
}

TEST(ExecutionExpertise, AHandIsMoreThanOneSkillSoOneLetterInAnotherShapeCannotWaiveItself) {
  // The expert's shapes except skill 2, written in reference 0's shape and far from the expert's, so far that
  // reference 0 fits better over all segments; without skill 2 it fits worse than the expert.
  std::vector<ExecutionTrial> trials = own_hand_trials(-0.05, -0.01);
  for (ExecutionTrial& t : trials) {
    t.segments[0].reward = -0.05, t.segments[2].reward = -1.5;
    t.segments[0].reference_rewards[0] = -0.3, t.segments[1].reference_rewards[0] = -0.3;
  }
  const ExecutionExpertise e = estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware);
  EXPECT_TRUE(e.learner_hands.empty());
  ASSERT_FALSE(e.estimate.targets.empty());
  EXPECT_EQ(e.estimate.targets[0], 2);
  EXPECT_EQ(e.why[0].reason, TargetReason::LargeError);
  // Done in reference 0's shape on two skills, it is the learner's hand.
  for (ExecutionTrial& t : trials) t.segments[1].reward = -1.5, t.segments[1].reference_rewards[0] = -0.01;
  EXPECT_EQ(estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware).learner_hands, std::vector<int>{0});
}

// `n` trials of a tidy learner, skills 0, 1, 2 all shown; skill 1 scores `skill1[t]` in trial t, the rest about 0.
std::vector<ExecutionTrial> repeated_trials(const std::vector<double>& skill1) {
  std::vector<ExecutionTrial> out;
  for (std::size_t t = 0; t < skill1.size(); ++t) {
    ExecutionTrial et = trial();
    et.trial.student = et.trial.expert;
    const double scatter = 0.01 * static_cast<double>(t);
    et.segments = {{-0.01 - scatter, 0, 10}, {skill1[t], 10, 20}, {-0.02 - scatter, 20, 30}};
    out.push_back(et);
  }
  return out;
}

NoiseFloor with_repeated(double twice, double more) {
  NoiseFloor f(-0.5);
  f.repeated_twice = twice;
  f.repeated_more = more;
  return f;
}

TEST(ExecutionExpertise, ASkillDoneWorseThanNoiseMakesEveryTimeIsChargedThoughNoSegmentPassesTheFloor) {
  // Each of skill 1's three segments scores -0.3: above the segment floor (-0.5), but noise does not spoil
  // one skill three times; its median is below the floor for medians of three (-0.2).
  const std::vector<ExecutionTrial> three = repeated_trials({-0.3, -0.3, -0.3});
  EXPECT_DOUBLE_EQ(estimate_execution_expertise(three, 3, 2, ExpertiseMode::QualityAware, -0.5).estimate.expertise[1],
                   0.0);
  const ExecutionExpertise e =
      estimate_execution_expertise(three, 3, 2, ExpertiseMode::QualityAware, with_repeated(-0.15, -0.2));
  EXPECT_NEAR(e.estimate.expertise[1], 3 * (-0.3 + 0.2) / 2, 1e-12);
  EXPECT_DOUBLE_EQ(e.estimate.expertise[0], 0.0);
  ASSERT_FALSE(e.estimate.targets.empty());
  EXPECT_EQ(e.estimate.targets[0], 1);
  EXPECT_EQ(e.why[0].reason, TargetReason::RepeatedError);
  EXPECT_STREQ(target_reason_words(e.why[0].reason), "done a little wrong every time");
  for (const ExpertiseContribution& c : e.estimate.contributions[1]) EXPECT_TRUE(c.execution && c.repeated);
  // Once in three is not repeated: the median is the learner's usual.
  const std::vector<ExecutionTrial> once = repeated_trials({-0.3, -0.02, -0.03});
  EXPECT_DOUBLE_EQ(estimate_execution_expertise(once, 3, 2, ExpertiseMode::QualityAware, with_repeated(-0.15, -0.2))
                       .estimate.expertise[1],
                   0.0);
}

TEST(ExecutionExpertise, TwoSegmentsAreJudgedByTheirMeanAgainstTheFloorForTwo) {
  const std::vector<ExecutionTrial> two = repeated_trials({-0.3, -0.1});  // mean -0.2
  const ExecutionExpertise e =
      estimate_execution_expertise(two, 3, 2, ExpertiseMode::QualityAware, with_repeated(-0.15, -0.5));
  EXPECT_NEAR(e.estimate.expertise[1], (-0.3 + 0.15) / 2, 1e-12);  // only the part beyond -0.15 counts
  EXPECT_DOUBLE_EQ(estimate_execution_expertise(two, 3, 2, ExpertiseMode::QualityAware, with_repeated(-0.25, -0.05))
                       .estimate.expertise[1],
                   0.0);  // -0.2 is within the floor for two; the floor for three or more does not apply to two
  EXPECT_DOUBLE_EQ(median_score({-0.3, -0.1}), -0.2);
  EXPECT_DOUBLE_EQ(median_score({-0.3, -0.1, -0.9, 0.0}), -0.2);
  EXPECT_THROW(median_score({}), InputError);
}

TEST(ExecutionExpertise, ALearnerInAHandOfItsOwnIsNotChargedForRepeatedDifferences) {
  // own_hand_trials: the learner takes reference 0 as its hand; its skill 1 differs from the expert's in every
  // trial by style and is within the hand. Repeated floors close to 0 would charge every skill of an expert's hand.
  const std::vector<ExecutionTrial> trials = own_hand_trials(-0.8, -0.01);
  const NoiseFloor tight = with_repeated(-0.001, -0.001);
  const ExecutionExpertise e = estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware, tight);
  EXPECT_EQ(e.learner_hands, std::vector<int>{0});
  for (double x : e.estimate.expertise) EXPECT_DOUBLE_EQ(x, 0.0);
  // The same scores with nothing to take as a hand: every skill is repeatedly worse than the tight floors.
  const ExecutionExpertise plain =
      estimate_execution_expertise(without_references(trials), 3, 2, ExpertiseMode::QualityAware, tight);
  for (double x : plain.estimate.expertise) EXPECT_LT(x, 0.0);
  NoiseFloor positive = tight;
  positive.repeated_more = 0.1;
  EXPECT_THROW(estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware, positive), InputError);
}

TEST(ExecutionExpertise, RefusesSegmentsScoredAgainstDifferentReferences) {
  std::vector<ExecutionTrial> trials = own_hand_trials(-0.8, -0.5);
  trials[1].segments[2].reference_rewards.pop_back();
  EXPECT_THROW(estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware), InputError);
  trials = own_hand_trials(-0.8, -0.5);
  trials[0].segments[0].reference_rewards[1] = 0.3;
  EXPECT_THROW(estimate_execution_expertise(trials, 3, 2, ExpertiseMode::QualityAware), InputError);
}

TEST(ExecutionExpertise, EveryModeHasOneNameThatParsesBack) {
  EXPECT_EQ(expertise_mode_name(ExpertiseMode::Alg2), "alg2");
  EXPECT_EQ(expertise_mode_name(ExpertiseMode::QualityAware), "quality-aware");
  ASSERT_EQ(expertise_modes_by_name().size(), 2u);
  for (const auto& [name, mode] : expertise_modes_by_name()) EXPECT_EQ(expertise_mode_name(mode), name);
}

}  // namespace
}  // namespace sc
