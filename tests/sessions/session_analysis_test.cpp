#include "teaching/sessions/session_analysis.hpp"

#include <gtest/gtest.h>

#include "tests/sessions/toy_task_kit.hpp"

namespace sc {
namespace {

// The pre-test as the session builds it: pool scenarios 0..4, each with the expert's skills and steps.
std::vector<TestTrial> pretest(const test::ToyTaskKit& kit, int forget, int instead) {
  std::vector<TestTrial> out;
  for (int id = 0; id < 5; ++id) {
    const ExpertDemo& expert = kit.expert_pool()[static_cast<std::size_t>(id)];
    out.push_back(
        {id, expert.skills, test::toy_trial(id, test::toy_learner_gestures(id, forget, instead)), expert.steps});
  }
  return out;
}

int execution_penalties(const ExpertiseEstimate& e) {
  int count = 0;
  for (const auto& per_skill : e.contributions)
    for (const ExpertiseContribution& c : per_skill) count += c.execution && c.delta > 0.0;
  return count;
}

TEST(SessionAnalysis, TheKitsLearnersExpertiseDecidesTheEstimate) {
  const test::ToyTaskKit alg2(8, ExpertiseMode::Alg2), quality(8, ExpertiseMode::QualityAware);
  // Gesture 2 played as 3: skill 2 goes missing, and the 1-D car's positions drift from there on.
  const ExpertiseEstimate a = diagnose_trials(alg2, pretest(alg2, 2, 3));
  const ExpertiseEstimate q = diagnose_trials(quality, pretest(quality, 2, 3));
  const ExpertiseEstimate plain = estimate_expertise(expertise_trials(alg2, pretest(alg2, 2, 3)), test::kToySkills,
                                                     alg2.curriculum_config().drills.num_targets);
  EXPECT_EQ(a.expertise, plain.expertise);  // Alg. 2 exactly
  EXPECT_EQ(a.targets, plain.targets);
  EXPECT_EQ(execution_penalties(a), 0);
  EXPECT_GT(execution_penalties(q), 0);
  ASSERT_FALSE(a.targets.empty());
  ASSERT_FALSE(q.targets.empty());
  EXPECT_EQ(a.targets.front(), 2);
  // Quality-aware keeps Alg. 2's penalties and adds execution ones: no skill gains expertise.
  for (std::size_t m = 0; m < a.expertise.size(); ++m) EXPECT_LE(q.expertise[m], a.expertise[m]) << m;
}

TEST(SessionAnalysis, ALearnerWhoRepeatsTheExpertLosesNoExpertiseInEitherMode) {
  for (ExpertiseMode mode : {ExpertiseMode::Alg2, ExpertiseMode::QualityAware}) {
    const test::ToyTaskKit kit(8, mode);
    const ExpertiseEstimate e = diagnose_trials(kit, pretest(kit, -1, -1));
    for (double value : e.expertise) EXPECT_EQ(value, 0.0) << expertise_mode_name(mode);
  }
}

// The diagnosis page's pictures: the same estimate as the session's, and for each target the trial of its
// largest penalty with the learner's steps aligned with the expert's segment, inside that trial.
TEST(SessionAnalysis, TheDiagnosisWithPlacesIsTheSessionsDiagnosisAndSaysWhereEachTargetWentWrong) {
  for (ExpertiseMode mode : {ExpertiseMode::Alg2, ExpertiseMode::QualityAware}) {
    const test::ToyTaskKit kit(8, mode);
    const std::vector<TestTrial> trials = pretest(kit, 2, 3);
    const PlacedDiagnosis diagnosis = diagnosis_with_places(kit, trials);
    const ExecutionExpertise& placed = diagnosis.expertise;
    const ExpertiseEstimate plain = diagnose_trials(kit, trials);
    EXPECT_EQ(placed.estimate.expertise, plain.expertise) << expertise_mode_name(mode);
    EXPECT_EQ(placed.estimate.targets, plain.targets) << expertise_mode_name(mode);
    ASSERT_EQ(placed.why.size(), plain.targets.size());
    // Skill 2 is missing wherever the expert used it (quality-aware: or done badly, if that penalty is larger): its
    // place is a trial whose expert sequence holds it.
    ASSERT_EQ(placed.why.front().skill, 2) << expertise_mode_name(mode);
    const TargetWhy& why = placed.why.front();
    if (mode == ExpertiseMode::Alg2) {
      EXPECT_EQ(why.reason, TargetReason::Missing);
    }
    EXPECT_NE(why.reason, TargetReason::NoMistake);
    const TestTrial& trial = trials.at(static_cast<std::size_t>(why.trial));
    EXPECT_EQ(trial.expert.segments.at(static_cast<std::size_t>(why.position - 1)).skill, 2);
    EXPECT_LE(0, why.learner_begin);
    EXPECT_LT(why.learner_begin, why.learner_end);
    EXPECT_LE(why.learner_end, kit.steps_of(trial.trial).length());
    ASSERT_EQ(diagnosis.learner_steps.size(), trials.size());
    EXPECT_EQ(diagnosis.learner_steps.at(static_cast<std::size_t>(why.trial)), kit.steps_of(trial.trial).length());
  }
}

}  // namespace
}  // namespace sc
