#include "teaching/sessions/training_session.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "engine/core/error.hpp"
#include "tests/sessions/toy_task_kit.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;
using records::TrialKind;

fs::path fresh_dir(const std::string& name) { return test::fresh_scratch_dir("sessions_" + name); }

TimestampSource fixed_clock() {
  return [] { return std::string("2024-05-01T12:00:00.000Z"); };
}

SessionSettings toy_settings(StudyCondition condition = StudyCondition::Adaptive) {
  SessionSettings settings;
  settings.learner = "ada";
  settings.device = "keyboard";
  settings.condition = condition;
  settings.pretest_count = 3;
  settings.eval_count = 3;
  settings.seed = 7;
  return settings;
}

constexpr int kForget = 2;  // the scripted learner never shows gesture 2 in the pre-test ...
constexpr int kInstead = 0;

// ... and plays tests perfectly after practice (so evaluation improves).
void play_test_trial(TrainingSession& s) {
  const int id = s.test_scenario().at("id").get<int>();
  const bool before = s.phase() == SessionPhase::Pretest;
  const Json trial = before ? test::toy_trial(id, test::toy_learner_gestures(id, kForget, kInstead))
                            : test::toy_trial(id, test::toy_expert_gestures(id));
  const SubmittedTrial r = s.submit_test_trial(trial, {});
  EXPECT_TRUE(r.saved.stored) << r.saved.message;
}

void play_practice_slot(TrainingSession& s) {
  const int item = s.current_item();
  s.record_demo(item, Json{{"task", "toy"}, {"demo", item}}, {});
  s.submit_practice(test::toy_practice_trial(s.drill(item), -1, -1), {});
}

// Plays until the session reaches `stop` (or the summary).
void play_until(TrainingSession& s, SessionPhase stop, int stop_item = 0) {
  while (!(s.phase() == stop && s.item_index() >= stop_item) && s.phase() != SessionPhase::Summary) {
    switch (s.phase()) {
      case SessionPhase::Pretest:
      case SessionPhase::Evaluation:
        play_test_trial(s);
        break;
      case SessionPhase::Diagnosis:
        s.analyse();
        break;
      case SessionPhase::Drills:
        play_practice_slot(s);
        break;
      case SessionPhase::Summary:
        break;
    }
  }
}

TEST(TrainingSession, PretestUsesDiverseScenariosAndKeepsEveryTrialWithItsResumePoint) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("pretest"));
  TrainingSession s(kit, store, toy_settings(), fixed_clock());
  ASSERT_EQ(s.phase(), SessionPhase::Pretest);
  ASSERT_EQ(s.test_count(), 3);
  // Alg. 1 covers all four gestures with three scenarios.
  std::vector<int> covered;
  for (int pool : s.pretest_pool_indices())
    for (int m : kit.expert_pool()[static_cast<std::size_t>(pool)].skills.skills()) covered.push_back(m);
  std::sort(covered.begin(), covered.end());
  covered.erase(std::unique(covered.begin(), covered.end()), covered.end());
  EXPECT_EQ(covered.size(), 4u);
  EXPECT_DOUBLE_EQ(
      s.test_time_limit(),
      kit.time_limit_seconds(kit.expert_pool()[static_cast<std::size_t>(s.pretest_pool_indices()[0])].steps.length()));

  play_test_trial(s);
  auto point = store.find_unfinished_session("ada", "toy");
  ASSERT_TRUE(point);
  EXPECT_EQ(point->trials_done, 1);
  EXPECT_EQ(point->session.progress, (records::SessionProgress{1, SessionPhase::Pretest, 1}));
  play_until(s, SessionPhase::Diagnosis);
  point = store.find_unfinished_session("ada", "toy");
  EXPECT_EQ(point->session.progress.phase, SessionPhase::Diagnosis);
  const auto trials = store.trials_of_session(s.session_id());
  ASSERT_EQ(trials.size(), 3u);
  int penalised = 0;
  for (const auto& t : trials) {
    EXPECT_EQ(t.record.kind, TrialKind::Pretest);
    EXPECT_EQ(t.record.device, "keyboard");
    ASSERT_TRUE(t.record.score);
    EXPECT_LE(*t.record.score, 0.0);
    penalised += *t.record.score < 0.0 ? 1 : 0;  // the forgotten gesture costs reward where the expert uses it
  }
  EXPECT_GE(penalised, 1);
}

TEST(TrainingSession, DiagnosisTargetsTheSkillTheLearnerNeverShowedAndIsStored) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("diagnosis"));
  TrainingSession s(kit, store, toy_settings(StudyCondition::IndDrills), fixed_clock());
  play_until(s, SessionPhase::Diagnosis);
  s.analyse();
  EXPECT_LT(s.last_analysis_seconds(), 0.5);
  ASSERT_FALSE(s.diagnosis().targets.empty());
  EXPECT_EQ(s.diagnosis().targets.front(), kForget);
  EXPECT_LT(s.diagnosis().expertise[kForget], 0.0);
  EXPECT_EQ(s.phase(), SessionPhase::Drills);
  ASSERT_FALSE(s.curriculum().items.empty());
  EXPECT_EQ(s.curriculum().items.front().target_skills, std::vector<int>{kForget});
  const auto diagnoses = store.diagnoses_of_session(s.session_id());
  ASSERT_EQ(diagnoses.size(), 1u);
  EXPECT_EQ(diagnoses[0].extractor, "toy-runs");
  const auto curricula = store.curricula_of_session(s.session_id());
  ASSERT_EQ(curricula.size(), 1u);
  EXPECT_EQ(curricula[0].condition, "ind-drills");
  EXPECT_EQ(curricula[0].drills.size(), s.curriculum().items.size());
}

TEST(TrainingSession, PracticeFollowsTheBudgetAndEvaluationUsesFreshScenarios) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("practice"));
  TrainingSession s(kit, store, toy_settings(StudyCondition::Skills), fixed_clock());
  play_until(s, SessionPhase::Drills);
  int sessions = 0;
  for (const auto& item : s.curriculum().items) sessions += item.sessions;
  EXPECT_EQ(s.practice_slot_count(), sessions);
  EXPECT_EQ(s.session_of_slot(), 1);
  const int first = s.current_item();
  s.submit_extra_practice(first, test::toy_practice_trial(s.drill(first), -1, -1), {});
  EXPECT_EQ(s.item_index(), 0);  // "try again" does not use up the budget
  play_until(s, SessionPhase::Evaluation);
  const auto pretest = s.pretest_scenarios();
  for (const ExpertDemo& e : s.eval_experts())
    EXPECT_EQ(std::find(pretest.begin(), pretest.end(), e.scenario), pretest.end()) << e.scenario.dump();
  play_until(s, SessionPhase::Summary);
  const auto trials = store.trials_of_session(s.session_id());
  const auto count = [&](TrialKind k) {
    return std::count_if(trials.begin(), trials.end(), [k](const auto& t) { return t.record.kind == k; });
  };
  EXPECT_EQ(count(TrialKind::Pretest), 3);
  EXPECT_EQ(count(TrialKind::Practice), sessions + 1);
  EXPECT_EQ(count(TrialKind::Demo), sessions);
  EXPECT_EQ(count(TrialKind::Eval), 3);
}

TEST(TrainingSession, SummaryShowsTheImprovementAndPerSkillChanges) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("summary"));
  TrainingSession s(kit, store, toy_settings(), fixed_clock());
  play_until(s, SessionPhase::Summary);
  const RoundSummary summary = s.summary();
  EXPECT_LT(summary.pretest_mean, 0.0);
  EXPECT_DOUBLE_EQ(summary.eval_mean, 0.0);  // evaluation played like the expert
  EXPECT_GT(summary.improvement, 0.0);
  ASSERT_EQ(summary.skills.size(), static_cast<std::size_t>(test::kToySkills));
  EXPECT_LT(summary.skills[kForget].before, 0.0);
  EXPECT_DOUBLE_EQ(summary.skills[kForget].after, 0.0);
  EXPECT_TRUE(summary.skills[kForget].drilled);
  s.finish();
  EXPECT_FALSE(store.find_unfinished_session("ada", "toy"));
}

TEST(TrainingSession, SummaryMarksDrilledOnlyTheSkillsPractisedThisRoundWithTheirTrials) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("drilled"));
  TrainingSession s(kit, store, toy_settings(StudyCondition::IndDrills), fixed_clock());
  play_until(s, SessionPhase::Drills);
  ASSERT_GE(s.curriculum().items.size(), 2u);
  const int first_target = s.curriculum().items[0].target_skills.at(0);
  play_practice_slot(s);  // one slot, one extra attempt at it, then the learner ends practice early
  s.submit_extra_practice(0, test::toy_practice_trial(s.drill(0), -1, -1), {});
  s.skip_practice();
  play_until(s, SessionPhase::Summary);
  const RoundSummary summary = s.summary();
  int drilled = 0;
  for (const SkillChange& c : summary.skills) {
    drilled += c.drilled ? 1 : 0;
    EXPECT_EQ(c.drilled, c.practice_trials > 0);
  }
  EXPECT_EQ(drilled, 1);  // the diagnosis targeted more, but only one skill was practised
  EXPECT_EQ(summary.skills.at(static_cast<std::size_t>(first_target)).practice_trials, 2);
  EXPECT_EQ(summary.practice_trials, 2);

  // Whole trajectories practise no skill on its own: nothing is "drilled".
  records::LearnerStore other(fresh_dir("drilled_full"));
  TrainingSession full(kit, other, toy_settings(StudyCondition::FullTrajectory), fixed_clock());
  play_until(full, SessionPhase::Summary);
  for (const SkillChange& c : full.summary().skills) EXPECT_FALSE(c.drilled) << c.skill;
}

TEST(TrainingSession, RoundSizeComesFromTheSettingsIsRecordedAndTold) {
  const test::ToyTaskKit kit;
  const fs::path dir = fresh_dir("round_size");
  records::LearnerStore store(dir);
  SessionSettings settings = toy_settings(StudyCondition::IndDrills);
  settings.weak_skills = 1;
  settings.drills_per_weak_skill = 1;
  settings.goal_region = GoalRegion::StudyCorner;
  TrainingSession s(kit, store, settings, fixed_clock());
  play_until(s, SessionPhase::Drills);
  EXPECT_EQ(s.curriculum().trials(), 1);
  EXPECT_EQ(s.practice_slot_count(), 1);
  // The toy kit's limit is 0.4 s per step: the round's minutes are its slots' limits, rounded up.
  EXPECT_EQ(s.practice_minutes(), static_cast<int>(std::ceil(0.4 * s.curriculum().total_steps() / 60.0)));
  EXPECT_GE(s.practice_minutes(), 1);
  const auto point = store.find_unfinished_session("ada", "toy");
  ASSERT_TRUE(point);
  const auto resumed = TrainingSession::resume(kit, store, *point, fixed_clock());
  EXPECT_EQ(resumed->settings().weak_skills, 1);
  EXPECT_EQ(resumed->settings().drills_per_weak_skill, 1);
  EXPECT_EQ(resumed->settings().goal_region, GoalRegion::StudyCorner);
  EXPECT_EQ(settings_of_session(point->session).lot(), GoalRegion::StudyCorner);
  EXPECT_EQ(resumed->curriculum().items, s.curriculum().items);
  settings.drills_per_weak_skill = 0;
  EXPECT_THROW(TrainingSession(kit, store, settings, fixed_clock()), InputError);
}

TEST(TrainingSession, AdaptiveSessionContinuesWithAnotherRoundOnFreshScenarios) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("adaptive"));
  TrainingSession s(kit, store, toy_settings(), fixed_clock());
  play_until(s, SessionPhase::Summary);
  const auto first_eval = s.eval_experts();
  ASSERT_TRUE(s.can_continue());
  s.start_next_round();
  EXPECT_EQ(s.round(), 2);
  EXPECT_EQ(s.phase(), SessionPhase::Diagnosis);
  s.analyse();
  EXPECT_FALSE(s.curriculum().items.empty());
  play_until(s, SessionPhase::Evaluation);
  EXPECT_NE(s.eval_experts()[0].scenario, first_eval[0].scenario);
  play_until(s, SessionPhase::Summary);
  EXPECT_EQ(s.summary().round, 2);
  EXPECT_EQ(store.diagnoses_of_session(s.session_id()).size(), 2u);
}

TEST(TrainingSession, NonAdaptiveConditionsEndAfterOneRound) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("one_round"));
  TrainingSession s(kit, store, toy_settings(StudyCondition::FullTrajectory), fixed_clock());
  play_until(s, SessionPhase::Summary);
  EXPECT_FALSE(s.can_continue());
  EXPECT_THROW(s.start_next_round(), std::logic_error);
}

TEST(TrainingSession, RefusesWorkOfAnotherPhase) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("phases"));
  TrainingSession s(kit, store, toy_settings(), fixed_clock());
  // A caller's bug, not bad input: never shown to a learner as an input problem.
  EXPECT_THROW(s.analyse(), std::logic_error);
  EXPECT_THROW(s.submit_practice(test::toy_trial(0, {1}), {}), std::logic_error);
  EXPECT_THROW((void)s.summary(), std::logic_error);
  play_until(s, SessionPhase::Diagnosis);
  EXPECT_THROW(s.submit_test_trial(test::toy_trial(0, {1}), {}), std::logic_error);
  EXPECT_THROW((void)s.curriculum(), std::logic_error);
}

// Stops at every point of a session, forgets the in-memory session and resumes from the database: the
// resumed session is where the old one stopped, and finishing it stores the same trials as a session
// played without interruption.
TEST(TrainingSession, ResumesWhereItStoppedAtEveryPointOfTheSession) {
  const test::ToyTaskKit kit;
  std::vector<std::string> reference;
  {
    records::LearnerStore store(fresh_dir("resume_reference"));
    TrainingSession s(kit, store, toy_settings(), fixed_clock());
    play_until(s, SessionPhase::Summary);
    for (const auto& t : store.trials_of_session(s.session_id())) reference.push_back(t.record.trajectory_json);
  }
  struct Stop {
    SessionPhase phase;
    int item;
  };
  for (const Stop stop :
       {Stop{SessionPhase::Pretest, 2}, Stop{SessionPhase::Diagnosis, 0}, Stop{SessionPhase::Drills, 1},
        Stop{SessionPhase::Evaluation, 0}, Stop{SessionPhase::Evaluation, 2}}) {
    records::LearnerStore store(fresh_dir("resume"));
    records::SessionProgress at;
    {
      TrainingSession s(kit, store, toy_settings(), fixed_clock());
      play_until(s, stop.phase, stop.item);
      at = {s.round(), s.phase(), s.item_index()};
    }
    const auto point = store.find_unfinished_session("ada", "toy");
    ASSERT_TRUE(point);
    auto resumed = TrainingSession::resume(kit, store, *point, fixed_clock());
    EXPECT_EQ(resumed->round(), at.round);
    EXPECT_EQ(resumed->phase(), at.phase) << records::to_string(stop.phase);
    EXPECT_EQ(resumed->item_index(), at.item_index);
    play_until(*resumed, SessionPhase::Summary);
    std::vector<std::string> got;
    for (const auto& t : store.trials_of_session(resumed->session_id())) got.push_back(t.record.trajectory_json);
    EXPECT_EQ(got, reference) << "stopped at " << records::to_string(stop.phase) << " " << stop.item;
  }
}

TEST(TrainingSession, ResumeRefusesASessionOfAnotherTask) {
  const test::ToyTaskKit kit;
  records::LearnerStore store(fresh_dir("other_task"));
  records::NewSession session;
  session.learner = "ada";
  session.task = "parking";
  session.condition = "adaptive";
  session.started = "2024-05-01T12:00:00.000Z";
  store.ensure_learner("ada", session.started);
  store.begin_session(session);
  const auto point = store.find_unfinished_session("ada");
  ASSERT_TRUE(point);
  EXPECT_THROW(TrainingSession::resume(kit, store, *point, fixed_clock()), InputError);
}

}  // namespace
}  // namespace sc
